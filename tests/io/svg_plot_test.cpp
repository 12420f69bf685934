#include "io/svg_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace frictionid::svg::svg_plot_test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::size_t count(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (auto pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1)) ++n;
  return n;
}

// The d attribute of the k-th <path> of a rendered plot.
std::string path_data(const std::string& svg, std::size_t k) {
  std::size_t pos = 0;
  for (std::size_t i = 0; i <= k; ++i) pos = svg.find("<path", pos) + 1;
  const auto begin = svg.find(" d=\"", pos) + 4;
  return svg.substr(begin, svg.find('"', begin) - begin);
}

Plot dots(std::vector<double> x, std::vector<double> y, bool log_x = false) {
  Plot p;
  p.title = "t";
  p.log_x = log_x;
  p.series.push_back({"data", "#000000", Mark::Dots, std::move(x), std::move(y)});
  return p;
}

TEST(LinearTicks, AreRoundStepsInsideTheRange) {
  const auto t = linear_ticks(0.13, 0.87, 6);
  ASSERT_GE(t.size(), 4u);
  ASSERT_LE(t.size(), 10u);
  EXPECT_GE(t.front(), 0.13);
  EXPECT_LE(t.back(), 0.87);
  const double step = t[1] - t[0];
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
              std::abs(mantissa - 5) < 1e-9)
      << step;
  for (double v : t) EXPECT_NEAR(v / step, std::round(v / step), 1e-9);
}

TEST(LogTicks, AreTheDecadesOfAWideRange) {
  EXPECT_EQ(log_ticks(0.009, 120.0), (std::vector<double>{0.01, 0.1, 1.0, 10.0, 100.0}));
}

TEST(LogTicks, AddTwoAndFiveWhenTheRangeIsNarrow) {
  EXPECT_EQ(log_ticks(0.15, 6.0), (std::vector<double>{0.2, 0.5, 1.0, 2.0, 5.0}));
}

TEST(TickLabel, IsShortAndWithoutTrailingZeros) {
  EXPECT_EQ(tick_label(0.1), "0.1");
  EXPECT_EQ(tick_label(250.0), "250");
  EXPECT_EQ(tick_label(0.0), "0");
  EXPECT_EQ(tick_label(1e6), "1e+06");
}

TEST(Render, SamePlotGivesTheSameBytesAndNoNan) {
  Plot p = dots({1, 2, kNaN, 4}, {0.5, kNaN, 3, 2});
  p.y_reference = 0.0;
  const std::string a = render(p), b = render(p);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.find("nan"), std::string::npos);
  EXPECT_EQ(a.find("inf"), std::string::npos);
}

TEST(Render, HugeValuesNeverPrintNanOrInf) {
  const std::string svg = render(dots({1, 2}, {-1.7e308, 1.7e308}));
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(Render, PointsALogAxisCannotShowAreSkipped) {
  const std::string svg = render(dots({-1, 0, kNaN, 0.1, 10}, {1, 2, 3, 4, 5}, true));
  EXPECT_EQ(count(path_data(svg, 0), "h0"), 2u);
}

TEST(Render, DotsInOneHalfPixelCellAreDrawnOnce) {
  std::vector<double> x(1000, 1.0), y(1000, 2.0);
  x.push_back(3.0), y.push_back(4.0);
  EXPECT_EQ(count(path_data(render(dots(x, y)), 0), "h0"), 2u);
}

TEST(Render, ALineBreaksAtAMissingPoint) {
  Plot p;
  p.series.push_back({"", "#000000", Mark::Line, {1, 2, 3, 4, 5}, {1, 2, kNaN, 4, 5}});
  const std::string d = path_data(render(p), 0);
  EXPECT_EQ(count(d, "M"), 2u);
  EXPECT_EQ(count(d, "L"), 2u);
}

TEST(Render, LegendListsOnlyLabelledSeries) {
  Plot p = dots({1, 2}, {1, 2});
  p.series.push_back({"", "#ff0000", Mark::Line, {1, 2}, {1, 2}});
  p.series.push_back({"model", "#00ff00", Mark::Line, {1, 2}, {2, 1}});
  const std::string svg = render(p);
  EXPECT_EQ(count(svg, ">data</text>"), 1u);
  EXPECT_EQ(count(svg, ">model</text>"), 1u);
  EXPECT_EQ(count(svg, "<circle"), 1u);  // the dot series' legend mark
}

TEST(Render, TextIsEscaped) {
  Plot p = dots({1}, {1});
  p.title = "a<b & \"c\"";
  EXPECT_NE(render(p).find("a&lt;b &amp; &quot;c&quot;"), std::string::npos);
}

TEST(Render, InlineElementHasNoNamespaceButTheFileHas) {
  const std::string svg = render(dots({1}, {1}));
  EXPECT_EQ(svg.find("http"), std::string::npos);  // inline in HTML: no URL at all
  const std::string file = standalone_file(svg);
  EXPECT_EQ(file.rfind("<?xml", 0), 0u);
  EXPECT_NE(file.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
}

}  // namespace
}  // namespace frictionid::svg::svg_plot_test
