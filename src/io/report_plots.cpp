// Report plots, drawn by io/svg_plot: per channel the collapse plot (the channel divided by its
// load scale and parity sign against eps, coloured by group, with the fitted curves), measured
// and fitted values, the residuals whitened by the sigma the fit used against eps and against
// the fitted value, and their normal quantile plot; then the channels against user columns
// (--plot-x).
#include "io/report_parts.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include <frictionid/model_comparison.hpp>
#include "identify/row_chunks.hpp"
#include "io/palette.hpp"
#include "io/svg_plot.hpp"
#include "io/text.hpp"

namespace frictionid {
namespace {

using text::kNaN;
constexpr double kInf = std::numeric_limits<double>::infinity();

// More distinct values than this in the colouring column are binned: one colour of the
// palette (io/palette.hpp) each, and more colours are not told apart.
constexpr std::size_t kMaxColourGroups = palette::kSeries.size();
// Per channel: collapse, measured and fitted, residuals against eps and against the fitted
// value, normal quantiles. Each kind is a section of the page with every channel's plot of
// that kind side by side (the plot's heading).
constexpr std::size_t kPlotsPerChannel = 5;
constexpr const char* kCollapseHeading = "Collapse plots";
constexpr const char* kFitHeading = "Measured and fitted";
constexpr const char* kResidualHeading = "Whitened residuals against eps";
constexpr const char* kResidualFittedHeading = "Whitened residuals against the fitted value";
constexpr const char* kQuantileHeading = "Normal quantiles of the whitened residuals";

const char* collapse_divisor(Channel c) {
  return (c == Channel::T_x || c == Channel::T_y) ? "N" : "(N R)";
}

// eps per row: the fitter's (the one the model saw), recomputed only when it is missing.
std::vector<double> row_eps(const FitResult& r, const Dataset& d) {
  const std::size_t n = d.rows();
  if (r.eps.size() == n) return r.eps;
  std::vector<double> eps(n, kNaN);
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= d.omega.size() || i >= d.R.size()) break;
    const double v = std::hypot(d.v_x[i], i < d.v_y.size() ? d.v_y[i] : 0.0);
    const double u = std::abs(d.omega[i]) * d.R[i];
    if (u > 0)
      eps[i] = v / u;
    else if (v > 0)
      eps[i] = kInf;
  }
  return eps;
}

// Where each row sits on the log eps axis: eps = 0 rows one decade-ish left of the data, eps =
// inf rows right of it, each behind a dashed marker.
struct EpsAxis {
  std::vector<double> x;  // per row; NaN when the row has no eps to place
  std::pair<double, double> range;
  std::vector<svg::XMarker> markers;
  std::string edge_note;  // empty when no row sits at an edge
};

EpsAxis place_eps(const std::vector<double>& eps) {
  double emin = kInf, emax = 0.0;
  bool has_zero = false, has_inf = false;
  for (double e : eps) {
    if (std::isnan(e) || e == -kInf) continue;
    if (e == kInf)
      has_inf = true;
    else if (e <= 0)
      has_zero = true;
    else
      emin = std::min(emin, e), emax = std::max(emax, e);
  }
  if (emax <= 0) emin = emax = 1.0;  // only edge rows: any decade will do
  const double left = emin / 8, right = emax * 8;
  EpsAxis a;
  a.x.reserve(eps.size());
  for (double e : eps)
    a.x.push_back(std::isnan(e) || e == -kInf ? kNaN : e == kInf ? right : e <= 0 ? left : e);
  // Room for the edge rows only where there are any.
  a.range = {has_zero ? emin / 16 : emin / 1.5, has_inf ? emax * 16 : emax * 1.5};
  if (has_zero) a.markers.push_back({std::sqrt(left * emin), "eps=0"});
  if (has_inf) a.markers.push_back({std::sqrt(right * emax), "eps=inf"});
  if (has_zero && has_inf)
    a.edge_note = "eps = 0 rows at the left edge, eps = inf rows at the right edge";
  else if (has_zero)
    a.edge_note = "eps = 0 rows at the left edge";
  else if (has_inf)
    a.edge_note = "eps = inf rows at the right edge";
  return a;
}

