// Pressure laws that are only piecewise smooth (docs/physics.md §1, §2): annulus:B, the ring law,
// and tables with steps (two rows with the same rho) and kinks. The exact model must meet the
// brute-force 2-D reference to 1e-10 of f N and f N R at any eps, slip angle, tilt and kappa,
// with the radial quadrature and with the tabulated ring integrals alike.
#include <frictionid/model/exact_model.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <frictionid/model/ring_integral_table.hpp>
#include <frictionid/model_variant.hpp>
#include "model/reference_integrator.hpp"
#include "model/test_support.hpp"

namespace frictionid::model::piecewise_law_test {
namespace {

using testing::kPi;

// A law under test with its independent description for the reference: sigma0 as a formula,
// its breakpoints, and the moment m1 in closed form.
struct Case {
  std::string name;
  PressureLaw<double> law;
  std::function<double(double)> sigma0;
  std::vector<double> breakpoints;
  double m1;
  bool rim_only = false;
};

Case annulus(double B) {
  return {"annulus:" + std::to_string(B),
          PressureLaw<double>::annulus(B),
          [B](double rho) { return rho >= B ? 1.0 : 0.0; },
          {B},
          0.5 * (1.0 - B * B)};
}

// The uniform annulus as a table with an explicit step at B.
Case step_table(double B) {
  auto t = std::make_shared<const PressureTable>(std::vector<double>{0.0, B, B, 1.0},
                                                 std::vector<double>{0.0, 0.0, 1.0, 1.0});
  Case c = annulus(B);
  c.name = "step table at " + std::to_string(B);
  c.law = PressureLaw<double>::tabulated(t);
  return c;
}

// Zero core, linear rise (kinks at 0.25 and 0.6), plateau, a step down at 0.8. Repeating a
// sample (same rho, same value) ends a run, so every run of two samples is a straight line.
Case kinked_table() {
  const std::vector<double> rho = {0.0, 0.25, 0.25, 0.6, 0.6, 0.8, 0.8, 1.0};
  const std::vector<double> sig = {0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.5, 0.5};
  auto sigma0 = [](double r) {
    if (r < 0.25) return 0.0;
    if (r < 0.6) return (r - 0.25) / 0.35;
    return r < 0.8 ? 1.0 : 0.5;
  };
  // m1 = ∫ sigma0 rho: the rise ∫_{0.25}^{0.6} (r - 0.25) r / 0.35, plateau, outer step.
  const double a = 0.25, b = 0.6;
  const double rise = ((b * b * b - a * a * a) / 3.0 - a * (b * b - a * a) / 2.0) / (b - a);
  const double m1 = rise + 0.5 * (0.64 - 0.36) + 0.5 * 0.5 * (1.0 - 0.64);
  return {"kinked table",
          PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(rho, sig)),
          sigma0,
          {0.25, 0.6, 0.8},
          m1};
}

Case ring() {
  return {"ring", PressureLaw<double>::ring(), [](double) { return 1.0; }, {}, 1.0, true};
}

// A fine table: 200 samples of Hertz, interpolated with the rim factor (1 - rho^2)^gamma. The
// reference integrates the interpolant itself (its accuracy as a Hertz law is another matter),
// split at every sample.
Case hertz_samples() {
  std::vector<double> rho, sig;
  for (int i = 0; i < 200; ++i) {
    rho.push_back(i / 199.0);
    sig.push_back(std::sqrt(std::max(0.0, (1.0 - rho.back()) * (1.0 + rho.back()))));
  }
  auto t = std::make_shared<const PressureTable>(rho, sig);
  const auto law = PressureLaw<double>::tabulated(t);
  // m1 of the interpolant by Gauss–Legendre per sample interval (independent of the model's
  // piece rules), the rim interval by the substitution rho = 1 - s^2 that removes sqrt(1 - rho).
  const auto& gl = testing::gauss_legendre(40);
  long double m1 = 0;
  for (int i = 0; i + 1 < 200; ++i) {
    const double a = rho[i], b = rho[i + 1];
    for (std::size_t j = 0; j < gl.x.size(); ++j) {
      const bool rim = i + 2 == 200;
      const long double x = gl.x[j];
      if (!rim) {
        const double r = a + (b - a) * 0.5 * static_cast<double>(1 + x);
        m1 += 0.5L * (b - a) * gl.w[j] * r * (*t)(r, 1.0 - r);
      } else {
        const double smax = std::sqrt(b - a), s = smax * 0.5 * static_cast<double>(1 + x);
        const double r = b - s * s;
        m1 += 0.5L * smax * gl.w[j] * 2 * s * r * (*t)(r, (1.0 - b) + s * s);
      }
    }
  }
  return {"200 Hertz samples", law, [t](double r) { return (*t)(r, 1.0 - r); }, t->breakpoints(),
          static_cast<double>(m1)};
}

struct Point {
  double f, kappa, h, eps;
  Kinematics k;
};

// Random kinematics; every fourth eps sits on or within 1e-9 relative of a breakpoint or eps = 1.
Point random_point(std::mt19937_64& rng, int i, const std::vector<double>& breakpoints) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double kappa = std::exp(std::log(0.3) + std::log(10.0) * u01(rng));
  const double h = -1.0 + 2.0 * u01(rng), f = 0.1 + u01(rng);
  const double alpha = kPi * (2 * u01(rng) - 1);
  double eps = std::pow(10.0, -3.0 + 6.0 * u01(rng));
  if (i % 4 == 3) {
    std::vector<double> special = breakpoints;
    special.push_back(1.0);
    const double at = special[static_cast<std::size_t>(i / 4) % special.size()];
    const double offset[] = {0.0, 1e-9, -1e-9, 1e-4, -1e-4};
    eps = at * (1.0 + offset[(i / 4) % 5]);
  }
  const double omega = (u01(rng) < 0.5 ? -1.0 : 1.0) * (0.3 + 3.0 * u01(rng));
  const double N = 5.0 + 500.0 * u01(rng), R = 0.01 + 0.3 * u01(rng);
  const double v = eps * std::fabs(omega) * R;
  return {f, kappa, h, eps, {v * std::cos(alpha), v * std::sin(alpha), omega, N, R}};
}

