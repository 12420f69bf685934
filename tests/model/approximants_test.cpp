// The seed's closed-form approximants and the corrected variant (docs/physics.md §3), extended to
// any slip direction with the structure of the exact general-alpha result (docs/physics.md §2).
#include <frictionid/model/approximants.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <frictionid/model/exact_model.hpp>
#include "model/test_support.hpp"

namespace frictionid::model::approximants_test {
namespace {

using testing::beta_moment;
using testing::kPi;

struct Law {
  std::string name;
  PressureLaw<double> law;
  double n;
  double m(int k) const { return beta_moment(n, k); }
};

std::vector<Law> laws() {
  return {{"uniform", PressureLaw<double>::uniform(), 0.0},
          {"hertz", PressureLaw<double>::hertz(), 0.5},
          {"parabolic", PressureLaw<double>::parabolic(), 1.0},
          {"power:1.7", PressureLaw<double>::power(1.7), 1.7}};
}

Resultants<double> approx(ApproximantForm form, const Law& law, const ApproximantParams<double>& p,
                          const Kinematics& k) {
  return approximant_resultants(form, p, approximant_shape(law_moments(law.law)), k);
}

// Coefficients matched to the law (§3) for the given kappa: a, b (seed) or b~ (corrected), m, p0.
ApproximantParams<double> matched(ApproximantForm form, const Law& law, double f, double kappa,
                                  double h) {
  const double m0 = law.m(0), m1 = law.m(1), m2 = law.m(2), m3 = law.m(3);
  const double a = std::pow(2 * m1 / m0, 2);
  const double b = form == ApproximantForm::Seed ? std::pow(2 * m1 / m3, 2) : std::pow(m2 / m3, 2);
  const double m = std::pow((1 + kappa) * m2 / (kappa * m3), 2);
  return {f, kappa, h, a, b, m, m2 / (2 * m1)};
}

Kinematics kin(double eps, double alpha, double omega, double N, double R) {
  const double v = eps * std::fabs(omega) * R;
  return {v * std::cos(alpha), v * std::sin(alpha), omega, N, R};
}

bool finite(const Resultants<double>& r) {
  return std::isfinite(r.T_x) && std::isfinite(r.T_y) && std::isfinite(r.M_z) &&
         std::isfinite(r.M_roll) && std::isfinite(r.N);
}

const std::vector<double> kEps = {0.0, 1e-9, 1e-4, 0.05, 0.5, 1.0, 1.7, 20.0, 1e4, 1e9};

// α = 0, v_x > 0, ω > 0: the three formulas of docs/physics.md §3, literally, for arbitrary (not
// matched) a, b, m; M0 = (1+κ)/2 (m2/m1) f N R.
TEST(Approximants, SeedIsThePublishedFormulasAtAlphaZero) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (const Law& law : laws()) {
    for (int i = 0; i < 5; ++i) {
      const double f = 0.2 + u01(rng), kappa = 0.3 + 2 * u01(rng), h = -0.5 + u01(rng);
      const double a = 0.2 + 3 * u01(rng), b = 4 + 40 * u01(rng), m = 2 + 30 * u01(rng);
      const double N = 1 + 100 * u01(rng), R = 0.01 + 0.2 * u01(rng), omega = 0.2 + 3 * u01(rng);
      const ApproximantParams<double> p{f, kappa, h, a, b, m, 0.123};
      const double F0 = f * N, M0 = (1 + kappa) / 2 * (law.m(2) / law.m(1)) * f * N * R;
      for (double eps : kEps) {
        const double u = omega * R, v = eps * u;
        const auto r = approx(ApproximantForm::Seed, law, p, Kinematics{v, 0.0, omega, N, R});
        SCOPED_TRACE(law.name + " eps=" + std::to_string(eps));
        EXPECT_NEAR(r.T_x, F0 * v / std::sqrt(v * v + a * u * u), 1e-14 * F0);
        EXPECT_NEAR(r.T_y,
                    h * kappa * F0 * u * v / std::sqrt((u * u + b * v * v) * (v * v + a * u * u)),
                    1e-14 * F0);
        EXPECT_NEAR(r.M_z, M0 * u / std::sqrt(u * u + m * v * v), 1e-14 * M0);
      }
    }
  }
}

// Corrected, α = 0: T_par and M as the seed; T_perp = hκF0 p0 u/sqrt(u² + b~ v²).
TEST(Approximants, CorrectedIsItsPublishedFormAtAlphaZero) {
  for (const Law& law : laws()) {
    const double f = 0.6, kappa = 1.7, h = 0.35, a = 0.8, bt = 5.5, m = 9.0, p0 = 0.27;
    const double N = 20.0, R = 0.05, omega = 1.3, F0 = f * N;
    const double M0 = (1 + kappa) / 2 * (law.m(2) / law.m(1)) * f * N * R;
    const ApproximantParams<double> p{f, kappa, h, a, bt, m, p0};
    for (double eps : kEps) {
      const double u = omega * R, v = eps * u;
      const auto r = approx(ApproximantForm::Corrected, law, p, Kinematics{v, 0.0, omega, N, R});
      SCOPED_TRACE(law.name + " eps=" + std::to_string(eps));
      EXPECT_NEAR(r.T_x, F0 * v / std::sqrt(v * v + a * u * u), 1e-14 * F0);
      EXPECT_NEAR(r.T_y, h * kappa * F0 * p0 * u / std::sqrt(u * u + bt * v * v), 1e-14 * F0);
      EXPECT_NEAR(r.M_z, M0 * u / std::sqrt(u * u + m * v * v), 1e-14 * M0);
    }
  }
}

TEST(Approximants, CorrectedPureSpinLateralForceIsHKappaFNp0) {
  for (const Law& law : laws()) {
    for (double omega : {0.7, -2.0}) {
      const double f = 0.6, kappa = 1.7, h = -0.3, N = 20.0, R = 0.05;
      const auto p = matched(ApproximantForm::Corrected, law, f, kappa, h);
      const auto r = approx(ApproximantForm::Corrected, law, p, Kinematics{0, 0, omega, N, R});
      const double s = omega > 0 ? 1 : -1;
      EXPECT_NEAR(r.T_y, s * h * kappa * f * N * law.m(2) / (2 * law.m(1)), 1e-14 * f * N);
      EXPECT_EQ(r.T_x, 0.0);
      // and it is the exact model's pure-spin force
      const auto e = ExactModel<double>({f, kappa, h}, law.law)(Kinematics{0, 0, omega, N, R});
      EXPECT_NEAR(r.T_y, e.T_y, 1e-11 * f * N) << law.name;
    }
  }
}

// T_y is even in v (both forms; the exact parity), T_x odd, M_z even in v and odd in ω.
TEST(Approximants, LateralForceIsEvenInSlipVelocity) {
  for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
    for (const Law& law : laws()) {
      const auto p = matched(form, law, 0.6, 1.4, 0.3);
      for (double eps : {1e-3, 0.4, 1.0, 3.0, 100.0}) {
        for (double omega : {1.0, -1.0}) {
          const Kinematics k = kin(eps, 0.0, omega, 5.0, 0.1);
          const Kinematics kr{-k.v_x, 0.0, omega, 5.0, 0.1};
          const auto a = approx(form, law, p, k), b = approx(form, law, p, kr);
          SCOPED_TRACE(law.name + " eps=" + std::to_string(eps));
          EXPECT_NEAR(b.T_y, a.T_y, 1e-15 * 3.0);
          EXPECT_NEAR(b.T_x, -a.T_x, 1e-15 * 3.0);
          EXPECT_NEAR(b.M_z, a.M_z, 1e-15 * 3.0);
          const Kinematics kw{k.v_x, 0.0, -omega, 5.0, 0.1};
          const auto c = approx(form, law, p, kw);
          EXPECT_NEAR(c.T_y, -a.T_y, 1e-15 * 3.0);
          EXPECT_NEAR(c.M_z, -a.M_z, 1e-15 * 3.0);
          EXPECT_GT(std::fabs(a.T_y), 0.0);
        }
      }
    }
  }
}

