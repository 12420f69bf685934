// The pieces write_report assembles (include/frictionid/io/report_writer.hpp): plots, the HTML
// page and the channel lookup they share with the Markdown report.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/io/report_writer.hpp>
#include <frictionid/model_comparison.hpp>

namespace frictionid {

// The estimate of the parameter called name in f, or none.
inline const ParameterEstimate* find_param(const FitResult& f, const std::string& name) {
  for (const auto& p : f.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

// The 95 % interval of p that the reports show in p's row: the one r's interval method puts
// first (ci95 for "model", else the sandwich or profile interval), except that under "model" a
// parameter that has a profile interval (computed because it is nearly collinear with another
// one, |correlation| > 0.99) shows that. interval_method names the row's method for the
// parameter tables: "model (t·stderr)", "profile" (with "open below/above/on both sides (ends at
// the bound)" where a side did not close), "HC3 (t·sandwich stderr)", or "—" without an
// interval. interval_caption: the words for the tables' caption.
const std::optional<std::array<double, 2>>& chosen_interval(const FitResult& r,
                                                            const ParameterEstimate& p);
std::string interval_method(const FitResult& r, const ParameterEstimate& p);
const char* interval_caption(const FitResult& r);

// %.6g-style with the exponent as "× 10ⁿ" (plain_number in io/estimate_text.hpp); never prints
// "nan" (the reports promise no NaN text): "—" for NaN or absent. For a number without an error;
// estimates with one go through estimate_text.
std::string num(double x);
std::string num(const std::optional<double>& x);

// The result line at the top of report.md and report.html, one item per parameter in FitResult
// order: "f = 0.850039 ± 0.000072 (0.0085 %)" (estimate_text in io/estimate_text.hpp), or the
// value with why it has no error: "h = 0 (fixed)", "a = 4 (at a bound)", "m = 7.5 (not
// determined)". Plain text; the caller escapes it.
std::vector<std::string> result_items(const FitResult& r);

// The unit of channel c in labels and table headers: "newton" for the forces T_x, T_y, "newton
// metre" for the moments. Spelled out, never "N": on these pages N is the normal load (the
// model's symbol and the data's column), so "N [N]" would name the load in itself. Labels read
// "T_x [newton]", "N [newton]" (docs/design.md §4.3, "Units").
const char* channel_unit(Channel c);

// The channel names joined by ", "; "none" for no channel.
std::string join_channels(const std::vector<Channel>& cs);

// The note column of a parameter table: "fixed", at a bound, not determined by the data, joined
// by "; ". `at_bound` and `undetermined` are the words a report uses for the last two.
std::string parameter_note(const ParameterEstimate& p, const char* at_bound,
                           const char* undetermined);

// Warnings grouped by cause, the most severe cause first (the fit did not finish, the model
// misses a channel, outliers, the noise model, undetermined parameters, closed-form
// coefficients, other): the cause's heading, a one-line severity, whether a page shows it
// unfolded, and its warnings' indices in the order given. Causes without warnings are left out.
struct WarningGroup {
  std::string heading, severity;
  bool open = false;
  std::vector<std::size_t> warnings;
};
std::vector<WarningGroup> group_warnings(const std::vector<std::string>& warnings);

// The summary of channel c in r, or nullptr when c was not fitted.
const ChannelSummary* find_summary(const FitResult& r, Channel c);

// The plot files make_plots gives for r with default options: collapse_<c>.svg, fit_<c>.svg,
// residuals_<c>.svg, residuals_fitted_<c>.svg and qq_<c>.svg for every fitted channel.
std::vector<std::string> default_plot_files(const FitResult& r);

// Rows kept in plots: with more than kMaxPlotRows rows, about one in plot_step(rows), chosen by a
// fixed hash of the row number. Every k-th row would alias with a periodic test design (loads
// or slip angles cycling row by row) and show only some of its levels; the hash does not, and
// the same rows give the same plots.
inline constexpr std::size_t kMaxPlotRows = 4000;  // ~4000 dots already fill a 720x440 plot
std::size_t plot_step(std::size_t rows);
bool plotted_row(std::size_t row, std::size_t step);
// The sentence plots and captions use, e.g. "about 1 in 25 of 100000 rows plotted (...)"; empty
// when every row is plotted.
std::string plotted_rows_note(std::size_t rows);

// One plot of the report: written as `file` next to report.md and inlined in report.html.
struct ReportPlot {
  std::string file;  // e.g. "collapse_T_x.svg"
  // The section it belongs to: its kind ("Collapse plots", "Measured and fitted", ...,
  // "Against slip_angle" for --plot-x), whose plots, one per channel, stand side by side.
  std::string heading;
  std::string caption;  // what is drawn and how rows were chosen
  std::string svg;      // an <svg> element (io/svg_plot.hpp), no namespace attribute
};

// Every plot of the report, in report order (per channel: collapse, fit, residuals against eps
// and against the fitted value, normal quantiles; then the --plot-x plots). Channels without
// predictions are left out. Throws std::invalid_argument when a column named in `o` is not in the
// dataset or (for plot_x) not numeric.
std::vector<ReportPlot> make_plots(const FitResult& r, const Dataset& d, const ReportOptions& o);

// A plot as an HTML <figure>: the inline SVG and a caption linking its file (no final newline).
std::string plot_figure(const ReportPlot& p);

// The correlation heat map's cell colour for a correlation c in [-1, 1] ("#rrggbb"): white at
// 0, towards red at +1 and blue at -1.
std::string correlation_colour(double c);

// The text colour, "#000000" or "#ffffff", with the higher WCAG 2 contrast against the
// background "#rrggbb" (from its relative luminance): at least 4.58:1 on any colour, above the
// 4.5:1 of WCAG AA.
const char* text_colour_on(const std::string& background);

// report.html from the plots make_plots gave.
std::string report_html_page(const FitResult& r, const std::vector<ReportPlot>& plots,
                             const Provenance& p = {}, const std::string& contact = "circle");

// ", contact ellipse:0.6" for a report's title; empty for the circle (plain text).
std::string contact_words(const std::string& contact);

// Whether any compared fit estimated a channel's noise: then each model is whitened by its own
// estimate, and only the chi2 under one noise (ModelComparison::chi2_common) compares.
bool compare_estimates_noise(const ModelComparison& c);

// Per channel every compared model over the measured data (compare_<channel>.svg), and
// compare.html from them.
std::vector<ReportPlot> compare_plots(const ModelComparison& c, const Dataset& d);
std::string compare_html_page(const ModelComparison& c, const std::vector<ReportPlot>& plots,
                              const Provenance& p = {});

// The provenance (io/provenance.hpp) as a Markdown section "## Traceability" with one bullet per
// line, ending in an empty line.
std::string provenance_markdown(const Provenance& p);

// report.json, report.md, report.html and the plots written into dir (which exists; no
// transaction, the caller holds one); returns the file names relative to dir in that order.
std::vector<std::string> write_report_files(const std::filesystem::path& dir, const FitResult& r,
                                            const Dataset& d, const ReportOptions& o = {});

// Writes STEM.md, STEM.html and the plots as SVG files into the staging directory dir, and
// appends their names to `names`.
void write_staged_pages(const std::filesystem::path& dir, const std::string& stem,
                        const std::string& markdown, const std::string& html,
                        const std::vector<ReportPlot>& plots, std::vector<std::string>& names);

}  // namespace frictionid