// Model against the reference at random points, with or without the eps-table.
void expect_matches_reference(const Case& c, bool with_table, int points, unsigned seed) {
  std::mt19937_64 rng(seed);
  const auto table = with_table ? std::make_shared<const RingIntegralTable>(c.law) : nullptr;
  for (int i = 0; i < points; ++i) {
    const Point p = random_point(rng, i, c.breakpoints);
    const Kinematics& k = p.k;
    const auto got = ExactModel<double>({p.f, p.kappa, p.h}, c.law, table)(k);
    const auto ref = testing::reference_resultants(c.sigma0, p.kappa, p.h, k.v_x / k.R, k.v_y / k.R,
                                                   k.omega, 1e-12, c.breakpoints, c.rim_only);
    const double unit = p.f * k.N / (2 * kPi * c.m1);
    SCOPED_TRACE(c.name + (with_table ? " (table)" : "") + " eps " + std::to_string(p.eps) +
                 " kappa " + std::to_string(p.kappa) + " h " + std::to_string(p.h));
    EXPECT_NEAR(got.T_x, unit * ref.T_x, 1e-10 * p.f * k.N);
    EXPECT_NEAR(got.T_y, unit * ref.T_y, 1e-10 * p.f * k.N);
    EXPECT_NEAR(got.M_z, unit * k.R * ref.M_z, 1e-10 * p.f * k.N * k.R);
  }
}

TEST(PiecewiseLaw, AnnulusMatchesTheTwoDimensionalReferenceTo1e10) {
  expect_matches_reference(annulus(0.3), false, 40, 11);
  expect_matches_reference(annulus(0.9), false, 20, 12);
}

