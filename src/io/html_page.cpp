#include "io/html_page.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "io/report_parts.hpp"
#include "io/svg_plot.hpp"
#include "io/text.hpp"

namespace frictionid::html {
namespace {

// The pages' style. Plots stand in grids (.plot-grid): one column on a narrow screen, two from
// 900 px, three from 1200 px, where the page widens and its text stays 1080 px wide. A plot is
// 440 px wide with 11 px text (io/svg_plot.hpp); below 1200 px it is drawn at least 402 px wide
// (400 inside its border: 10 px text), its figure scrolling sideways on a narrower screen, as a
// wide table scrolls in its box; the page itself never outgrows the window. In print nothing
// scrolls, headings stay with what follows and tables and figures are kept whole.
constexpr const char* kStyle = R"(
body { font-family: sans-serif; font-size: 16px; max-width: 1080px; margin: 1.5em auto;
       padding: 0 1em; color: #222; line-height: 1.4; overflow-wrap: break-word; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { border-bottom: 1px solid #ddd; padding-bottom: 0.15em; margin-top: 1.6em; }
.summary { color: #444; }
.warnings { background: #fff4d6; border: 1px solid #e0b84c; padding: 0.4em 1em; }
.ok { background: #e9f6e9; border: 1px solid #8cc68c; padding: 0.4em 1em; }
.warnings h2 { margin-top: 0.4em; }
details.warning-cause { margin: 0.4em 0; }
details.warning-cause summary { cursor: pointer; }
nav { margin: 0.8em 0; }
nav a { margin-right: 1em; display: inline-block; }
table { border-collapse: collapse; margin: 0.6em 0; display: block; max-width: 100%;
        overflow-x: auto; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; }
th { background: #f3f3f3; }
th > button.sort { font: inherit; font-weight: bold; color: inherit; background: none; border: 0;
                   padding: 0; margin: 0; cursor: pointer; text-align: inherit; }
th > button.sort:focus-visible { outline: 2px solid #0072b2; outline-offset: 2px; }
th[aria-sort="ascending"] > button.sort::after { content: " \25B2"; }
th[aria-sort="descending"] > button.sort::after { content: " \25BC"; }
dl.traceability code { overflow-wrap: anywhere; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.estimate, td.interval-method { white-space: nowrap; }
table.heat td { text-align: center; min-width: 3.5em; }
.plot-grid { display: grid; grid-template-columns: minmax(0, 1fr); gap: 1em; margin: 1em 0;
             align-items: start; }
figure.plot { margin: 1em 0; min-width: 0; overflow-x: auto; }
.plot-grid > figure.plot { margin: 0; }
figure.plot svg { display: block; width: 100%; max-width: 660px; height: auto;
                  border: 1px solid #eee; box-sizing: border-box; }
figcaption { color: #444; font-size: 0.92em; max-width: 720px; }
dt { font-weight: bold; margin-top: 0.5em; }
@media (max-width: 1199px) {
  figure.plot svg { min-width: 402px; }
}
@media (max-width: 600px) {
  body { margin-top: 0.8em; padding: 0 0.6em; }
}
@media (min-width: 900px) {
  .plot-grid { grid-template-columns: repeat(2, minmax(0, 1fr)); }
}
@media (min-width: 1200px) {
  body { max-width: 1720px; }
  body > :not(.plot-grid) { max-width: 1080px; }
  .plot-grid { grid-template-columns: repeat(3, minmax(0, 1fr)); }
}
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 11pt; }
  body > :not(.plot-grid) { max-width: none; }
  nav { display: none; }
  h1, h2, h3, caption, summary, dt { break-after: avoid; page-break-after: avoid; }
  table, figure, figure.plot, tr, .warnings, .ok, details, dl.traceability dd {
    break-inside: avoid; page-break-inside: avoid; }
  table { display: table; overflow: visible; font-size: 9pt; }
  figure.plot { overflow: visible; }
  figure.plot svg { min-width: 0; max-width: 100%; }
  .plot-grid { grid-template-columns: repeat(2, minmax(0, 1fr)); }
  th, td, thead { position: static; }
}
)";

// Run on load, in order: sortable tables, then what a headless browser's --dump-dom shows of the
// rendered page (the tests read it): each plot's rendered size, its position on the page and the
// size its smallest text is drawn at (data-rendered-size, data-rendered-at, data-text-px on its
// figure); the page's width beside the window's (data-widths on the body: wide tables and plots
// scroll inside their boxes, so the page never outgrows the window) and the body's font size.
//
// A sortable table's header cells become buttons (so that a page without script shows no
// control that does nothing), reachable and pressed from the keyboard like any button; the
// header cell's aria-sort says how the rows are sorted. sortable(table, sortBy) does this and
// returns sort(col, up), which orders the rows (sortBy) and marks the header; a page's own
// script (page_end's `script`) uses it for tables with their own order.
constexpr const char* kScript = R"(
const sortable = (table, sortBy) => {
  const heads = Array.from(table.tHead.rows[0].cells);
  const sort = (col, up) => {
    sortBy(col, up);
    heads.forEach((th, k) => {
      if (k === col) th.dataset.order = up ? 'up' : 'down';
      else delete th.dataset.order;
      th.setAttribute('aria-sort', k !== col ? 'none' : up ? 'ascending' : 'descending');
    });
  };
  heads.forEach((th, col) => {
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'sort';
    button.append(...th.childNodes);
    th.append(button);
    th.setAttribute('aria-sort', 'none');
    button.addEventListener('click', () => sort(col, th.dataset.order !== 'up'));
  });
  return sort;
};
for (const table of document.querySelectorAll('table.sortable')) {
  const body = table.tBodies[0];
  const key = (td) => td.dataset.value !== undefined ? Number(td.dataset.value) : td.textContent;
  sortable(table, (col, up) => {
    const rows = Array.from(body.rows);
    rows.sort((a, b) => {
      const x = key(a.cells[col]), y = key(b.cells[col]);
      return (x < y ? -1 : x > y ? 1 : 0) * (up ? 1 : -1);
    });
    rows.forEach((tr) => body.appendChild(tr));
  });
}
)";

// After the page's own script: the measurements (see kScript).
constexpr const char* kMeasure = R"(
for (const fig of document.querySelectorAll('figure.plot')) {
  const svg = fig.querySelector('svg');
  const box = svg.getBoundingClientRect(), at = fig.getBoundingClientRect();
  fig.dataset.renderedSize = Math.round(box.width) + 'x' + Math.round(box.height);
  fig.dataset.renderedAt = Math.round(at.left + window.scrollX) + ',' +
                           Math.round(at.top + window.scrollY);
  let smallest = Infinity;
  for (const t of svg.querySelectorAll('text'))
    smallest = Math.min(smallest, parseFloat(getComputedStyle(t).fontSize));
  const view = svg.viewBox.baseVal;  // drawn into the content box, inside the border
  if (smallest < Infinity && view && view.width > 0)
    fig.dataset.textPx = (smallest * (svg.clientWidth || box.width) / view.width).toFixed(1);
}
document.body.dataset.widths = document.documentElement.scrollWidth + 'x' + window.innerWidth;
document.body.dataset.fontPx = parseFloat(getComputedStyle(document.body).fontSize);
)";

}  // namespace

std::string page_start(const std::string& escaped_title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         escaped_title + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
}

std::string page_end(const std::string& script) {
  return std::string("<script>") + kScript + script + kMeasure + "</script>\n</body>\n</html>\n";
}

std::string num_cell(const std::optional<double>& x) {
  if (!x || !std::isfinite(*x)) return "<td class=\"num\">" + num(x) + "</td>";
  return fmt::format("<td class=\"num\" data-value=\"{}\">{}</td>", *x, num(*x));
}

std::string text_cell(const std::optional<double>& x, const std::string& shown) {
  if (!x || !std::isfinite(*x)) return "<td class=\"num\">" + svg::escape(shown) + "</td>";
  return fmt::format("<td class=\"num\" data-value=\"{}\">{}</td>", *x, svg::escape(shown));
}

std::string provenance_section(const Provenance& p) {
  std::string h = "<h2 id=\"traceability\">Traceability</h2>\n<dl class=\"traceability\">\n";
  for (const auto& [label, text] : provenance_lines(p))
    h += "<dt>" + svg::escape(label) + "</dt><dd><code>" + isolated(text) + "</code></dd>\n";
  return h + "</dl>\n";
}

namespace {

// A character that sets or changes the direction of text around it: a bidirectional control
// (marks, embeddings, overrides, isolates), or a letter of a right-to-left script (Hebrew,
// Arabic, Syriac, Thaana, N'Ko and their presentation forms; the historic RTL blocks above
// U+10800 and U+1E800).
bool directional(char32_t c) {
  return c == 0x061c || c == 0x200e || c == 0x200f || (c >= 0x202a && c <= 0x202e) ||
         (c >= 0x2066 && c <= 0x2069) || (c >= 0x0590 && c <= 0x08ff) ||
         (c >= 0xfb1d && c <= 0xfdff) || (c >= 0xfe70 && c <= 0xfeff) ||
         (c >= 0x10800 && c <= 0x10fff) || (c >= 0x1e800 && c <= 0x1efff);
}

bool has_directional(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto lead = static_cast<unsigned char>(text[i]);
    if (lead < 0x80) continue;
    const std::size_t n = text::utf8_sequence_length(text, i);
    if (n == 0) continue;  // not UTF-8: svg::escape shows it as \xNN, which is ASCII
    char32_t c = lead & (0xff >> (n + 1));
    for (std::size_t k = 1; k < n; ++k)
      c = c << 6 | (static_cast<unsigned char>(text[i + k]) & 0x3f);
    if (directional(c)) return true;
    i += n - 1;
  }
  return false;
}

}  // namespace

std::string isolated(const std::string& text) {
  const std::string escaped = svg::escape(text);
  return has_directional(text) ? "<bdi>" + escaped + "</bdi>" : escaped;
}

std::string warnings_section(const std::vector<std::string>& warnings,
                             const std::vector<std::string>& prefixes, const std::string& none) {
  if (warnings.empty()) return "<p class=\"ok\" id=\"warnings\">" + svg::escape(none) + "</p>\n";
  std::string h = fmt::format(
      "<div class=\"warnings\" id=\"warnings\"><h2>Warnings</h2>\n<p>{} warning{}, by cause, "
      "the most severe first; click a cause to unfold its warnings.</p>\n",
      warnings.size(), warnings.size() == 1 ? "" : "s");
  for (const auto& g : group_warnings(warnings)) {
    h += fmt::format(
        "<details class=\"warning-cause\"{}><summary><strong>{}</strong> ({}): {}</summary><ul>\n",
        g.open ? " open" : "", g.heading, g.warnings.size(), g.severity);
    for (std::size_t i : g.warnings)
      h += "<li>" + (i < prefixes.size() ? isolated(prefixes[i]) : std::string()) +
           svg::escape(warnings[i]) + "</li>\n";
    h += "</ul></details>\n";
  }
  return h + "</div>\n";
}

}  // namespace frictionid::html

namespace frictionid {
namespace {

// A cause of warnings: the words that mark its warnings, its heading and its one-line severity.
struct WarningCause {
  std::vector<const char*> marks;
  const char* heading;
  const char* severity;
  bool open;  // shown unfolded
};

const std::vector<WarningCause>& warning_causes() {
  static const std::vector<WarningCause> causes = {
      {{"did not converge", "no degree of freedom", "global stage failed"},
       "The fit did not finish",
       "severe: the estimates may not be at the optimum; do not use them as they are.",
       true},
      {{"far more than outliers", "the fit explains", "have structure against eps"},
       "The model misses a channel",
       "severe: a misfit, not noise; the estimates and their errors describe the wrong model. "
       "Check sign conventions, units and column names, or compare models.",
       true},
      {{"looks like an outlier"},
       "Outliers",
       "moderate: a few rows far from the fit take weight from their channel; check them.",
       false},
      {{"noise estimate of", "grow with the measured magnitude", "from the noise model (",
        "at rounding level"},
       "Noise model",
       "moderate: the weights of the rows, and the standard errors that rely on them, may be "
       "off; the sandwich errors do not rely on them.",
       false},
      {{"not determined by the data", "strongly correlated", "poorly determined",
        "does not close inside"},
       "Parameters the data do not determine",
       "moderate: some parameters, or their errors, are not pinned down by these rows.",
       false},
      {{"pressure implies at"},
       "Closed-form coefficients",
       "information: the closed forms are approximations, so their fitted coefficients need "
       "not equal the pressure law's.",
       false},
  };
  return causes;
}

}  // namespace

std::vector<WarningGroup> group_warnings(const std::vector<std::string>& warnings) {
  const auto& causes = warning_causes();
  std::vector<WarningGroup> groups(causes.size() + 1);
  for (std::size_t k = 0; k < causes.size(); ++k)
    groups[k] = {causes[k].heading, causes[k].severity, causes[k].open, {}};
  groups.back() = {"Other", "read each: it names what to check.", false, {}};
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    std::size_t k = 0;
    for (; k < causes.size(); ++k)
      if (std::any_of(causes[k].marks.begin(), causes[k].marks.end(),
                      [&](const char* m) { return warnings[i].find(m) != std::string::npos; }))
        break;
    groups[k].warnings.push_back(i);
  }
  groups.erase(std::remove_if(groups.begin(), groups.end(),
                              [](const WarningGroup& g) { return g.warnings.empty(); }),
               groups.end());
  return groups;
}

}  // namespace frictionid
