#include <frictionid/io/summary_html.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <regex>
#include <string>
#include <vector>

namespace frictionid {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

SummaryParameter parameter(const std::string& name, double value, std::optional<double> stderr_,
                           bool with_interval) {
  SummaryParameter p;
  p.name = name;
  p.value = value;
  p.std_error = stderr_;
  if (with_interval && stderr_) {
    p.ci95_lo = value - 2 * *stderr_;
    p.ci95_hi = value + 2 * *stderr_;
  }
  return p;
}

// A successful run at load N of surface `surface` with f and kappa as given.
SummaryRow ok_run(const std::string& label, double N, const std::string& surface, double f,
                  double kappa) {
  SummaryRow r;
  r.label = label;
  r.ok = true;
  r.rows = 200;
  r.parameters = {parameter("kappa", kappa, 1e-3, true), parameter("f", f, 2e-3, false)};
  r.cost = 1.25;
  r.reduced_chi2 = 1.0 / 3.0;
  r.warnings = {"W_AT_BOUND: h at its bound"};
  r.covariates = {{"mean_N", N}, {"mean_speed", 1.5}, {"surface", surface}, {"load", "2000"}};
  return r;
}

SummaryRow failed_run(const std::string& label) {
  return failed_summary_row(label, 0, "bad.csv:3:2: expected a number, found 'x'",
                            {{"surface", std::string("dry")}});
}

std::vector<SummaryRow> campaign() {
  return {ok_run("a", 1000.0, "dry", 0.1 + 0.2, 0.71), ok_run("b", 2000.0, "dry", 0.35, 0.72),
          ok_run("c", 1000.0, "wet", 1.0 / 3.0, 0.7), failed_run("d")};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The page's trends section (everything from its heading on).
std::string trends(const std::string& page) {
  const auto at = page.find("id=\"trends\"");
  return at == std::string::npos ? std::string() : page.substr(at);
}

// The exact value in the data-value attribute that follows `attribute` in row `label`.
std::optional<double> cell_value(const std::string& page, const std::string& label,
                                 const std::string& attribute) {
  const auto row = page.find("data-label=\"" + label + "\"");
  if (row == std::string::npos) return std::nullopt;
  const auto end = page.find("</tr>", row);
  const auto cell = page.find(attribute, row);
  if (cell == std::string::npos || cell > end) return std::nullopt;
  const auto value = page.find("data-value=\"", cell);
  if (value == std::string::npos || value > page.find("</td>", cell)) return std::nullopt;
  return std::strtod(page.c_str() + value + 12, nullptr);
}

TEST(SummaryHtml, EveryRunsParameterValuesAreInTheTableExactly) {
  const auto rows = campaign();
  const std::string page = summary_html(rows, {});
  for (const auto& row : rows)
    for (const auto& p : row.parameters) {
      EXPECT_EQ(cell_value(page, row.label, "data-param=\"" + p.name + "\""), p.value)
          << row.label << " " << p.name;
      EXPECT_EQ(cell_value(page, row.label, "data-stderr-of=\"" + p.name + "\""), p.std_error)
          << row.label << " " << p.name;
    }
  EXPECT_EQ(cell_value(page, "b", "data-value"), 200.0);  // the rows column comes first
}

TEST(SummaryHtml, HeaderCountsRunsAndFailedRuns) {
  const std::string page = summary_html(campaign(), {});
  EXPECT_NE(page.find("data-runs=\"4\" data-failed=\"1\""), std::string::npos);
  EXPECT_NE(page.find("4 runs: 3 fitted"), std::string::npos);
}

TEST(SummaryHtml, FailedRunsAreMarkedWithTheirErrorAndLeftOutOfThePlots) {
  const std::string page = summary_html(campaign(), {});
  EXPECT_NE(page.find("data-label=\"d\" class=\"failed\""), std::string::npos);
  EXPECT_EQ(count(page, "class=\"failed\""), 1u);
  // The error text, escaped, in the table and the list of failed runs.
  EXPECT_EQ(count(page, "found 'x'"), 2u);
  const std::string t = trends(page);
  EXPECT_NE(t.find("Failed runs are left out: d."), std::string::npos);
  // Three runs plotted per parameter: each dot is an "h0" subpath of the dot path.
  std::size_t figures = 0;
  for (auto at = t.find("<figure"); at != std::string::npos; at = t.find("<figure", at + 1)) {
    const std::string figure = t.substr(at, t.find("</figure>", at) - at);
    EXPECT_EQ(count(figure, "h0"), 3u) << figure;
    ++figures;
  }
  EXPECT_EQ(figures, 2u);  // kappa and f
}

TEST(SummaryHtml, OneSeriesPerValueOfTheOtherTextCovariates) {
  const std::string t = trends(summary_html(campaign(), {}));
  // surface varies and repeats (dry twice): a series each; load is the same in every run.
  EXPECT_NE(t.find(">surface=dry</text>"), std::string::npos);
  EXPECT_NE(t.find(">surface=wet</text>"), std::string::npos);
  EXPECT_EQ(t.find("load="), std::string::npos);
}

TEST(SummaryHtml, ErrorBarsSpanTheIntervalOrOnePointNineSixStderr) {
  // One run, so the plot's pixel scale is fixed by the bar alone: check the bar is drawn at all
  // for both kinds (ci95 for kappa, 1.96 stderr for f) as a vertical line.
  const std::string t = trends(summary_html({ok_run("a", 1000.0, "dry", 0.3, 0.7)}, {}));
  const std::regex vertical("d=\"M([0-9.]+) ([0-9.]+)L([0-9.]+) ([0-9.]+)\"");
  std::size_t bars = 0;
  for (std::sregex_iterator it(t.begin(), t.end(), vertical), end; it != end; ++it) {
    EXPECT_EQ((*it)[1], (*it)[3]);
    EXPECT_NE((*it)[2], (*it)[4]);
    ++bars;
  }
  EXPECT_EQ(bars, 2u);
}

TEST(SummaryHtml, TheSortingScriptAndSortKeysArePresent) {
  const std::string page = summary_html(campaign(), {});
  EXPECT_NE(page.find("<table class=\"runs\" id=\"runs\">"), std::string::npos);
  EXPECT_NE(page.find("addEventListener('click'"), std::string::npos);
  EXPECT_NE(page.find("#sort="), std::string::npos);
  for (const char* key : {"label", "status", "rows", "f", "f_stderr", "kappa", "reduced_chi2",
                          "warnings", "error", "mean_N", "surface"})
    EXPECT_NE(page.find("<th data-key=\"" + std::string(key) + "\">"), std::string::npos) << key;
}

TEST(SummaryHtml, LabelsLinkToTheRunReportsThatWereWritten) {
  const auto rows = campaign();
  SummaryHtmlOptions o;
  o.run_directories = {{"a", "a"}, {"b", "b_x"}, {"c", "c"}, {"d", "d"}};
  EXPECT_EQ(summary_html(rows, o).find("<a href=\"runs/"), std::string::npos);  // None
  o.run_reports = RunReports::Full;
  std::string page = summary_html(rows, o);
  EXPECT_NE(page.find("<a href=\"runs/b_x/report.html\">b</a>"), std::string::npos);
  EXPECT_EQ(count(page, "<a href=\"runs/"), 3u);  // not the failed run d
  o.run_reports = RunReports::Json;
  page = summary_html(rows, o);
  EXPECT_NE(page.find("<a href=\"runs/a/report.json\">a</a>"), std::string::npos);
  EXPECT_EQ(count(page, "report.html"), 0u);
}

TEST(SummaryHtml, NoNaNAndNoUrlEvenForMissingValues) {
  auto rows = campaign();
  rows[0].reduced_chi2.reset();
  rows[0].parameters[1].std_error = kNaN;
  rows[1].covariates[0].value = kNaN;  // a null mean_N read back from a journal
  rows[2].parameters[0].ci95_lo = kNaN;
  const std::string page = summary_html(rows, {});
  for (const char* bad : {"nan", "NaN", "+inf", "-inf", "http://", "https://"})
    EXPECT_EQ(page.find(bad), std::string::npos) << bad;
  EXPECT_NE(trends(page).find("Left out, no value of mean_N: b."), std::string::npos);
}

TEST(SummaryHtml, ANonNumericOrUnknownTrendXIsStatedNotPlotted) {
  SummaryHtmlOptions o;
  o.trend_x = "surface";
  std::string t = trends(summary_html(campaign(), o));
  EXPECT_NE(t.find("Left out, surface is not a number: a (dry), b (dry), c (wet)."),
            std::string::npos);
  EXPECT_NE(t.find("nothing to plot"), std::string::npos);
  EXPECT_EQ(t.find("<figure"), std::string::npos);
  o.trend_x = "pressure";
  t = trends(summary_html(campaign(), o));
  EXPECT_NE(t.find("No run has a covariate named pressure"), std::string::npos);
  EXPECT_EQ(t.find("<figure"), std::string::npos);
}

TEST(SummaryHtml, ATextCovariateThatReadsAsANumberCanBeTheTrendX) {
  auto rows = campaign();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (auto& c : rows[i].covariates)
      if (c.name == "load") c.value = std::to_string(1000 * (i + 1));
  SummaryHtmlOptions o;
  o.trend_x = "load";
  const std::string t = trends(summary_html(rows, o));
  EXPECT_NE(t.find("kappa against load"), std::string::npos);
  EXPECT_EQ(t.find("is not a number"), std::string::npos);
}

TEST(SummaryHtml, TheSameRowsGiveTheSameBytes) {
  SummaryHtmlOptions o;
  o.run_reports = RunReports::Full;
  o.run_directories = {{"a", "a"}};
  EXPECT_EQ(summary_html(campaign(), o), summary_html(campaign(), o));
}

TEST(SummaryHtml, NoRunsIsAPageThatSaysSo) {
  const std::string page = summary_html({}, {});
  EXPECT_NE(page.find("No runs."), std::string::npos);
  EXPECT_NE(page.find("</html>"), std::string::npos);
}

}  // namespace
}  // namespace frictionid
