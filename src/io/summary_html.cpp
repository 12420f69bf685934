// summary.html (docs/design.md §4.5): the runs of a batch in one sortable table and every
// parameter's trend against a covariate, on one self-contained page like report.html: inline
// SVG, inline style and script, no URL that leaves the file.
#include <frictionid/io/summary_html.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <frictionid/parameters.hpp>
#include "io/estimate_text.hpp"
#include "io/html_page.hpp"
#include "io/palette.hpp"
#include "io/report_parts.hpp"
#include "io/summary_columns.hpp"
#include "io/svg_plot.hpp"

namespace frictionid {
namespace {

using html::isolated;
using svg::escape;

// More series than the palette has colours (io/palette.hpp) are drawn as one: a legend of
// dozens of colours tells nothing apart.
constexpr std::size_t kMaxSeries = palette::kSeries.size();
// Error bars reach at most this many times the spread of the values (or the median bar, if
// larger) beyond them, so that one undetermined parameter (a huge stderr) does not flatten the
// trend of all the others.
constexpr double kMaxBarReach = 3.0;

// Style and sorting for the runs table. Missing values sort last in both directions, numbers
// (data-value) before text, ties keep the label order; "#sort=COL" or "#sort=-COL" in the URL
// sorts by the header whose data-key is COL when the page loads. The headers become buttons with
// aria-sort through sortable() of the page's script (io/html_page.cpp).
constexpr const char* kStyle = R"(
.table-scroll { overflow-x: auto; }
table.runs th { white-space: nowrap; }
table.runs tr.failed td { background: #fde8e8; }
table.runs td.status-failed { color: #a40000; font-weight: bold; }
@media print {
  .table-scroll { overflow: visible; }
}
)";
constexpr const char* kSortScript = R"(
(() => {
  const table = document.getElementById('runs');
  if (!table) return;
  const body = table.tBodies[0];
  const heads = Array.from(table.tHead.rows[0].cells);
  const key = (td) => td.dataset.value !== undefined ? Number(td.dataset.value)
      : td.classList.contains('num') || td.textContent === '' ? null : td.textContent;
  const compare = (a, b, up) => {
    if (a === null || b === null) return (a === null) - (b === null);
    if (typeof a !== typeof b) return typeof a === 'number' ? -1 : 1;
    return (a < b ? -1 : a > b ? 1 : 0) * (up ? 1 : -1);
  };
  const sortBy = sortable(table, (col, up) => {
    const rows = Array.from(body.rows);
    rows.sort((a, b) => compare(key(a.cells[col]), key(b.cells[col]), up) ||
                        Number(a.dataset.index) - Number(b.dataset.index));
    rows.forEach((tr) => body.appendChild(tr));
  });
  // A malformed escape in the fragment (#sort=%E0%A4%A) makes decodeURIComponent throw: the
  // fragment is then read as it is, and the page works without the sort it cannot name.
  let hash = location.hash;
  try {
    hash = decodeURIComponent(hash);
  } catch (e) {
    if (!(e instanceof URIError)) throw e;
  }
  const m = /^#sort=(-?)(.+)$/.exec(hash);
  const col = m ? heads.findIndex((th) => th.dataset.key === m[2]) : -1;
  if (col >= 0) sortBy(col, m[1] !== '-');
})();
)";

// A covariate's name with its unit, for a header or an axis: the covariates every run has
// (io/summary_table.hpp) have known units, a manifest's or group's column has none we know. The
// newton is written out: N is the load (docs/design.md §4.3, "Units").
std::string covariate_label(const std::string& name) {
  if (name == "mean_N") return name + " [newton]";
  if (name == "mean_speed" || name == "mean_omega_R") return name + " [m/s]";
  return name;
}

using html::line;

const SummaryParameter* find_parameter(const SummaryRow& row, const std::string& name) {
  for (const auto& p : row.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

const Covariate* find_covariate(const SummaryRow& row, const std::string& name) {
  for (const auto& c : row.covariates)
    if (c.name == name) return &c;
  return nullptr;
}

// Text that is a whole finite number ("2000", "2.2") as that number.
std::optional<double> text_number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

std::optional<double> covariate_number(const Covariate& c) {
  if (const double* x = std::get_if<double>(&c.value))
    return std::isfinite(*x) ? std::optional<double>(*x) : std::nullopt;
  return text_number(std::get<std::string>(c.value));
}

// A number cell with extra attributes (e.g. data-param) and the exact value in data-value,
// showing `shown` (num(x) by default).
std::string number_td(const std::string& attributes, const std::optional<double>& x,
                      const std::optional<std::string>& shown = std::nullopt) {
  if (!x || !std::isfinite(*x)) return "<td class=\"num\"" + attributes + ">—</td>";
  return fmt::format("<td class=\"num\"{} data-value=\"{}\">{}</td>", attributes, *x,
                     shown ? escape(*shown) : num(*x));
}

std::string covariate_td(const Covariate* c) {
  if (!c) return "<td class=\"num\">—</td>";
  if (std::holds_alternative<double>(c->value)) return number_td("", std::get<double>(c->value));
  const std::string& text = std::get<std::string>(c->value);
  const auto x = text_number(text);
  return x ? fmt::format("<td data-value=\"{}\">{}</td>", *x, isolated(text))
           : "<td>" + isolated(text) + "</td>";
}

std::string label_td(const SummaryRow& row, const SummaryHtmlOptions& o) {
  const auto dir = o.run_directories.find(row.label);
  if (!row.ok || o.run_reports == RunReports::None || dir == o.run_directories.end())
    return "<td>" + isolated(row.label) + "</td>";
  const char* file = o.run_reports == RunReports::Full ? "report.html" : "report.json";
  return fmt::format("<td><a href=\"runs/{}/{}\">{}</a></td>", escape(dir->second), file,
                     isolated(row.label));
}

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
  return out;
}

void runs_section(std::string& h, const std::vector<SummaryRow>& rows,
                  const SummaryHtmlOptions& o) {
  const auto params = summary_parameter_names(rows);
  const auto covariates = summary_covariate_names(rows);
  line(h, "<h2 id=\"runs-heading\">Runs</h2>");
  line(h, "<div class=\"table-scroll\"><table class=\"runs\" id=\"runs\"><thead><tr>");
  std::string head =
      "<th data-key=\"label\">label</th><th data-key=\"status\">status</th>"
      "<th data-key=\"rows\">rows</th>";
  for (const auto& p : params)
    head += fmt::format("<th data-key=\"{0}\">{0}</th><th data-key=\"{0}_stderr\">± stderr</th>",
                        escape(p));
  head +=
      "<th data-key=\"reduced_chi2\">reduced χ²</th><th data-key=\"warnings\">warnings</th>"
      "<th data-key=\"error\">error</th>";
  for (const auto& c : covariates)
    head += fmt::format("<th data-key=\"{}\">{}</th>", escape(c), escape(covariate_label(c)));
  line(h, head + "</tr></thead><tbody>");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SummaryRow& row = rows[i];
    std::string tr = fmt::format("<tr data-index=\"{}\" data-label=\"{}\"{}>", i, escape(row.label),
                                 row.ok ? "" : " class=\"failed\"");
    tr += label_td(row, o);
    tr += row.ok ? "<td>ok</td>" : "<td class=\"status-failed\">failed</td>";
    tr += number_td("", static_cast<double>(row.rows));
    for (const auto& name : params) {
      const SummaryParameter* p = find_parameter(row, name);
      // The value to the decimal place of its stderr's second digit (io/estimate_text.hpp).
      const EstimateText e =
          p ? estimate_text(p->value, p->std_error) : EstimateText{kNoNumber, "", "", ""};
      tr += number_td(" data-param=\"" + escape(name) + "\"",
                      p ? std::optional<double>(p->value) : std::nullopt, e.value_alone());
      tr += number_td(" data-stderr-of=\"" + escape(name) + "\"", p ? p->std_error : std::nullopt,
                      e.error_alone());
    }
    tr += number_td("", row.reduced_chi2);
    if (row.ok)
      tr += fmt::format("<td class=\"num\" data-value=\"{}\" title=\"{}\">{}</td>",
                        row.warnings.size(), escape(join(row.warnings, "; ")), row.warnings.size());
    else
      tr += "<td class=\"num\">—</td>";
    tr += "<td class=\"error\">" + isolated(row.error) + "</td>";
    for (const auto& name : covariates) tr += covariate_td(find_covariate(row, name));
    line(h, tr + "</tr>");
  }
  line(h, "</tbody></table></div>");
  line(h,
       "<p>Click a column header to sort by it, again to reverse; missing values stay last. "
       "Opening the page as summary.html#sort=COL (or #sort=-COL, descending) sorts by column "
       "COL, e.g. #sort=mean_N. A label links to the run's report where one was written.</p>");
}

// Failed runs with their errors, and the warnings in plain words, each once with the runs that
// have it (a campaign's runs often share most of theirs). A long list starts folded.
void problems_section(std::string& h, const std::vector<SummaryRow>& rows) {
  std::vector<std::string> failed, warnings;
  std::vector<std::vector<std::string>> warned_runs;
  std::size_t runs_with_warnings = 0;
  for (const auto& row : rows) {
    if (!row.ok) failed.push_back(isolated(row.label) + ": " + isolated(row.error));
    if (!row.warnings.empty()) ++runs_with_warnings;
    for (const auto& w : row.warnings) {
      const auto it = std::find(warnings.begin(), warnings.end(), w);
      if (it == warnings.end()) {
        warnings.push_back(w);
        warned_runs.push_back({isolated(row.label)});
      } else {
        warned_runs[static_cast<std::size_t>(it - warnings.begin())].push_back(isolated(row.label));
      }
    }
  }
  if (failed.empty() && warnings.empty()) {
    line(h, "<p class=\"ok\" id=\"warnings\">Every run was fitted without a warning.</p>");
    return;
  }
  line(h, "<div class=\"warnings\" id=\"warnings\">");
  if (!failed.empty()) {
    line(h, "<h2>Failed runs</h2><ul id=\"failed-runs\">");
    for (const auto& f : failed) line(h, "<li>" + f + "</li>");
    line(h, "</ul>");
  }
  if (!warnings.empty()) {
    line(h, fmt::format("<details{}><summary><strong>Warnings</strong>: {} different, in {} of {} "
                        "runs</summary><ul>",
                        warnings.size() <= 5 ? " open" : "", warnings.size(), runs_with_warnings,
                        rows.size()));
    for (std::size_t k = 0; k < warnings.size(); ++k)
      line(h, fmt::format("<li>{} <em>({})</em></li>", isolated(warnings[k]),
                          warned_runs[k].size() == rows.size() ? std::string("every run")
                                                               : join(warned_runs[k], ", ")));
    line(h, "</ul></details>");
  }
  line(h, "</div>");
}

// One point of a trend: a successful run with a numeric x.
struct TrendRun {
  const SummaryRow* row;
  double x;
  std::size_t series;
};

struct Trends {
  std::vector<TrendRun> runs;
  std::vector<std::string> series_labels;  // one per series; {""} when there is one series
  std::vector<std::string> grouping;       // the columns the series stand for
  std::vector<std::string> notes;          // escaped HTML sentences about runs left out
};

// The text covariates other than x that tell groups of runs apart: they vary between the
// plotted runs, and some value is shared by two of them (a column with a value per run names
// runs, not groups).
std::vector<std::string> grouping_columns(const std::vector<TrendRun>& runs,
                                          const std::vector<std::string>& covariates,
                                          const std::string& x) {
  std::vector<std::string> out;
  for (const auto& name : covariates) {
    if (name == x) continue;
    std::vector<std::string> values;
    bool text = false;
    for (const auto& r : runs) {
      const Covariate* c = find_covariate(*r.row, name);
      if (c && std::holds_alternative<std::string>(c->value)) text = true;
      values.push_back(c && std::holds_alternative<std::string>(c->value)
                           ? std::get<std::string>(c->value)
                           : std::string());
    }
    if (!text) continue;
    std::vector<std::string> distinct = values;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() > 1 && distinct.size() < values.size()) out.push_back(name);
  }
  return out;
}

Trends trend_runs(const std::vector<SummaryRow>& rows, const std::string& x) {
  Trends t;
  std::vector<std::string> failed, missing, not_numeric;
  for (const auto& row : rows) {
    if (!row.ok) {
      failed.push_back(isolated(row.label));
      continue;
    }
    const Covariate* c = find_covariate(row, x);
    const auto value = c ? covariate_number(*c) : std::nullopt;
    if (value)
      t.runs.push_back({&row, *value, 0});
    else if (c && std::holds_alternative<std::string>(c->value) &&
             !std::get<std::string>(c->value).empty())
      not_numeric.push_back(
          fmt::format("{} ({})", isolated(row.label), isolated(std::get<std::string>(c->value))));
    else
      missing.push_back(isolated(row.label));
  }
  if (!failed.empty()) t.notes.push_back("Failed runs are left out: " + join(failed, ", ") + ".");
  if (!not_numeric.empty())
    t.notes.push_back(
        fmt::format("Left out, {} is not a number: {}.", isolated(x), join(not_numeric, ", ")));
  if (!missing.empty())
    t.notes.push_back(
        fmt::format("Left out, no value of {}: {}.", isolated(x), join(missing, ", ")));

  t.grouping = grouping_columns(t.runs, summary_covariate_names(rows), x);
  std::vector<std::string> labels;
  for (auto& r : t.runs) {
    std::vector<std::string> parts;
    for (const auto& name : t.grouping) {
      const Covariate* c = find_covariate(*r.row, name);
      const std::string value = c && std::holds_alternative<std::string>(c->value)
                                    ? std::get<std::string>(c->value)
                                    : "—";
      parts.push_back(name + "=" + value);
    }
    const std::string label = join(parts, ", ");
    const auto it = std::find(labels.begin(), labels.end(), label);
    r.series = static_cast<std::size_t>(it - labels.begin());
    if (it == labels.end()) labels.push_back(label);
  }
  if (labels.size() > kMaxSeries) {
    t.notes.push_back(fmt::format(
        "{} combinations of {}: too many to tell apart by colour, so every run is drawn in one "
        "colour.",
        labels.size(), escape(join(t.grouping, ", "))));
    for (auto& r : t.runs) r.series = 0;
    labels = {""};
    t.grouping.clear();
  }
  if (labels.empty()) labels = {""};
  t.series_labels = labels;
  return t;
}

// The 95 % interval of a run's parameter: its ci95, else value ± 1.96 stderr, else none.
std::optional<std::pair<double, double>> bar(const SummaryParameter& p) {
  if (p.ci95_lo && p.ci95_hi && std::isfinite(*p.ci95_lo) && std::isfinite(*p.ci95_hi))
    return std::make_pair(*p.ci95_lo, *p.ci95_hi);
  if (p.std_error && std::isfinite(*p.std_error))
    return std::make_pair(p.value - 1.96 * *p.std_error, p.value + 1.96 * *p.std_error);
  return std::nullopt;
}

// Where the error bars are cut: kMaxBarReach times the larger of the values' spread and the
// median half-width of the bars beyond the values. A bar of typical size is never cut; one
// hundreds of times wider than the rest (an undetermined parameter) is.
std::pair<double, double> bar_limits(const std::vector<const SummaryParameter*>& values) {
  double lo = INFINITY, hi = -INFINITY;
  std::vector<double> half_widths;
  for (const SummaryParameter* p : values) {
    if (!p) continue;
    lo = std::min(lo, p->value), hi = std::max(hi, p->value);
    if (const auto b = bar(*p)) half_widths.push_back((b->second - b->first) / 2);
  }
  double reach = hi - lo;
  if (!half_widths.empty()) {
    auto middle = half_widths.begin() + static_cast<std::ptrdiff_t>(half_widths.size() / 2);
    std::nth_element(half_widths.begin(), middle, half_widths.end());
    reach = std::max(reach, *middle);
  }
  if (!(reach > 0)) reach = std::max(std::abs(lo), 1e-300);
  return {lo - kMaxBarReach * reach, hi + kMaxBarReach * reach};
}

// A straight segment of a Mark::Line series; the NaN lifts the pen before the next one.
void segment(svg::Series& s, double x0, double y0, double x1, double y1) {
  s.x.insert(s.x.end(), {x0, x1, NAN});
  s.y.insert(s.y.end(), {y0, y1, NAN});
}

// One parameter's trend plot, or an empty string when no plotted run has the parameter. Each run
// is a dot with a short horizontal tick at its value and a capped vertical bar (no cap at a cut
// end); series are shifted sideways a little so that runs at the same x do not hide each other.
std::string trend_figure(const Trends& t, const std::string& param, const std::string& x) {
  std::vector<const SummaryParameter*> values;
  double x_lo = INFINITY, x_hi = -INFINITY;
  for (const auto& r : t.runs) {
    const SummaryParameter* p = find_parameter(*r.row, param);
    values.push_back(p && std::isfinite(p->value) ? p : nullptr);
    if (values.back()) x_lo = std::min(x_lo, r.x), x_hi = std::max(x_hi, r.x);
  }
  if (!(x_lo <= x_hi)) return "";
  const auto [floor, ceiling] = bar_limits(values);
  const double x_span = x_hi > x_lo ? x_hi - x_lo : std::max(std::abs(x_lo), 1.0) * 0.2;
  const double cap = 0.01 * x_span;
  const std::size_t n_series = t.series_labels.size();
  const double shift =
      n_series > 1 ? std::min(2.5 * cap, 0.1 * x_span / static_cast<double>(n_series - 1)) : 0.0;

  std::vector<svg::Series> dots(n_series), bars(n_series);
  std::size_t clipped = 0;
  for (std::size_t s = 0; s < n_series; ++s) {
    const std::string colour = palette::series(s);
    dots[s] = {t.series_labels[s], colour, svg::Mark::Dots, {}, {}};
    bars[s] = {"", colour, svg::Mark::Line, {}, {}};
  }
  for (std::size_t i = 0; i < t.runs.size(); ++i) {
    const SummaryParameter* p = values[i];
    if (!p) continue;
    const std::size_t s = t.runs[i].series;
    const double xc =
        t.runs[i].x + shift * (static_cast<double>(s) - static_cast<double>(n_series - 1) / 2);
    dots[s].x.push_back(xc);
    dots[s].y.push_back(p->value);
    segment(bars[s], xc - 1.5 * cap, p->value, xc + 1.5 * cap, p->value);
    const auto b = bar(*p);
    if (!b) continue;
    const double lo = std::max(b->first, floor), hi = std::min(b->second, ceiling);
    if (lo != b->first || hi != b->second) ++clipped;
    segment(bars[s], xc, lo, xc, hi);
    if (lo == b->first) segment(bars[s], xc - cap, lo, xc + cap, lo);
    if (hi == b->second) segment(bars[s], xc - cap, hi, xc + cap, hi);
  }
  svg::Plot plot;
  plot.title = param + " against " + x;
  plot.x_label = covariate_label(x);
  plot.y_label = param;
  if (clipped > 0)
    plot.notes.push_back(fmt::format("error bars of {} run{} cut (no cap at the cut end)", clipped,
                                     clipped == 1 ? "" : "s"));
  for (auto& s : bars) plot.series.push_back(std::move(s));
  for (auto& s : dots) plot.series.push_back(std::move(s));
  std::string caption = fmt::format(
      "{} of each successful run against its {}, with the 95 % interval (ci95, or ±1.96 stderr "
      "where the run has no interval) as an error bar",
      escape(param), escape(x));
  if (!t.grouping.empty())
    caption += fmt::format(
        "; one colour per value of {}, each colour shifted sideways by {} from the next so that "
        "runs at the same {} stay apart",
        escape(join(t.grouping, ", ")), svg::tick_label(shift), escape(x));
  return fmt::format(
      "<figure class=\"plot\" data-param=\"{}\">\n{}\n<figcaption>{}.</figcaption>"
      "\n</figure>",
      escape(param), svg::render(plot), caption);
}

void trends_section(std::string& h, const std::vector<SummaryRow>& rows, const std::string& x) {
  line(h, fmt::format("<h2 id=\"trends\">Trends against {}</h2>", escape(x)));
  const auto covariates = summary_covariate_names(rows);
  if (std::find(covariates.begin(), covariates.end(), x) == covariates.end()) {
    line(h, fmt::format("<p class=\"note\">No run has a covariate named {}; the covariates are: "
                        "{}. Nothing is plotted.</p>",
                        escape(x), covariates.empty() ? "none" : escape(join(covariates, ", "))));
    return;
  }
  const Trends t = trend_runs(rows, x);
  for (const auto& note : t.notes) line(h, "<p class=\"note\">" + note + "</p>");
  if (t.runs.empty()) {
    line(h, fmt::format("<p class=\"note\">No successful run has a numeric {}: nothing to "
                        "plot.</p>",
                        escape(x)));
    return;
  }
  std::vector<SummaryRow> plotted;
  for (const auto& r : t.runs) plotted.push_back(*r.row);
  // The parameters' plots side by side (three columns on a wide screen, one on a narrow one).
  line(h, "<div class=\"plot-grid\" data-kind=\"trends\">");
  for (const auto& param : summary_parameter_names(plotted)) {
    const std::string figure = trend_figure(t, param, x);
    if (!figure.empty()) line(h, figure);
  }
  line(h, "</div>");
}

}  // namespace

