// summary.html: a campaign's summary table (include/frictionid/io/summary_table.hpp) as one
// self-contained page (docs/design.md §4.5): a sortable table of the runs with links to their
// reports, and trend plots of every parameter against a covariate. Like summary.csv it is a pure
// function of its rows and options: the same rows give the same bytes.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <frictionid/io/provenance.hpp>
#include <frictionid/io/summary_table.hpp>

namespace frictionid {

// What each run's directory runs/<directory>/ holds, as `frictionid batch --per-run-reports`.
enum class RunReports { None, Json, Full };

struct SummaryHtmlOptions {
  std::string title = "frictionid batch summary";  // the page's title and heading
  std::string note;  // a paragraph under the heading (plain text), e.g. what the rows are
  // The covariate on the x axis of the trend plots. A number, or a text covariate whose values
  // read as numbers (a manifest or group-by column); runs where it is neither are left out of
  // the plots and named on the page.
  std::string trend_x = "mean_N";
  // A successful run's label links to runs/<directory>/report.html (Full) or report.json (Json);
  // no link with None, for a failed run, or for a label without an entry here.
  RunReports run_reports = RunReports::None;
  std::map<std::string, std::string> run_directories;  // label -> directory under runs/
  Provenance provenance;  // the batch's command and input files, at the end of the page
};

// The page. Missing numbers show as "—", never NaN; numbers keep their exact value in
// data-value attributes (shortest text that reads back to the same double). Adding "#sort=COL"
// (or "#sort=-COL", descending) to the page's URL sorts the runs by the column whose header has
// data-key COL when the page loads; clicking a header sorts by it.
std::string summary_html(const std::vector<SummaryRow>& rows, const SummaryHtmlOptions& options);

}  // namespace frictionid