// A column by name: a canonical kinematic column, eps, a measured channel, or an extra column
// (then every value must be a number).
std::optional<std::vector<double>> numeric_column(const Dataset& d, const std::vector<double>& eps,
                                                  const std::string& name) {
  const std::pair<const char*, const std::vector<double>*> canonical[] = {
      {"v_x", &d.v_x}, {"v_y", &d.v_y}, {"omega", &d.omega},
      {"N", &d.N},     {"R", &d.R},     {"eps", &eps}};
  for (const auto& [n, v] : canonical)
    if (name == n) return *v;
  for (Channel c : kAllChannels)
    if (name == channel_name(c)) return d.value[static_cast<int>(c)];
  for (std::size_t k = 0; k < d.extra_names.size(); ++k) {
    if (d.extra_names[k] != name) continue;
    std::vector<double> out(d.rows(), kNaN);
    for (std::size_t i = 0; i < d.rows(); ++i) {
      const std::string& t = d.extra_values[k][i];
      if (t.empty()) continue;  // an empty cell is a missing value
      if (text::parse_double_strict(t, out[i]) != nullptr) return std::nullopt;
    }
    return out;
  }
  return std::nullopt;
}

bool has_column(const Dataset& d, const std::string& name) {
  for (const char* n : {"v_x", "v_y", "omega", "N", "R", "eps"})
    if (name == n) return true;
  for (Channel c : kAllChannels)
    if (name == channel_name(c)) return true;
  return std::find(d.extra_names.begin(), d.extra_names.end(), name) != d.extra_names.end();
}

// The slip angle after the mirror images the collapse divides out (collapse_factor).
constexpr const char* kAngleWords = "slip angle atan2(sgn(omega) v_y, |v_x|) in degrees";
constexpr const char* kAngleRule = "colour: slip angle atan2(sgn(omega) v_y, |v_x|) in degrees";

// Rows coloured alike in the collapse plots, and the sentence that says how they were formed.
struct ColourGroups {
  std::vector<int> of_row;  // -1: not in any group (missing value)
  std::vector<std::string> names;
  std::string rule;
};

// The slip angle per row after the mirror images the collapse divides out (collapse_factor),
// in degrees; the default colouring when the rows have more than one.
constexpr const char* kAngleColumn = "slip angle [deg]";

std::vector<double> mirrored_angles(const Dataset& d) {
  std::vector<double> a(d.rows());
  for (std::size_t i = 0; i < d.rows(); ++i) a[i] = mirrored_slip_angle_deg(d, i);
  return a;
}

bool several_values(const std::vector<double>& v) {
  for (double x : v)
    if (x != v.front()) return true;
  return false;
}

ColourGroups colour_groups(const Dataset& d, const std::vector<double>& eps,
                           const std::string& color_by) {
  ColourGroups g;
  const std::size_t n = d.rows();
  g.of_row.assign(n, 0);
  std::string column = color_by.empty() ? "N" : color_by;
  std::optional<std::vector<double>> values;
  if (color_by.empty() && n > 0) {
    values = mirrored_angles(d);
    if (several_values(*values))
      column = kAngleColumn;
    else
      values.reset();
  }
  if (!values) values = numeric_column(d, eps, column);
  if (values) {
    // The distinct values: a short list while there are few (the usual case, and linear in the
    // rows), a full sort only when there are many.
    std::vector<double> distinct;
    for (double v : *values) {
      if (!std::isfinite(v) || std::find(distinct.begin(), distinct.end(), v) != distinct.end())
        continue;
      distinct.push_back(v);
      if (distinct.size() > kMaxColourGroups) break;
    }
    if (distinct.size() > kMaxColourGroups) {
      // Many values: the ranges below come from the rows the plots show (plotted_row) and the
      // extremes, so a million rows need no full sort.
      const std::size_t step = plot_step(n);
      double lo = kInf, hi = -kInf;
      for (double v : *values)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      distinct = {lo, hi};
      for (std::size_t i = 0; i < n; ++i)
        if (plotted_row(i, step) && std::isfinite((*values)[i])) distinct.push_back((*values)[i]);
    }
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (color_by.empty() && column == "N" && distinct.size() > kMaxColourGroups) {
      g.names = {"all rows"};
      g.rule = fmt::format("one colour: the load takes more than {} values", kMaxColourGroups);
      return g;
    }
    if (distinct.size() <= kMaxColourGroups) {
      for (double v : distinct) g.names.push_back(fmt::format("{} = {:.6g}", column, v));
      for (std::size_t i = 0; i < n; ++i) {
        const double v = (*values)[i];
        g.of_row[i] = std::isfinite(v)
                          ? static_cast<int>(std::lower_bound(distinct.begin(), distinct.end(), v) -
                                             distinct.begin())
                          : -1;
      }
      g.rule = column == kAngleColumn ? std::string(kAngleRule) : fmt::format("colour: {}", column);
      return g;
    }
    // Many values: kMaxColourGroups ranges holding about equally many distinct values.
    std::vector<double> upper;
    for (std::size_t k = 0; k < kMaxColourGroups; ++k) {
      const std::size_t first = k * distinct.size() / kMaxColourGroups;
      const std::size_t last = (k + 1) * distinct.size() / kMaxColourGroups - 1;
      upper.push_back(distinct[last]);
      g.names.push_back(
          fmt::format("{} in [{:.4g}, {:.4g}]", column, distinct[first], distinct[last]));
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double v = (*values)[i];
      // Beyond the last range (cannot happen: the extremes are in it) would be the last colour.
      const auto group = std::lower_bound(upper.begin(), upper.end(), v) - upper.begin();
      g.of_row[i] = std::isfinite(v)
                        ? static_cast<int>(std::min<std::ptrdiff_t>(
                              group, static_cast<std::ptrdiff_t>(kMaxColourGroups) - 1))
                        : -1;
    }
    g.rule = fmt::format("colour: {} in {} ranges of equally many distinct plotted values",
                         column == kAngleColumn ? kAngleWords : column.c_str(), kMaxColourGroups);
    return g;
  }
  // A text column: one colour per value in sorted order; beyond the palette, "other".
  const auto it = std::find(d.extra_names.begin(), d.extra_names.end(), column);
  const auto& texts = d.extra_values[static_cast<std::size_t>(it - d.extra_names.begin())];
  std::map<std::string, int> index;
  for (const auto& t : texts)
    if (!t.empty()) index.emplace(t, 0);
  int k = 0;
  for (auto& [name, i] : index) {
    i = std::min(k++, static_cast<int>(kMaxColourGroups) - 1);
    if (i == k - 1) g.names.push_back(column + " = " + name);
  }
  if (index.size() > kMaxColourGroups) g.names.back() = column + ": other values";
  for (std::size_t i = 0; i < n; ++i) g.of_row[i] = texts[i].empty() ? -1 : index.at(texts[i]);
  g.rule = fmt::format("colour: {}", column);
  return g;
}