TEST(PiecewiseLaw, StepTableMatchesTheTwoDimensionalReferenceTo1e10) {
  expect_matches_reference(step_table(0.3), false, 40, 13);
}

TEST(PiecewiseLaw, KinkedTableWithZeroCoreMatchesTheTwoDimensionalReferenceTo1e10) {
  expect_matches_reference(kinked_table(), false, 40, 14);
}

TEST(PiecewiseLaw, FineTableMatchesTheTwoDimensionalReferenceTo1e10) {
  expect_matches_reference(hertz_samples(), false, 12, 19);
  expect_matches_reference(hertz_samples(), true, 12, 20);
}

TEST(PiecewiseLaw, RingLawMatchesTheRimReferenceTo1e10) {
  expect_matches_reference(ring(), false, 40, 15);
}

TEST(PiecewiseLaw, TabulatedRingIntegralsOfStepsAndKinksMatchTheReferenceTo1e10) {
  expect_matches_reference(annulus(0.3), true, 30, 16);
  expect_matches_reference(step_table(0.7), true, 30, 17);
  expect_matches_reference(kinked_table(), true, 30, 18);
}

// The ring law in closed form (docs/physics.md §2 kernels at rho = 1, k = eps), with the standard
// library's complete elliptic integrals (modulus k): aligned, isotropic and untilted,
//   T/(f N) = P(eps)/(2 pi),  M_z/(f N R) = J(eps)/(2 pi).
TEST(PiecewiseLaw, RingLawIsTheKernelClosedForms) {
  // (eps >= 0.1: below, E - (1 - k^2) K cancels in these textbook forms, docs/physics.md §2.)
  for (double eps : {0.1, 0.2, 0.7, 0.999, 1.0, 1.001, 1.5, 4.0, 100.0}) {
    double P, J;
    if (eps < 1.0) {
      const double K = std::comp_ellint_1(eps), E = std::comp_ellint_2(eps);
      P = 4.0 / eps * (E - (1.0 - eps * eps) * K);
      J = 4.0 * E;
    } else if (eps > 1.0) {
      const double q = 1.0 / eps, K = std::comp_ellint_1(q), E = std::comp_ellint_2(q);
      P = 4.0 * E;
      J = 4.0 * eps * (E - (1.0 - q * q) * K);
    } else {
      P = J = 4.0;  // E(1) = 1, (1 - k^2) K -> 0
    }
    const auto r = ExactModel<double>({1.0, 1.0, 0.0}, ring().law)({eps, 0.0, 1.0, 1.0, 1.0});
    EXPECT_NEAR(r.T_x, P / (2 * kPi), 1e-12) << eps;
    EXPECT_NEAR(r.M_z, J / (2 * kPi), 1e-12) << eps;
    EXPECT_EQ(r.T_y, 0.0) << eps;
  }
}

// A fit with a table or an annulus evaluates the eps-table, as with Hertz; the ring law's
// integrals are closed-form kernel values and need none.
TEST(PiecewiseLaw, TableAndAnnulusLawsGetTheEpsTableForFitting) {
  EXPECT_NE(ring_table_for(ModelKind::Exact, step_table(0.3).law, 0.0, false), nullptr);
  EXPECT_NE(ring_table_for(ModelKind::Exact, kinked_table().law, 0.0, false), nullptr);
  EXPECT_NE(ring_table_for(ModelKind::Exact, annulus(0.3).law, 0.0, false), nullptr);
  EXPECT_EQ(ring_table_for(ModelKind::Exact, ring().law, 0.0, false), nullptr);
}

// The uniform annulus B = 0.3 at large eps: no Coulomb contact exceeds f N.
TEST(PiecewiseLaw, AnnulusForceNeverExceedsCoulombAtLargeEps) {
  for (double eps : {0.5, 2.0, 4.0, 30.0}) {
    const auto r = ExactModel<double>({1.0, 1.0, 0.0}, annulus(0.3).law)({eps, 0.0, 1.0, 1.0, 1.0});
    EXPECT_LE(r.T_x, 1.0) << eps;
  }
}

