// The colours of the reports: the categorical palette is Okabe and Ito's, its colours stay apart
// for colour-blind readers (simulated), and the correlation heat map's text meets WCAG AA
// contrast on every colour its ramp can take.
#include "io/palette.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "io/report_parts.hpp"

namespace frictionid::palette_test {
namespace {

using Rgb = std::array<double, 3>;

// "#rrggbb" as linear-light sRGB in [0, 1].
Rgb linear_rgb(const std::string& hex) {
  Rgb out{};
  for (int k = 0; k < 3; ++k) {
    const double v =
        std::stoi(hex.substr(1 + 2 * static_cast<std::size_t>(k), 2), nullptr, 16) / 255.0;
    out[static_cast<std::size_t>(k)] =
        v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  }
  return out;
}

// WCAG 2's relative luminance and contrast ratio.
double luminance(const std::string& hex) {
  const Rgb c = linear_rgb(hex);
  return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}
double contrast(const std::string& a, const std::string& b) {
  const double la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

// CIELAB (D65) of linear sRGB.
Rgb lab(const Rgb& c) {
  const double x = (0.4124 * c[0] + 0.3576 * c[1] + 0.1805 * c[2]) / 0.95047;
  const double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  const double z = (0.0193 * c[0] + 0.1192 * c[1] + 0.9505 * c[2]) / 1.08883;
  const auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
  };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

// Machado, Oliveira and Fernandes (2009), severity 1, on linear sRGB.
using Matrix = std::array<Rgb, 3>;
const Matrix kDeuteranopia = {{{0.367322, 0.860646, -0.227968},
                               {0.280085, 0.672501, 0.047413},
                               {-0.011820, 0.042940, 0.968881}}};
const Matrix kProtanopia = {{{0.152286, 1.052583, -0.204868},
                             {0.114503, 0.786281, 0.099216},
                             {-0.003882, -0.048116, 1.051998}}};
const Matrix kTritanopia = {{{1.255528, -0.076749, -0.178779},
                             {-0.078411, 0.930809, 0.147602},
                             {0.004733, 0.691367, 0.303900}}};

Rgb seen_as(const Matrix& m, const Rgb& c) {
  Rgb out{};
  for (std::size_t i = 0; i < 3; ++i)
    out[i] = std::clamp(m[i][0] * c[0] + m[i][1] * c[1] + m[i][2] * c[2], 0.0, 1.0);
  return out;
}

// The smallest CIE76 colour difference between two colours of `colours` as a reader with the
// deficiency m sees them.
double smallest_difference(const std::vector<std::string>& colours, const Matrix& m) {
  double smallest = INFINITY;
  for (std::size_t i = 0; i < colours.size(); ++i)
    for (std::size_t k = i + 1; k < colours.size(); ++k) {
      const Rgb a = lab(seen_as(m, linear_rgb(colours[i])));
      const Rgb b = lab(seen_as(m, linear_rgb(colours[k])));
      smallest = std::min(smallest, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    }
  return smallest;
}

std::vector<std::string> series_colours() {
  return {palette::kSeries.begin(), palette::kSeries.end()};
}

TEST(Palette, IsOkabeAndItosWithoutBlack) {
  // Okabe and Ito, "Color Universal Design" (2008): orange, sky blue, bluish green, yellow,
  // blue, vermillion, reddish purple; their black is the reference colour.
  const std::set<std::string> okabe_ito = {"#e69f00", "#56b4e9", "#009e73", "#f0e442",
                                           "#0072b2", "#d55e00", "#cc79a7"};
  const auto ours = series_colours();
  EXPECT_EQ(std::set<std::string>(ours.begin(), ours.end()), okabe_ito);
  EXPECT_EQ(ours.size(), okabe_ito.size());
  EXPECT_EQ(std::string(palette::kReference), "#000000");
  for (std::size_t k = 0; k < 2 * ours.size(); ++k)
    EXPECT_EQ(palette::series(k), ours[k % ours.size()]);
}

TEST(Palette, ColoursStayApartForColourBlindReaders) {
  const auto ours = series_colours();
  for (const Matrix* m : {&kDeuteranopia, &kProtanopia, &kTritanopia})
    EXPECT_GT(smallest_difference(ours, *m), 15.0);
  // The reference colour is told apart from every series colour as well.
  auto with_reference = ours;
  with_reference.push_back(palette::kReference);
  for (const Matrix* m : {&kDeuteranopia, &kProtanopia, &kTritanopia})
    EXPECT_GT(smallest_difference(with_reference, *m), 15.0);
  // The check tells: the reports' former palette (matplotlib's tab10) fails it.
  const std::vector<std::string> tab10 = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                          "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  EXPECT_LT(smallest_difference(tab10, kDeuteranopia), 15.0);
  EXPECT_LT(smallest_difference(tab10, kProtanopia), 15.0);
}

// Every colour the heat map's ramp can give a cell, from -1 to +1 in steps of 1e-4 (the ramp
// is rounded to 8 bits per channel, so this reaches every colour it has), carries text of at
// least 4.5:1 contrast.
TEST(HeatMap, TextHasAAContrastOnEveryCellColour) {
  double worst = INFINITY;
  std::set<std::string> backgrounds;
  for (int k = -10000; k <= 10000; ++k) {
    const std::string background = correlation_colour(k * 1e-4);
    const std::string text = text_colour_on(background);
    backgrounds.insert(background);
    worst = std::min(worst, contrast(background, text));
    ASSERT_GE(contrast(background, text), 4.5) << background << " with " << text;
  }
  EXPECT_GT(backgrounds.size(), 300u);  // the ramp was sampled, not one colour
  EXPECT_GE(worst, 4.5);
  // The check tells: the former rule (white text beyond |c| = 0.6, else #222222) fails it.
  double former = INFINITY;
  for (int k = -100; k <= 100; ++k) {
    const double c = k * 0.01;
    former = std::min(former,
                      contrast(correlation_colour(c), std::abs(c) > 0.6 ? "#ffffff" : "#222222"));
  }
  EXPECT_LT(former, 4.5);
}

// The page uses that choice: every coloured cell of report.html's heat map.
TEST(HeatMap, ReportCellsCarryTheirContrastingText) {
  FitResult r;
  r.model = "seed";
  r.pressure = "hertz";
  r.correlation_names = {"f", "kappa", "h"};
  r.correlation = {{1.0, 0.61, -0.45}, {0.61, 1.0, -0.93}, {-0.45, -0.93, 1.0}};
  const std::string page = report_html_page(r, {});
  std::size_t cells = 0;
  const std::string mark = "<td style=\"background:";
  for (auto at = page.find(mark); at != std::string::npos; at = page.find(mark, at + 1)) {
    const std::string background = page.substr(at + mark.size(), 7);
    const auto text = page.find(";color:", at) + 7;
    ASSERT_EQ(page[text], '#');
    EXPECT_GE(contrast(background, page.substr(text, 7)), 4.5) << page.substr(at, 80);
    ++cells;
  }
  EXPECT_EQ(cells, 9u);
}

}  // namespace
}  // namespace frictionid::palette_test
