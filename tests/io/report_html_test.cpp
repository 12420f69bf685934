#include <frictionid/io/report_writer.hpp>

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace frictionid::report_html_test {
namespace {

// Two loads, a slip sweep at fixed spin; T_x = 0.5 N eps / (1 + eps) measured with a small
// wiggle, predicted without it; an extra numeric column and an extra text column.
Dataset make_dataset() {
  Dataset d;
  d.source = "two_loads.csv";
  d.extra_names = {"slip_angle", "run"};
  d.extra_values.resize(2);
  for (double load : {100.0, 200.0})
    for (int k = 0; k < 20; ++k) {
      const double eps = 0.01 * std::pow(1.6, k);
      d.line.push_back(d.line.size() + 2);
      d.v_x.push_back(eps * 2.0 * 0.05);
      d.v_y.push_back(0.0);
      d.omega.push_back(2.0);
      d.N.push_back(load);
      d.R.push_back(0.05);
      d.value[0].push_back(0.5 * load * eps / (1 + eps) * (1 + 0.01 * std::sin(k)));
      d.present[0].push_back(1);
      d.extra_values[0].push_back(fmt::format("{}", 0.5 * k));
      d.extra_values[1].push_back(k % 2 ? "A" : "B");
    }
  for (int c : {1, 2, 3}) {
    d.value[c].assign(d.rows(), 0.0);
    d.present[c].assign(d.rows(), 0);
  }
  return d;
}

FitResult make_result(const Dataset& d) {
  FitResult r;
  r.model = "seed";
  r.pressure = "hertz";
  r.rows = d.rows();
  r.channels = {Channel::T_x};
  ParameterEstimate f;
  f.name = "f";
  f.value = 0.49987654321;
  f.std_error = 0.00123;
  f.ci95 = std::array<double, 2>{0.4974, 0.5023};
  f.lower = 0.01;
  f.upper = 5;
  ParameterEstimate kappa;
  kappa.name = "kappa";
  kappa.value = 1.0;
  kappa.fixed = true;
  r.parameters = {f, kappa};
  r.correlation_names = {"f"};
  r.correlation = {{1.0}};
  r.warnings = {"T_x <residuals> trend with eps"};
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const double eps = d.v_x[i] / (d.omega[i] * d.R[i]);
    r.eps.push_back(eps);
    r.fitted[0].push_back(0.5 * d.N[i] * eps / (1 + eps));
  }
  return r;
}

std::size_t count(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (auto pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1)) ++n;
  return n;
}

TEST(ReportHtml, FetchesNothingOutsideThePage) {
  const Dataset d = make_dataset();
  const std::string html = report_html(make_result(d), d);
  EXPECT_EQ(html.find("http:"), std::string::npos);
  EXPECT_EQ(html.find("https:"), std::string::npos);
  EXPECT_EQ(html.find(" src="), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("url("), std::string::npos);
}

TEST(ReportHtml, HoldsEveryParameterValueExactly) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  const std::string html = report_html(r, d);
  for (const auto& p : r.parameters) {
    const auto row = html.find("<tr data-param=\"" + p.name + "\">");
    ASSERT_NE(row, std::string::npos) << p.name;
    const auto cell = html.find("data-value=\"", row) + 12;
    EXPECT_EQ(std::stod(html.substr(cell, html.find('"', cell) - cell)), p.value) << p.name;
  }
}

TEST(ReportHtml, ValuesAreShownToTheDigitsTheirStderrSupports) {
  const Dataset d = make_dataset();
  const std::string html = report_html(make_result(d), d);
  // f = 0.49987654321 ± 0.00123: the stderr to 2 digits, the value to the same place, the
  // interval to 2 digits of its width; every cell keeps the exact value in data-value.
  EXPECT_NE(html.find("<td class=\"num\" data-value=\"0.49987654321\">0.4999</td>"
                      "<td class=\"num\" data-value=\"0.00123\">0.0012</td>"
                      "<td class=\"num\" data-value=\"0.4974\">0.4974</td>"
                      "<td class=\"num\" data-value=\"0.5023\">0.5023</td>"),
            std::string::npos)
      << html;
}

TEST(ReportHtml, ResultLineComesBeforeTheDetails) {
  const Dataset d = make_dataset();
  const std::string html = report_html(make_result(d), d);
  const auto result = html.find(
      "<p class=\"result\" id=\"result\"><strong>Result:</strong> <span class=\"estimate\">f = "
      "0.4999 ± 0.0012 (0.25 %)</span>; <span class=\"estimate\">kappa = 1 (fixed)</span>.</p>");
  ASSERT_NE(result, std::string::npos) << html;
  EXPECT_LT(result, html.find("id=\"warnings\""));
  EXPECT_LT(result, html.find("id=\"parameters\""));
}