std::string summary_html(const std::vector<SummaryRow>& rows, const SummaryHtmlOptions& o) {
  std::size_t failed = 0;
  for (const auto& row : rows)
    if (!row.ok) ++failed;
  std::string h = html::page_start(escape(o.title));
  line(h, std::string("<style>") + kStyle + "</style>");
  line(h, "<h1>" + escape(o.title) + "</h1>");
  if (!o.note.empty()) line(h, "<p id=\"note\">" + escape(o.note) + "</p>");
  line(h, fmt::format("<p class=\"summary\" id=\"counts\" data-runs=\"{0}\" data-failed=\"{1}\">"
                      "{0} run{2}: {3} fitted, {4}{1} failed{5}.</p>",
                      rows.size(), failed, rows.size() == 1 ? "" : "s", rows.size() - failed,
                      failed > 0 ? "<strong>" : "", failed > 0 ? "</strong>" : ""));
  if (rows.empty()) {
    line(h, "<p>No runs.</p>");
    return h + html::provenance_section(o.provenance) + html::page_end();
  }
  line(h, "<nav><a href=\"#runs-heading\">Runs</a><a href=\"#trends\">Trends</a></nav>");
  problems_section(h, rows);
  runs_section(h, rows, o);
  trends_section(h, rows, o.trend_x);
  return h + html::provenance_section(o.provenance) + html::page_end(kSortScript);
}

}  // namespace frictionid
