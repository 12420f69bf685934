// The contact spot S (docs/physics.md §9): a circle, an ellipse, a rectangle or a measured
// pressure map, and the static pressure sigma0 on it. Lengths are in units of the contact radius
// R. The ellipse and the rectangle are integrated in reference coordinates (X, Y) = (x, y/q), in
// which they are the unit disk and the square [-1, 1]^2 whatever their aspect q: q then enters
// the integrands smoothly, so that it can be identified with autodiff.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/scalar_ops.hpp>
#include <frictionid/model/shortest_number.hpp>

namespace frictionid::model {

enum class SpotKind { Circle, Ellipse, Rect, Map };

// A measured pressure map: sigma0 sampled on a rectangular grid, bilinear inside the cells and
// zero outside the grid. The map is the pressure (no law applies), in any scale: the load
// normalises it.
struct PressureMap {
  std::vector<double> x, y;    // strictly increasing, at least two each (units of R)
  std::vector<double> sigma0;  // sigma0[j * x.size() + i] is the sample at (x[i], y[j])
  std::string source;          // where it came from (a file name), for messages and reports

  std::size_t nx() const { return x.size(); }
  std::size_t ny() const { return y.size(); }
  double sample(std::size_t i, std::size_t j) const { return sigma0[j * x.size() + i]; }

  // Index i of the cell x[i] <= X <= x[i + 1] (clamped to the grid).
  static std::size_t cell_of(const std::vector<double>& grid, double X) {
    const auto it = std::upper_bound(grid.begin(), grid.end(), X);
    const std::size_t i = it == grid.begin() ? 0 : static_cast<std::size_t>(it - grid.begin()) - 1;
    return std::min(i, grid.size() - 2);
  }

  // Bilinear interpolation inside the grid, zero outside it.
  double operator()(double X, double Y) const {
    if (!(X >= x.front() && X <= x.back() && Y >= y.front() && Y <= y.back())) return 0.0;
    const std::size_t i = cell_of(x, X), j = cell_of(y, Y);
    const double tx = (X - x[i]) / (x[i + 1] - x[i]), ty = (Y - y[j]) / (y[j + 1] - y[j]);
    return (1.0 - ty) * ((1.0 - tx) * sample(i, j) + tx * sample(i + 1, j)) +
           ty * ((1.0 - tx) * sample(i, j + 1) + tx * sample(i + 1, j + 1));
  }
};

class SpotIntegralCache;  // spot_integral_cache.hpp
class SpotIntegralTable;  // spot_integral_table.hpp

struct ContactSpot {
  SpotKind kind = SpotKind::Circle;
  // Aspect of an ellipse (semi-axes R along x, qR along y) or a rectangle (|x| <= R,
  // |y| <= qR): the value a model uses unless the fit frees q. 1 for the circle and the map.
  double q = 1.0;
  std::shared_ptr<const PressureMap> map;  // only for SpotKind::Map
  // The integrals of a fit's rows, computed once (spot_integral_cache.hpp); a model uses them
  // when its q and exponent are the ones they were computed for.
  std::shared_ptr<const SpotIntegralCache> cache;
  // The integrals over the whole plane of the centre of rotation (spot_integral_table.hpp), for
  // many rows: a model uses it when its q and law are the table's.
  std::shared_ptr<const SpotIntegralTable> table;

