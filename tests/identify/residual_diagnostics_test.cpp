#include "identify/residual_diagnostics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <frictionid/fitter.hpp>
#include <frictionid/synthetic_data.hpp>

namespace frictionid::residual_diagnostics_test {
namespace {

TEST(RankCorrelation, IsOneForAnIncreasingMapAndMinusOneForADecreasingOne) {
  std::vector<double> x, up, down;
  for (int i = 0; i < 50; ++i) {
    const double v = std::sin(1.7 * i) * 10;  // unordered, distinct
    x.push_back(v);
    up.push_back(std::exp(v));
    down.push_back(-v * v * v);
  }
  EXPECT_NEAR(rank_correlation(x, up), 1.0, 1e-15);
  EXPECT_NEAR(rank_correlation(x, down), -1.0, 1e-15);
}

TEST(RankCorrelation, IndependentSamplesStayWithinFourStandardErrorsOfZero) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  const int n = 4000;
  std::vector<double> a(n), b(n);
  for (int i = 0; i < n; ++i) a[i] = g(rng), b[i] = g(rng);
  EXPECT_LT(std::fabs(rank_correlation(a, b)), 4.0 / std::sqrt(n - 1.0));
}

bool warns_of_growth(const NoiseSpec& noise, NoiseModelKind model = NoiseModelKind::Auto) {
  using Law = model::PressureLaw<double>;
  const Law law = Law::hertz();
  auto truth = default_parameters(law, 0.85, 1.3, 0.12);
  const Dataset d = generate_dataset(ModelKind::Seed, law, truth, SyntheticDesign{}, noise, 3);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "hertz");
  s.global_evaluations = 500;
  s.noise_model = model;
  const FitResult r = Fitter(s).fit(d);
  for (const auto& w : r.warnings)
    if (w.find("grow with the measured magnitude") != std::string::npos) return true;
  return false;
}

// A constant noise model cannot follow noise proportional to the signal: that is warned of.
TEST(ResidualGrowth, ProportionalNoiseUnderAConstantNoiseModelIsWarnedOf) {
  EXPECT_TRUE(warns_of_growth(NoiseSpec{0.01, 0.0, false}, NoiseModelKind::Constant));
}

// The default noise model (auto) follows it, and sigma columns state it: no warning then.
TEST(ResidualGrowth, NoWarningWhereTheNoiseModelOrSigmaColumnsTakeCareOfIt) {
  EXPECT_FALSE(warns_of_growth(NoiseSpec{0.01, 0.0, false}));
  EXPECT_FALSE(warns_of_growth(NoiseSpec{0.01, 0.0, false}, NoiseModelKind::Relative));
  EXPECT_FALSE(warns_of_growth(NoiseSpec{0.01, 0.0, true}));
  EXPECT_FALSE(warns_of_growth(NoiseSpec{}));
}

}  // namespace
}  // namespace frictionid::residual_diagnostics_test
