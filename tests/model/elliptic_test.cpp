#include <frictionid/model/elliptic.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace frictionid::model::elliptic_test {
namespace {

// Independent reference: the periodic trapezoid rule on [0, 2 pi) converges geometrically for
// these analytic integrands, K = (1/4)∫ (1 - m sin^2)^(-1/2), E = (1/4)∫ (1 - m sin^2)^(1/2).
// (libstdc++'s comp_ellint_2 loses ~1e-13 near k = 1, so it is not used as the oracle.)
double trapezoid_k(double m, bool second_kind) {
  const int n = 20000;
  long double sum = 0;
  for (int i = 0; i < n; ++i) {
    const long double s = std::sin(2 * M_PI * i / n);
    const long double r = std::sqrt(1.0L - m * s * s);
    sum += second_kind ? r : 1.0L / r;
  }
  return static_cast<double>(sum * 2 * M_PI / n / 4);
}

TEST(Elliptic, KAndEMatchDirectQuadratureOverTheModulusRange) {
  for (double k = 0.0; k < 0.99; k += 0.0371) {
    const double m = k * k;
    const auto e = elliptic_parts(m, (1.0 - k) * (1.0 + k));
    EXPECT_NEAR(e.K, trapezoid_k(m, false), 4e-15 * e.K) << "k=" << k;
    EXPECT_NEAR(e.E, trapezoid_k(m, true), 4e-15) << "k=" << k;
  }
}

TEST(Elliptic, AssociateIntegralsSatisfyTheirDefiningIdentities) {
  for (double k : {0.05, 0.3, 0.6, 0.9, 0.99}) {
    const double m = k * k, m1 = 1 - m;
    const auto e = elliptic_parts(m, m1);
    EXPECT_NEAR(e.B + e.D, e.K, 1e-14 * e.K);  // K = B + D
    EXPECT_NEAR(e.B + m1 * e.D, e.E, 1e-14);   // E = B + (1-m) D
    EXPECT_NEAR(e.b_minus_d_over_m * m, e.B - e.D, 1e-14);
  }
}

// As m -> 0 the associate integrals have the series B = pi/4 (1 + m/8 + ...),
// D = pi/4 (1 + 3m/8 + ...), so (B - D)/m -> -pi/16: computed without cancellation.
TEST(Elliptic, AssociateIntegralsKeepFullPrecisionAsModulusVanishes) {
  const double m = 1e-12;
  const auto e = elliptic_parts(m, 1.0 - m);
  EXPECT_NEAR(e.B, M_PI / 4 * (1 + m / 8), 4e-16);
  EXPECT_NEAR(e.D, M_PI / 4 * (1 + 3 * m / 8), 4e-16);
  EXPECT_NEAR(e.b_minus_d_over_m, -M_PI / 16, 1e-12);
  const auto z = elliptic_parts(0.0, 1.0);
  EXPECT_DOUBLE_EQ(z.K, M_PI / 2);
  EXPECT_DOUBLE_EQ(z.E, M_PI / 2);
}

// K ~ ln(4/k') as k' -> 0; with m1 given exactly the logarithm is resolved to full precision.
TEST(Elliptic, KFollowsItsLogarithmicAsymptoteNearModulusOne) {
  for (double m1 : {1e-10, 1e-20, 1e-100, 1e-300}) {
    const auto e = elliptic_parts(1.0 - m1, m1);
    const double kp = std::sqrt(m1);
    EXPECT_NEAR(e.K, std::log(4.0 / kp), 1e-9) << m1;
    EXPECT_NEAR(e.E, 1.0, 1e-9) << m1;
    EXPECT_TRUE(std::isfinite(e.B) && std::isfinite(e.D));
  }
}

}  // namespace
}  // namespace frictionid::model::elliptic_test