// α = π/2 (slip along y): d11 = κ, d22 = 1, d12 = 0. The exact model's general-α formula gives
// T_x = 0, T_y = κ (I_P + s h I_S), M_z = s (I_Q + κ I_S) − h (I_U − κ I_V); the approximants
// replace the integrals by their stand-ins with the same structure: T_x = 0 and T_y/κ independent
// of κ when h = 0.
TEST(Approximants, SlipAcrossTheRollingDirectionHasTheExactStructure) {
  for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
    for (const Law& law : laws()) {
      for (double eps : {1e-3, 0.5, 1.0, 4.0}) {
        for (double kappa : {0.5, 2.0}) {
          const Kinematics k = kin(eps, kPi / 2, 1.2, 3.0, 0.2);
          const Kinematics ky{0.0, k.v_y, 1.2, 3.0, 0.2};  // v_x exactly zero
          const auto r = approx(form, law, matched(form, law, 0.7, kappa, 0.3), ky);
          const auto e = ExactModel<double>({0.7, kappa, 0.3}, law.law)(ky);
          EXPECT_EQ(r.T_x, 0.0) << law.name;
          EXPECT_NEAR(e.T_x, 0.0, 1e-15) << law.name;
          const auto r0 = approx(form, law, matched(form, law, 0.7, kappa, 0.0), ky);
          const auto r1 = approx(form, law, matched(form, law, 0.7, 1.0, 0.0), ky);
          EXPECT_NEAR(r0.T_y / kappa, r1.T_y, 1e-15) << law.name;
          const auto e0 = ExactModel<double>({0.7, kappa, 0.0}, law.law)(ky);
          const auto e1 = ExactModel<double>({0.7, 1.0, 0.0}, law.law)(ky);
          EXPECT_NEAR(e0.T_y / kappa, e1.T_y, 1e-14) << law.name;
        }
      }
    }
  }
}