// The rows one channel's plots show: the plotted rows (plotted_row) that measure c with finite
// values.
struct ChannelRows {
  std::vector<std::size_t> rows;
  std::vector<std::string> notes;
};

ChannelRows channel_rows(const FitResult& r, const Dataset& d, Channel c, const EpsAxis& axis) {
  const int ci = static_cast<int>(c);
  const std::size_t n = d.rows();
  ChannelRows out;
  const std::size_t step = plot_step(n);
  std::size_t dropped = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!d.present[ci][i] || !plotted_row(i, step)) continue;
    if (std::isnan(axis.x[i]) || !std::isfinite(d.value[ci][i]) || !std::isfinite(r.fitted[ci][i]))
      ++dropped;
    else
      out.rows.push_back(i);
  }
  if (step > 1) out.notes.push_back(plotted_rows_note(n));
  if (!axis.edge_note.empty()) out.notes.push_back(axis.edge_note);
  if (dropped > 0)
    out.notes.push_back(fmt::format("{} rows without a finite eps or prediction dropped", dropped));
  return out;
}

std::string join_notes(const std::vector<std::string>& notes) {
  std::string out;
  for (const auto& s : notes) out += (out.empty() ? "" : "; ") + s;
  return out;
}

const char* kEpsLabel = "eps = v/(|omega| R)";

// More curves than this (fitted lines) in one plot: the fitted values are drawn as dots, since
// so many lines could not be followed.
constexpr std::size_t kMaxFittedLines = 48;

// Dots drawn fainter and smaller when a plot holds many, so that their density shows.
void thin_dots(std::vector<svg::Series>& dots) {
  std::size_t total = 0;
  for (const auto& s : dots) total += s.x.size();
  if (total <= 1500) return;
  for (auto& s : dots) s.dot_size = 2.6, s.opacity = total > 3000 ? 0.45 : 0.55;
}

// The rows of each colour group, in row order.
std::vector<std::vector<std::size_t>> group_members(const ColourGroups& groups,
                                                    const ChannelRows& rows) {
  std::vector<std::vector<std::size_t>> members(groups.names.size());
  for (std::size_t i : rows.rows)
    if (groups.of_row[i] >= 0) members[static_cast<std::size_t>(groups.of_row[i])].push_back(i);
  return members;
}

