// Bounds every Coulomb contact obeys (docs/physics.md §1): the local traction is at most
// f max(1, kappa) sigma, so wherever the tilted pressure sigma0 (1 + h rho cos theta) stays
// non-negative (|h| <= 1)
//   |T| <= f max(1, kappa) N   and   |M_z| <= f max(1, kappa) N R m2/m1
// (the tilt term integrates to zero in both bounds). Checked for every kind of law, with the
// radial quadrature and the tabulated ring integrals.
#include <frictionid/model/exact_model.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <frictionid/model/ring_integral_table.hpp>

namespace frictionid::model::resultant_bounds_test {
namespace {

struct NamedLaw {
  std::string name;
  PressureLaw<double> law;
};

std::vector<NamedLaw> every_kind_of_law() {
  auto table = [](std::vector<double> rho, std::vector<double> sigma) {
    return PressureLaw<double>::tabulated(
        std::make_shared<const PressureTable>(std::move(rho), std::move(sigma)));
  };
  return {
      {"uniform", PressureLaw<double>::uniform()},
      {"hertz", PressureLaw<double>::hertz()},
      {"parabolic", PressureLaw<double>::parabolic()},
      {"power:0.2", PressureLaw<double>::power(0.2)},
      {"power:6", PressureLaw<double>::power(6.0)},
      {"annulus:0", PressureLaw<double>::annulus(0.0)},
      {"annulus:0.5", PressureLaw<double>::annulus(0.5)},
      {"annulus:0.99", PressureLaw<double>::annulus(0.99)},
      {"ring", PressureLaw<double>::ring()},
      {"step table", table({0.0, 0.3, 0.3, 1.0}, {0.0, 0.0, 1.0, 1.0})},
      {"centre-heavy step table", table({0.0, 0.2, 0.2, 1.0}, {5.0, 5.0, 0.1, 0.1})},
      {"thin-ring table", table({0.0, 0.97, 0.97, 1.0}, {0.0, 0.0, 1.0, 1.0})},
      {"rough table",
       table({0.0, 0.1, 0.35, 0.4, 0.4, 0.7, 0.9, 1.0}, {0.2, 3.0, 0.0, 0.0, 2.0, 0.5, 1.5, 0.0})},
  };
}

TEST(ResultantBounds, ForceAndSpinTorqueStayWithinTheCoulombBoundsForEveryLaw) {
  std::mt19937_64 rng(0xb0d5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (const auto& l : every_kind_of_law()) {
    const auto mo = law_moments(l.law);
    const double mu_M = mo[2] / mo[1];
    const auto table = l.law.kind == PressureKind::Ring
                           ? nullptr
                           : std::make_shared<const RingIntegralTable>(l.law);
    for (int i = 0; i < 300; ++i) {
      const double kappa = std::exp(std::log(0.2) + std::log(25.0) * u01(rng));
      const double h = i % 7 == 0 ? (i % 2 ? 1.0 : -1.0) : -1.0 + 2.0 * u01(rng);
      const double f = 0.1 + u01(rng), alpha = M_PI * (2 * u01(rng) - 1);
      const double eps = i % 11 == 0 ? 1.0 : std::pow(10.0, -4.0 + 8.0 * u01(rng));
      const double omega = (u01(rng) < 0.5 ? -1.0 : 1.0) * (0.1 + 5.0 * u01(rng));
      const double N = 1.0 + 100.0 * u01(rng), R = 0.01 + u01(rng);
      const double v = eps * std::fabs(omega) * R;
      const Kinematics k{v * std::cos(alpha), v * std::sin(alpha), omega, N, R};
      const double force_bound = f * std::max(1.0, kappa) * N;
      const double torque_bound = force_bound * R * mu_M;
      for (bool tabulated : {false, true}) {
        const auto r = ExactModel<double>({f, kappa, h}, l.law, tabulated ? table : nullptr)(k);
        SCOPED_TRACE(l.name + " eps " + std::to_string(eps) + " kappa " + std::to_string(kappa) +
                     " h " + std::to_string(h) + (tabulated ? " tabulated" : ""));
        EXPECT_LE(std::hypot(r.T_x, r.T_y), force_bound * (1 + 1e-12));
        EXPECT_LE(std::fabs(r.M_z), torque_bound * (1 + 1e-12));
      }
    }
  }
}

}  // namespace
}  // namespace frictionid::model::resultant_bounds_test
