// The approximants' coefficients of a non-circular spot (spot_coefficients.hpp): a map's come
// from its strips and corner sums, a rectangle's from the rays at the fine rules, so a uniform map
// on [-1, 1] x [-q, q] checks the one against the other.
#include <frictionid/model/spot_coefficients.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>

namespace frictionid::model::spot_coefficients_test {
namespace {

TEST(SpotCoefficients, AUniformMapHasTheCoefficientsOfTheUniformRectangle) {
  const double q = 0.7, kappa = 1.3;
  auto map = std::make_shared<PressureMap>();
  // 41 x 31 lines, unevenly spaced.
  for (int i = 0; i <= 40; ++i) map->x.push_back(std::sin(0.5 * M_PI * (i - 20) / 20.0));
  for (int j = 0; j <= 30; ++j)
    map->y.push_back(q * (j - 15) / 15.0 * (1.0 - 0.2 * (j % 2) / 15.0));
  map->sigma0.assign(map->x.size() * map->y.size(), 2.0);
  const PressureLaw<double> uniform = PressureLaw<double>::uniform();
  const Coefficients<double> m =
      spot_coefficients(ContactSpot::pressure_map(map), uniform, 1.0, kappa);
  const Coefficients<double> r = spot_coefficients(ContactSpot::rect(q), uniform, q, kappa);
  // a from a central difference of two integrals 2e-6 apart: ~1e-14 / 1e-6 of its size (2e-9
  // measured); the others 2e-14.
  EXPECT_NEAR(m.a / r.a, 1.0, 2e-8);
  EXPECT_NEAR(m.b / r.b, 1.0, 1e-12);
  EXPECT_NEAR(m.m / r.m, 1.0, 1e-12);
  EXPECT_NEAR(m.p0, r.p0, 1e-12);
  EXPECT_NEAR(m.b_tilde / r.b_tilde, 1.0, 1e-12);
  EXPECT_NEAR(m.mu_M, r.mu_M, 1e-12);
  EXPECT_NEAR(m.rho_roll, r.rho_roll, 1e-12);
}

}  // namespace
}  // namespace frictionid::model::spot_coefficients_test
