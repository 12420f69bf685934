// Approximant coefficients a, b, m, b_tilde, p0, mu_M (docs/physics.md §3) against hand-derived
// closed forms, their consistency bounds over random pressure shapes, and m(alpha) with d22.
//
// Hand derivation from m_k = ∫ sigma0 rho^k drho:
//   uniform   m0..m3 = 1, 1/2, 1/3, 1/4         a = 1, b = 16, m = [4(1+κ)/(3κ)]²,
//             b~ = (4/3)², p0 = 1/3, mu_M = 2/3, rho_roll = m3/(2 m1) = 1/4
//   Hertz     m0..m3 = π/4, 1/3, π/16, 2/15     a = (8/(3π))², b = 25, m = [15π(1+κ)/(32κ)]²,
//             b~ = (15π/32)², p0 = 3π/32, mu_M = 3π/16, rho_roll = 1/5
//   parabolic m0..m3 = 2/3, 1/4, 2/15, 1/12     a = 9/16, b = 36, m = [8(1+κ)/(5κ)]²,
//             b~ = (8/5)², p0 = 4/15, mu_M = 8/15, rho_roll = 1/6
#include <frictionid/model/coefficients.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/pressure_table.hpp>
#include "model/test_support.hpp"

namespace frictionid::model::coefficients_test {
namespace {

using testing::beta_moment;
using testing::kPi;

struct Expected {
  double a, b, m_factor, b_tilde, p0, mu_M, rho_roll;  // m = [m_factor (1+κ)/κ]²
};

void expect_coefficients(const PressureLaw<double>& law, const Expected& e,
                         const std::string& name) {
  for (double kappa : {0.3, 1.0, 2.7}) {
    const auto c = coefficients(law_moments(law), kappa);
    const double m = std::pow(e.m_factor * (1 + kappa) / kappa, 2);
    SCOPED_TRACE(name + " kappa=" + std::to_string(kappa));
    EXPECT_NEAR(c.a, e.a, 1e-14 * e.a);
    EXPECT_NEAR(c.b, e.b, 1e-14 * e.b);
    EXPECT_NEAR(c.m, m, 1e-14 * m);
    EXPECT_NEAR(c.b_tilde, e.b_tilde, 1e-14 * e.b_tilde);
    EXPECT_NEAR(c.p0, e.p0, 1e-15);
    EXPECT_NEAR(c.mu_M, e.mu_M, 1e-15);
    EXPECT_NEAR(c.rho_roll, e.rho_roll, 1e-15);
  }
}

TEST(Coefficients, UniformClosedForms) {
  expect_coefficients(PressureLaw<double>::uniform(),
                      {1.0, 16.0, 4.0 / 3.0, 16.0 / 9.0, 1.0 / 3.0, 2.0 / 3.0, 0.25}, "uniform");
}

TEST(Coefficients, HertzClosedForms) {
  expect_coefficients(PressureLaw<double>::hertz(),
                      {std::pow(8.0 / (3.0 * kPi), 2), 25.0, 15.0 * kPi / 32.0,
                       std::pow(15.0 * kPi / 32.0, 2), 3.0 * kPi / 32.0, 3.0 * kPi / 16.0, 0.2},
                      "hertz");
}

TEST(Coefficients, ParabolicClosedForms) {
  expect_coefficients(PressureLaw<double>::parabolic(),
                      {9.0 / 16.0, 36.0, 8.0 / 5.0, 64.0 / 25.0, 4.0 / 15.0, 8.0 / 15.0, 1.0 / 6.0},
                      "parabolic");
}

// Power laws: the definitions of §3 with Beta-function moments.
TEST(Coefficients, PowerLawsFollowTheMomentDefinitions) {
  for (double n : {0.1, 0.5, 1.7, 4.0}) {
    const double m0 = beta_moment(n, 0), m1 = beta_moment(n, 1), m2 = beta_moment(n, 2),
                 m3 = beta_moment(n, 3);
    const double kappa = 1.6;
    const auto c = coefficients(law_moments(PressureLaw<double>::power(n)), kappa);
    EXPECT_NEAR(c.a, std::pow(2 * m1 / m0, 2), 1e-13 * c.a) << n;
    EXPECT_NEAR(c.b, std::pow(2 * m1 / m3, 2), 1e-13 * c.b) << n;
    EXPECT_NEAR(c.m, std::pow((1 + kappa) * m2 / (kappa * m3), 2), 1e-13 * c.m) << n;
    EXPECT_NEAR(c.b_tilde, std::pow(m2 / m3, 2), 1e-13 * c.b_tilde) << n;
    EXPECT_NEAR(c.p0, m2 / (2 * m1), 1e-13 * c.p0) << n;
    EXPECT_NEAR(c.mu_M, m2 / m1, 1e-13 * c.mu_M) << n;
  }
}

// a and b do not depend on kappa or the slip direction; b_tilde, p0, mu_M neither.
TEST(Coefficients, AAndBDoNotDependOnKappaOrAlpha) {
  const auto mo = law_moments(PressureLaw<double>::power(1.3));
  const auto ref = coefficients(mo, 1.0, 0.0);
  for (double kappa : {0.2, 1.0, 5.0}) {
    for (double alpha : {0.0, 0.4, 1.2, kPi / 2, 2.8}) {
      const auto c = coefficients(mo, kappa, alpha);
      EXPECT_EQ(c.a, ref.a);
      EXPECT_EQ(c.b, ref.b);
      EXPECT_EQ(c.b_tilde, ref.b_tilde);
      EXPECT_EQ(c.p0, ref.p0);
      EXPECT_EQ(c.mu_M, ref.mu_M);
    }
  }
}

// m(alpha) = [(1+κ) m2/(d22 m3)]², d22 = sin²α + κ cos²α: κ at α = 0, 1 at α = π/2.
TEST(Coefficients, MOfAlphaUsesD22) {
  const auto mo = law_moments(PressureLaw<double>::hertz());
  const double r = (15.0 * kPi / 32.0);  // m2/m3 for Hertz
  for (double kappa : {0.4, 2.5}) {
    for (double alpha : {0.0, 0.3, 1.0, kPi / 2, 2.0, -0.7}) {
      const double d22 = std::pow(std::sin(alpha), 2) + kappa * std::pow(std::cos(alpha), 2);
      const double want = std::pow((1 + kappa) * r / d22, 2);
      EXPECT_NEAR(coefficients(mo, kappa, alpha).m, want, 1e-14 * want) << kappa << " " << alpha;
    }
    const double at_half_pi = coefficients(mo, kappa, kPi / 2).m;
    EXPECT_NEAR(at_half_pi, std::pow((1 + kappa) * r, 2), 1e-13 * at_half_pi);
  }
}

// The bounds of §3 hold for >= 200 random power laws, kappa and alpha; checked both with the
// library's check and directly from Beta-function moments.
TEST(Coefficients, ConsistencyBoundsHoldForRandomPowerLaws) {
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> un(0.0, 8.0), ua(-kPi, kPi),
      ul(std::log(0.1), std::log(10.0));
  for (int i = 0; i < 250; ++i) {
    const double n = un(rng), kappa = std::exp(ul(rng)), alpha = ua(rng);
    const auto c = coefficients(law_moments(PressureLaw<double>::power(n)), kappa, alpha);
    const double d22 = std::pow(std::sin(alpha), 2) + kappa * std::pow(std::cos(alpha), 2);
    const double r2 = std::pow((1 + kappa) / d22, 2);
    SCOPED_TRACE("n=" + std::to_string(n) + " kappa=" + std::to_string(kappa) +
                 " alpha=" + std::to_string(alpha));
    EXPECT_TRUE(check_consistency(c, kappa, alpha).all());
    EXPECT_LE(c.a, 4.0);
    EXPECT_GE(c.b, 4.0);
    EXPECT_GE(c.m, r2 * (1 - 1e-14));
    EXPECT_LE(c.m, r2 * std::sqrt(c.b) / 2 * (1 + 1e-14));
    // the same with independent moments
    const double m0 = beta_moment(n, 0), m1 = beta_moment(n, 1), m2 = beta_moment(n, 2),
                 m3 = beta_moment(n, 3);
    const double a = std::pow(2 * m1 / m0, 2), b = std::pow(2 * m1 / m3, 2);
    const double m = std::pow((1 + kappa) * m2 / (d22 * m3), 2);
    EXPECT_NEAR(c.m, m, 1e-12 * m);
    EXPECT_LE(a, 4.0);
    EXPECT_GE(b, 4.0);
    EXPECT_GE(m, r2 * (1 - 1e-14));
    EXPECT_LE(m, r2 * std::sqrt(b) / 2 * (1 + 1e-14));
  }
}

// Any sigma0 >= 0 satisfies the bounds, not just the power family: random tabulated shapes,
// including ones concentrated near the rim (where a, b and m approach their limits).
TEST(Coefficients, ConsistencyBoundsHoldForRandomTabulatedShapes) {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int t = 0; t < 40; ++t) {
    std::vector<double> rho, sigma;
    for (int i = 0; i <= 20; ++i) {
      rho.push_back(i / 20.0);
      sigma.push_back(t % 4 == 0 ? (i >= 19 ? 1.0 : 0.0) : u(rng));
    }
    const auto law =
        PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(rho, sigma));
    const double kappa = 0.1 + 9.9 * u(rng), alpha = 6.0 * u(rng);
    const auto c = coefficients(law_moments(law), kappa, alpha);
    EXPECT_TRUE(check_consistency(c, kappa, alpha).all()) << "table " << t;
  }
}

