#include <frictionid/io/summary_html.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <regex>
#include <string>
#include <vector>

namespace frictionid::summary_html_test {
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

// The trend figures of a page, each as its text.
std::vector<std::string> figures(const std::string& page) {
  std::vector<std::string> out;
  for (auto at = page.find("<figure"); at != std::string::npos; at = page.find("<figure", at + 1))
    out.push_back(page.substr(at, page.find("</figure>", at) - at));
  return out;
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
  const auto figs = figures(t);
  EXPECT_EQ(figs.size(), 2u);  // kappa and f
  for (const auto& figure : figs) EXPECT_EQ(count(figure, "h0"), 3u) << figure;
}

TEST(SummaryHtml, OneSeriesPerValueOfTheOtherTextCovariates) {
  const std::string t = trends(summary_html(campaign(), {}));
  // surface varies and repeats (dry twice): a series each; load is the same in every run.
  EXPECT_NE(t.find(">surface=dry</text>"), std::string::npos);
  EXPECT_NE(t.find(">surface=wet</text>"), std::string::npos);
  EXPECT_EQ(t.find("load="), std::string::npos);
}

struct Segment {
  double x0, y0, x1, y1;
};

// The straight segments of a figure's error bars (its Mark::Line paths), in SVG pixels.
std::vector<Segment> bar_segments(const std::string& figure) {
  std::vector<Segment> out;
  const std::regex path("stroke-width=\"1.8\" stroke-linejoin=\"round\" d=\"([^\"]*)\"");
  const std::regex move("M([-0-9.]+) ([-0-9.]+)L([-0-9.]+) ([-0-9.]+)");
  for (std::sregex_iterator p(figure.begin(), figure.end(), path), end; p != end; ++p) {
    const std::string d = (*p)[1];
    for (std::sregex_iterator m(d.begin(), d.end(), move); m != end; ++m)
      out.push_back(
          {std::stod((*m)[1]), std::stod((*m)[2]), std::stod((*m)[3]), std::stod((*m)[4])});
  }
  return out;
}

TEST(SummaryHtml, EachRunIsACappedErrorBarWithATickAtItsValue) {
  // kappa has a ci95, f only a stderr: both get a bar.
  const auto page = summary_html({ok_run("a", 1000.0, "dry", 0.3, 0.7)}, {});
  const auto figs = figures(page);
  ASSERT_EQ(figs.size(), 2u);
  for (const auto& figure : figs) {
    const auto segments = bar_segments(figure);
    ASSERT_EQ(segments.size(), 4u) << figure;  // value tick, bar, two caps
    const Segment& tick = segments[0];
    const Segment& bar = segments[1];
    EXPECT_EQ(tick.y0, tick.y1);
    EXPECT_EQ(bar.x0, bar.x1);
    EXPECT_GT(std::abs(bar.y1 - bar.y0), 10.0);  // a visible bar
    EXPECT_LT(std::min(bar.y0, bar.y1), tick.y0);
    EXPECT_GT(std::max(bar.y0, bar.y1), tick.y0);
    for (const Segment& c : {segments[2], segments[3]}) {
      EXPECT_EQ(c.y0, c.y1);
      EXPECT_TRUE(c.y0 == bar.y0 || c.y0 == bar.y1);
      EXPECT_LT(c.x0, bar.x0);
      EXPECT_GT(c.x1, bar.x0);
    }
  }
}

TEST(SummaryHtml, AHugeErrorBarIsCutWithoutCapsAndSaysSo) {
  auto rows = campaign();
  rows[1].parameters[1].std_error = 1e6;  // f of run b: undetermined
  const auto figs = figures(summary_html(rows, {}));
  ASSERT_EQ(figs.size(), 2u);
  const std::string& f = figs[0];  // canonical order: f, then kappa
  ASSERT_NE(f.find("f against mean_N"), std::string::npos);
  EXPECT_NE(f.find("error bars of 1 run cut"), std::string::npos);
  // Three ticks and three bars; caps only on the two runs whose bars were not cut.
  EXPECT_EQ(bar_segments(f).size(), 3u + 3u + 4u);
  EXPECT_EQ(figs[1].find(" cut"), std::string::npos);  // kappa's bars are all whole
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
}  // namespace frictionid::summary_html_test
