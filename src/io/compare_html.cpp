// compare.html and the comparison's plots: the models side by side on one self-contained page,
// and per channel every model over the measured data, divided by load and parity sign.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <frictionid/io/compare_report.hpp>
#include "io/estimate_text.hpp"
#include "io/html_page.hpp"
#include "io/palette.hpp"
#include "io/report_parts.hpp"
#include "io/svg_plot.hpp"

namespace frictionid {
namespace {

using html::num_cell;
using svg::escape;

constexpr const char* kModelDashes[] = {"", "7 4", "2 3", "9 3 2 3", "4 4"};
// More curves (slip direction, spin sign, tilt sign) than this: models as dots, not lines.
constexpr std::size_t kMaxCompareCurves = 24;

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
    p.y_reference = 0.0;
    if (step > 1) p.notes.push_back(plotted_rows_note(n));
    svg::Series measured("measured", palette::kBackdrop, svg::Mark::Dots);
    measured.tag = "measured";
    // The plotted rows of each curve (slip_curve), sorted by eps: a model's collapsed
    // predictions along one curve are a line.
    std::map<SlipCurve, std::vector<std::size_t>> curves;
    for (std::size_t i = 0; i < n; ++i) {
      if (!plotted_row(i, step) || !d.present[ci][i] || !(eps[i] > 0.0) || !std::isfinite(eps[i]))
        continue;
      measured.x.push_back(eps[i]);
      measured.y.push_back(d.value[ci][i] * collapse_factor(d, ch, i));
      curves[slip_curve(d, i)].push_back(i);
    }
    if (measured.x.empty()) continue;
    if (measured.x.size() > 1500) measured.dot_size = 2.6, measured.opacity = 0.4;
    for (auto& [key, rows] : curves)
      std::stable_sort(rows.begin(), rows.end(),
                       [&](std::size_t a, std::size_t b) { return eps[a] < eps[b]; });
    const bool lines = curves.size() <= kMaxCompareCurves;
    p.series.push_back(std::move(measured));
    // Every model as lines, each in its colour and dash pattern with a white outline, so that a
    // model that agrees with another shows as a dashed line over it; with more curves than
    // kMaxCompareCurves, as dots of decreasing size, the first model's largest.
    for (std::size_t k = 0; k < c.fits.size(); ++k) {
      const auto& fitted = c.fits[k].fitted[ci];
      if (fitted.size() != n) continue;
      const char* colour = palette::series(k);
      if (!lines) {
        svg::Series dots(c.fits[k].model, colour, svg::Mark::Dots);
        dots.tag = c.fits[k].model;
        dots.dot_size = std::max(1.2, 3.4 - 0.7 * static_cast<double>(k));
        dots.opacity = 0.9;
        for (const auto& [key, rows] : curves)
          for (std::size_t i : rows) {
            dots.x.push_back(eps[i]);
            dots.y.push_back(fitted[i] * collapse_factor(d, ch, i));
          }
        p.series.push_back(std::move(dots));
        continue;
      }
      bool first = true;
      for (const auto& [key, rows] : curves) {
        svg::Series line(first ? c.fits[k].model : "", colour, svg::Mark::Line);
        first = false;
        line.tag = c.fits[k].model;
        line.outline = true;
        line.dash = kModelDashes[k % 5];
        for (std::size_t i : rows) {
          line.x.push_back(eps[i]);
          line.y.push_back(fitted[i] * collapse_factor(d, ch, i));
        }
        p.series.push_back(std::move(line));
      }
    }
    ReportPlot out;
    out.file = "compare_" + name + ".svg";
    out.heading = "Every model over the measured data";
    out.caption = fmt::format(
        "Measured {0} (grey dots) and each model's prediction at the same rows, divided by {1} "
        "and by the parity sign (sgn v_x for T_x, sgn omega for T_y and M_z), against eps (rows "
        "with eps = 0 or inf left out). {2}",
        name, divisor,
        lines ? "Each model is drawn as lines in its own colour and dash pattern, one line per "
                "slip direction, spin sign and tilt sign, sorted by eps; where two models "
                "agree their lines overlap and both dash patterns show."
              : fmt::format("More than {} slip directions and spin signs: each model as dots, "
                            "the later models' smaller, so that every model shows.",
                            kMaxCompareCurves));
    if (step > 1) out.caption += " (" + plotted_rows_note(n) + ".)";
    out.svg = svg::render(p);
    plots.push_back(std::move(out));
  }
  return plots;
}

