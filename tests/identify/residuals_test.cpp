#include "identify/residuals.hpp"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>

namespace frictionid::residuals_test {
namespace {

// The scaled residuals of a row must square-sum to rho(s) of its unscaled squared norm s.
TEST(Residuals, RobustRowFactorTurnsTheSquaredNormIntoTheLoss) {
  const double c = 1.5;
  for (double s : {0.01, 1.0, 2.25, 9.0, 400.0}) {
    const double huber = s <= c * c ? s : 2 * c * std::sqrt(s) - c * c;
    const double cauchy = c * c * std::log1p(s / (c * c));
    const double soft = 2 * c * c * (std::sqrt(1 + s / (c * c)) - 1);
    auto sq = [&](LossKind k) {
      const double f = robust_row_factor(s, k, c);
      return f * f * s;
    };
    EXPECT_NEAR(sq(LossKind::Huber), huber, 1e-12 * huber);
    EXPECT_NEAR(sq(LossKind::Cauchy), cauchy, 1e-12 * cauchy);
    EXPECT_NEAR(sq(LossKind::SoftL1), soft, 1e-12 * soft);
    EXPECT_EQ(sq(LossKind::None), s);
  }
}

// Near an exact fit (s -> 0) the loss must behave like least squares, derivatives included:
// rho(s)/s = 1 - s/(2c^2) + ... (Cauchy), 1 - s/(4c^2) + ... (soft L1), so the factor's slope
// at 0 is -1/(4c^2) and -1/(8c^2); elsewhere it matches central differences.
TEST(Residuals, RobustRowFactorHasFiniteExactDerivativesDownToAnExactFit) {
  using Jet = ceres::Jet<double, 1>;
  const double c = 1.5, c2 = c * c;
  for (double s : {1e-30, 1e-20, 1e-12, 1e-6}) {
    const Jet fc = robust_row_factor(Jet(s, 0), LossKind::Cauchy, c);
    const Jet fs = robust_row_factor(Jet(s, 0), LossKind::SoftL1, c);
    EXPECT_NEAR(fc.a, 1.0, 1e-6);
    EXPECT_NEAR(fs.a, 1.0, 1e-6);
    EXPECT_NEAR(fc.v[0], -1.0 / (4 * c2), 1e-5 / c2) << s;
    EXPECT_NEAR(fs.v[0], -1.0 / (8 * c2), 1e-5 / c2) << s;
  }
  for (LossKind k : {LossKind::Huber, LossKind::Cauchy, LossKind::SoftL1})
    for (double s : {1e-4, 5e-4, 2e-3, 0.5, 3.0, 40.0}) {
      const double h = 1e-4 * s;
      const double fd = (robust_row_factor(s + h, k, c) - robust_row_factor(s - h, k, c)) / (2 * h);
      EXPECT_NEAR(robust_row_factor(Jet(s, 0), k, c).v[0], fd, 1e-6 * (std::fabs(fd) + 1e-3))
          << static_cast<int>(k) << " " << s;
    }
}

TEST(Residuals, WhiteningDividesByTheSigmaColumnOrTheChannelScale) {
  Dataset d;
  d.v_x = {0.1};
  d.v_y = {0.0};
  d.omega = {2.0};
  d.N = {1000.0};
  d.R = {0.05};
  for (int c = 0; c < kChannelCount; ++c) {
    d.value[c] = {1.0};
    d.present[c] = {1};
  }
  d.sigma[0] = {0.5};  // T_x has a sigma column
  ResidualRows rows;
  rows.data = &d;
  rows.channels = {Channel::T_x, Channel::T_y};
  rows.scale = {7.0, 4.0, 1.0, 1.0};
  rows.begin = 0;
  rows.end = 1;
  const auto law = model::PressureLaw<double>::hertz();
  const auto p = default_parameters(law, 0.8, 1.2, 0.1);
  double r[2];
  ASSERT_TRUE(evaluate_residuals(rows, ModelKind::Seed, law, LossKind::None, 1.0, p.data(), r));
  const auto pred = ModelEvaluator<double>(
      ModelKind::Seed, law, p.data())(model::Kinematics{0.1, 0.0, 2.0, 1000.0, 0.05});
  EXPECT_DOUBLE_EQ(r[0], (pred.T_x - 1.0) / 0.5);
  EXPECT_DOUBLE_EQ(r[1], (pred.T_y - 1.0) / 4.0);
}

// The Cauchy loss switches to a series of log1p(x)/x below x = s/c^2 = 1e-3: its value must be
// c^2 log1p(s/c^2) on both sides of the switch, to rounding (the series' first omitted term,
// x^5/6, is below 2e-16 there).
TEST(Residuals, CauchyLossEqualsItsFormulaOnBothSidesOfTheSeriesSwitch) {
  const double c = 2.0;
  for (double x : {1e-9, 1e-6, 1e-4, 5e-4, 1e-3 * (1 - 1e-9), 1e-3, 1e-3 * (1 + 1e-9), 2e-3}) {
    const double s = x * c * c;
    const double expected = c * c * std::log1p(x);
    const double f = robust_row_factor(s, LossKind::Cauchy, c);
    EXPECT_NEAR(f * f * s, expected, 1e-14 * expected) << "x = " << x;
    EXPECT_NEAR(robust_rho(s, LossKind::Cauchy, c), expected, 1e-14 * expected) << "x = " << x;
  }
}

}  // namespace
}  // namespace frictionid::residuals_test