// The measured dots, one series per colour group that has rows, at (x_of(i), y_of(i)), thinned
// as many dots need.
template <typename X, typename Y>
std::vector<svg::Series> group_dots(const std::vector<std::vector<std::size_t>>& members,
                                    const ColourGroups& groups, const X& x_of, const Y& y_of) {
  std::vector<svg::Series> dots;
  for (std::size_t g = 0; g < members.size(); ++g) {
    if (members[g].empty()) continue;
    svg::Series s(groups.names[g], palette::series(g), svg::Mark::Dots);
    s.tag = groups.names[g];
    for (std::size_t i : members[g]) {
      s.x.push_back(x_of(i));
      s.y.push_back(y_of(i));
    }
    dots.push_back(std::move(s));
  }
  thin_dots(dots);
  return dots;
}

// A curve's name for its line's data-tag: "direction=45 spin=-1 tilt=1" (degrees).
std::string curve_tag(const SlipCurve& k) {
  return fmt::format("direction={:.6g} spin={} tilt={}",
                     static_cast<double>(k.direction) * 1e-6 * (180.0 / 3.14159265358979323846),
                     k.spin, k.tilt);
}

// The fitted lines: per colour group, one line per curve (slip_curve; with by_load also per load
// and radius, for values that are not divided by them), through the model's predictions at the
// group's rows sorted by eps, each value times factor(row). Empty when there would be more than
// kMaxFittedLines.
template <class Factor>
std::vector<svg::Series> fitted_lines(const FitResult& r, const Dataset& d, Channel c,
                                      const EpsAxis& axis, const ColourGroups& groups,
                                      const std::vector<std::vector<std::size_t>>& members,
                                      bool by_load, Factor factor) {
  const int ci = static_cast<int>(c);
  std::vector<svg::Series> lines;
  for (std::size_t g = 0; g < members.size(); ++g) {
    std::map<std::tuple<SlipCurve, double, double>, std::vector<std::size_t>> curves;
    for (std::size_t i : members[g]) {
      curves[{slip_curve(d, i), by_load ? d.N[i] : 0.0, by_load ? d.R[i] : 0.0}].push_back(i);
      if (curves.size() + lines.size() > kMaxFittedLines) return {};
    }
    for (auto& [key, rows] : curves) {
      std::stable_sort(rows.begin(), rows.end(),
                       [&](std::size_t a, std::size_t b) { return axis.x[a] < axis.x[b]; });
      svg::Series line("", palette::series(g), svg::Mark::Line);
      line.outline = true;
      line.tag = groups.names[g] + "; " + curve_tag(std::get<0>(key));
      if (by_load)
        line.tag += fmt::format("; N={:.6g} R={:.6g}", std::get<1>(key), std::get<2>(key));
      for (std::size_t i : rows) {
        line.x.push_back(axis.x[i]);
        line.y.push_back(r.fitted[ci][i] * factor(i));
      }
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

// Measured values as dots coloured by group (value times factor(row)), and the fitted model on
// top: lines with a white outline, or dark dots when there are too many curves. Returns whether
// lines were drawn.
template <class Factor>
bool measured_and_fitted(svg::Plot& p, const FitResult& r, const Dataset& d, Channel c,
                         const EpsAxis& axis, const ChannelRows& rows, const ColourGroups& groups,
                         bool by_load, Factor factor) {
  const int ci = static_cast<int>(c);
  const auto members = group_members(groups, rows);
  auto dots = group_dots(
      members, groups, [&](std::size_t i) { return axis.x[i]; },
      [&](std::size_t i) { return d.value[ci][i] * factor(i); });
  auto lines = fitted_lines(r, d, c, axis, groups, members, by_load, factor);
  const bool drawn = !lines.empty();
  for (auto& s : dots) p.series.push_back(std::move(s));
  if (drawn) {
    for (auto& s : lines) p.series.push_back(std::move(s));
    return true;
  }
  svg::Series fitted("fitted", palette::kReference, svg::Mark::Dots);
  fitted.tag = "fitted";
  fitted.dot_size = 2.2;
  for (std::size_t i : rows.rows) {
    fitted.x.push_back(axis.x[i]);
    fitted.y.push_back(r.fitted[ci][i] * factor(i));
  }
  p.series.push_back(std::move(fitted));
  return false;
}

ReportPlot collapse_plot(const FitResult& r, const Dataset& d, Channel c, const EpsAxis& axis,
                         const ChannelRows& rows, const ColourGroups& groups) {
  const std::string name = channel_name(c);
  svg::Plot p;
  p.title = fmt::format("{}: collapse, {} / {} against eps", name, name, collapse_divisor(c));
  p.notes = rows.notes;
  p.x_label = kEpsLabel;
  p.y_label = fmt::format("{} / {} (parity sign removed)", name, collapse_divisor(c));
  p.log_x = true;
  p.x_range = axis.range;
  p.x_markers = axis.markers;
  p.y_reference = 0.0;
  const bool lines = measured_and_fitted(p, r, d, c, axis, rows, groups, false,
                                         [&](std::size_t i) { return collapse_factor(d, c, i); });
  p.notes.push_back(groups.rule + (lines ? "; lines: the fitted model" : ""));

  ReportPlot out;
  out.file = "collapse_" + name + ".svg";
  out.heading = kCollapseHeading;
  out.caption = fmt::format(
      "Collapse plot: measured {0} divided by {1} and by its parity sign (coloured dots), "
      "against eps. The parity sign is sgn v_x for T_x, sgn omega for T_y and M_z: the signs the "
      "model's mirror images y → −y and (v, omega) → (−v, −omega) take (docs/physics.md §2.3), "
      "which carry every row to v_x ≥ 0, omega ≥ 0. Rows at every load of one slip direction, "
      "spin sign and tilt sign fall on one curve of eps. {2} {3}.",
      name, collapse_divisor(c),
      lines ? "The lines, drawn over the dots, join the fitted model's predictions at the same "
              "rows, divided the same way: one line per colour, slip direction, spin sign and "
              "tilt sign, sorted by eps."
            : fmt::format("Dark dots: the fitted model's predictions at the same rows, divided "
                          "the same way (more than {} curves: no lines).",
                          kMaxFittedLines),
      groups.rule);
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  out.svg = svg::render(p);
  return out;
}

ReportPlot fit_plot(const FitResult& r, const Dataset& d, Channel c, const EpsAxis& axis,
                    const ChannelRows& rows, const ColourGroups& groups) {
  const std::string name = channel_name(c);
  svg::Plot p;
  p.title = name + ": measured and fitted";
  p.notes = rows.notes;
  p.x_label = kEpsLabel;
  p.y_label = fmt::format("{} [{}]", name, channel_unit(c));
  p.log_x = true;
  p.x_range = axis.range;
  p.x_markers = axis.markers;
  const bool lines =
      measured_and_fitted(p, r, d, c, axis, rows, groups, true, [](std::size_t) { return 1.0; });
  p.notes.push_back(groups.rule + (lines ? "; lines: the fitted model" : ""));
  ReportPlot out{"fit_" + name + ".svg", kFitHeading, "", svg::render(p)};
  out.caption = fmt::format(
      "Measured {0}, in {1}, against eps (dots, {2}) and the fitted model over them: {3}.", name,
      channel_unit(c), groups.rule,
      lines ? "one line per colour, slip direction, spin sign, tilt sign, load and radius, "
              "sorted by eps"
            : fmt::format("dark dots at the same rows (more than {} curves: no lines)",
                          kMaxFittedLines));
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  return out;
}

// The standard normal quantile: Acklam's rational approximation and one Halley step on erfc
// (relative error below 1e-15 in double).
double normal_quantile(double p) {
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                                 -2.759285104469687e+02, 1.383577518672690e+02,
                                 -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                                 -1.556989798598866e+02, 6.680131188771972e+01,
                                 -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                                 -2.400758277161838e+00, -2.549732539343734e+00,
                                 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double e[] = {7.784695709041462e-03, 3.224671290700398e-01,
                                 2.445134137142996e+00, 3.754408661907416e+00};
  double x;
  if (p < 0.02425) {
    const double q = std::sqrt(-2 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((e[0] * q + e[1]) * q + e[2]) * q + e[3]) * q + 1);
  } else if (p > 1 - 0.02425) {
    const double q = std::sqrt(-2 * std::log(1 - p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((e[0] * q + e[1]) * q + e[2]) * q + e[3]) * q + 1);
  } else {
    const double q = p - 0.5, t = q * q;
    x = (((((a[0] * t + a[1]) * t + a[2]) * t + a[3]) * t + a[4]) * t + a[5]) * q /
        (((((b[0] * t + b[1]) * t + b[2]) * t + b[3]) * t + b[4]) * t + 1);
  }
  const double err = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
  const double u = err * std::sqrt(2 * 3.14159265358979323846) * std::exp(x * x / 2);
  return x - u / (1 + x * u / 2);
}

// The whitened residuals of one channel: (measured - fitted) / sigma_i, sigma_i the one the fit
// divided by (fit_sigma), and the words for what sigma_i is.
struct Whitened {
  std::vector<double> z;  // per row; NaN where there is none
  std::string sigma_words;
};

Whitened whitened_residuals(const FitResult& r, const Dataset& d, Channel c) {
  const int ci = static_cast<int>(c);
  Whitened w;
  const std::vector<double> sigma = fit_sigma(r, d, c);
  w.z.assign(d.rows(), kNaN);
  for (std::size_t i = 0; i < sigma.size(); ++i)
    if (std::isfinite(sigma[i]) && sigma[i] > 0)
      w.z[i] = (d.value[ci][i] - r.fitted[ci][i]) / sigma[i];
  const ChannelSummary* summary = find_summary(r, c);
  if (d.has_sigma(c))
    w.sigma_words = "the row's sigma column";
  else if (summary && summary->noise)
    w.sigma_words = "the row's sigma under the fitted noise model (" + summary->scale_source + ")";
  else if (summary)
    w.sigma_words = fmt::format("the channel's fixed scale {:.4g} {} ({})", summary->scale,
                                channel_unit(c), summary->scale_source);
  else
    w.sigma_words = "1";
  return w;
}

const char* kWhitenedLabel = "(measured - fitted) / sigma_i";

// Whitened residuals against x (eps on the log axis, or the fitted value), one colour per group.
void residual_dots(svg::Plot& p, const std::vector<double>& x, const Whitened& w,
                   const ChannelRows& rows, const ColourGroups& groups) {
  const auto members = group_members(groups, rows);
  auto dots = group_dots(
      members, groups, [&](std::size_t i) { return x[i]; }, [&](std::size_t i) { return w.z[i]; });
  for (auto& s : dots) p.series.push_back(std::move(s));
}

std::string residual_caption(const std::string& name, const Whitened& w) {
  return fmt::format(
      "Residuals of {} divided by {}: when the model and the noise model fit, they scatter "
      "without a trend or a funnel, with a standard deviation near 1 in every colour, about 95 % "
      "within ±2.",
      name, w.sigma_words);
}

ReportPlot residual_plot(const Whitened& w, Channel c, const EpsAxis& axis, const ChannelRows& rows,
                         const ColourGroups& groups) {
  const std::string name = channel_name(c);
  svg::Plot p;
  p.title = name + ": whitened residuals against eps";
  p.notes = rows.notes;
  p.notes.push_back(groups.rule);
  p.x_label = kEpsLabel;
  p.y_label = kWhitenedLabel;
  p.log_x = true;
  p.x_range = axis.range;
  p.x_markers = axis.markers;
  p.y_reference = 0.0;
  residual_dots(p, axis.x, w, rows, groups);
  ReportPlot out{"residuals_" + name + ".svg", kResidualHeading, "", svg::render(p)};
  out.caption = residual_caption(name, w) + " Colours: " + groups.rule + ".";
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  return out;
}

ReportPlot residual_fitted_plot(const FitResult& r, const Whitened& w, Channel c,
                                const ChannelRows& rows, const ColourGroups& groups) {
  const std::string name = channel_name(c);
  svg::Plot p;
  p.title = name + ": whitened residuals against the fitted value";
  p.notes = rows.notes;
  p.notes.push_back(groups.rule);
  p.x_label = fmt::format("fitted {} [{}]", name, channel_unit(c));
  p.y_label = kWhitenedLabel;
  p.y_reference = 0.0;
  residual_dots(p, r.fitted[static_cast<int>(c)], w, rows, groups);
  ReportPlot out{"residuals_fitted_" + name + ".svg", kResidualFittedHeading, "", svg::render(p)};
  out.caption = residual_caption(name, w) +
                " Against the fitted value, a funnel means the noise model's sigma does not "
                "follow the data's. Colours: " +
                groups.rule + ".";
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  return out;
}

ReportPlot qq_plot(const Whitened& w, Channel c, const ChannelRows& rows) {
  const std::string name = channel_name(c);
  std::vector<double> z;
  for (std::size_t i : rows.rows)
    if (std::isfinite(w.z[i])) z.push_back(w.z[i]);
  std::sort(z.begin(), z.end());
  svg::Plot p;
  p.title = name + ": normal quantile plot of the whitened residuals";
  p.notes = rows.notes;
  p.x_label = "standard normal quantile";
  p.y_label = "sorted " + std::string(kWhitenedLabel);
  svg::Series dots("whitened residuals", palette::series(0), svg::Mark::Dots);
  dots.tag = "quantiles";
  const double n = static_cast<double>(z.size());
  for (std::size_t k = 0; k < z.size(); ++k) {
    dots.x.push_back(normal_quantile((static_cast<double>(k) + 0.5) / n));
    dots.y.push_back(z[k]);
  }
  svg::Series line("y = x", palette::kReference, svg::Mark::Line);
  line.dash = "6 4";
  if (!z.empty()) {
    const double q = std::max(std::fabs(dots.x.front()), 1.0);
    line.x = {-q, q};
    line.y = {-q, q};
  }
  p.series.push_back(std::move(dots));
  p.series.push_back(std::move(line));
  ReportPlot out{"qq_" + name + ".svg", kQuantileHeading, "", svg::render(p)};
  out.caption = fmt::format(
      "The whitened residuals of {} ({}) sorted, against the quantiles of the standard normal "
      "at (k − 0.5)/n: on the dashed line y = x when they are normal with standard deviation 1. "
      "A steeper line is a noise scale too small, S-shaped ends heavy tails or outliers.",
      name, w.sigma_words);
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  return out;
}

// A column name made safe for a file name.
std::string file_part(const std::string& s) {
  std::string out;
  for (char ch : s)
    out += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-') ? ch : '_';
  return out;
}

ReportPlot column_plot(const FitResult& r, const Dataset& d, Channel c, const std::string& column,
                       const std::vector<double>& x, const ChannelRows& rows,
                       const ColourGroups& groups) {
  const int ci = static_cast<int>(c);
  const std::string name = channel_name(c);
  svg::Plot p;
  p.title = fmt::format("{}: measured and fitted against {}", name, column);
  p.notes = rows.notes;
  p.notes.push_back(groups.rule);
  p.x_label = column;
  p.y_label = fmt::format("{} [{}]", name, channel_unit(c));
  const auto members = group_members(groups, rows);
  auto dots = group_dots(
      members, groups, [&](std::size_t i) { return x[i]; },
      [&](std::size_t i) { return d.value[ci][i]; });
  for (auto& s : dots) p.series.push_back(std::move(s));
  svg::Series fitted("fitted", palette::kReference, svg::Mark::Dots);
  fitted.tag = "fitted";
  fitted.dot_size = 2.0;
  for (std::size_t i : rows.rows) {
    fitted.x.push_back(x[i]);
    fitted.y.push_back(r.fitted[ci][i]);
  }
  p.series.push_back(std::move(fitted));
  ReportPlot out{fmt::format("x_{}_{}.svg", file_part(column), name), "Against " + column, "",
                 svg::render(p)};
  out.caption = fmt::format(
      "Measured {} (coloured dots, {}) and fitted (small dark dots, drawn over them) against the "
      "column {}.",
      name, groups.rule, column);
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  return out;
}

}  // namespace

std::size_t plot_step(std::size_t rows) {
  return rows > kMaxPlotRows ? (rows + kMaxPlotRows - 1) / kMaxPlotRows : 1;
}

bool plotted_row(std::size_t row, std::size_t step) {
  if (step <= 1) return true;
  std::uint64_t z = static_cast<std::uint64_t>(row) + 0x9e3779b97f4a7c15ull;  // splitmix64
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return (z ^ (z >> 31)) % step == 0;
}

std::string plotted_rows_note(std::size_t rows) {
  const std::size_t step = plot_step(rows);
  if (step <= 1) return "";
  return fmt::format("about 1 in {} of {} rows plotted (a fixed pseudo-random choice)", step, rows);
}

const std::optional<std::array<double, 2>>& chosen_interval(const FitResult& r,
                                                            const ParameterEstimate& p) {
  if (r.intervals == IntervalMethod::Sandwich) return p.ci95_sandwich;
  // Under the default method a parameter has a profile interval only when it is nearly
  // collinear with another one, where the symmetric interval can miss on one side.
  if (r.intervals == IntervalMethod::Profile || p.ci95_profile) return p.ci95_profile;
  return p.ci95;
}

std::string interval_method(const FitResult& r, const ParameterEstimate& p) {
  if (!chosen_interval(r, p)) return "—";
  if (r.intervals == IntervalMethod::Sandwich) return "HC3 (t·sandwich stderr)";
  if (r.intervals == IntervalMethod::Model && !p.ci95_profile) return "model (t·stderr)";
  if (!p.profile_closed[0] || !p.profile_closed[1])
    return std::string("profile, open ") +
           (p.profile_closed[0]   ? "above"
            : p.profile_closed[1] ? "below"
                                  : "on both sides") +
           " (ends at the bound)";
  return "profile";
}

const char* interval_caption(const FitResult& r) {
  if (r.intervals == IntervalMethod::Sandwich)
    return "value ± t(0.975, dof) × the HC3 sandwich stderr (HC3)";
  if (r.intervals == IntervalMethod::Profile)
    return "where the profile of the cost rises by t(0.975, dof)² (profile, docs/physics.md "
           "§8.12)";
  return "value ± t(0.975, dof) × stderr (model), except for parameters with |correlation| > "
         "0.99 to another one: their symmetric interval can miss on one side, and theirs is "
         "where the profile of the cost rises by t(0.975, dof)² (profile, docs/physics.md §8.12)";
}

const ChannelSummary* find_summary(const FitResult& r, Channel c) {
  for (const auto& s : r.channel_summaries)
    if (s.channel == c) return &s;
  return nullptr;
}

std::vector<std::string> default_plot_files(const FitResult& r) {
  std::vector<std::string> files;
  for (Channel c : r.channels)
    for (const char* kind : {"collapse", "fit", "residuals", "residuals_fitted", "qq"})
      files.push_back(fmt::format("{}_{}.svg", kind, channel_name(c)));
  return files;
}

void check_report_columns(const Dataset& d, const ReportOptions& o) {
  const std::vector<double> no_eps;
  for (const auto& column : o.plot_x) {
    if (!has_column(d, column))
      throw std::invalid_argument("--plot-x " + column + ": no such column in " + d.source);
    if (column != "eps" && !numeric_column(d, no_eps, column))
      throw std::invalid_argument("--plot-x " + column +
                                  ": the column holds text; expected numbers");
  }
  if (!o.color_by.empty() && !has_column(d, o.color_by))
    throw std::invalid_argument("--color-by " + o.color_by + ": no such column in " + d.source);
}

std::vector<ReportPlot> make_plots(const FitResult& r, const Dataset& d, const ReportOptions& o) {
  check_report_columns(d, o);
  const std::size_t n = d.rows();
  const std::vector<double> eps = row_eps(r, d);
  std::vector<std::vector<double>> x_columns;
  for (const auto& column : o.plot_x) x_columns.push_back(*numeric_column(d, eps, column));

  std::vector<ReportPlot> plots;
  if (n == 0) return plots;
  const EpsAxis axis = place_eps(eps);
  const ColourGroups groups = colour_groups(d, eps, o.color_by);
  std::vector<std::pair<Channel, ChannelRows>> shown;
  for (Channel c : r.channels) {
    const int ci = static_cast<int>(c);
    if (r.fitted[ci].size() != n || d.value[ci].size() != n || d.present[ci].size() != n) continue;
    ChannelRows rows = channel_rows(r, d, c, axis);
    if (!rows.rows.empty()) shown.emplace_back(c, std::move(rows));
  }
  // Each channel's plots are drawn by one task into its own slots; the order of the list (per
  // channel collapse, fit, residuals; then the --plot-x plots) does not depend on the threads.
  const std::size_t per_channel = kPlotsPerChannel + o.plot_x.size();
  std::vector<ReportPlot> drawn(shown.size() * per_channel);
  for_each_task(shown.size(), resolve_thread_count(o.threads), [&](std::size_t j) {
    const auto& [c, rows] = shown[j];
    ReportPlot* out = &drawn[j * per_channel];
    const Whitened w = whitened_residuals(r, d, c);
    out[0] = collapse_plot(r, d, c, axis, rows, groups);
    out[1] = fit_plot(r, d, c, axis, rows, groups);
    out[2] = residual_plot(w, c, axis, rows, groups);
    out[3] = residual_fitted_plot(r, w, c, rows, groups);
    out[4] = qq_plot(w, c, rows);
    for (std::size_t k = 0; k < o.plot_x.size(); ++k)
      out[kPlotsPerChannel + k] = column_plot(r, d, c, o.plot_x[k], x_columns[k], rows, groups);
  });
  for (std::size_t j = 0; j < shown.size(); ++j)
    for (std::size_t m = 0; m < kPlotsPerChannel; ++m)
      plots.push_back(std::move(drawn[j * per_channel + m]));
  for (std::size_t k = 0; k < o.plot_x.size(); ++k)
    for (std::size_t j = 0; j < shown.size(); ++j)
      plots.push_back(std::move(drawn[j * per_channel + kPlotsPerChannel + k]));
  return plots;
}

}  // namespace frictionid
