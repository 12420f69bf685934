// Report plots, drawn by io/svg_plot: per channel the collapse plot (the channel divided by its
// load scale against eps, coloured by group, with the fitted curve), measured and fitted values,
// and whitened residuals against eps; then the channels against user columns (--plot-x).
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
#include <utility>

#include <fmt/format.h>

#include <frictionid/model_comparison.hpp>
#include "identify/row_chunks.hpp"
#include "io/svg_plot.hpp"
#include "io/text.hpp"

namespace frictionid {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// More distinct values than this in the colouring column are binned: more colours are not told
// apart.
constexpr std::size_t kMaxColourGroups = 8;
constexpr const char* kPalette[kMaxColourGroups] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                    "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
constexpr const char* kMeasuredColour = "#1f77b4";
constexpr const char* kFittedColour = "#d62728";

const char* channel_unit(Channel c) {
  return (c == Channel::T_x || c == Channel::T_y) ? "N" : "N m";
}
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

// Rows coloured alike in the collapse plots, and the sentence that says how they were formed.
struct ColourGroups {
  std::vector<int> of_row;  // -1: not in any group (missing value)
  std::vector<std::string> names;
  std::string rule;
};

ColourGroups colour_groups(const Dataset& d, const std::vector<double>& eps,
                           const std::string& color_by) {
  ColourGroups g;
  const std::size_t n = d.rows();
  g.of_row.assign(n, 0);
  const std::string column = color_by.empty() ? "N" : color_by;
  if (const auto values = numeric_column(d, eps, column)) {
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
    if (color_by.empty() && distinct.size() > kMaxColourGroups) {
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
      g.rule = fmt::format("colour: {}", column);
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
    g.rule = fmt::format("colour: {} in {} ranges of equally many distinct plotted values", column,
                         kMaxColourGroups);
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

// Slip direction atan2(v_y, v_x) in micro-radians: rows of one direction share a fitted line.
long long slip_direction_key(const Dataset& d, std::size_t i) {
  return std::llround(std::atan2(d.v_y[i], d.v_x[i]) * 1e6);
}

// More slip directions than this among the plotted rows: the fitted values are drawn as dots,
// since lines per direction would be too many to follow.
constexpr std::size_t kMaxFittedLinesPerColour = 12;

ReportPlot collapse_plot(const FitResult& r, const Dataset& d, Channel c, const EpsAxis& axis,
                         const ChannelRows& rows, const ColourGroups& groups) {
  const int ci = static_cast<int>(c);
  const std::string name = channel_name(c);
  std::vector<long long> directions;
  std::vector<long long> key_of(d.rows());  // filled for the plotted rows only
  for (std::size_t i : rows.rows) {
    key_of[i] = slip_direction_key(d, i);
    if (directions.size() <= kMaxFittedLinesPerColour &&
        std::find(directions.begin(), directions.end(), key_of[i]) == directions.end())
      directions.push_back(key_of[i]);
  }
  const bool lines = directions.size() <= kMaxFittedLinesPerColour;
  std::sort(directions.begin(), directions.end());

  svg::Plot p;
  p.title = fmt::format("{}: collapse, {} / {} against eps", name, name, collapse_divisor(c));
  p.notes = rows.notes;
  p.notes.push_back(groups.rule + (lines ? "; lines: the fitted model" : ""));
  p.x_label = kEpsLabel;
  p.y_label = fmt::format("{} / {} (parity sign removed)", name, collapse_divisor(c));
  p.log_x = true;
  p.x_range = axis.range;
  p.x_markers = axis.markers;
  std::vector<std::vector<std::size_t>> members(groups.names.size());
  for (std::size_t i : rows.rows)
    if (groups.of_row[i] >= 0) members[static_cast<std::size_t>(groups.of_row[i])].push_back(i);
  std::vector<svg::Series> fitted, measured;
  svg::Series fitted_dots{"fitted", "#222222", svg::Mark::Dots, {}, {}};
  for (std::size_t g = 0; g < members.size(); ++g) {
    if (members[g].empty()) continue;
    const char* colour = kPalette[g % kMaxColourGroups];
    svg::Series dots{groups.names[g], colour, svg::Mark::Dots, {}, {}};
    for (std::size_t i : members[g]) {
      dots.x.push_back(axis.x[i]);
      dots.y.push_back(d.value[ci][i] * collapse_factor(d, c, i));
    }
    measured.push_back(std::move(dots));
    if (!lines) {
      for (std::size_t i : members[g]) {
        fitted_dots.x.push_back(axis.x[i]);
        fitted_dots.y.push_back(r.fitted[ci][i] * collapse_factor(d, c, i));
      }
      continue;
    }
    // A fitted line joins the model's predictions at this colour's rows of one slip direction,
    // sorted by eps: the collapsed channel depends on eps alone only at a fixed direction
    // (docs/physics.md §2), so one line per direction stays a curve at any slip angle.
    std::vector<std::size_t> order = members[g];
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return axis.x[a] < axis.x[b]; });
    for (long long key : directions) {
      svg::Series line{"", colour, svg::Mark::Line, {}, {}};
      for (std::size_t i : order) {
        if (key_of[i] != key) continue;
        line.x.push_back(axis.x[i]);
        line.y.push_back(r.fitted[ci][i] * collapse_factor(d, c, i));
      }
      if (!line.x.empty()) fitted.push_back(std::move(line));
    }
  }
  // Lines under the dots, so the data stay visible where they sit on the curve; fitted dots
  // (many directions) over them.
  for (auto& s : fitted) p.series.push_back(std::move(s));
  for (auto& s : measured) p.series.push_back(std::move(s));
  if (!lines) p.series.push_back(std::move(fitted_dots));

  ReportPlot out;
  out.file = "collapse_" + name + ".svg";
  out.heading = name;
  out.caption = fmt::format(
      "Collapse plot: measured {0} divided by {1} and by its parity sign (coloured dots), "
      "against eps; by the model (docs/physics.md §2) rows at every load and one slip direction "
      "fall "
      "on one curve of eps. {2} {3}.",
      name, collapse_divisor(c),
      lines ? "The lines join the fitted model's predictions at the same rows, divided the same "
              "way, one line per colour and slip direction, sorted by eps."
            : "Dark dots: the fitted model's predictions at the same rows, divided the same way "
              "(more than 12 slip directions: no lines).",
      groups.rule);
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  out.svg = svg::render(p);
  return out;
}

ReportPlot fit_plot(const FitResult& r, const Dataset& d, Channel c, const EpsAxis& axis,
                    const ChannelRows& rows) {
  const int ci = static_cast<int>(c);
  const std::string name = channel_name(c);
  svg::Plot p;
  p.title = name + ": measured and fitted";
  p.notes = rows.notes;
  p.x_label = kEpsLabel;
  p.y_label = fmt::format("{} [{}]", name, channel_unit(c));
  p.log_x = true;
  p.x_range = axis.range;
  p.x_markers = axis.markers;
  svg::Series measured{"measured", kMeasuredColour, svg::Mark::Dots, {}, {}};
  svg::Series fitted{"fitted", kFittedColour, svg::Mark::Dots, {}, {}};
  for (std::size_t i : rows.rows) {
    measured.x.push_back(axis.x[i]);
    measured.y.push_back(d.value[ci][i]);
    fitted.x.push_back(axis.x[i]);
    fitted.y.push_back(r.fitted[ci][i]);
  }
  p.series = {std::move(measured), std::move(fitted)};
  ReportPlot out{"fit_" + name + ".svg", name, "", svg::render(p)};
  out.caption =
      fmt::format("Measured (blue) and fitted (red) {} in {} against eps.", name, channel_unit(c));
  if (!rows.notes.empty()) out.caption += " (" + join_notes(rows.notes) + ".)";
  return out;
}

ReportPlot residual_plot(const FitResult& r, const Dataset& d, Channel c, const EpsAxis& axis,
                         const ChannelRows& rows) {
  const int ci = static_cast<int>(c);
  const std::string name = channel_name(c);
  const ChannelSummary* summary = find_summary(r, c);
  const bool scale_ok = summary && std::isfinite(summary->scale) && summary->scale > 0;
  const bool use_sigma = d.has_sigma(c) && d.sigma[ci].size() == d.rows();
  std::string scale_text = "1 (no scale known)";
  if (use_sigma)
    scale_text = "sigma";
  else if (scale_ok)
    scale_text = fmt::format("scale ({:.4g} {})", summary->scale, channel_unit(c));

  svg::Plot p;
  p.title = name + ": whitened residuals";
  p.notes = rows.notes;
  p.x_label = kEpsLabel;
  p.y_label = "(measured - fitted) / " + scale_text;
  p.log_x = true;
  p.x_range = axis.range;
  p.x_markers = axis.markers;
  p.y_reference = 0.0;
  svg::Series res{"residual", kMeasuredColour, svg::Mark::Dots, {}, {}};
  for (std::size_t i : rows.rows) {
    double s = scale_ok ? summary->scale : 1.0;
    if (use_sigma && std::isfinite(d.sigma[ci][i]) && d.sigma[ci][i] > 0) s = d.sigma[ci][i];
    res.x.push_back(axis.x[i]);
    res.y.push_back((d.value[ci][i] - r.fitted[ci][i]) / s);
  }
  p.series = {std::move(res)};
  ReportPlot out{"residuals_" + name + ".svg", name, "", svg::render(p)};
  out.caption = fmt::format(
      "Residuals of {} divided by {}: without a trend and mostly within ±2 when the model fits "
      "and the noise scale is right.",
      name, scale_text);
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
                       const std::vector<double>& x, const ChannelRows& rows) {
  const int ci = static_cast<int>(c);
  const std::string name = channel_name(c);
  svg::Plot p;
  p.title = fmt::format("{}: measured and fitted against {}", name, column);
  p.notes = rows.notes;
  p.x_label = column;
  p.y_label = fmt::format("{} [{}]", name, channel_unit(c));
  svg::Series measured{"measured", kMeasuredColour, svg::Mark::Dots, {}, {}};
  svg::Series fitted{"fitted", kFittedColour, svg::Mark::Dots, {}, {}};
  for (std::size_t i : rows.rows) {
    measured.x.push_back(x[i]);
    measured.y.push_back(d.value[ci][i]);
    fitted.x.push_back(x[i]);
    fitted.y.push_back(r.fitted[ci][i]);
  }
  p.series = {std::move(measured), std::move(fitted)};
  ReportPlot out{fmt::format("x_{}_{}.svg", file_part(column), name),
                 fmt::format("{} against {}", name, column), "", svg::render(p)};
  out.caption =
      fmt::format("Measured (blue) and fitted (red) {} against the column {}.", name, column);
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
  if (r.intervals == IntervalMethod::Profile) return p.ci95_profile;
  return p.ci95;
}

const char* interval_caption(const FitResult& r) {
  if (r.intervals == IntervalMethod::Sandwich)
    return "value ± t(0.975, dof) × the HC3 sandwich stderr";
  if (r.intervals == IntervalMethod::Profile)
    return "where the profile of the cost rises by t(0.975, dof)² (docs/physics.md §8.12)";
  return "value ± t(0.975, dof) × stderr";
}

const ChannelSummary* find_summary(const FitResult& r, Channel c) {
  for (const auto& s : r.channel_summaries)
    if (s.channel == c) return &s;
  return nullptr;
}

std::vector<std::string> default_plot_files(const FitResult& r) {
  std::vector<std::string> files;
  for (Channel c : r.channels)
    for (const char* kind : {"collapse", "fit", "residuals"})
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
  const std::size_t per_channel = 3 + o.plot_x.size();
  std::vector<ReportPlot> drawn(shown.size() * per_channel);
  for_each_task(shown.size(), resolve_thread_count(o.threads), [&](std::size_t j) {
    const auto& [c, rows] = shown[j];
    ReportPlot* out = &drawn[j * per_channel];
    out[0] = collapse_plot(r, d, c, axis, rows, groups);
    out[1] = fit_plot(r, d, c, axis, rows);
    out[2] = residual_plot(r, d, c, axis, rows);
    for (std::size_t k = 0; k < o.plot_x.size(); ++k)
      out[3 + k] = column_plot(r, d, c, o.plot_x[k], x_columns[k], rows);
  });
  for (std::size_t j = 0; j < shown.size(); ++j)
    for (std::size_t m = 0; m < 3; ++m) plots.push_back(std::move(drawn[j * per_channel + m]));
  for (std::size_t k = 0; k < o.plot_x.size(); ++k)
    for (std::size_t j = 0; j < shown.size(); ++j)
      plots.push_back(std::move(drawn[j * per_channel + 3 + k]));
  return plots;
}

}  // namespace frictionid