TEST(PiecewiseLaw, StepTableEqualsTheNamedAnnulus) {
  for (double B : {0.05, 0.3, 0.7, 0.95}) {
    const Case named = annulus(B), table = step_table(B);
    std::mt19937_64 rng(21);
    for (int i = 0; i < 60; ++i) {
      const Point p = random_point(rng, i, {B});
      const auto a = ExactModel<double>({p.f, p.kappa, p.h}, named.law)(p.k);
      const auto b = ExactModel<double>({p.f, p.kappa, p.h}, table.law)(p.k);
      const double fn = p.f * p.k.N;
      EXPECT_NEAR(a.T_x, b.T_x, 1e-12 * fn) << B << " " << p.eps;
      EXPECT_NEAR(a.T_y, b.T_y, 1e-12 * fn) << B << " " << p.eps;
      EXPECT_NEAR(a.M_z, b.M_z, 1e-12 * fn * p.k.R) << B << " " << p.eps;
      EXPECT_NEAR(a.M_roll, b.M_roll, 1e-12 * p.k.N * p.k.R) << B << " " << p.eps;
    }
  }
}

// As B -> 1 the annulus concentrates on the rim: N-normalised results differ by O(1 - B).
TEST(PiecewiseLaw, AnnulusTendsToTheRingAsBTendsToOne) {
  for (double eps : {0.1, 0.7, 1.0, 1.5, 10.0}) {
    const Kinematics k{eps * std::cos(0.4), eps * std::sin(0.4), 1.0, 1.0, 1.0};
    const auto ring_r = ExactModel<double>({1.0, 1.3, 0.2}, PressureLaw<double>::ring())(k);
    double last = HUGE_VAL;
    for (double gap : {1e-2, 1e-3, 1e-4}) {
      const auto a = ExactModel<double>({1.0, 1.3, 0.2}, PressureLaw<double>::annulus(1 - gap))(k);
      const double d = std::fabs(a.T_x - ring_r.T_x) + std::fabs(a.T_y - ring_r.T_y) +
                       std::fabs(a.M_z - ring_r.M_z);
      EXPECT_LT(d, 20 * gap) << eps << " " << gap;
      EXPECT_LT(d, last) << eps << " " << gap;
      last = d;
    }
  }
}

// eps crossing a table sample: sigma0's kink or step enters the integrals as (eps - rho_i)^2
// ln|eps - rho_i| at most, so the N-normalised results are continuous there.
TEST(PiecewiseLaw, ResultsAreContinuousAcrossTableSamples) {
  for (const Case& c : {kinked_table(), step_table(0.3)}) {
    for (double at : c.breakpoints) {
      for (bool tabulated : {false, true}) {
        const auto table = tabulated ? std::make_shared<const RingIntegralTable>(c.law) : nullptr;
        const ExactModel<double> model({1.0, 1.4, 0.3}, c.law, table);
        const auto below = model(
            {at * (1 - 1e-9) * std::cos(0.3), at * (1 - 1e-9) * std::sin(0.3), 1.0, 1.0, 1.0});
        const auto above = model(
            {at * (1 + 1e-9) * std::cos(0.3), at * (1 + 1e-9) * std::sin(0.3), 1.0, 1.0, 1.0});
        EXPECT_NEAR(below.T_x, above.T_x, 1e-8) << c.name << " " << at << " " << tabulated;
        EXPECT_NEAR(below.T_y, above.T_y, 1e-8) << c.name << " " << at << " " << tabulated;
        EXPECT_NEAR(below.M_z, above.M_z, 1e-8) << c.name << " " << at << " " << tabulated;
      }
    }
  }
}

}  // namespace
}  // namespace frictionid::model::piecewise_law_test
