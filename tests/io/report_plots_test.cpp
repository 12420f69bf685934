// The report's plots read back from their SVG: residuals whitened by the sigma per row that the
// fit used, and collapse lines that follow one slip direction and spin sign each.
#include "io/report_parts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace frictionid::report_plots_test {
namespace {

const ReportPlot& plot_named(const std::vector<ReportPlot>& plots, const std::string& file) {
  for (const auto& p : plots)
    if (p.file == file) return p;
  ADD_FAILURE() << "no plot " << file;
  return plots.front();
}

// The <path> elements of an SVG that carry a data-tag: (tag, y pixel of every point).
std::vector<std::pair<std::string, std::vector<double>>> tagged_paths(const std::string& svg) {
  std::vector<std::pair<std::string, std::vector<double>>> out;
  const std::regex path("<path [^>]*data-tag=\"([^\"]*)\" d=\"([^\"]*)\"");
  const std::regex point("[ML](-?[0-9.]+) (-?[0-9.]+)");
  for (auto m = std::sregex_iterator(svg.begin(), svg.end(), path); m != std::sregex_iterator();
       ++m) {
    const std::string d = (*m)[2];
    std::vector<double> ys;
    for (auto p = std::sregex_iterator(d.begin(), d.end(), point); p != std::sregex_iterator(); ++p)
      ys.push_back(std::stod((*p)[2]));
    out.emplace_back((*m)[1], ys);
  }
  return out;
}

void add_row(Dataset& d, double vx, double vy, double omega, double n) {
  d.line.push_back(d.line.size() + 2);
  d.v_x.push_back(vx);
  d.v_y.push_back(vy);
  d.omega.push_back(omega);
  d.N.push_back(n);
  d.R.push_back(0.05);
}

FitResult fit_of(const Dataset& d, Channel c) {
  FitResult r;
  r.model = "exact";
  r.rows = d.rows();
  r.channels = {c};
  ChannelSummary s;
  s.channel = c;
  s.rows = d.rows();
  s.rmse = 1.0;
  r.channel_summaries = {s};
  for (std::size_t i = 0; i < d.rows(); ++i)
    r.eps.push_back(std::hypot(d.v_x[i], d.v_y[i]) / (std::fabs(d.omega[i]) * d.R[i]));
  return r;
}

// A relative noise: sigma_i = 0.05 |fitted_i| over four decades of T_x. Every residual is +1.5
// or -1.5 of its row's sigma, so the whitened residuals take two values: two rows of dots. A
// plot that divided by one scale per channel would spread them over four decades.
TEST(ReportPlots, ResidualsAreDividedByTheSigmaOfTheirRowUnderTheFittedNoiseModel) {
  Dataset d;
  for (int i = 0; i < 41; ++i) add_row(d, 0.01 * std::pow(10.0, i / 10.0), 0.0, 2.0, 1000.0);
  for (int c = 0; c < 4; ++c) {
    d.value[c].assign(d.rows(), 0.0);
    d.present[c].assign(d.rows(), c == 0);
  }
  FitResult r = fit_of(d, Channel::T_x);
  r.channel_summaries[0].noise =
      NoiseEstimate{NoiseModelKind::Relative, "relative", 0.0, 0.05, 1e-6, ""};
  r.channel_summaries[0].scale_source = "noise model relative: sigma = 0.05 |fitted|";
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const double y = std::pow(10.0, static_cast<double>(i) / 10.0);
    r.fitted[0].push_back(y);
    d.value[0][i] = y + (i % 2 ? 1.5 : -1.5) * 0.05 * y;
  }
  for (int c = 1; c < 4; ++c) r.fitted[c].assign(d.rows(), 0.0);
  const auto plots = make_plots(r, d, ReportOptions{});
  for (const char* file : {"residuals_T_x.svg", "residuals_fitted_T_x.svg"}) {
    const ReportPlot& p = plot_named(plots, file);
    std::set<double> levels;
    std::size_t dots = 0;
    for (const auto& [tag, ys] : tagged_paths(p.svg)) {
      dots += ys.size();
      levels.insert(ys.begin(), ys.end());
    }
    EXPECT_GE(dots, 2u) << file;
    EXPECT_EQ(levels.size(), 2u) << file << ": the dots sit at more than two heights";
    EXPECT_NE(p.caption.find("noise model"), std::string::npos) << p.caption;
  }
  // The normal quantile plot holds every row.
  const auto qq = tagged_paths(plot_named(plots, "qq_T_x.svg").svg);
  ASSERT_EQ(qq.size(), 1u);
  EXPECT_EQ(qq[0].first, "quantiles");
}

// T_y of a model with the mirror symmetry y -> -y: T_y / N = sin(alpha) eps/(1+eps) +
// 0.1 sgn(omega)/(1+eps). Slip angles 0 and 90 degrees (lateral slip), both spin signs, two
// loads. Every (direction, spin sign) gets its own fitted line, and along each the collapsed
// T_y changes sign at most once; a line through both spin signs' rows would alternate.
TEST(ReportPlots, CollapseLinesFollowOneSlipDirectionAndSpinSignEach) {
  Dataset d;
  for (double n : {1000.0, 2000.0})
    for (double angle : {0.0, 90.0})
      for (double spin : {1.0, -1.0})
        for (int k = 0; k < 12; ++k) {
          const double v = 0.1 * 0.03 * std::pow(1.9, k);
          add_row(d, angle == 0.0 ? v : 0.0, angle == 0.0 ? 0.0 : v, 2.0 * spin, n);
        }
  for (int c = 0; c < 4; ++c) {
    d.value[c].assign(d.rows(), 0.0);
    d.present[c].assign(d.rows(), c == 1);
  }
  FitResult r = fit_of(d, Channel::T_y);
  for (int c = 0; c < 4; ++c) r.fitted[c].assign(d.rows(), 0.0);
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const double e = r.eps[i], s = d.omega[i] < 0 ? -1.0 : 1.0;
    const double sin_alpha = d.v_y[i] > 0 ? 1.0 : 0.0;
    r.fitted[1][i] = d.N[i] * (sin_alpha * e / (1 + e) + 0.1 * s / (1 + e));
    d.value[1][i] = r.fitted[1][i];
  }
  const auto plots = make_plots(r, d, ReportOptions{});
  const ReportPlot& p = plot_named(plots, "collapse_T_y.svg");
  const std::smatch zero = [&] {
    std::smatch m;
    const std::regex line("<line x1=\"[0-9.]+\" y1=\"([0-9.]+)\" [^>]*stroke-dasharray=\"5 4\"");
    EXPECT_TRUE(std::regex_search(p.svg, m, line)) << "no zero line";
    return m;
  }();
  const double zero_px = std::stod(zero[1]);
  std::set<std::string> curves;
  for (const auto& [tag, ys] : tagged_paths(p.svg)) {
    const auto at = tag.find("direction=");
    if (at == std::string::npos) continue;  // the measured dots
    curves.insert(tag.substr(at, tag.find(" tilt=") - at));
    int changes = 0;
    for (std::size_t k = 1; k < ys.size(); ++k)
      if ((ys[k] < zero_px) != (ys[k - 1] < zero_px)) ++changes;
    EXPECT_LE(changes, 1) << tag;
  }
  EXPECT_EQ(curves, (std::set<std::string>{"direction=0 spin=-1", "direction=0 spin=1",
                                           "direction=90 spin=-1", "direction=90 spin=1"}));
  EXPECT_NE(p.caption.find("spin sign"), std::string::npos);
}

}  // namespace
}  // namespace frictionid::report_plots_test