// The α = π/2 limits of both forms are the exact model's: ε → 0: T_y → sκh f N p0, M_z → s M0;
// ε → ∞: T_y → κ f N, M_z → hκ f N R m3/(2 m1). Leading slopes too: (T_y − T_y(0))/ε →
// κ f N m0/(2 m1) and (M_z − M_z(∞)) ε → s f N R m3/(2 m1), with matched coefficients.
TEST(Approximants, LimitsAcrossTheRollingDirectionAreTheExactModels) {
  for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
    for (const Law& law : laws()) {
      for (double omega : {1.5, -1.5}) {
        const double f = 0.7, kappa = 1.8, h = 0.3, N = 3.0, R = 0.2, F = f * N;
        const double s = omega > 0 ? 1 : -1, m1 = law.m(1);
        const double M0 = (1 + kappa) / 2 * (law.m(2) / m1) * F * R;
        const auto p = matched(form, law, f, kappa, h);
        const ExactModel<double> ex({f, kappa, h}, law.law);
        auto at = [&](double eps) {
          const Kinematics k{0.0, eps * std::fabs(omega) * R, omega, N, R};
          return std::make_pair(approx(form, law, p, k), ex(k));
        };
        SCOPED_TRACE(law.name + (form == ApproximantForm::Seed ? " seed" : " corrected") +
                     " omega=" + std::to_string(omega));
        // eps -> 0 (the stand-ins' values at 0 are reached at eps = 1e-12 to ~1e-12)
        const auto [a0, e0] = at(1e-12);
        EXPECT_NEAR(a0.T_y, s * kappa * h * F * law.m(2) / (2 * m1), 1e-10 * F);
        EXPECT_NEAR(e0.T_y, s * kappa * h * F * law.m(2) / (2 * m1), 1e-10 * F);
        EXPECT_NEAR(a0.M_z, s * M0, 1e-10 * F * R);
        EXPECT_NEAR(e0.M_z, s * M0, 1e-10 * F * R);
        // slope at 0
        const double slope = kappa * F * law.m(0) / (2 * m1);
        const auto [a1, e1] = at(1e-6);
        EXPECT_NEAR((a1.T_y - a0.T_y) / 1e-6, slope, 1e-4 * slope);
        EXPECT_NEAR((e1.T_y - e0.T_y) / 1e-6, slope, 1e-4 * slope);
        // eps -> inf
        const double Minf = h * kappa * F * R * law.m(3) / (2 * m1);
        const auto [ai, ei] = at(1e12);
        EXPECT_NEAR(ai.T_y, kappa * F, 1e-10 * F);
        EXPECT_NEAR(ei.T_y, kappa * F, 1e-10 * F);
        EXPECT_NEAR(ai.M_z, Minf, 1e-10 * F * R);
        EXPECT_NEAR(ei.M_z, Minf, 1e-10 * F * R);
        const double tail = s * F * R * law.m(3) / (2 * m1);
        const auto [a6, e6] = at(1e6);
        EXPECT_NEAR((a6.M_z - Minf) * 1e6, tail, 1e-4 * std::fabs(tail));
        EXPECT_NEAR((e6.M_z - Minf) * 1e6, tail, 1e-4 * std::fabs(tail));
      }
    }
  }
}

