// compare.html and the comparison's plots: the models side by side on one self-contained page,
// and per channel every model over the measured data, divided by load and parity sign.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <frictionid/io/compare_report.hpp>
#include "io/estimate_text.hpp"
#include "io/html_page.hpp"
#include "io/report_parts.hpp"
#include "io/svg_plot.hpp"

namespace frictionid {
namespace {

using html::num_cell;
using svg::escape;

constexpr const char* kModelColours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e"};

const ParameterEstimate* find_param(const FitResult& f, const std::string& name) {
  for (const auto& p : f.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace

std::vector<ReportPlot> compare_plots(const ModelComparison& c, const Dataset& d) {
  std::vector<ReportPlot> plots;
  if (c.fits.empty()) return plots;
  const std::size_t n = d.rows();
  const auto& eps = c.fits.front().eps;
  if (eps.size() != n) return plots;
  const std::size_t step = plot_step(n);
  for (Channel ch : c.fits.front().channels) {
    const int ci = static_cast<int>(ch);
    const std::string name = channel_name(ch);
    const char* divisor = ch == Channel::T_x || ch == Channel::T_y ? "N" : "(N R)";
    svg::Plot p;
    p.title = name + ": measured and every model";
    p.x_label = "eps = v/(|omega| R)";
    p.y_label = fmt::format("{} / {} (parity sign removed)", name, divisor);
    p.log_x = true;
    if (step > 1) p.notes.push_back(plotted_rows_note(n));
    svg::Series measured{"measured", "#666666", svg::Mark::Dots, {}, {}};
    std::vector<svg::Series> models;
    for (std::size_t k = 0; k < c.fits.size(); ++k)
      models.push_back({c.fits[k].model, kModelColours[k % 5], svg::Mark::Dots, {}, {}});
    for (std::size_t i = 0; i < n; ++i) {
      if (!plotted_row(i, step) || !d.present[ci][i] || !(eps[i] > 0.0) || !std::isfinite(eps[i]))
        continue;
      const double s = collapse_factor(d, ch, i);
      measured.x.push_back(eps[i]);
      measured.y.push_back(d.value[ci][i] * s);
      for (std::size_t k = 0; k < c.fits.size(); ++k)
        if (c.fits[k].fitted[ci].size() == n) {
          models[k].x.push_back(eps[i]);
          models[k].y.push_back(c.fits[k].fitted[ci][i] * s);
        }
    }
    if (measured.x.empty()) continue;
    p.series.push_back(std::move(measured));
    for (auto& m : models) p.series.push_back(std::move(m));
    ReportPlot out;
    out.file = "compare_" + name + ".svg";
    out.heading = name;
    out.caption = fmt::format(
        "Measured {0} (grey) and each model's prediction at the same rows, divided by {1} and "
        "by the parity sign, against eps (rows with eps = 0 or inf left out).",
        name, divisor);
    if (step > 1) out.caption += " (" + plotted_rows_note(n) + ".)";
    out.svg = svg::render(p);
    plots.push_back(std::move(out));
  }
  return plots;
}

namespace {

// Each section below appends its lines to the page h; line() adds one and its newline.
void line(std::string& h, const std::string& s) {
  (h += s) += '\n';
}

void warnings_section(std::string& h, const ModelComparison& c) {
  std::vector<std::string> warnings;
  for (const auto& f : c.fits)
    for (const auto& w : f.warnings) warnings.push_back(f.model + ": " + w);
  if (warnings.empty()) {
    line(h, "<p class=\"ok\" id=\"warnings\">No warnings for any model.</p>");
    return;
  }
  line(h, "<div class=\"warnings\" id=\"warnings\"><h2>Warnings</h2><ul>");
  for (const auto& w : warnings) line(h, "<li>" + escape(w) + "</li>");
  line(h, "</ul></div>");
}

void quality_section(std::string& h, const ModelComparison& c) {
  const FitResult& first = c.fits.front();
  line(h, "<h2 id=\"quality\">Fit quality</h2>");
  std::string head =
      "<table class=\"sortable\"><thead><tr><th>model</th><th>cost</th><th>χ²</th><th>AIC</th>"
      "<th>ΔAIC</th><th>BIC</th><th>ΔBIC</th>";
  for (const auto& cs : first.channel_summaries)
    head +=
        fmt::format("<th>RMSE {0}</th><th>residual lag-1 corr. {0}</th>", channel_name(cs.channel));
  line(h, head + "</tr></thead><tbody>");
  for (std::size_t k = 0; k < c.fits.size(); ++k) {
    const FitResult& f = c.fits[k];
    std::string row =
        fmt::format("<tr data-model=\"{}\"><td>{}</td>", escape(f.model), escape(f.model));
    row += num_cell(f.cost) + num_cell(f.chi2) + num_cell(f.aic) + num_cell(c.delta_aic[k]) +
           num_cell(f.bic) + num_cell(c.delta_bic[k]);
    for (const auto& cs : first.channel_summaries) {
      const ChannelSummary* own = find_summary(f, cs.channel);
      row += num_cell(own ? own->rmse : std::nullopt);
      const auto it = c.residual_autocorrelation[k].find(channel_name(cs.channel));
      row += it == c.residual_autocorrelation[k].end()
                 ? std::string("<td class=\"num\">—</td>")
                 : fmt::format("<td class=\"num\" data-value=\"{}\">{:.2f}</td>", it->second,
                               it->second);
    }
    line(h, row + "</tr>");
  }
  line(h, "</tbody></table>");
  line(h,
       "<p>A residual lag-1 correlation near 1 (residuals ordered by eps) is a systematic shape "
       "misfit; near 0, noise. AIC and BIC: lower is better; the Δ columns are the differences "
       "to the best model.</p>");
}

void parameter_section(std::string& h, const ModelComparison& c) {
  line(h, "<h2 id=\"parameters\">Parameters</h2>");
  std::vector<std::string> names;
  for (const auto& f : c.fits)
    for (const auto& p : f.parameters)
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
  std::string head = "<table id=\"parameter-table\"><thead><tr><th>parameter</th>";
  for (const auto& f : c.fits)
    head += fmt::format("<th>{0}</th><th>{0} stderr</th>", escape(f.model));
  if (!c.implied_by_exact.empty()) head += "<th>implied by exact</th>";
  line(h, head + "</tr></thead><tbody>");
  for (const auto& name : names) {
    std::string row = fmt::format("<tr data-param=\"{0}\"><td>{0}</td>", escape(name));
    for (const auto& f : c.fits) {
      const ParameterEstimate* p = find_param(f, name);
      if (!p) {
        row += "<td></td><td></td>";
        continue;
      }
      // The value to the decimal place of its stderr's second digit (io/estimate_text.hpp).
      const EstimateText e = estimate_text(p->value, p->fixed ? std::nullopt : p->std_error);
      row += fmt::format("<td class=\"num\" data-model=\"{}\" data-value=\"{}\">{}</td>",
                         escape(f.model), p->value, escape(e.value_alone()));
      row += p->fixed       ? "<td>fixed</td>"
             : p->std_error ? html::text_cell(p->std_error, e.error_alone())
                            : "<td>not determined</td>";
    }
    if (!c.implied_by_exact.empty()) {
      const auto it = c.implied_by_exact.find(name);
      row += it == c.implied_by_exact.end() ? "<td></td>" : num_cell(it->second);
    }
    line(h, row + "</tr>");
  }
  line(h, "</tbody></table>");
}

// What the coefficients mean, the per-model report links and the plots.
void closing_sections(std::string& h, const ModelComparison& c,
                      const std::vector<ReportPlot>& plots) {
  line(h, "<h2 id=\"coefficients\">What the coefficients mean</h2><ul>");
  const auto notes = coefficient_notes(c);
  if (notes.empty()) line(h, "<li>no exact fit to compare with</li>");
  for (const auto& n : notes) line(h, "<li>" + escape(n) + "</li>");
  line(h, "</ul>");

  line(h, "<h2 id=\"models\">Per-model reports</h2><ul>");
  for (const auto& f : c.fits)
    line(h, fmt::format("<li><a href=\"{}/report.html\">{}</a></li>",
                        escape(compare_variant_directory(f.model)), escape(f.model)));
  line(h, "</ul>");

  for (const auto& p : plots) {
    line(h, fmt::format("<h2 id=\"plots-{0}\">{0}</h2>", escape(p.heading)));
    line(h, plot_figure(p));
  }
}

}  // namespace

std::string compare_html_page(const ModelComparison& c, const std::vector<ReportPlot>& plots,
                              const Provenance& provenance) {
  std::string h = html::page_start("frictionid compare");
  line(h, "<h1>frictionid compare</h1>");
  if (c.fits.empty()) {
    line(h, "<p>No models were fitted.</p>");
    return h + html::provenance_section(provenance) + html::page_end();
  }
  line(h,
       fmt::format("<p class=\"summary\">{} rows; the same rows, channels and whitening for every "
                   "model. Preferred by AIC: <strong>{}</strong>; by BIC: <strong>{}</strong>.</p>",
                   c.fits.front().rows, escape(c.preferred_by_aic), escape(c.preferred_by_bic)));
  warnings_section(h, c);
  quality_section(h, c);
  parameter_section(h, c);
  closing_sections(h, c, plots);
  return h + html::provenance_section(provenance) + html::page_end();
}

std::string compare_html(const ModelComparison& c, const Dataset& d, const Provenance& p,
                         const std::vector<std::string>& contacts) {
  const ModelComparison named = compare_named_variants(c, contacts);
  return compare_html_page(named, compare_plots(named, d), p);
}

}  // namespace frictionid
