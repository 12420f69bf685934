// Pressure laws (docs/physics.md §1): shapes, moments m0..m5 against the Beta function, the
// equivalences power:0 = uniform, power:0.5 = hertz, power:1 = parabolic, and tabulated laws.
#include <frictionid/model/pressure_law.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/pressure_table.hpp>
#include "model/test_support.hpp"

namespace frictionid::model::pressure_law_test {
namespace {

using testing::beta_moment;

// Interior radii (and the centre) where every law is defined by the same formula.
const std::vector<double> kRho = {0.0, 1e-8, 0.1, 0.25, 0.5, 0.7, 0.9, 0.99, 0.999999};

void expect_moments(const LawMoments<double>& got, double n, double rel, const std::string& what) {
  for (int k = 0; k < 6; ++k) {
    const double want = beta_moment(n, k);
    EXPECT_NEAR(got[k], want, rel * want) << what << " m" << k;
  }
}

TEST(PressureLaw, FixedLawMomentsAreTheBetaFunctionValues) {
  expect_moments(law_moments(PressureLaw<double>::uniform()), 0.0, 1e-14, "uniform");
  expect_moments(law_moments(PressureLaw<double>::hertz()), 0.5, 1e-14, "hertz");
  expect_moments(law_moments(PressureLaw<double>::parabolic()), 1.0, 1e-14, "parabolic");
}

TEST(PressureLaw, PowerLawMomentsAreTheBetaFunctionValues) {
  std::vector<double> ns = {0.0, 1e-6, 0.1, 0.25, 0.5, 1.0, 1.7, 2.5, 3.0, 5.0, 8.0};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 8.0);
  for (int i = 0; i < 50; ++i) ns.push_back(u(rng));
  for (double n : ns)
    expect_moments(law_moments(PressureLaw<double>::power(n)), n, 1e-13,
                   "power:" + std::to_string(n));
}

// Gauss–Legendre quadrature of the law's own sigma0 with rho = sin(t), where
// (1-rho^2)^n drho = cos(t)^{2n+1} dt is analytic for the half-integer and integer n used here.
TEST(PressureLaw, Sigma0IntegratesToTheReportedMoments) {
  const auto& gl = testing::gauss_legendre(64);
  for (const auto& law : {PressureLaw<double>::uniform(), PressureLaw<double>::hertz(),
                          PressureLaw<double>::parabolic(), PressureLaw<double>::power(1.5),
                          PressureLaw<double>::power(3.0)}) {
    const auto mo = law_moments(law);
    for (int k = 0; k < 6; ++k) {
      long double sum = 0;
      for (int p = 0; p < 4; ++p) {  // t in [0, pi/2] as 4 panels
        const long double a = p * testing::kPiL / 8, b = (p + 1) * testing::kPiL / 8;
        for (std::size_t i = 0; i < gl.x.size(); ++i) {
          const long double t = 0.5L * (a + b) + 0.5L * (b - a) * gl.x[i];
          const double rho = static_cast<double>(std::sin(t));
          // 1 - rho = 2 sin²(pi/4 - t/2) (no cancellation near the rim)
          const long double h = std::sin(testing::kPiL / 4 - t / 2);
          const double omr = static_cast<double>(2 * h * h);
          sum += 0.5L * (b - a) * gl.w[i] * std::cos(t) * std::pow(rho, k) * law(rho, omr);
        }
      }
      EXPECT_NEAR(mo[k], static_cast<double>(sum), 1e-13 * mo[k])
          << pressure_name(law.kind) << " n=" << law.n << " m" << k;
    }
  }
}

TEST(PressureLaw, ShapesFollowPhysicsSection1) {
  const auto u = PressureLaw<double>::uniform();
  const auto hz = PressureLaw<double>::hertz();
  const auto pa = PressureLaw<double>::parabolic();
  const auto pw = PressureLaw<double>::power(2.3);
  for (double rho : kRho) {
    const double omr = 1.0 - rho, rim = (1.0 - rho) * (1.0 + rho);
    EXPECT_EQ(u(rho, omr), 1.0) << rho;
    EXPECT_NEAR(hz(rho, omr), std::sqrt(rim), 1e-15) << rho;
    EXPECT_NEAR(pa(rho, omr), rim, 1e-15) << rho;
    EXPECT_NEAR(pw(rho, omr), std::pow(rim, 2.3), 1e-14) << rho;
  }
  // At the rim sigma0 vanishes for every n > 0.
  EXPECT_EQ(hz(1.0, 0.0), 0.0);
  EXPECT_EQ(pa(1.0, 0.0), 0.0);
  EXPECT_EQ(pw(1.0, 0.0), 0.0);
}

void expect_same_law(const PressureLaw<double>& a, const PressureLaw<double>& b,
                     const std::string& what) {
  for (double rho : kRho)
    EXPECT_NEAR(a(rho, 1.0 - rho), b(rho, 1.0 - rho), 1e-15) << what << " rho=" << rho;
  const auto ma = law_moments(a), mb = law_moments(b);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(ma[k], mb[k], 1e-14 * mb[k]) << what << " m" << k;
}

TEST(PressureLaw, PowerZeroIsUniform) {
  expect_same_law(PressureLaw<double>::power(0.0), PressureLaw<double>::uniform(), "power:0");
}

TEST(PressureLaw, PowerHalfIsHertz) {
  expect_same_law(PressureLaw<double>::power(0.5), PressureLaw<double>::hertz(), "power:0.5");
}

TEST(PressureLaw, PowerOneIsParabolic) {
  expect_same_law(PressureLaw<double>::power(1.0), PressureLaw<double>::parabolic(), "power:1");
}

// (1 - rho^2)^0 = 1 everywhere, also on the rim (0^0 = 1, as std::pow has it).
TEST(PressureLaw, PowerZeroIsUniformOnTheRim) {
  const auto p0 = PressureLaw<double>::power(0.0);
  EXPECT_EQ(p0(1.0, 0.0), 1.0);
}

// A table of 200 samples of Hertz, uniform in rho, with sigma0(1) = 0.
std::shared_ptr<const PressureTable> hertz_table() {
  std::vector<double> rho(200), sigma(200);
  for (int i = 0; i < 200; ++i) {
    rho[i] = i / 199.0;
    sigma[i] = std::sqrt((1.0 - rho[i]) * (1.0 + rho[i]));
  }
  rho.back() = 1.0;
  sigma.back() = 0.0;
  return std::make_shared<const PressureTable>(rho, sigma);
}

TEST(PressureTable, HertzSamplesReproduceTheHertzMoments) {
  const auto law = PressureLaw<double>::tabulated(hertz_table());
  const auto mo = law_moments(law);
  for (int k = 0; k < 6; ++k) {
    const double want = beta_moment(0.5, k);
    EXPECT_NEAR(mo[k], want, 1e-6 * want) << "m" << k;
  }
}

TEST(PressureTable, HertzSamplesReproduceTheHertzCoefficients) {
  const auto law = PressureLaw<double>::tabulated(hertz_table());
  for (double kappa : {0.5, 1.0, 2.0}) {
    const auto got = coefficients(law_moments(law), kappa, 0.3);
    const auto want = coefficients(law_moments(PressureLaw<double>::hertz()), kappa, 0.3);
    EXPECT_NEAR(got.a, want.a, 1e-6 * want.a);
    EXPECT_NEAR(got.b, want.b, 1e-6 * want.b);
    EXPECT_NEAR(got.m, want.m, 1e-6 * want.m);
    EXPECT_NEAR(got.b_tilde, want.b_tilde, 1e-6 * want.b_tilde);
    EXPECT_NEAR(got.p0, want.p0, 1e-6 * want.p0);
    EXPECT_NEAR(got.mu_M, want.mu_M, 1e-6 * want.mu_M);
    EXPECT_NEAR(got.rho_roll, want.rho_roll, 1e-6 * want.rho_roll);
  }
}

TEST(PressureTable, InterpolatesThroughItsSamplesAndStaysNonNegative) {
  const auto t = hertz_table();
  for (int i = 0; i < 200; ++i) {
    const double rho = i / 199.0, want = std::sqrt((1.0 - rho) * (1.0 + rho));
    EXPECT_NEAR((*t)(rho, 1.0 - rho), want, 1e-12) << rho;
  }
  for (int i = 0; i <= 10000; ++i) {
    const double rho = i / 10000.0;
    const double v = (*t)(rho, 1.0 - rho);
    EXPECT_GE(v, 0.0) << rho;
    EXPECT_NEAR(v, std::sqrt((1.0 - rho) * (1.0 + rho)), 1e-5) << rho;
  }
}

// A constant table (no rim zero) and one that starts at rho = 0.2 (constant extension to the
// centre) are the uniform law.
TEST(PressureTable, ConstantSamplesAreTheUniformLaw) {
  for (double first : {0.0, 0.2}) {
    std::vector<double> rho, sigma;
    for (int i = 0; i <= 10; ++i) {
      rho.push_back(first + (1.0 - first) * i / 10.0);
      sigma.push_back(2.5);
    }
    const auto mo = law_moments(
        PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(rho, sigma)));
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(mo[k], 2.5 / (k + 1), 1e-14) << first << " m" << k;
  }
}

