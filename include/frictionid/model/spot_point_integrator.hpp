// The twelve spot integrals at one centre of rotation, by the integrator that suits the spot
// (docs/physics.md §9.3): a rectangle by strips with the y-integral in closed form
// (RectStripIntegrator: exact next to the corners, where the rays' default angular rule errs by
// up to 5e-9 A0, and 3-10 times faster), except under the ring law, which has no density to
// integrate across; a pressure map cell by cell with the y-integral in closed form
// (MapStripIntegrator: 35-65 times faster than rays); the ellipse by rays about the centre
// (SpotIntegrator).
#pragma once

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
    else
      rays_.emplace(spot, law, q, rules);
  }

  SpotIntegrals operator()(double cx, double cy) const {
    return strips_ ? (*strips_)(cx, cy) : map_strips_ ? (*map_strips_)(cx, cy) : (*rays_)(cx, cy);
  }

 private:
  std::optional<RectStripIntegrator> strips_;
  std::optional<MapStripIntegrator> map_strips_;
  std::optional<SpotIntegrator> rays_;
};

}  // namespace frictionid::model
