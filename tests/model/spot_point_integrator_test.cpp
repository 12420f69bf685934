// The integrator a row without a table takes (model/spot_point_integrator.hpp) against the
// brute-force 2-D oracle of spot_reference.hpp, where it does more than call one integrator.
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/spot_model.hpp>
#include <frictionid/model/spot_point_integrator.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace spot_point_integrator_test {
namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;
namespace fm = frictionid::model;

// An annulus of inner radius B on an ellipse is the uniform ellipse less the one scaled by B,
// U(c) - B^(2+d) U(c/B), two closed-form ray integrations. The difference holds the annulus'
// own load (1 - B^2) A0, so its error grows as B nears 1: B from 0.05 to 0.95, aspects 0.1 to
// 4, centres anywhere (eps 0.05 to 6, pure spin and pure sliding), within 1e-9 of the outer or
// the inner rim on either side, and beyond the distance where the rays give way to the
// interpolation in 1/|c| (1e4 spot radii).
TEST(SpotPointIntegrator, AnAnnulusOnAnEllipseFromTheUniformOneMatchesTheOracle) {
  sc::Uniform u(0xa22u);
  sc::Worst worst{"annulus on an ellipse vs oracle, friction / (f N), (f N R)"};
  int i = 0;
  for (double B : {0.05, 0.4, 0.75, 0.95})
    for (double q : {0.1, 0.6, 2.5, 4.0})
      for (int j = 0; j < 5; ++j, ++i) {
        const sr::Params p = sc::random_params(u, q);
        sr::Motion m = sc::random_motion(u, i, 5);
        if (j >= 2) {  // c on the outer rim (j = 2), the inner one (3) or 3e4 radii away (4)
          const double t = u.in(-sc::kPi, sc::kPi);
          const double scale = j == 2   ? 1.0 + u.sign() * 1e-9
                               : j == 3 ? B * (1.0 + u.sign() * 1e-9)
                                        : 3e4 * std::max(1.0, q);
          sc::centre_on_ellipse(m, q, t, scale);
        }
        const sr::Spot ref = sc::ellipse(q, sr::annulus_law(B));
        const std::string name = "annulus:" + std::to_string(B);
        SCOPED_TRACE("case " + std::to_string(i) + ": " + sc::describe(ref, name, p, m));
        const sc::OracleErrors e =
            sc::ellipse_vs_oracle(ref, fm::PressureLaw<double>::annulus(B), p, m);
        worst.add(e.friction);
        EXPECT_LT(e.friction, 1e-10);
        EXPECT_LT(e.moment, 1e-12);
      }
}

// The same rows by the uniform ellipse's two integrations and by the annulus' own rays, cut at
// the step, with their fine rules: two independent ways to the same integrals.
TEST(SpotPointIntegrator, AnAnnulusOnAnEllipseAgreesWithItsOwnRays) {
  sc::Uniform u(0xa23u);
  double worst = 0.0;
  for (double B : {0.3, 0.8})
    for (double q : {0.15, 1.7}) {
      const fm::ContactSpot spot = fm::ContactSpot::ellipse(q);
      const fm::PressureLaw<double> law = fm::PressureLaw<double>::annulus(B);
      const fm::SpotPointIntegrator two(spot, law, q);
      const fm::SpotIntegrator rays(
          spot, law, q, fm::SpotRules{&fm::radial_rule(), &fm::radial_rule(), false, false});
      const double A0 = fm::spot_moments(spot, fm::law_moments(law), q).A0;
      for (int k = 0; k < 12; ++k) {
        const double r = u.log_in(0.01, 5.0), t = u.in(-sc::kPi, sc::kPi);
        const double cx = r * std::cos(t), cy = q * r * std::sin(t);
        const auto a = two(cx, cy).channels(), b = rays(cx, cy).channels();
        for (int ch = 0; ch < 12; ++ch) worst = std::max(worst, std::fabs(a[ch] - b[ch]) / A0);
      }
    }
  std::printf("[ worst    ] annulus, two uniform integrations vs its own rays: %.2g A0\n", worst);
  EXPECT_LT(worst, 1e-10);
}

}  // namespace
}  // namespace spot_point_integrator_test
