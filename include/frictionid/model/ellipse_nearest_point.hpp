// The point of the ellipse x^2 + (y/q)^2 = 1 nearest a given point, from inside or outside
// (after D. Eberly, "Distance from a point to an ellipse, an ellipsoid, or a hyperellipsoid").
// In the frame where the semi-axes are e0 >= e1 and the point (y0, y1) lies in the first
// quadrant, the nearest point is (e0^2 y0/(t + e0^2), e1^2 y1/(t + e1^2)) for the root t of
// (e0 y0/(t + e0^2))^2 + (e1 y1/(t + e1^2))^2 = 1, which is monotone in t on the bracket used
// here, so Newton's method guarded by bisection finds it to the last bit. Plain double: the
// integrators use it to place their cuts, not inside any derivative.
#pragma once

#include <cmath>
#include <utility>

namespace frictionid::model {

struct RimPoint {
  double x = 0.0, y = 0.0;  // the nearest point of the rim
  double distance = 0.0;    // from the given point to it
};

inline RimPoint nearest_rim_point(double q, double x, double y) {
  double e0 = 1.0, e1 = q, y0 = std::fabs(x), y1 = std::fabs(y);
  const bool swapped = e1 > e0;
  if (swapped) {
    std::swap(e0, e1);
    std::swap(y0, y1);
  }
  RimPoint p;
  if (!(std::isfinite(y0) && std::isfinite(y1))) {
    p.distance = HUGE_VAL;
    return p;
  }
  double x0 = e0, x1 = 0.0;  // the nearest point in the first quadrant, e0 >= e1
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0, z1 = y1 / e1, g = z0 * z0 + z1 * z1 - 1.0;
      if (g == 0.0) {
        x0 = y0;
        x1 = y1;
        p.distance = 0.0;
      } else {
        const double r0 = (e0 / e1) * (e0 / e1), n0 = r0 * z0;
        // In w = t + 1, whose lower end z1 keeps its relative precision: next to the long axis
        // (z1 below ~1e-8) t + 1 lost it, and from inside with z1 < 2^-53 it rounded to 0, the
        // rim point to infinity.
        double lo = z1, hi = g < 0.0 ? 1.0 : std::hypot(n0, z1), w = lo;
        // f is convex and decreasing for w > 0 and f(lo) >= 0, so Newton from lo rises to the
        // root without passing it; a step that gains less than half the bracket is followed by
        // a bisection. 5-10 evaluations where bisection to the last bit took ~60.
        for (int i = 0; i < 200 && lo < hi; ++i) {
          const double u = 1.0 / (w + (r0 - 1.0)), v = 1.0 / w;
          const double a = n0 * u, b = z1 * v, f = a * a + b * b - 1.0;
          if (f < 0.0) {
            hi = w;
          } else {
            lo = w;
            if (f == 0.0) break;
            const double newton = w + f / (2.0 * (a * a * u + b * b * v));
            if (!(newton > w)) break;  // converged to the last bit
            // Converging quadratically: this step leaves ~1e-18 of w, below its last bit.
            if (newton - w <= 1e-9 * w) {
              lo = newton;
              break;
            }
            if (newton < hi && newton - lo >= 0.5 * (hi - lo)) {
              w = newton;
              continue;
            }
            if (newton < hi) lo = newton;
          }
          const double mid = 0.5 * (lo + hi);
          if (mid == lo || mid == hi) break;
          w = mid;
        }
        w = lo;
        x0 = r0 * y0 / (w + (r0 - 1.0));
        x1 = y1 / w;
        p.distance = std::hypot(x0 - y0, x1 - y1);
      }
    } else {
      x0 = 0.0;
      x1 = e1;
      p.distance = std::fabs(y1 - e1);
    }
  } else {
    // On the long axis: the nearest point leaves it only from inside its evolute's span.
    const double num = e0 * y0, den = e0 * e0 - e1 * e1;
    p.distance = std::fabs(y0 - e0);
    if (num < den) {
      const double u = num / den, a = e0 * u, b = e1 * std::sqrt(1.0 - u * u);
      const double d = std::hypot(a - y0, b);
      if (d < p.distance) {
        x0 = a;
        x1 = b;
        p.distance = d;
      }
    }
  }
  if (swapped) std::swap(x0, x1);
  p.x = std::copysign(x0, x);
  p.y = std::copysign(x1, y);
  return p;
}

}  // namespace frictionid::model