  static ContactSpot circle() { return {}; }
  static ContactSpot ellipse(double q) { return {SpotKind::Ellipse, q, nullptr, nullptr, nullptr}; }
  static ContactSpot rect(double q) { return {SpotKind::Rect, q, nullptr, nullptr, nullptr}; }
  static ContactSpot pressure_map(std::shared_ptr<const PressureMap> m) {
    return {SpotKind::Map, 1.0, std::move(m), nullptr, nullptr};
  }
  // Whether the aspect q is a property of the spot that a fit can identify.
  bool has_aspect() const { return kind == SpotKind::Ellipse || kind == SpotKind::Rect; }
};

// The spot as --contact spells it: "circle", "ellipse:Q" and "rect:Q" with the shortest text
// that reads back as Q, "map:FILE" with the map's source as given. Reports and
// FitResult::contact name a fit's spot with it.
inline std::string contact_spot_label(const ContactSpot& spot) {
  switch (spot.kind) {
    case SpotKind::Circle:
      return "circle";
    case SpotKind::Ellipse:
      return "ellipse:" + shortest_number(spot.q);
    case SpotKind::Rect:
      return "rect:" + shortest_number(spot.q);
    case SpotKind::Map:
      return "map:" + (spot.map ? spot.map->source : std::string());
  }
  return "?";
}

// Moments of sigma0 over the spot, in units of R^2 (A0), R^3 (Ax, Ay), R^4 (Axx, Axy, Ayy):
// A0 = ∫sigma0 dA, Ax = ∫sigma0 x dA, ... They give the load's normalisation and the centre of
// pressure (docs/physics.md §9.2).
template <typename T>
struct SpotMoments {
  T A0, Ax, Ay, Axx, Axy, Ayy;
};

// Exact moments of a bilinear map: per cell, sigma0 is bilinear and x, y are linear, so the
// 3-point Gauss–Legendre product rule integrates every product of degree <= 5 in each variable.
inline SpotMoments<double> map_moments(const PressureMap& m) {
  static const std::vector<QuadratureNode> rule = make_gauss_legendre_rule(3);
  SpotMoments<double> r{0, 0, 0, 0, 0, 0};
  for (std::size_t j = 0; j + 1 < m.ny(); ++j) {
    const double y0 = m.y[j], hy = m.y[j + 1] - m.y[j];
    for (std::size_t i = 0; i + 1 < m.nx(); ++i) {
      const double x0 = m.x[i], hx = m.x[i + 1] - m.x[i];
      const double s00 = m.sample(i, j), s10 = m.sample(i + 1, j);
      const double s01 = m.sample(i, j + 1), s11 = m.sample(i + 1, j + 1);
      for (const auto& qy : rule) {
        for (const auto& qx : rule) {
          const double tx = qx.from_left, ty = qy.from_left;
          const double s =
              (1 - ty) * ((1 - tx) * s00 + tx * s10) + ty * ((1 - tx) * s01 + tx * s11);
          const double w = qx.weight * qy.weight * hx * hy * s;
          const double x = x0 + hx * tx, y = y0 + hy * ty;
          r.A0 += w;
          r.Ax += w * x;
          r.Ay += w * y;
          r.Axx += w * x * x;
          r.Axy += w * x * y;
          r.Ayy += w * y * y;
        }
      }
    }
  }
  return r;
}

// The moments of any spot from the law's radial moments m_k (pressure_law.hpp):
// ellipse: dA = q rho drho dtheta in reference polar coordinates, so A0 = 2 pi q m1,
// Axx = pi q m3, Ayy = pi q^3 m3; rectangle: sigma0(|x|) on |y| <= q, so A0 = 4 q m0,
// Axx = 4 q m2, Ayy = (4/3) q^3 m0. Both are symmetric: the first moments and Axy vanish.
template <typename T>
SpotMoments<T> spot_moments(const ContactSpot& spot, const LawMoments<T>& m, const T& q) {
  const T zero = T(0);
  switch (spot.kind) {
    case SpotKind::Circle:
      return {T(2 * M_PI) * m[1], zero, zero, T(M_PI) * m[3], zero, T(M_PI) * m[3]};
    case SpotKind::Ellipse:
      return {T(2 * M_PI) * q * m[1], zero, zero,
              T(M_PI) * q * m[3],     zero, T(M_PI) * q * q * q * m[3]};
    case SpotKind::Rect:
      return {T(4) * q * m[0], zero, zero, T(4) * q * m[2], zero, T(4.0 / 3.0) * q * q * q * m[0]};
    case SpotKind::Map: {
      const SpotMoments<double> d = map_moments(*spot.map);
      return {T(d.A0), T(d.Ax), T(d.Ay), T(d.Axx), T(d.Axy), T(d.Ayy)};
    }
  }
  return {zero, zero, zero, zero, zero, zero};
}

// Where the tilted pressure 1 + h x + h_y y would turn negative on the spot, if anywhere: the
// point of the spot's support where it is least. Empty when the pressure stays >= 0.
struct TiltViolation {
  bool negative = false;
  double x = 0.0, y = 0.0;  // the point (units of R)
};

inline TiltViolation tilt_violation(const ContactSpot& spot, double q, double h, double h_y) {
  TiltViolation v;
  auto check = [&v, h, h_y](double x, double y) {
    if (1.0 + h * x + h_y * y < -1e-15 && !v.negative) v = {true, x, y};
  };
  switch (spot.kind) {
    case SpotKind::Circle:
    case SpotKind::Ellipse: {
      // The minimum of h x + h_y y on the ellipse x = cos t, y = q sin t.
      const double a = h, b = h_y * q, len = std::hypot(a, b);
      if (len > 0.0) check(-a / len, -(b / len) * q);
      break;
    }
    case SpotKind::Rect:
      for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) check(sx, sy * q);
      break;
    case SpotKind::Map: {
      // The tilt is linear: its minimum over a cell is at a corner; only loaded cells count.
      const PressureMap& m = *spot.map;
      for (std::size_t j = 0; j + 1 < m.ny(); ++j)
        for (std::size_t i = 0; i + 1 < m.nx(); ++i) {
          if (m.sample(i, j) == 0.0 && m.sample(i + 1, j) == 0.0 && m.sample(i, j + 1) == 0.0 &&
              m.sample(i + 1, j + 1) == 0.0)
            continue;
          for (std::size_t dj : {0, 1})
            for (std::size_t di : {0, 1}) check(m.x[i + di], m.y[j + dj]);
        }
      break;
    }
  }
  return v;
}

}  // namespace frictionid::model
