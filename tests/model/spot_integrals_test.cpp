// The rays of SpotIntegrator (model/spot_integrals.hpp) against the brute-force 2-D oracle of
// spot_reference.hpp.
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/spot_model.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;
namespace fm = frictionid::model;

// Every law (1 - rho^2)^n takes its rays in closed form: 2n whole up to power:4 by the powers
// of u, any other n by the incomplete beta function's series. Ellipses of aspect 0.1 to 4, the
// centre of rotation anywhere (eps 0.05 to 6, pure spin and pure sliding) and within 1e-9 of
// the rim on either side; the model integrates every row (no table).
TEST(SpotIntegrator, ClosedFormRaysOfEveryPowerLawMatchTheOracle) {
  using L = fm::PressureLaw<double>;
  struct Law {
    std::string name;
    sr::RadialLaw ref;
    L law;
  };
  const std::vector<Law> laws = {{"uniform", sr::uniform_law(), L::uniform()},
                                 {"hertz", sr::hertz_law(), L::hertz()},
                                 {"parabolic", sr::parabolic_law(), L::parabolic()},
                                 {"power:0.3", sr::power_law(0.3), L::power(0.3)},
                                 {"power:1.5", sr::power_law(1.5), L::power(1.5)},
                                 {"power:1.7", sr::power_law(1.7), L::power(1.7)},
                                 {"power:4", sr::power_law(4.0), L::power(4.0)},
                                 {"power:5.5", sr::power_law(5.5), L::power(5.5)}};
  sc::Uniform u(0x5eed5);
  sc::Worst worst{"closed-form rays vs oracle, friction / (f N), (f N R)"};
  int i = 0;
  for (const Law& l : laws)
    for (double q : {0.1, 0.35, 1.0, 2.2, 4.0})
      for (int j = 0; j < 3; ++j, ++i) {
        const sr::Params p = sc::random_params(u, q);
        sr::Motion m = sc::random_motion(u, i, 5);
        if (j == 2) {  // c = (-v_y, v_x)/(omega R) on the rim, 1e-9 inside or outside
          const double t = u.in(-sc::kPi, sc::kPi), scale = 1.0 + u.sign() * 1e-9;
          const double w = (m.omega != 0.0 ? m.omega : 1.0) * m.R;
          m.omega = w / m.R;
          m.v_x = scale * q * std::sin(t) * w;
          m.v_y = -scale * std::cos(t) * w;
        }
        const sr::Spot ref = sc::ellipse(q, l.ref);
        SCOPED_TRACE("case " + std::to_string(i) + ": " + sc::describe(ref, l.name, p, m));
        const fm::Kinematics k{m.v_x, m.v_y, m.omega, m.N, m.R};
        const fm::Resultants<double> r = fm::spot_resultants<double>(
            {p.f, p.kappa, p.h, p.h_y, q}, l.law, fm::ContactSpot::ellipse(q), k);
        const sr::Result got{r.T_x, r.T_y, r.M_z, r.M_roll, r.M_tilt, r.N, 0.0};
        const sr::Result want = sr::spot_reference(ref, p, m);
        const double e = sc::friction_error(got, want, p, m);
        worst.add(e);
        EXPECT_LT(e, 3e-11);
        EXPECT_LT(sc::moment_error(got, want, m), 1e-12);
      }
}

}  // namespace
