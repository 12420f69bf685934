#include <frictionid/io/compare_report.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace frictionid::compare_html_test {
namespace {

// Ten rows at two loads, T_x measured; two models whose predictions differ.
Dataset make_dataset() {
  Dataset d;
  d.source = "rows.csv";
  for (int i = 0; i < 10; ++i) {
    d.line.push_back(static_cast<std::size_t>(i) + 2);
    d.v_x.push_back(0.01 * (i + 1));
    d.v_y.push_back(0.0);
    d.omega.push_back(2.0);
    d.N.push_back(i < 5 ? 100.0 : 200.0);
    d.R.push_back(0.05);
    d.value[0].push_back(0.8 * d.N.back() * std::tanh(d.v_x.back() / 0.1));
    d.present[0].push_back(1);
  }
  for (int c : {1, 2, 3}) {
    d.value[c].assign(d.rows(), 0.0);
    d.present[c].assign(d.rows(), 0);
  }
  return d;
}

FitResult fit_of(const std::string& model, double f, const Dataset& d) {
  FitResult r;
  r.model = model;
  r.rows = d.rows();
  r.channels = {Channel::T_x};
  ParameterEstimate p;
  p.name = "f";
  p.value = f;
  p.std_error = 0.01;
  r.parameters = {p};
  for (std::size_t i = 0; i < d.rows(); ++i) {
    r.eps.push_back(d.v_x[i] / (d.omega[i] * d.R[i]));
    r.fitted[0].push_back(f * d.N[i] * std::tanh(d.v_x[i] / 0.1));
  }
  ChannelSummary s;
  s.channel = Channel::T_x;
  s.rmse = 0.5;
  r.channel_summaries = {s};
  return r;
}

ModelComparison make_comparison(const Dataset& d) {
  ModelComparison c;
  c.fits = {fit_of("seed", 0.75, d), fit_of("exact", 0.8125, d)};
  c.delta_aic = {12.0, 0.0};
  c.delta_bic = {12.0, 0.0};
  c.preferred_by_aic = c.preferred_by_bic = "exact";
  c.residual_autocorrelation = {{{"T_x", 0.9}}, {{"T_x", 0.05}}};
  return c;
}

TEST(CompareHtml, PutsEveryModelsParameterSideBySide) {
  const Dataset d = make_dataset();
  const std::string html = compare_html(make_comparison(d), d);
  const auto row = html.find("<tr data-param=\"f\">");
  ASSERT_NE(row, std::string::npos);
  const std::string cells = html.substr(row, html.find("</tr>", row) - row);
  const auto seed = cells.find("data-model=\"seed\" data-value=\"0.75\"");
  const auto exact = cells.find("data-model=\"exact\" data-value=\"0.8125\"");
  ASSERT_NE(seed, std::string::npos);
  ASSERT_NE(exact, std::string::npos);
  EXPECT_LT(seed, exact);  // in the order the models were fitted
}

TEST(CompareHtml, OverlaysEveryModelOnTheDataAndLinksTheModelReports) {
  const Dataset d = make_dataset();
  const std::string html = compare_html(make_comparison(d), d);
  const auto fig = html.find("<figure class=\"plot\" data-file=\"compare_T_x.svg\">");
  ASSERT_NE(fig, std::string::npos);
  const std::string plot = html.substr(fig, html.find("</figure>", fig) - fig);
  for (const char* legend : {">measured</text>", ">seed</text>", ">exact</text>"})
    EXPECT_NE(plot.find(legend), std::string::npos) << legend;
  EXPECT_NE(html.find("<a href=\"seed/report.html\">"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"exact/report.html\">"), std::string::npos);
}

TEST(CompareHtml, IsSelfContainedAndByteStable) {
  const Dataset d = make_dataset();
  const std::string html = compare_html(make_comparison(d), d);
  EXPECT_EQ(html, compare_html(make_comparison(d), d));
  EXPECT_EQ(html.find("http:"), std::string::npos);
  EXPECT_EQ(html.find("https:"), std::string::npos);
  EXPECT_EQ(html.find(" src="), std::string::npos);
}

// Each model's own noise estimate puts its own chi2 near the number of cells: here the worse
// model (seed, by AIC) has the smaller own chi2. The page must not rank by it: it shows the chi2
// under one noise (exact's) and says whose, and claims no common whitening.
TEST(CompareHtml, ShowsTheChi2UnderOneNoiseNotEachModelsOwn) {
  const Dataset d = make_dataset();
  ModelComparison c = make_comparison(d);
  c.fits[0].chi2 = 9.0;   // seed, the worse model
  c.fits[1].chi2 = 10.0;  // exact
  c.chi2_common = {431.0, 10.0};
  c.common_noise_fit = 1;
  for (auto& f : c.fits)
    f.channel_summaries[0].noise =
        NoiseEstimate{NoiseModelKind::Constant, "constant", 0.5, 0.0, 0.0, ""};
  const std::string html = compare_html(c, d);
  EXPECT_EQ(html.find("whitening for every"), std::string::npos);
  EXPECT_NE(html.find("<th>χ², one noise</th>"), std::string::npos);
  EXPECT_NE(html.find("noise estimated for <strong>exact</strong>"), std::string::npos);
  const auto table = html.substr(html.find("id=\"quality\""));
  EXPECT_NE(table.find("data-value=\"431\""), std::string::npos);
  EXPECT_EQ(table.substr(0, table.find("</table>")).find("data-value=\"9\""), std::string::npos)
      << "the seed's own chi2 is in the table";
}

// Without any noise estimate (sigma columns or fixed scales) every model is whitened alike, and
// the page says so.
TEST(CompareHtml, SaysTheWhiteningIsCommonWhenNoModelEstimatesNoise) {
  const Dataset d = make_dataset();
  const std::string html = compare_html(make_comparison(d), d);
  EXPECT_NE(html.find("the same whitening for every model (sigma columns or fixed scales)"),
            std::string::npos);
  EXPECT_EQ(html.find("own noise estimate"), std::string::npos);
}

}  // namespace
}  // namespace frictionid::compare_html_test