TEST(ReportHtml, WarningsComeFirstAndAreEscaped) {
  const Dataset d = make_dataset();
  const std::string html = report_html(make_result(d), d);
  const auto warning = html.find("T_x &lt;residuals&gt; trend with eps");
  ASSERT_NE(warning, std::string::npos);
  EXPECT_LT(warning, html.find("id=\"parameters\""));
}

// Warnings are grouped by cause, the most severe first and unfolded; a misfit of 95 % of the
// rows beyond 6 sigma is filed as a misfit, not as outliers; each cause says how severe it is.
TEST(ReportHtml, WarningsAreGroupedByCauseTheMostSevereFirst) {
  const Dataset d = make_dataset();
  FitResult r = make_result(d);
  r.warnings = {
      "m = 5.4 differs from the value 7.6 that the hertz pressure implies at this fit's kappa = "
      "1.1 by 24 standard errors",
      "1 row of T_x lie beyond 6 sigma of the fit; the worst, at line 7, looks like an outlier",
      "38 of 40 rows of T_y (95 %) lie beyond 6 sigma of the fit, far more than outliers",
      "2 rows of M_z lie beyond 6 sigma of the fit; the worst, at line 9, looks like an outlier"};
  const std::string html = report_html(r, d);
  const auto misfit = html.find(
      "<details class=\"warning-cause\" open><summary><strong>The "
      "model misses a channel</strong> (1): severe");
  const auto outliers = html.find("<strong>Outliers</strong> (2): moderate");
  const auto closed = html.find("<strong>Closed-form coefficients</strong> (1): information");
  ASSERT_NE(misfit, std::string::npos);
  ASSERT_NE(outliers, std::string::npos);
  ASSERT_NE(closed, std::string::npos);
  EXPECT_LT(misfit, outliers);
  EXPECT_LT(outliers, closed);
  EXPECT_LT(misfit, html.find("far more than outliers"));
  EXPECT_LT(html.find("far more than outliers"), outliers);
}

TEST(ReportHtml, EveryChannelHasACollapsePlotColouredByLoad) {
  const Dataset d = make_dataset();
  const std::string html = report_html(make_result(d), d);
  const auto fig = html.find("<figure class=\"plot\" data-file=\"collapse_T_x.svg\">");
  ASSERT_NE(fig, std::string::npos);
  const std::string plot = html.substr(fig, html.find("</figure>", fig) - fig);
  EXPECT_NE(plot.find(">N = 100</text>"), std::string::npos);
  EXPECT_NE(plot.find(">N = 200</text>"), std::string::npos);
  EXPECT_EQ(count(plot, "stroke-width=\"1.8\""), 2u);  // one fitted line per load
  EXPECT_NE(html.find("data-file=\"fit_T_x.svg\""), std::string::npos);
  EXPECT_NE(html.find("data-file=\"residuals_T_x.svg\""), std::string::npos);
}

TEST(ReportHtml, ColourByATextColumnGivesOneColourPerValue) {
  const Dataset d = make_dataset();
  ReportOptions o;
  o.color_by = "run";
  const std::string html = report_html(make_result(d), d, o);
  EXPECT_NE(html.find(">run = A</text>"), std::string::npos);
  EXPECT_NE(html.find(">run = B</text>"), std::string::npos);
  EXPECT_EQ(html.find(">N = 100</text>"), std::string::npos);
}

// One range per colour of the palette: seven, Okabe and Ito's colours without black.
TEST(ReportHtml, ManyValuesAreColouredInSevenRangesCoveringThemAll) {
  const Dataset d = make_dataset();  // slip_angle takes 20 values, 0 to 9.5
  ReportOptions o;
  o.color_by = "slip_angle";
  const std::string html = report_html(make_result(d), d, o);
  const auto fig = html.find("data-file=\"collapse_T_x.svg\"");
  const std::string plot = html.substr(fig, html.find("</figure>", fig) - fig);
  EXPECT_EQ(count(plot, ">slip_angle in ["), 7u);
  EXPECT_NE(plot.find(">slip_angle in [0, "), std::string::npos);
  EXPECT_NE(plot.find(", 9.5]</text>"), std::string::npos);
}

TEST(ReportHtml, PlotXAddsAPlotAgainstTheColumn) {
  const Dataset d = make_dataset();
  ReportOptions o;
  o.plot_x = {"slip_angle"};
  const std::string html = report_html(make_result(d), d, o);
  EXPECT_NE(html.find("data-file=\"x_slip_angle_T_x.svg\""), std::string::npos);
  EXPECT_NE(html.find("T_x: measured and fitted against slip_angle"), std::string::npos);
}

TEST(ReportHtml, UnknownOrTextPlotColumnsAreRejected) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  ReportOptions missing;
  missing.plot_x = {"camber"};
  EXPECT_THROW(report_html(r, d, missing), std::invalid_argument);
  ReportOptions text;
  text.plot_x = {"run"};
  EXPECT_THROW(report_html(r, d, text), std::invalid_argument);
  ReportOptions colour;
  colour.color_by = "camber";
  EXPECT_THROW(report_html(r, d, colour), std::invalid_argument);
}