TEST(Coefficients, ConsistencyCheckFlagsEachViolation) {
  auto c = coefficients(law_moments(PressureLaw<double>::hertz()), 1.5);
  ASSERT_TRUE(check_consistency(c, 1.5).all());
  auto bad = c;
  bad.a = 4.01;
  EXPECT_FALSE(check_consistency(bad, 1.5).a_at_most_4);
  bad = c;
  bad.b = 3.99;
  EXPECT_FALSE(check_consistency(bad, 1.5).b_at_least_4);
  const double r2 = std::pow(2.5 / 1.5, 2);
  bad = c;
  bad.m = 0.99 * r2;
  EXPECT_FALSE(check_consistency(bad, 1.5).m_lower);
  bad = c;
  bad.m = 1.01 * r2 * std::sqrt(c.b) / 2;
  EXPECT_FALSE(check_consistency(bad, 1.5).m_upper);
  EXPECT_FALSE(check_consistency(bad, 1.5).all());
}

// Given kappa, (a, b, m) fix the moment ratios: m0/m1 = 2/√a, m3/m1 = 2/√b,
// m2/m3 = κ√m/(1+κ).
TEST(Coefficients, TripleFixesTheMomentRatios) {
  for (double n : {0.0, 0.5, 1.0, 2.2}) {
    const double kappa = 0.7;
    const auto c = coefficients(law_moments(PressureLaw<double>::power(n)), kappa);
    const double m0 = beta_moment(n, 0), m1 = beta_moment(n, 1), m2 = beta_moment(n, 2),
                 m3 = beta_moment(n, 3);
    EXPECT_NEAR(2 / std::sqrt(c.a), m0 / m1, 1e-13 * m0 / m1) << n;
    EXPECT_NEAR(2 / std::sqrt(c.b), m3 / m1, 1e-13 * m3 / m1) << n;
    EXPECT_NEAR(kappa * std::sqrt(c.m) / (1 + kappa), m2 / m3, 1e-13 * m2 / m3) << n;
  }
}

}  // namespace
}  // namespace frictionid::model::coefficients_test
