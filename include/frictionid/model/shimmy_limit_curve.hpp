// The friction limit of the towed wheel's spot (docs/physics.md §10.3). With v_x = 0 the slip is
// s = (u_y, omega R) = |s| (cos theta, sin theta) and the model's resistances depend on theta
// only (homogeneous of degree 0). Under maximal dissipation the loads (T_y, M_z/R) the contact
// can carry without slipping form the convex set whose support function in the direction
// d(theta) is the dissipation per unit slip speed
//   D(theta) = T_y(theta) cos theta + M_z(theta)/R sin theta,                      (10.3)
// the integrated form of the pointwise cohesion condition |f^-1 tau| <= sigma. A load W sticks
// iff W.d(theta) <= D(theta) for every theta: the margin min_theta (D - W.d) is >= 0.
// The curve is tabulated once per run (the friction is a function of theta alone), the minimum
// refined on the model itself; the table also serves the slip phase of an expensive model.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <frictionid/model/kinematics.hpp>
#include <frictionid/model/shimmy_wheel.hpp>

namespace frictionid::model {

class ShimmyLimitCurve {
 public:
  // friction: Kinematics -> Resultants<double>; n: samples of theta over a full turn.
  template <typename Friction>
  ShimmyLimitCurve(const Friction& friction, double N, double R, int n = 720)
      : N_(N), R_(R), n_(n) {
    forces_.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) forces_.push_back(at(friction, theta(i)));
  }

  double theta(int i) const { return 2.0 * M_PI * i / n_; }
  int size() const { return n_; }
  const ContactForces& sample(int i) const { return forces_[static_cast<std::size_t>(i)]; }

  // The resultants at slip direction theta, from the model.
  template <typename Friction>
  ContactForces at(const Friction& friction, double th) const {
    const Kinematics k{0.0, std::cos(th), std::sin(th) / R_, N_, R_};
    const Resultants<double> r = friction(k);
    return {r.T_x, r.T_y, r.M_z};
  }

  // d(T_x, T_y, M_z)/d theta at theta, from the friction's own derivative along the kinematics
  // (its slip_slope: the model's automatic derivative, docs/physics.md §10.8), in the direction
  // d/d theta of (v_y, omega R) = (cos theta, sin theta).
  template <typename Friction>
  ContactForces slope(const Friction& friction, double th) const {
    const Kinematics k{0.0, std::cos(th), std::sin(th) / R_, N_, R_};
    const Kinematics dk{0.0, -std::sin(th), std::cos(th) / R_, N_, R_};
    return friction.slip_slope(k, dk);
  }

  // D(theta) - W.d(theta) for the load W = (T_y, M_z/R).
  double support_gap(const ContactForces& f, double th, const ContactForces& W) const {
    const double c = std::cos(th), s = std::sin(th);
    return (f.T_y - W.T_y) * c + (f.M_z - W.M_z) / R_ * s;
  }

  struct Margin {
    double value;  // min over theta of D(theta) - W.d(theta) [N]; >= 0: the contact holds W
    double theta;  // where the minimum lies: the most violated (or least reserved) support
  };

  // The margin of W: the tabulated minimum, refined by a golden-section search between the
  // neighbouring samples on the model itself.
  template <typename Friction>
  Margin margin(const Friction& friction, const ContactForces& W) const {
    int best = 0;
    double best_gap = HUGE_VAL;
    for (int i = 0; i < n_; ++i) {
      const double g = support_gap(forces_[static_cast<std::size_t>(i)], theta(i), W);
      if (g < best_gap) {
        best_gap = g;
        best = i;
      }
    }
    const double step = 2.0 * M_PI / n_;
    double a = theta(best) - step, b = theta(best) + step;
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    const auto gap = [&](double th) { return support_gap(at(friction, th), th, W); };
    double x1 = b - r * (b - a), x2 = a + r * (b - a);
    double g1 = gap(x1), g2 = gap(x2);
    for (int it = 0; it < 40; ++it) {
      if (g1 < g2) {
        b = x2;
        x2 = x1;
        g2 = g1;
        x1 = b - r * (b - a);
        g1 = gap(x1);
      } else {
        a = x1;
        x1 = x2;
        g1 = g2;
        x2 = a + r * (b - a);
        g2 = gap(x2);
      }
    }
    Margin m{best_gap, theta(best)};
    const double g = std::min(g1, g2);
    if (g < m.value) m = {g, g1 < g2 ? x1 : x2};
    return m;
  }

  // The largest dissipation per unit slip speed, a force scale of the contact [N].
  double scale() const {
    double d = 0.0;
    for (int i = 0; i < n_; ++i)
      d = std::max(d, support_gap(forces_[static_cast<std::size_t>(i)], theta(i), {}));
    return d;
  }

 private:
  double N_, R_;
  int n_;
  std::vector<ContactForces> forces_;
};

// The direction in which slip starts from s = 0 when the contact cannot hold the load
// (docs/physics.md §10.3): theta such that the slip acceleration under the friction of direction
// theta points along d(theta) itself, d s/dt = lambda d(theta) with lambda > 0. Scanned on the
// curve's samples, refined by bisection of the cross product; of several, the fastest start.
// Falls back to `fallback` (the most violated support) when there is none.
template <typename Friction>
double slip_start_direction(const Friction& friction, const ShimmyLimitCurve& curve,
                            const ShimmyWheel& w, const ShimmyState& x, double fallback) {
  const auto rate = [&](double th) { return slip_rate(w, x, curve.at(friction, th)); };
  const auto cross = [](double th, const std::array<double, 2>& a) {
    return std::cos(th) * a[1] - std::sin(th) * a[0];
  };
  double best = fallback, best_speed = 0.0;
  const int n = curve.size();
  std::array<double, 2> prev = slip_rate(w, x, curve.sample(0));
  for (int i = 1; i <= n; ++i) {
    const double t0 = curve.theta(i - 1), t1 = 2.0 * M_PI * i / n;
    const std::array<double, 2> cur = slip_rate(w, x, curve.sample(i % n));
    const double c0 = cross(t0, prev), c1 = cross(t1, cur);
    if ((c0 <= 0.0) != (c1 <= 0.0)) {
      double a = t0, b = t1, ca = c0;
      for (int it = 0; it < 50; ++it) {
        const double mid = 0.5 * (a + b);
        const double cm = cross(mid, rate(mid));
        if ((cm <= 0.0) == (ca <= 0.0)) {
          a = mid;
          ca = cm;
        } else {
          b = mid;
        }
      }
      const double th = 0.5 * (a + b);
      const auto r = rate(th);
      const double speed = std::cos(th) * r[0] + std::sin(th) * r[1];
      if (speed > best_speed) {
        best_speed = speed;
        best = th;
      }
    }
    prev = cur;
  }
  return best;
}

}  // namespace frictionid::model
