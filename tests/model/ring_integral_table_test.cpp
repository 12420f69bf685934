// The tabulated ring integrals (ring_integral_table.hpp) against the radial quadrature on a
// finer rule, the brute-force 2-D reference, the n-derivative by central differences, and the
// known limits at both ends of eps.
#include <frictionid/model/ring_integral_table.hpp>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <frictionid/model/exact_model.hpp>
#include "model/reference_integrator.hpp"
#include "model/test_support.hpp"

namespace frictionid::model::ring_integral_table_test {
namespace {

using testing::beta_moment;
using testing::kPi;

struct NamedLaw {
  std::string name;
  PressureLaw<double> law;
  double n;  // sigma0 = (1 - rho^2)^n
};

std::vector<NamedLaw> laws() {
  return {{"uniform", PressureLaw<double>::uniform(), 0.0},
          {"hertz", PressureLaw<double>::hertz(), 0.5},
          {"parabolic", PressureLaw<double>::parabolic(), 1.0},
          {"power:0.3", PressureLaw<double>::power(0.3), 0.3},
          {"power:1.7", PressureLaw<double>::power(1.7), 1.7},
          {"power:6", PressureLaw<double>::power(6.0), 6.0}};
}

std::array<double, 6> as_array(const RingIntegrals<double>& in) {
  return {in.P, in.Q, in.S, in.U, in.V, in.X};
}

// eps log-uniform over [1e-13, 1e10], every third one within 1e-12..1e-1 of the rim ring eps = 1.
std::vector<double> sample_eps(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<double> out;
  for (int i = 0; i < count; ++i) {
    if (i % 3 == 0)
      out.push_back(1.0 + (i % 2 ? 1.0 : -1.0) * std::pow(10.0, -12.0 + 11.0 * u01(rng)));
    else
      out.push_back(std::pow(10.0, -13.0 + 23.0 * u01(rng)));
  }
  return out;
}

TEST(RingIntegralTable, MatchesAFinerQuadratureToTwelveDigitsForEveryLaw) {
  const auto finer = make_tanh_sinh_rule(1.0 / 32.0, 1e-20);  // independent of the table's rule
  for (const auto& l : laws()) {
    const RingIntegralTable table(l.law);
    for (double eps : sample_eps(400, 5)) {
      double got[6];
      table.evaluate(eps, got);
      const auto want = as_array(weighted_ring_integrals<double>(l.law, eps, finer));
      for (int j = 0; j < 6; ++j)
        ASSERT_NEAR(got[j], want[static_cast<std::size_t>(j)],
                    1e-12 * std::fabs(want[static_cast<std::size_t>(j)]))
            << l.name << " integral " << j << " eps " << eps;
    }
  }
}

TEST(RingIntegralTable, EndsTakeTheKnownLimits) {
  for (const auto& l : laws()) {
    const RingIntegralTable table(l.law);
    const double m1 = beta_moment(l.n, 1), m2 = beta_moment(l.n, 2), m3 = beta_moment(l.n, 3);
    double v[6];
    // Pure spin: no net slip force, I_Q = I_S = pi m2 (Q(0) = S(0) = pi).
    table.evaluate(0.0, v);
    EXPECT_EQ(v[0], 0.0);
    EXPECT_EQ(v[3], 0.0);
    EXPECT_EQ(v[4], 0.0);
    EXPECT_EQ(v[5], 0.0);
    EXPECT_NEAR(v[1], kPi * m2, 1e-11 * m2) << l.name;
    EXPECT_NEAR(v[2], kPi * m2, 1e-11 * m2) << l.name;
    // Nearly pure sliding: I_P -> 2 pi m1, eps I_Q -> pi m3, I_V, I_X -> pi m3.
    const double big = 1e12;
    table.evaluate(big, v);
    EXPECT_NEAR(v[0], 2 * kPi * m1, 1e-11 * m1) << l.name;
    EXPECT_NEAR(big * v[1], kPi * m3, 1e-11 * m3) << l.name;
    EXPECT_NEAR(v[4], kPi * m3, 1e-11 * m3) << l.name;
    EXPECT_NEAR(v[5], kPi * m3, 1e-11 * m3) << l.name;
  }
}

TEST(RingIntegralTable, ExponentSlopesMatchCentralDifferencesOfTheQuadrature) {
  for (double n : {0.3, 1.7, 6.0}) {
    const RingIntegralTable table(PressureLaw<double>::power(n), true);
    for (double eps : sample_eps(60, 9)) {
      double v[6], dn[6];
      table.evaluate(eps, v, dn);
      for (int j = 0; j < 6; ++j) {
        const auto integral = [&](double nn) {
          return as_array(weighted_ring_integrals<double>(
              PressureLaw<double>::power(nn), eps, fine_rule()))[static_cast<std::size_t>(j)];
        };
        const double fd = testing::central_difference(integral, n, 1e-3);
        EXPECT_NEAR(dn[j], fd, 1e-8 * std::fabs(v[j]) + 1e-9 * std::fabs(fd))
            << "n " << n << " integral " << j << " eps " << eps;
      }
    }
  }
}

// The tabulated exact model at random points, any slip direction, against the 2-D reference.
TEST(RingIntegralTable, TabulatedExactModelMatchesTheTwoDimensionalReference) {
  std::mt19937_64 rng(0x7ab1e);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const auto all = laws();
  std::vector<std::shared_ptr<const RingIntegralTable>> tables;
  for (const auto& l : all) tables.push_back(std::make_shared<const RingIntegralTable>(l.law));
  for (int i = 0; i < 120; ++i) {
    const std::size_t li = static_cast<std::size_t>(i) % all.size();
    const auto& l = all[li];
    const double kappa = std::exp(std::log(0.3) + std::log(10.0) * u01(rng));
    const double h = -0.5 + u01(rng), f = 0.1 + u01(rng);
    const double alpha = kPi * (2 * u01(rng) - 1);
    const double eps = i % 10 == 7 ? 1.0 : std::pow(10.0, -3.0 + 6.0 * u01(rng));
    const double omega = (u01(rng) < 0.5 ? -1.0 : 1.0) * (0.3 + 3.0 * u01(rng));
    const double N = 5.0 + 500.0 * u01(rng), R = 0.01 + 0.3 * u01(rng);
    const double v = eps * std::fabs(omega) * R;
    const Kinematics k{v * std::cos(alpha), v * std::sin(alpha), omega, N, R};
    const auto got = ExactModel<double>({f, kappa, h}, l.law, tables[li])(k);
    const auto ref = testing::reference_resultants(testing::power_sigma0(l.n), kappa, h, k.v_x / R,
                                                   k.v_y / R, omega, 1e-12);
    const double unit = f * N / (2 * kPi * beta_moment(l.n, 1));
    SCOPED_TRACE(l.name + " eps " + std::to_string(eps) + " alpha " + std::to_string(alpha));
    EXPECT_NEAR(got.T_x, unit * ref.T_x, 1e-10 * f * N);
    EXPECT_NEAR(got.T_y, unit * ref.T_y, 1e-10 * f * N);
    EXPECT_NEAR(got.M_z, unit * R * ref.M_z, 1e-10 * f * N * R);
  }
}

// With a free exponent the Jet derivatives come from the table's slopes: they must match
// central differences of the quadrature model in every parameter.
TEST(RingIntegralTable, JetDerivativesOfTheTabulatedModelMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 4>;
  const double f = 0.8, kappa = 1.4, h = 0.15, n = 1.3;
  const auto table = std::make_shared<const RingIntegralTable>(PressureLaw<double>::power(n), true);
  const ExactModel<Jet> model({Jet(f, 0), Jet(kappa, 1), Jet(h, 2)},
                              PressureLaw<Jet>::power(Jet(n, 3)), table);
  for (double eps : {1e-4, 0.2, 0.97, 1.0, 1.6, 40.0}) {
    for (double alpha : {0.0, 0.7, -2.4}) {
      const double v = eps * 2.0 * 0.1;
      const Kinematics k{v * std::cos(alpha), v * std::sin(alpha), 2.0, 300.0, 0.1};
      const auto r = model(k);
      const double x0[4] = {f, kappa, h, n};
      for (int p = 0; p < 4; ++p) {
        const auto channel = [&](int c) {
          return [&, c](double value) {
            double x[4] = {x0[0], x0[1], x0[2], x0[3]};
            x[p] = value;
            const auto q =
                ExactModel<double>({x[0], x[1], x[2]}, PressureLaw<double>::power(x[3]))(k);
            return c == 0 ? q.T_x : c == 1 ? q.T_y : q.M_z;
          };
        };
        const double step = 1e-4 * std::max(1.0, std::fabs(x0[p]));
        const double scale_f = f * 300.0, scale_m = scale_f * 0.1;
        EXPECT_NEAR(r.T_x.v[p], testing::central_difference(channel(0), x0[p], step),
                    1e-6 * scale_f)
            << "eps " << eps << " alpha " << alpha << " parameter " << p;
        EXPECT_NEAR(r.T_y.v[p], testing::central_difference(channel(1), x0[p], step),
                    1e-6 * scale_f)
            << "eps " << eps << " alpha " << alpha << " parameter " << p;
        EXPECT_NEAR(r.M_z.v[p], testing::central_difference(channel(2), x0[p], step),
                    1e-6 * scale_m)
            << "eps " << eps << " alpha " << alpha << " parameter " << p;
      }
    }
  }
}

TEST(RingIntegralTable, ATableOfAnotherLawIsRejected) {
  const auto table = std::make_shared<const RingIntegralTable>(PressureLaw<double>::hertz());
  EXPECT_THROW(ExactModel<double>({1.0, 1.0, 0.0}, PressureLaw<double>::parabolic(), table),
               std::invalid_argument);
  const auto power = std::make_shared<const RingIntegralTable>(PressureLaw<double>::power(1.5));
  EXPECT_THROW(ExactModel<double>({1.0, 1.0, 0.0}, PressureLaw<double>::power(1.6), power),
               std::invalid_argument);
}

}  // namespace
}  // namespace frictionid::model::ring_integral_table_test
