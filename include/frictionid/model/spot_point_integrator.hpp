// The twelve spot integrals at one centre of rotation, by the integrator that suits the spot
// (docs/physics.md §9.3): a rectangle by strips with the y-integral in closed form
// (RectStripIntegrator: exact next to the corners, where the rays' default angular rule errs by
// up to 5e-9 A0, and 3-10 times faster), except under the ring law, which has no density to
// integrate across; a pressure map cell by cell with the y-integral in closed form
// (MapStripIntegrator: 35-65 times faster than rays); the ellipse by rays about the centre
// (SpotIntegrator). Rays from a far centre lose digits in proportion to its distance (1e-9 of
// the integrals at |c| ~ 1e7, all of them at 1e15, where pure sliding meets a rounding-level
// spin): beyond kFar spot radii the integrals are the quadratic in t = 1/|c| through the sliding
// limit (t = 0, from the spot's moments) and the rays at |c| = kFar and 2 kFar spot radii in the
// same direction. They are analytic in t for |t| < 1/max|r| (the table's far patch uses the
// same), so the next term costs (1/kFar)^3 ~ 1e-12 of them.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/map_strip_integrator.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_integrals.hpp>

namespace frictionid::model {

class SpotPointIntegrator {
 public:
  SpotPointIntegrator(const ContactSpot& spot, const PressureLaw<double>& law, double q,
                      SpotRules rules = {}) {
    if (spot.kind == SpotKind::Rect && law.kind != PressureKind::Ring)
      strips_.emplace(law, q);
    else if (spot.kind == SpotKind::Map && spot.map)
      map_strips_.emplace(*spot.map);
    else {
      rays_.emplace(spot, law, q, rules);
      moments_ = spot_moments(spot, law_moments(law), q);
      far_ = kFar * std::max(1.0, q);
    }
  }

  SpotIntegrals operator()(double cx, double cy) const {
    if (strips_) return (*strips_)(cx, cy);
    if (map_strips_) return (*map_strips_)(cx, cy);
    const double r = std::hypot(cx, cy);
    if (!(r > far_)) return (*rays_)(cx, cy);
    // Lagrange weights on the nodes t = 0, t1/2, t1 (interpolation: each in [-0.125, 1]).
    const double t = r < HUGE_VAL ? 1.0 / r : 0.0, t1 = 1.0 / far_, t2 = 0.5 * t1;
    const double gamma = std::atan2(cy, cx), c = std::cos(gamma), s = std::sin(gamma);
    const double w0 = (t - t2) * (t - t1) / (t2 * t1);
    const double w2 = t * (t - t1) / (t2 * (t2 - t1));
    const double w1 = t * (t - t2) / (t1 * (t1 - t2));
    SpotIntegrals out = sliding_limit_integrals(moments_, gamma) * w0;
    out += (*rays_)(c / t2, s / t2) * w2;
    out += (*rays_)(c / t1, s / t1) * w1;
    return out;
  }

 private:
  std::optional<RectStripIntegrator> strips_;
  std::optional<MapStripIntegrator> map_strips_;
  std::optional<SpotIntegrator> rays_;

  static constexpr double kFar = 1e4;  // spot radii beyond which the rays give way (above)
  SpotMoments<double> moments_{1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  double far_ = HUGE_VAL;
};

}  // namespace frictionid::model
