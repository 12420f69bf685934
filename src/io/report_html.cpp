// report.html: the whole fit on one self-contained page. Plots are inline SVG, style and the
// small script are inline, and nothing is fetched (no http(s) URL anywhere), so the page opens
// from a file:// URL on a machine without network.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/estimate_text.hpp"
#include "io/html_page.hpp"
#include "io/report_parts.hpp"
#include "io/svg_plot.hpp"

namespace frictionid {
namespace {

using html::num_cell;
using html::text_cell;
using svg::escape;

// An id for a heading: letters, digits, '-' and '_' only.
std::string anchor(const std::string& s) {
  std::string out = "plots-";
  for (char ch : s)
    out += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-') ? ch : '-';
  return out;
}

// Each section below appends its lines to the page h (html::line).
using html::line;

// The answer at the top, one estimate per parameter, each kept on one line.
void result_line(std::string& h, const FitResult& r) {
  if (r.parameters.empty()) return;
  std::string items;
  for (const auto& item : result_items(r))
    items += (items.empty() ? "" : "; ") + ("<span class=\"estimate\">" + escape(item) + "</span>");
  line(h, "<p class=\"result\" id=\"result\"><strong>Result:</strong> " + items + ".</p>");
}

// Warnings first: they decide whether the numbers below can be used.
void warnings_section(std::string& h, const FitResult& r) {
  h += html::warnings_section(
      r.warnings, {},
      "No warnings: the fit converged without a sign of trouble the tool checks for.");
}

// The plot headings in order of first appearance.
std::vector<std::string> plot_headings(const std::vector<ReportPlot>& plots) {
  std::vector<std::string> headings;
  for (const auto& p : plots)
    if (std::find(headings.begin(), headings.end(), p.heading) == headings.end())
      headings.push_back(p.heading);
  return headings;
}

void navigation(std::string& h, const std::vector<std::string>& headings) {
  line(h, "<nav><a href=\"#parameters\">Parameters</a><a href=\"#correlation\">Correlation</a>");
  for (const auto& hd : headings)
    line(h, fmt::format("<a href=\"#{}\">{}</a>", anchor(hd), escape(hd)));
  line(h,
       "<a href=\"#statistics\">Statistics</a><a href=\"#solver\">Search and solver</a>"
       "<a href=\"#traceability\">Traceability</a><a href=\"#glossary\">Glossary</a></nav>");
}

// The ends to the digit that tells them apart (io/estimate_text.hpp), exact in data-value.
std::string interval_cells(const std::optional<std::array<double, 2>>& ci) {
  if (!ci) return num_cell(std::nullopt) + num_cell(std::nullopt);
  const auto [lo, hi] = interval_text((*ci)[0], (*ci)[1]);
  return text_cell((*ci)[0], lo) + text_cell((*ci)[1], hi);
}

// A standard error alone, to 2 significant digits, exact in data-value.
std::string stderr_cell(const std::optional<double>& s) {
  return text_cell(s, stderr_text(s));
}

void parameter_section(std::string& h, const FitResult& r) {
  line(h, "<h2 id=\"parameters\">Parameters</h2>");
  line(h,
       "<table class=\"sortable\" id=\"parameter-table\"><thead><tr><th>name</th><th>value</th>"
       "<th>stderr</th><th>95% interval low</th><th>95% interval high</th>"
       "<th>interval method</th><th>sandwich stderr</th>" +
           std::string(r.bootstrap_replicates > 0 ? "<th>bootstrap stderr</th><th>bootstrap "
                                                    "low</th><th>bootstrap high</th>"
                                                  : "") +
           "<th>initial</th><th>lower bound</th><th>upper bound</th><th>note</th></tr></thead>"
           "<tbody>");
  for (const auto& p : r.parameters) {
    std::string row = "<tr data-param=\"" + escape(p.name) + "\"><td>" + escape(p.name) + "</td>";
    // The value to the decimal place of its stderr's second digit, the stderr to two digits.
    const EstimateText e = estimate_text(p.value, p.std_error);
    row += text_cell(p.value, e.value_alone()) + text_cell(p.std_error, e.error_alone());
    row += interval_cells(chosen_interval(r, p));
    row += "<td class=\"interval-method\">" + escape(interval_method(r, p)) + "</td>";
    row += stderr_cell(p.std_error_sandwich);
    if (r.bootstrap_replicates > 0)
      row += stderr_cell(p.std_error_bootstrap) + interval_cells(p.ci95_bootstrap);
    row += num_cell(p.initial) + num_cell(p.lower) + num_cell(p.upper);
    row += "<td>" +
           escape(parameter_note(p, "at a bound: the stderr is not meaningful",
                                 "not determined by the data")) +
           "</td></tr>";
    line(h, row);
  }
  line(h, "</tbody></table>");
  line(h,
       std::string("<p>Click a column header to sort. The 95 % interval is ") +
           interval_caption(r) +
           "; the column interval method names each row's. The sandwich stderr assumes nothing "
           "about the noise." +
           (r.bootstrap_replicates > 0 ? " Bootstrap: " + std::to_string(r.bootstrap_replicates) +
                                             " wild (Rademacher) refits, percentile interval."
                                       : std::string()) +
           "</p>");
}

// One cell of the correlation heat map: coloured by the value, "—" where there is none.
std::string correlation_cell(const FitResult& r, std::size_t i, std::size_t k) {
  const bool have =
      i < r.correlation.size() && k < r.correlation[i].size() && std::isfinite(r.correlation[i][k]);
  if (!have) return "<td>—</td>";
  const double c = r.correlation[i][k];
  std::string text = fmt::format("{:.2f}", c);
  if (text == "-0.00") text = "0.00";
  const std::string background = correlation_colour(c);
  return fmt::format("<td style=\"background:{};color:{}\" data-value=\"{}\">{}</td>", background,
                     text_colour_on(background), c, text);
}

void correlation_section(std::string& h, const FitResult& r) {
  line(h, "<h2 id=\"correlation\">Correlation</h2>");
  if (r.correlation_names.empty()) {
    line(h, "<p>No free parameter with a standard error.</p>");
    return;
  }
  line(h, "<table class=\"heat\"><thead><tr><th></th>");
  std::string head;
  for (const auto& n : r.correlation_names) head += "<th>" + escape(n) + "</th>";
  line(h, head + "</tr></thead><tbody>");
  for (std::size_t i = 0; i < r.correlation_names.size(); ++i) {
    std::string row = "<tr><th>" + escape(r.correlation_names[i]) + "</th>";
    for (std::size_t k = 0; k < r.correlation_names.size(); ++k) row += correlation_cell(r, i, k);
    line(h, row + "</tr>");
  }
  line(h, "</tbody></table>");
  line(h,
       "<p>Red: positive, blue: negative. Near ±1 the data cannot tell the two parameters "
       "apart; their stderrs are then large together.</p>");
}

// One section per kind of plot, its channels' plots side by side in a grid (three columns on a
// wide screen, one on a narrow one).
void plot_sections(std::string& h, const std::vector<ReportPlot>& plots,
                   const std::vector<std::string>& headings) {
  if (plots.empty()) line(h, "<h2>Plots</h2><p>No channel had predictions to plot.</p>");
  for (const auto& hd : headings) {
    line(h, fmt::format("<h2 id=\"{}\">{}</h2>", anchor(hd), escape(hd)));
    line(h, fmt::format("<div class=\"plot-grid\" data-kind=\"{}\">", escape(hd)));
    for (const auto& p : plots)
      if (p.heading == hd) line(h, plot_figure(p));
    line(h, "</div>");
  }
}

void statistics_section(std::string& h, const FitResult& r) {
  line(h, "<h2 id=\"statistics\">Statistics</h2>");
  line(h, "<table><tbody>");
  const std::pair<const char*, std::string> stats[] = {
      {"cost (½ Σ loss of whitened residuals)", num(r.cost)},
      {"χ²", num(r.chi2)},
      {"residuals", std::to_string(r.residuals)},
      {"degrees of freedom", std::to_string(r.dof)},
      {"reduced χ²", num(r.reduced_chi2)},
      {"AIC", num(r.aic)},
      {"BIC", num(r.bic)},
      {"loss", escape(r.loss)},
      {"covariance", r.covariance_scaled_by_reduced_chi2 ? "scaled by the reduced χ²"
                                                         : "from absolute σ (not rescaled)"}};
  for (const auto& [name, value] : stats)
    line(h, fmt::format("<tr><th>{}</th><td class=\"num\">{}</td></tr>", name, value));
  line(h, "</tbody></table>");
  if (r.channel_summaries.empty()) return;
  line(h,
       "<table class=\"sortable\"><thead><tr><th>channel</th><th>unit</th><th>rows</th>"
       "<th>RMSE</th><th>R²</th><th>scale σ</th><th>scale source</th></tr></thead><tbody>");
  for (const auto& s : r.channel_summaries)
    line(h,
         fmt::format("<tr><td>{}</td><td>{}</td>{}{}{}{}<td>{}</td></tr>", channel_name(s.channel),
                     channel_unit(s.channel), num_cell(static_cast<double>(s.rows)),
                     num_cell(s.rmse), num_cell(s.r2), num_cell(s.scale), escape(s.scale_source)));
  line(h, "</tbody></table>");
  line(h,
       "<p>RMSE and the scale σ are in the channel's unit. N is the normal load; the newton is "
       "written out.</p>");
}

void solver_section(std::string& h, const FitResult& r) {
  line(h, "<h2 id=\"solver\">Global search and solver</h2><ul>");
  line(h, fmt::format("<li>global search: {}, seed {}, {} evaluations on {} subsampled rows</li>",
                      r.global.algorithm.empty() ? "none" : escape(r.global.algorithm),
                      r.global.seed, r.global.evaluations, r.global.subsample_rows));
  line(h, fmt::format("<li>local starts: {}, of which {} reached the best cost{}</li>",
                      r.global.starts, r.global.reached_best,
                      r.global.local_fits_on_subsample
                          ? " (fitted on the subsample; the best was then refined on all rows)"
                          : ""));
  line(h, fmt::format("<li>solver: {} iterations, termination {}, {}</li>", r.solver.iterations,
                      r.solver.termination.empty() ? "—" : escape(r.solver.termination),
                      r.solver.converged ? "converged" : "NOT converged"));
  line(h, "</ul>");
}

void glossary_section(std::string& h) {
  line(h, "<h2 id=\"glossary\">What these numbers mean</h2><dl>");
  const std::pair<const char*, const char*> glossary[] = {
      {"value ± stderr",
       "The fitted parameter and its standard error from the curvature of the cost at the "
       "optimum: about a 68 % chance that the true value is within one stderr, if the model is "
       "right."},
      {"95% interval",
       "value ± t(0.975, dof) × stderr: where the true value lies with 95 % "
       "confidence under the same assumptions."},
      {"at a bound",
       "The optimum sits on a bound given to the fit: the data push beyond it, and the stderr "
       "says nothing. Widen the bound or question the model."},
      {"eps",
       "The slip ratio v/(|ω| R): 0 is pure spin, large eps is pure sliding. By the model "
       "(docs/physics.md §2) the forces divided by N and the moments divided by N R depend on "
       "eps alone."},
      {"collapse plot",
       "Each channel divided by its load scale and parity sign against eps. If the physics "
       "holds, rows at all loads of one slip direction and spin sign fall on one curve, and the "
       "fitted line of that curve runs through them."},
      {"whitened residual",
       "(measured − fitted) / σ_i, with σ_i the noise the fit assumed for that row: standard "
       "deviation about 1 in every group for noise of the stated size; a trend against eps "
       "means the model's shape misses, a funnel that the noise model does not fit."},
      {"reduced χ²",
       "χ² per degree of freedom: near 1 when the residuals are as large as the noise scale "
       "says; much larger means misfit or an underestimated σ."},
      {"AIC, BIC",
       "Fit quality penalised by the number of parameters; lower is better, and only "
       "differences between models fitted to the same rows mean something."},
      {"correlation",
       "How strongly two parameter estimates move together; near ±1 they trade "
       "off and neither is well determined alone."}};
  for (const auto& [term, meaning] : glossary)
    line(h, fmt::format("<dt>{}</dt><dd>{}</dd>", escape(term), escape(meaning)));
  line(h, "</dl>");
  line(h,
       "<p>More in docs/physics.md (the model) and docs/design.md (report.json and the fit) of "
       "the frictionid sources.</p>");
}

}  // namespace

std::string correlation_colour(double c) {
  // White at 0, red towards +1, blue towards -1.
  const double t = std::isfinite(c) ? std::min(1.0, std::abs(c)) : 0.0;
  const int base[3] = {255, 255, 255};
  const int pos[3] = {214, 39, 40}, neg[3] = {31, 119, 180};
  const int* end = c >= 0 ? pos : neg;
  int rgb[3];
  for (int k = 0; k < 3; ++k)
    rgb[k] = static_cast<int>(std::lround(base[k] + (end[k] - base[k]) * t));
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

const char* text_colour_on(const std::string& background) {
  // WCAG 2 relative luminance of an sRGB colour "#rrggbb".
  double luminance = 1.0;
  if (background.size() == 7 && background[0] == '#') {
    const double weight[3] = {0.2126, 0.7152, 0.0722};
    luminance = 0;
    for (int k = 0; k < 3; ++k) {
      const double v = std::stoi(background.substr(1 + 2 * k, 2), nullptr, 16) / 255.0;
      luminance += weight[k] * (v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
    }
  }
  // Contrast (L1 + 0.05) / (L2 + 0.05) against white (L = 1) and against black (L = 0): the
  // larger is at least 4.58, where the two are equal (L = 0.179).
  return 1.05 / (luminance + 0.05) >= (luminance + 0.05) / 0.05 ? "#ffffff" : "#000000";
}

std::string report_html_page(const FitResult& r, const std::vector<ReportPlot>& plots,
                             const Provenance& provenance, const std::string& contact) {
  std::string h;
  h.reserve(64 * 1024);
  const std::string title = fmt::format("frictionid fit: model {}, pressure {}{}", escape(r.model),
                                        escape(r.pressure), escape(contact_words(contact)));

  h += html::page_start(title);
  line(h, "<h1>" + title + "</h1>");
  line(h,
       fmt::format("<p class=\"summary\">{} rows; fitted channels: {}; loss: {}; solver: {}.</p>",
                   r.rows, join_channels(r.channels), escape(r.loss),
                   r.solver.converged ? "converged" : "<strong>not converged</strong>"));
  result_line(h, r);
  warnings_section(h, r);
  const std::vector<std::string> headings = plot_headings(plots);
  navigation(h, headings);
  parameter_section(h, r);
  correlation_section(h, r);
  plot_sections(h, plots, headings);
  statistics_section(h, r);
  solver_section(h, r);
  h += html::provenance_section(provenance);
  glossary_section(h);
  h += html::page_end();
  return h;
}

}  // namespace frictionid