void expect_invalid(std::vector<double> rho, std::vector<double> sigma, const std::string& what) {
  EXPECT_THROW(PressureTable(std::move(rho), std::move(sigma)), std::invalid_argument) << what;
}

TEST(PressureTable, RejectsNonIncreasingRho) {
  expect_invalid({0.0, 0.5, 0.5, 0.5, 1.0}, {1, 1, 1, 1, 0}, "rho three times");
  expect_invalid({0.0, 0.6, 0.5, 1.0}, {1, 1, 1, 0}, "decreasing rho");
}

// Two samples with the same rho: the value before, then the value after the step; the runs on
// either side are interpolated separately (a run of two samples is a straight line).
TEST(PressureTable, ARepeatedRhoIsAStep) {
  const PressureTable t({0.0, 0.4, 0.4, 1.0}, {2.0, 1.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(t(0.2, 0.8), 1.5);
  EXPECT_DOUBLE_EQ(t(0.4 - 1e-12, 0.6 + 1e-12), 1.0 + 2.5e-12);
  EXPECT_DOUBLE_EQ(t(0.4, 0.6), 3.0);  // the value after the step
  EXPECT_DOUBLE_EQ(t(0.7, 0.3), 3.5);
  EXPECT_EQ(t.steps(), std::vector<double>{0.4});
  EXPECT_EQ(t.breakpoints(), std::vector<double>{0.4});
}

// A step table's moments are those of its pieces: here the annulus B = 0.3.
TEST(PressureTable, StepTableMomentsAreTheAnnulusMoments) {
  const auto law = PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(
      std::vector<double>{0.0, 0.3, 0.3, 1.0}, std::vector<double>{0.0, 0.0, 1.0, 1.0}));
  const auto mo = law_moments(law);
  for (int k = 0; k < 6; ++k) {
    const double want = (1.0 - std::pow(0.3, k + 1)) / (k + 1);
    EXPECT_NEAR(mo[k], want, 1e-15) << "m" << k;
  }
}

TEST(PressureLaw, AnnulusMomentsAreOneMinusBToTheKPlusOneOverKPlusOne) {
  for (double B : {0.0, 1e-9, 0.3, 0.9, 0.999999}) {
    const auto mo = law_moments(PressureLaw<double>::annulus(B));
    for (int k = 0; k < 6; ++k) {
      // (1 - B^(k+1))/(k+1) = (1 - B)(1 + B + ... + B^k)/(k+1), no cancellation as B -> 1.
      double geometric = 0.0;
      for (int j = 0; j <= k; ++j) geometric += std::pow(B, j);
      const double want = (1.0 - B) * geometric / (k + 1);
      EXPECT_NEAR(mo[k], want, 1e-14 * want) << B << " m" << k;
    }
  }
}

TEST(PressureLaw, AnnulusZeroIsUniform) {
  const auto a = law_moments(PressureLaw<double>::annulus(0.0));
  const auto u = law_moments(PressureLaw<double>::uniform());
  for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(a[k], u[k]);
  EXPECT_TRUE(PressureLaw<double>::annulus(0.0).breakpoints().empty());
  EXPECT_EQ(PressureLaw<double>::annulus(0.4).breakpoints(), std::vector<double>{0.4});
}

// All load on the rim: every moment m_k = ∫ delta(rho - 1) rho^k is 1, so a = b = 4 and m sits
// on both of its bounds (docs/physics.md §3): the extreme the consistency bounds allow.
TEST(PressureLaw, RingMomentsAreAllOneAndItsCoefficientsSitOnTheBounds) {
  const auto mo = law_moments(PressureLaw<double>::ring());
  for (int k = 0; k < 6; ++k) EXPECT_EQ(mo[k], 1.0);
  for (double kappa : {0.5, 1.0, 2.0}) {
    const auto c = coefficients(mo, kappa);
    EXPECT_DOUBLE_EQ(c.a, 4.0);
    EXPECT_DOUBLE_EQ(c.b, 4.0);
    EXPECT_DOUBLE_EQ(c.m, std::pow((1 + kappa) / kappa, 2));
    EXPECT_TRUE(check_consistency(c, kappa).all());
  }
}

// Every annulus satisfies the consistency bounds, and a -> 4, b -> 4 as B -> 1.
TEST(PressureLaw, AnnulusCoefficientsSatisfyTheBoundsAndTendToTheRing) {
  double last_gap = HUGE_VAL;
  for (double B : {0.0, 0.3, 0.6, 0.9, 0.99, 0.999}) {
    const auto c = coefficients(law_moments(PressureLaw<double>::annulus(B)), 1.3);
    EXPECT_TRUE(check_consistency(c, 1.3).all()) << B;
    const double gap = (4.0 - c.a) + (c.b - 4.0);
    EXPECT_LT(gap, last_gap) << B;
    last_gap = gap;
  }
  EXPECT_LT(last_gap, 20 * (1 - 0.999));  // (4 - a) + (b - 4) = O(1 - B)
}

TEST(PressureTable, RejectsRhoOutsideTheUnitInterval) {
  expect_invalid({-0.1, 0.5, 1.0}, {1, 1, 0}, "rho < 0");
  expect_invalid({0.0, 0.5, 1.1}, {1, 1, 0}, "rho > 1");
  expect_invalid({0.0, NAN, 1.0}, {1, 1, 0}, "rho NaN");
}

TEST(PressureTable, RejectsNegativeSigma0) {
  expect_invalid({0.0, 0.5, 1.0}, {1, -1e-12, 0}, "sigma0 < 0");
  expect_invalid({0.0, 0.5, 1.0}, {1, NAN, 0}, "sigma0 NaN");
}

TEST(PressureTable, RejectsAllZeroSigma0) {
  expect_invalid({0.0, 0.5, 1.0}, {0, 0, 0}, "zero");
}

TEST(PressureTable, RejectsMismatchedOrTooShortInput) {
  expect_invalid({0.0, 0.5, 1.0}, {1, 1}, "length mismatch");
  expect_invalid({0.5}, {1}, "one sample");
}

// The slope the layers of an ellipse integrate (ellipse_law_integrator.hpp): dsigma0/drho
// against 4th-order central differences of the law itself, away from its samples, for the
// closed forms, a table with an edge exponent and a table with a step.
TEST(PressureLaw, ItsSlopeIsTheDerivativeOfTheLawBetweenBreakpoints) {
  std::vector<double> rho = {0.0, 0.2, 0.45, 0.7, 0.9, 1.0}, sig = {1.0, 0.9, 1.1, 0.6, 0.35, 0.0};
  const auto edged = std::make_shared<const PressureTable>(rho, sig);
  ASSERT_GT(edged->gamma(), 0.0);
  const auto stepped =
      std::make_shared<const PressureTable>(std::vector<double>{0.0, 0.3, 0.5, 0.5, 0.8, 1.0},
                                            std::vector<double>{0.2, 0.4, 0.3, 1.0, 0.9, 0.5});
  const std::vector<PressureLaw<double>> laws = {
      PressureLaw<double>::hertz(),          PressureLaw<double>::parabolic(),
      PressureLaw<double>::power(0.3),       PressureLaw<double>::power(2.5),
      PressureLaw<double>::tabulated(edged), PressureLaw<double>::tabulated(stepped)};
  std::mt19937_64 g(17);
  std::uniform_real_distribution<double> u(0.01, 0.97);
  for (const auto& law : laws)
    for (int i = 0; i < 200; ++i) {
      const double r = u(g), h = 1e-4;
      bool near_break = false;
      for (double b : law.breakpoints()) near_break = near_break || std::fabs(r - b) < 3 * h;
      if (near_break) continue;
      auto at = [&](double x) { return law(x, 1.0 - x); };
      const double fd = (at(r - 2 * h) - 8 * at(r - h) + 8 * at(r + h) - at(r + 2 * h)) / (12 * h);
      EXPECT_NEAR(law_slope(law, r, 1.0 - r), fd, 1e-8 * std::max(1.0, std::fabs(fd)))
          << pressure_name(law.kind) << " at " << r;
    }
}

// Its steps: where sigma0 jumps and by how much it drops there, as the law itself says just
// inside and just outside.
TEST(PressureLaw, ItsJumpsAreTheDropsOfTheLawAtItsSteps) {
  const auto table = std::make_shared<const PressureTable>(
      std::vector<double>{0.0, 0.3, 0.5, 0.5, 0.8, 0.8, 1.0},
      std::vector<double>{0.2, 0.4, 0.3, 1.0, 0.9, 0.9, 0.5});  // a step at 0.5; none at 0.8
  for (const auto& law :
       {PressureLaw<double>::tabulated(table), PressureLaw<double>::annulus(0.4)}) {
    const std::vector<PressureTable::Jump> jumps = law_jumps(law);
    ASSERT_EQ(jumps.size(), 1u) << pressure_name(law.kind);
    const double b = jumps[0].rho, d = 1e-12;
    EXPECT_NEAR(jumps[0].drop, law(b - d, 1.0 - b + d) - law(b + d, 1.0 - b - d), 1e-9)
        << pressure_name(law.kind);
  }
  EXPECT_TRUE(law_jumps(PressureLaw<double>::hertz()).empty());
}

// The kinks a spot's table grades at: the jump of sigma0'' at each sample, against one-sided
// second differences of the law on either side, and largest first.
TEST(PressureTable, ItsKinksAreTheJumpsOfTheSecondDerivativeAtItsSamples) {
  std::vector<double> rho, sig;
  for (int i = 0; i <= 20; ++i) {
    rho.push_back(i / 20.0);
    sig.push_back(1.0 + 0.3 * std::sin(7.0 * rho.back()));
  }
  const PressureTable table(rho, sig);
  const std::vector<PressureTable::Kink> kinks = table.kinks();
  ASSERT_EQ(kinks.size(), 19u);
  const double h = 1e-4;
  auto f = [&](double x) { return table(x, 1.0 - x); };
  for (std::size_t k = 0; k < kinks.size(); ++k) {
    const double r = kinks[k].rho;
    // sigma0 is continuous, so f(r) serves both sides.
    const double left = (2 * f(r) - 5 * f(r - h) + 4 * f(r - 2 * h) - f(r - 3 * h)) / (h * h);
    const double right = (2 * f(r) - 5 * f(r + h) + 4 * f(r + 2 * h) - f(r + 3 * h)) / (h * h);
    EXPECT_NEAR(kinks[k].strength, std::fabs(right - left), 1e-4 * (1.0 + std::fabs(right - left)))
        << "at " << r;
    if (k > 0) {
      EXPECT_LE(kinks[k].strength, kinks[k - 1].strength);
    }
  }
}

}  // namespace
}  // namespace frictionid::model::pressure_law_test