// Any α: at ε → ∞ both forms tend to the exact model (T = f N D e, M_z = hκ f N R m3 sinα/(2m1)
// in total, from the tilt terms); at ε → 0 the corrected form does too, the seed only without
// tilt (its T_perp vanishes at v = 0: the known defect of §3).
TEST(Approximants, LimitsAtAnyAngleAreTheExactModels) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (const Law& law : laws()) {
    for (int i = 0; i < 10; ++i) {
      const double alpha = kPi * (2 * u01(rng) - 1), kappa = 0.3 + 2.7 * u01(rng);
      const double omega = u01(rng) < 0.5 ? -1.1 : 1.1, f = 0.5, N = 4.0, R = 0.3, F = f * N;
      for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
        for (double h : {0.0, 0.4}) {
          const auto p = matched(form, law, f, kappa, h);
          const ExactModel<double> ex({f, kappa, h}, law.law);
          SCOPED_TRACE(law.name + " alpha=" + std::to_string(alpha) +
                       " kappa=" + std::to_string(kappa) + " h=" + std::to_string(h) +
                       (form == ApproximantForm::Seed ? " seed" : " corrected"));
          const Kinematics big = kin(1e12, alpha, omega, N, R);
          const auto ab = approx(form, law, p, big), eb = ex(big);
          EXPECT_NEAR(ab.T_x, eb.T_x, 1e-10 * F);
          EXPECT_NEAR(ab.T_y, eb.T_y, 1e-10 * F);
          EXPECT_NEAR(ab.M_z, eb.M_z, 1e-10 * F * R);
          if (form == ApproximantForm::Seed && h != 0.0) continue;
          const Kinematics small = kin(1e-12, alpha, omega, N, R);
          const auto as = approx(form, law, p, small), es = ex(small);
          EXPECT_NEAR(as.T_x, es.T_x, 1e-10 * F);
          EXPECT_NEAR(as.T_y, es.T_y, 1e-10 * F);
          EXPECT_NEAR(as.M_z, es.M_z, 1e-10 * F * R);
        }
      }
    }
  }
}

// The stand-ins match the exact integrals' value and leading slope at eps -> 0 and their leading
// term at eps -> inf (approximants.hpp), so with matched coefficients the approximant differs
// from the exact model by O(eps^2) at small eps and O(1/eps^2) at large eps, for any slip
// angle: at eps = 1e-4 and 1e4 the difference is ~1e-8 F, where a wrong slope would show as
// ~1e-4 F. (Small eps: corrected form, or the seed without tilt.)
TEST(Approximants, MatchValueAndLeadingTermAtBothEndsForAnyAngle) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (const Law& law : laws()) {
    for (int i = 0; i < 10; ++i) {
      const double alpha = kPi * (2 * u01(rng) - 1), kappa = 0.3 + 2.7 * u01(rng);
      const double omega = u01(rng) < 0.5 ? -1.1 : 1.1, f = 0.5, N = 4.0, R = 0.3, F = f * N;
      for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
        for (double h : {0.0, -0.4}) {
          const auto p = matched(form, law, f, kappa, h);
          const ExactModel<double> ex({f, kappa, h}, law.law);
          SCOPED_TRACE(law.name + " alpha=" + std::to_string(alpha) +
                       " kappa=" + std::to_string(kappa) + " h=" + std::to_string(h) +
                       (form == ApproximantForm::Seed ? " seed" : " corrected"));
          for (double eps : {1e-4, 1e4}) {
            if (eps < 1 && form == ApproximantForm::Seed && h != 0.0) continue;
            const Kinematics k = kin(eps, alpha, omega, N, R);
            const auto a = approx(form, law, p, k), e = ex(k);
            EXPECT_NEAR(a.T_x, e.T_x, 1e-6 * F) << eps;
            EXPECT_NEAR(a.T_y, e.T_y, 1e-6 * F) << eps;
            EXPECT_NEAR(a.M_z, e.M_z, 1e-6 * F * R) << eps;
          }
        }
      }
    }
  }
}

