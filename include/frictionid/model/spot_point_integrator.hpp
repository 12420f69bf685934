// The twelve spot integrals at one centre of rotation, by the integrator that suits the spot
// (docs/physics.md §9.3): a rectangle by strips with the y-integral in closed form
// (RectStripIntegrator: exact next to the corners, where the rays' default angular rule errs by
// up to 5e-9 A0, and 3-10 times faster), except under the ring law, which has no density to
// integrate across; a pressure map cell by cell with the y-integral in closed form
// (MapStripIntegrator: 60-120 times faster than rays); an ellipse under a table law by layers
// of the uniform ellipse (EllipseLawIntegrator on that ellipse's table, built once per aspect:
// exact for any number of samples, 0.05-0.3 ms a point where rays cut at every sample took 39
// ms for 41); an annulus of inner radius B on an ellipse as the uniform ellipse less the one
// scaled by B, U(c) - B^(2+d) U(c/B) (docs/physics.md (9.8)), two closed-form ray integrations
// (~20 us where rays cut at the step took ~400 us at q = 0.1); any other ellipse by rays about
// the centre (SpotIntegrator). Rays from a far centre
// lose digits in proportion to its distance (1e-9 of the integrals at |c| ~ 1e7, all of them at
// 1e15, where pure sliding meets a rounding-level spin): beyond kFar spot radii the integrals are
// the quadratic in t = 1/|c| through the sliding limit (t = 0, from the spot's moments) and the
// rays at |c| = kFar and 2 kFar spot radii in the same direction. They are analytic in t for |t| <
// 1/max|r| (the table's far patch uses the same), so the next term costs (1/kFar)^3 ~ 1e-12 of
// them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/ellipse_law_integrator.hpp>
#include <frictionid/model/map_strip_integrator.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_integrals.hpp>

namespace frictionid::model {

inline constexpr std::size_t kKeptUniformTables = 8;

// The uniform ellipse's table of aspect q, built once for the last few aspects asked for (a
// fit that frees q asks for three at every step) and shared.
inline std::shared_ptr<const SpotIntegralTable> uniform_ellipse_table(double q) {
  static std::mutex mutex;
  static std::vector<std::pair<double, std::shared_ptr<const SpotIntegralTable>>> kept;
  const std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [aspect, table] : kept)
    if (aspect == q) return table;
  auto table = std::make_shared<const SpotIntegralTable>(
      ContactSpot::ellipse(q), PressureLaw<double>::uniform(), q, std::function<bool()>{}, 0);
  if (kept.size() == kKeptUniformTables) kept.erase(kept.begin());
  kept.emplace_back(q, table);
  return table;
}

class SpotPointIntegrator {
 public:
  SpotPointIntegrator(const ContactSpot& spot, const PressureLaw<double>& law, double q,
                      SpotRules rules = {}) {
    const bool default_rules = rules.radial == &radial_rule() && rules.angular == &radial_rule();
    const double aspect = spot.has_aspect() ? q : 1.0;
    if (spot.kind == SpotKind::Rect && law.kind != PressureKind::Ring)
      strips_.emplace(law, q);
    else if (spot.kind == SpotKind::Map && spot.map)
      map_strips_.emplace(*spot.map);
    else if (law.kind == PressureKind::Table && default_rules)
      layers_.emplace(uniform_ellipse_table(aspect), law, aspect);
    else if (spot.kind == SpotKind::Ellipse && law.kind == PressureKind::Annulus &&
             rules.closed_rays && law.inner_radius() > 0.0) {
      // The uniform ellipse's rays are closed forms; the annulus' own would cut at the step.
      rays_.emplace(spot, PressureLaw<double>::uniform(), q, rules);
      inner_ = law.inner_radius();
      inner_weight_ = SpotIntegrals::scale_weights(inner_);
      moments_ = spot_moments(spot, law_moments(law), q);
      far_ = kFar * std::max(1.0, q);
    } else {
      rays_.emplace(spot, law, q, rules);
      moments_ = spot_moments(spot, law_moments(law), q);
      far_ = kFar * std::max(1.0, q);
    }
  }

  SpotIntegrals operator()(double cx, double cy) const {
    if (strips_) return (*strips_)(cx, cy);
    if (map_strips_) return (*map_strips_)(cx, cy);
    if (layers_) return (*layers_)(cx, cy);
    const double r = std::hypot(cx, cy);
    if (!(r > far_)) return near(cx, cy);
    // Lagrange weights on the nodes t = 0, t1/2, t1 (interpolation: each in [-0.125, 1]).
    const double t = r < HUGE_VAL ? 1.0 / r : 0.0, t1 = 1.0 / far_, t2 = 0.5 * t1;
    const double gamma = std::atan2(cy, cx), c = std::cos(gamma), s = std::sin(gamma);
    const double w0 = (t - t2) * (t - t1) / (t2 * t1);
    const double w2 = t * (t - t1) / (t2 * (t2 - t1));
    const double w1 = t * (t - t2) / (t1 * (t1 - t2));
    SpotIntegrals out = sliding_limit_integrals(moments_, gamma) * w0;
    out += near(c / t2, s / t2) * w2;
    out += near(c / t1, s / t1) * w1;
    return out;
  }

 private:
  std::optional<RectStripIntegrator> strips_;
  std::optional<MapStripIntegrator> map_strips_;
  std::optional<SpotIntegrator> rays_;
  std::optional<EllipseLawIntegrator<SpotIntegralTable>> layers_;

  // The rays' integrals, or an annulus' from the uniform ellipse's.
  SpotIntegrals near(double cx, double cy) const {
    if (!(inner_ > 0.0)) return (*rays_)(cx, cy);
    std::array<double, 12> v = (*rays_)(cx, cy).channels();
    const std::array<double, 12> in = (*rays_)(cx / inner_, cy / inner_).channels();
    for (std::size_t j = 0; j < 12; ++j) v[j] -= inner_weight_[j] * in[j];
    return SpotIntegrals::from_channels(v.data());
  }
  double inner_ = 0.0;  // an annulus' inner radius B (0: none)
  std::array<double, 12> inner_weight_{};

  static constexpr double kFar = 1e4;  // spot radii beyond which the rays give way (above)
  SpotMoments<double> moments_{1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  double far_ = HUGE_VAL;
};

}  // namespace frictionid::model
