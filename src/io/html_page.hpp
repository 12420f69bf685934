// What report.html and compare.html share: the page frame (inline style, the small inline
// script) and number cells. Nothing on a page is fetched: no URL, no external script or font.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <frictionid/io/provenance.hpp>

namespace frictionid::html {

// The pages are built by appending to one string h: line() adds s and its newline.
inline void line(std::string& h, const std::string& s) {
  (h += s) += '\n';
}

// Doctype, head with title and inline style, opening <body>.
std::string page_start(const std::string& escaped_title);
// The inline script (sortable tables, then plot sizes into the DOM), closing </body></html>.
// `script` runs between the two, after the function sortable(table, sortBy) is defined (see
// html_page.cpp): a page's own sorting, e.g. summary.html's.
std::string page_end(const std::string& script = "");

// A table cell holding a number: the shown text rounded (num in io/report_parts.hpp), the exact
// value (shortest text that reads back to the same double, as in the JSON reports) in data-value
// for sorting and checks.
std::string num_cell(const std::optional<double>& x);

// A number cell that shows `shown` (an estimate rounded to its error, io/estimate_text.hpp) and
// keeps the exact value in data-value as num_cell does; no data-value when x is absent or not
// finite.
std::string text_cell(const std::optional<double>& x, const std::string& shown);

// The provenance (io/provenance.hpp) as a section "Traceability" (id "traceability"): a heading
// and one definition per line, user text escaped. Not "provenance" on a page: the pages promise
// no "nan" in their text, and tests look for those letters.
std::string provenance_section(const Provenance& p);

// User text inside a sentence or a list (a run label, a file name, a column's value) as HTML:
// escaped (svg::escape), and inside <bdi> when it holds a bidirectional control (such as U+202E)
// or a right-to-left letter, so that it cannot reorder the text around it. Other text cannot,
// and is written as it always was.
std::string isolated(const std::string& text);

// Warnings grouped by cause, most severe first: per cause a heading with how many warnings it
// holds and one line saying what it means for the results, and the warnings themselves folded
// in a <details> element (open for the causes that make the numbers unusable). `prefixes` are
// written before each warning's text (e.g. a model's name), empty for none. The section's id is
// "warnings"; without warnings, `none` as a <p class="ok">.
std::string warnings_section(const std::vector<std::string>& warnings,
                             const std::vector<std::string>& prefixes, const std::string& none);

}  // namespace frictionid::html