TEST(ReportHtml, SameInputGivesTheSameBytesAndNoNanText) {
  const Dataset d = make_dataset();
  FitResult r = make_result(d);
  r.parameters[0].std_error = std::numeric_limits<double>::quiet_NaN();
  r.correlation[0][0] = std::numeric_limits<double>::quiet_NaN();
  r.reduced_chi2 = std::numeric_limits<double>::infinity();
  const std::string html = report_html(r, d);
  EXPECT_EQ(html, report_html(r, d));
  std::string lower = html;
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  EXPECT_EQ(lower.find(">nan<"), std::string::npos);
  EXPECT_EQ(lower.find("\"nan\""), std::string::npos);
}

// The cells of one parameter's row in report.html, in order (their text).
std::vector<std::string> row_cells(const std::string& html, const std::string& name) {
  const auto row = html.find("<tr data-param=\"" + name + "\">");
  if (row == std::string::npos) return {};
  const std::string tr = html.substr(row, html.find("</tr>", row) - row);
  std::vector<std::string> cells;
  for (auto at = tr.find("<td"); at != std::string::npos; at = tr.find("<td", at + 1)) {
    const auto begin = tr.find('>', at) + 1;
    cells.push_back(tr.substr(begin, tr.find("</td>", begin) - begin));
  }
  return cells;
}

// Under the default interval method a parameter nearly collinear with another one (it has a
// profile interval) shows the profile interval and says so; the others show the symmetric
// model interval and say that. Both pages name each row's method.
TEST(ReportHtml, EachParameterRowNamesItsIntervalMethod) {
  const Dataset d = make_dataset();
  FitResult r = make_result(d);
  ParameterEstimate b;
  b.name = "b";
  b.value = 22.0;
  b.std_error = 2.5;
  b.ci95 = std::array<double, 2>{17.0, 27.0};
  b.ci95_profile = std::array<double, 2>{17.6, 27.9};
  b.lower = 0;
  b.upper = 100;
  ParameterEstimate m = b;
  m.name = "m";
  m.value = 7.1;
  m.std_error = 0.4;
  m.ci95 = std::array<double, 2>{6.3, 7.9};
  m.ci95_profile = std::array<double, 2>{6.4, 8.1};
  m.profile_closed = {true, false};
  r.parameters.push_back(b);
  r.parameters.push_back(m);
  const std::string html = report_html(r, d);
  // name, value, stderr, low, high, method, ...
  const auto f = row_cells(html, "f"), bc = row_cells(html, "b"), mc = row_cells(html, "m");
  const auto kappa = row_cells(html, "kappa");
  ASSERT_GT(f.size(), 5u);
  ASSERT_GT(bc.size(), 5u);
  ASSERT_GT(mc.size(), 5u);
  ASSERT_GT(kappa.size(), 5u);
  EXPECT_EQ(f[5], "model (t·stderr)");
  EXPECT_EQ(f[3], "0.4974");
  EXPECT_EQ(bc[5], "profile");
  // The profile's ends, 17.6 and 27.9, to 2 significant digits of the width (the model
  // interval's would read 17 and 27).
  EXPECT_EQ(bc[3], "18");
  EXPECT_EQ(bc[4], "28");
  EXPECT_EQ(mc[5], "profile, open above (ends at the bound)");
  EXPECT_EQ(kappa[5], "—");  // fixed: no interval
  EXPECT_NE(html.find("<th>interval method</th>"), std::string::npos);

  const std::string md = report_markdown(r);
  EXPECT_NE(md.find("| note | 95% CI method |"), std::string::npos) << md;
  EXPECT_NE(md.find("| b | 22.0 ± 2.5 | [18, 28] |"), std::string::npos) << md;
  const auto line_of = [&md](const std::string& start) {
    const auto at = md.find(start);
    return at == std::string::npos ? std::string() : md.substr(at, md.find('\n', at) - at);
  };
  const std::string f_line = line_of("| f |"), b_line = line_of("| b |");
  EXPECT_EQ(f_line.substr(f_line.rfind("| ", f_line.size() - 3)), "| model (t·stderr) |");
  EXPECT_EQ(b_line.substr(b_line.rfind("| ", b_line.size() - 3)), "| profile |");

  // With --intervals sandwich every row says so, whatever was profiled.
  r.intervals = IntervalMethod::Sandwich;
  r.parameters[0].ci95_sandwich = std::array<double, 2>{0.497, 0.503};
  EXPECT_EQ(row_cells(report_html(r, d), "f")[5], "HC3 (t·sandwich stderr)");
  EXPECT_EQ(row_cells(report_html(r, d), "b")[5], "—");
}

}  // namespace
}  // namespace frictionid::report_html_test