TEST(Approximants, SeedLateralForceVanishesUnderPureSpin) {
  for (const Law& law : laws()) {
    const auto p = matched(ApproximantForm::Seed, law, 0.6, 1.4, 0.3);
    const auto r = approx(ApproximantForm::Seed, law, p, Kinematics{0, 0, 1.0, 5.0, 0.1});
    EXPECT_EQ(r.T_y, 0.0) << law.name;
  }
}

TEST(Approximants, FiniteAtZeroAndInfiniteEpsAndAtRest) {
  for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
    for (const Law& law : laws()) {
      for (double alpha : {0.0, 1.0, kPi / 2, -2.5}) {
        const auto p = matched(form, law, 0.6, 1.4, 0.3);
        const std::vector<Kinematics> ks = {
            kin(0.0, alpha, 1.0, 5.0, 0.1),      kin(1e-300, alpha, 1.0, 5.0, 0.1),
            kin(1e300, alpha, 1e-300, 5.0, 0.1), {std::cos(alpha), std::sin(alpha), 0.0, 5, 0.1},
            {0.0, 0.0, 0.0, 5.0, 0.1},           {0.0, 0.0, -3.0, 5.0, 0.1}};
        for (const Kinematics& k : ks) {
          const auto r = approx(form, law, p, k);
          EXPECT_TRUE(finite(r)) << law.name << " alpha=" << alpha << " v=(" << k.v_x << ","
                                 << k.v_y << ") omega=" << k.omega;
        }
        const auto rest = approx(form, law, p, Kinematics{0, 0, 0, 5.0, 0.1});
        EXPECT_EQ(rest.T_x, 0.0);
        EXPECT_EQ(rest.T_y, 0.0);
        EXPECT_EQ(rest.M_z, 0.0);
        // omega = 0: pure sliding, T = f N D e exactly
        const auto slide =
            approx(form, law, p, Kinematics{std::cos(alpha), std::sin(alpha), 0, 5, 0.1});
        EXPECT_NEAR(slide.T_x, 3.0 * std::cos(alpha), 1e-15 * 3.0);
        EXPECT_NEAR(slide.T_y, 3.0 * 1.4 * std::sin(alpha), 1e-15 * 3.0);
      }
    }
  }
}

TEST(Approximants, AntiRollingCoupleIsHNRm3Over2m1) {
  for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
    for (const Law& law : laws()) {
      const double h = 0.35, N = 8.0, R = 0.06;
      const auto r = approx(form, law, matched(form, law, 0.6, 1.4, h), kin(0.7, 0.3, 1.0, N, R));
      EXPECT_NEAR(r.M_roll, h * N * R * law.m(3) / (2 * law.m(1)), 1e-14 * N * R) << law.name;
      EXPECT_EQ(r.N, N);
    }
  }
}

// docs/physics.md §3: with matched coefficients the approximants are right at both ends but not in
// between; the worst relative error of the seed's T_par and M against §2 is of order 10%, near
// eps ~ 1 (the tool must not present them as exact).
TEST(Approximants, AreNotExactInBetween) {
  for (const Law& law : laws()) {
    const auto p = matched(ApproximantForm::Seed, law, 1.0, 1.0, 0.0);
    const ExactModel<double> ex({1.0, 1.0, 0.0}, law.law);
    double worst = 0.0, where = 0.0;
    for (double le = -2; le <= 2; le += 0.05) {
      const Kinematics k = kin(std::pow(10.0, le), 0.0, 1.0, 1.0, 1.0);
      const auto a = approx(ApproximantForm::Seed, law, p, k), e = ex(k);
      for (double err : {std::fabs(a.T_x / e.T_x - 1), std::fabs(a.M_z / e.M_z - 1)}) {
        if (err > worst) {
          worst = err;
          where = std::pow(10.0, le);
        }
      }
    }
    EXPECT_GT(worst, 0.01) << law.name;
    EXPECT_LT(worst, 0.6) << law.name;
    EXPECT_GT(where, 0.1) << law.name;
    EXPECT_LT(where, 10.0) << law.name;
  }
}

}  // namespace
}  // namespace frictionid::model::approximants_test