namespace {

// Each section below appends its lines to the page h (html::line).
using html::line;

void warnings_section(std::string& h, const ModelComparison& c) {
  std::vector<std::string> warnings, models;
  for (const auto& f : c.fits)
    for (const auto& w : f.warnings) {
      warnings.push_back(w);
      models.push_back(f.model + ": ");
    }
  h += html::warnings_section(warnings, models, "No warnings for any model.");
}

void quality_section(std::string& h, const ModelComparison& c) {
  const FitResult& first = c.fits.front();
  line(h, "<h2 id=\"quality\">Fit quality</h2>");
  std::string head =
      "<table class=\"sortable\"><thead><tr><th>model</th><th>AIC</th><th>ΔAIC</th><th>BIC</th>"
      "<th>ΔBIC</th><th>χ², one noise</th>";
  for (const auto& cs : first.channel_summaries)
    head += fmt::format("<th>RMSE {0} [{1}]</th><th>residual lag-1 corr. {0}</th>",
                        channel_name(cs.channel), channel_unit(cs.channel));
  line(h, head + "</tr></thead><tbody>");
  for (std::size_t k = 0; k < c.fits.size(); ++k) {
    const FitResult& f = c.fits[k];
    std::string row =
        fmt::format("<tr data-model=\"{}\"><td>{}</td>", escape(f.model), escape(f.model));
    row +=
        num_cell(f.aic) + num_cell(c.delta_aic[k]) + num_cell(f.bic) + num_cell(c.delta_bic[k]) +
        num_cell(k < c.chi2_common.size() ? std::optional<double>(c.chi2_common[k]) : std::nullopt);
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
       "<p>AIC and BIC: lower is better; the Δ columns are the differences to the best model. "
       "They include the log-likelihood of each model's noise (docs/physics.md §8.7), so they "
       "compare models even where each estimates its own noise.</p>");
  if (compare_estimates_noise(c))
    line(h, fmt::format(
                "<p>χ², one noise: every model's residuals divided by the same sigma per row, "
                "that of the noise estimated for <strong>{}</strong> (the model AIC prefers), so "
                "that these χ² compare. Each model's own χ² (in compare.json) divides by its own "
                "noise estimate, which makes it close to the number of cells for every model: "
                "it does not rank them.</p>",
                escape(c.fits[std::min(c.common_noise_fit, c.fits.size() - 1)].model)));
  else
    line(h,
         "<p>χ², one noise: every model's residuals divided by the same sigma per row (the "
         "sigma columns or fixed scales, alike for every model).</p>");
  line(h,
       "<p>Residual lag-1 correlation: of the residuals (divided by the same sigma) in eps "
       "order along each curve of one slip direction, spin sign, tilt sign, load and radius, "
       "pooled over the curves. Near 1 is a systematic shape misfit; near 0, noise.</p>");
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

  if (plots.empty()) return;
  // Every channel's plot side by side (three columns on a wide screen, one on a narrow one).
  line(h, "<h2 id=\"plots\">Every model over the measured data</h2>");
  line(h, "<div class=\"plot-grid\" data-kind=\"compare\">");
  for (const auto& p : plots) line(h, plot_figure(p));
  line(h, "</div>");
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
  line(h, fmt::format("<p class=\"summary\">{} rows; the same rows and channels for every model, "
                      "{}. Preferred by AIC: <strong>{}</strong>; by BIC: <strong>{}</strong>.</p>",
                      c.fits.front().rows,
                      compare_estimates_noise(c)
                          ? "each whitened by its own noise estimate"
                          : "the same whitening for every model (sigma columns or fixed scales)",
                      escape(c.preferred_by_aic), escape(c.preferred_by_bic)));
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
