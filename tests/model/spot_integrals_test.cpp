// The rays of SpotIntegrator (model/spot_integrals.hpp) against the brute-force 2-D oracle of
// spot_reference.hpp.
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/spot_model.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace spot_integrals_test {
namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;
namespace fm = frictionid::model;

// Every law (1 - rho^2)^n takes its rays in closed form: 2n whole up to power:4 by the powers
// of u, any other n by the incomplete beta function's series; from inside (and, for 2n whole,
// from outside, in the angle of the ray's distance) the angular integral by Gauss–Legendre
// sized by its singular directions. Ellipses of aspect 0.1 to 4, the centre
// of rotation anywhere (eps 0.05 to 6, pure spin and pure sliding), within 1e-9 of the rim on
// either side and within 1e-6..1e-2 of the spot's centre; the model integrates every row (no
// table).
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
      for (int j = 0; j < 4; ++j, ++i) {
        const sr::Params p = sc::random_params(u, q);
        sr::Motion m = sc::random_motion(u, i, 5);
        if (j >= 2) {  // c on the rim, 1e-9 inside or outside, or within 1e-6..1e-2 of the centre
          const double t = u.in(-sc::kPi, sc::kPi);
          const double scale = j == 2 ? 1.0 + u.sign() * 1e-9 : std::pow(10.0, u.in(-6.0, -2.0));
          sc::centre_on_ellipse(m, q, t, scale);
        }
        const sr::Spot ref = sc::ellipse(q, l.ref);
        SCOPED_TRACE("case " + std::to_string(i) + ": " + sc::describe(ref, l.name, p, m));
        const sc::OracleErrors e = sc::ellipse_vs_oracle(ref, l.law, p, m);
        worst.add(e.friction);
        EXPECT_LT(e.friction, 3e-11);
        EXPECT_LT(e.moment, 1e-12);
      }
}

// The ring law's integral along the rim of an elongated ellipse, where the far side lies 2q
// away and the nearest rim point can be far from the reference angle of c: against the
// periodic trapezoidal rule with 2^17 nodes (geometric convergence: centres at least 1e-3 from
// the rim, where it errs by ~exp(-131) of the integrals).
TEST(SpotIntegrator, TheRingOnElongatedEllipsesMatchesTheTrapezoidalRuleAlongTheRim) {
  sc::Uniform u(0x41e9);
  double worst = 0.0;
  for (double q : {0.05, 0.1, 4.0}) {
    const fm::SpotIntegrator rays(fm::ContactSpot::ellipse(q), fm::PressureLaw<double>::ring(), q);
    const double A0 = fm::spot_moments(fm::ContactSpot::ellipse(q),
                                       fm::law_moments(fm::PressureLaw<double>::ring()), q)
                          .A0;
    for (int i = 0; i < 24; ++i) {
      double cx = 0.0, cy = 0.0;
      const double t = u.in(-sc::kPi, sc::kPi);
      if (i % 3 == 0) {  // anywhere near the spot
        cx = u.in(-2.0, 2.0);
        cy = q * u.in(-2.0, 2.0);
      } else if (i % 3 == 1) {  // 1e-3..1e-1 from the rim along its normal, either side
        const double nx = std::cos(t), ny = std::sin(t) / q, d = std::hypot(nx, ny);
        const double off = u.sign() * std::pow(10.0, u.in(-3.0, -1.0));
        cx = std::cos(t) + off * nx / d;
        cy = q * std::sin(t) + off * ny / d;
      } else {  // inside, next to the long axis
        cx = u.in(-0.95, 0.95) * (q < 1.0 ? 1.0 : 0.0);
        cy = u.in(-0.95, 0.95) * (q < 1.0 ? 0.0 : q);
        (q < 1.0 ? cy : cx) = u.in(-0.02, 0.02);
      }
      std::array<double, 12> want{};
      constexpr int kNodes = 1 << 17;
      for (int k = 0; k < kNodes; ++k) {
        const double s = 2.0 * sc::kPi * (k + 0.5) / kNodes, x = std::cos(s), y = q * std::sin(s);
        const double dx = x - cx, dy = y - cy, w = q * 2.0 * sc::kPi / kNodes / std::hypot(dx, dy);
        const double ex = -dy * w, ey = dx * w;
        const double v[12] = {ex,     x * ex,     y * ex,     ey,     x * ey,     y * ey,
                              x * ey, x * x * ey, x * y * ey, y * ex, x * y * ex, y * y * ex};
        for (std::size_t j = 0; j < 12; ++j) want[j] += v[j];
      }
      const std::array<double, 12> got = rays(cx, cy).channels();
      for (std::size_t j = 0; j < 12; ++j) {
        const double e = std::fabs(got[j] - want[j]) / A0;
        worst = std::max(worst, e);
        EXPECT_LT(e, 1e-12) << "q " << q << " at (" << cx << ", " << cy << "), channel " << j;
      }
    }
  }
  std::printf("[ worst    ] ring along the rim vs trapezoidal rule / A0: %.3g\n", worst);
}

}  // namespace
}  // namespace spot_integrals_test
