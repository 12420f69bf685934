// Brute-force reference for the resultants of a general contact spot (test oracle).
//
// Spots (lengths in units of the contact radius R):
//   ellipse:Q  x^2 + (y/Q)^2 <= 1,  sigma0 = law(rho_e), rho_e = sqrt(x^2 + (y/Q)^2)
//   rect:Q     |x| <= 1, |y| <= Q,  sigma0 = law(|x|)
//   map        sigma0 bilinear on a rectangular grid, zero outside the grid's rectangle
// Pressure sigma = c sigma0 (1 + h x + h_y y), c such that ∫sigma dA = N. Sliding velocity
// v_S = (v_x - omega R y, v_y + omega R x), traction tau = -sigma f D v_S/|v_S|, D = diag(1,
// kappa). Resultants (resistance convention): T = -∫tau dA, M_z = -∫(x tau_y - y tau_x) dA, M_roll
// = ∫sigma x dA, M_tilt = ∫sigma y dA.
//
// Method: nested adaptive Gauss–Kronrod (G10K21, ref_quad::gk21/adapt of reference_integrator.hpp)
// about the spot's centre, never polar coordinates about the instantaneous centre
// c = (-v_y, v_x)/(omega R) (the production model's method):
//   ellipse   elliptic-polar x = rho cos t, y = Q rho sin t, dA = Q rho drho dt; rho outer, split
//             at rho_e(c) and at the law's breakpoints; t inner, starting and ending at t(c),
//             so the point where the direction jumps sits at the ends of the inner interval.
//   rect/map  Cartesian, x outer, y inner; x split at 0, c_x, the law's breakpoints (+-) or the
//             grid lines; y split at c_y (and the grid lines).
// Every outer piece [a, b] is mapped by u = a + (b - a) s^2 (3 - 2 s), which softens the rim
// singularities (1 - rho^2)^n and the (u - c) log|u - c| kinks at both ends; distances to the
// rim and to c are formed from the piece's ends, without cancellation.
//
// The law functions here are written independently of src/model (only the standard library).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model/reference_integrator.hpp"

namespace frictionid::testing::spot_ref {

namespace rq = frictionid::testing::ref_quad;

// ---------------------------------------------------------------------------------------------
// Radial laws sigma0(rho), rho in [0, 1].

struct RadialLaw {
  std::string name;
  // sigma0(rho, 1 - rho); the second argument is exact near the rim.
  std::function<double(double, double)> sigma0;
  std::vector<double> breaks;  // rho in (0, 1) where sigma0 or its slope jumps
  // m_k = ∫_0^1 sigma0(rho) rho^k drho in closed form (or exactly, for piecewise-linear laws).
  std::function<double(int)> moment;
};

// ∫_0^1 (1 - rho^2)^n rho^k drho = B((k + 1)/2, n + 1)/2.
inline double power_moment(double n, int k) {
  const double a = 0.5 * (k + 1), b = n + 1.0;
  return 0.5 * std::exp(std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b));
}

inline RadialLaw uniform_law() {
  return {"uniform", [](double, double) { return 1.0; }, {}, [](int k) { return 1.0 / (k + 1); }};
}
inline RadialLaw hertz_law() {
  return {"hertz",
          [](double r, double omr) { return std::sqrt(std::max(0.0, omr * (1.0 + r))); },
          {},
          [](int k) { return power_moment(0.5, k); }};
}
inline RadialLaw parabolic_law() {
  return {"parabolic",
          [](double r, double omr) { return std::max(0.0, omr * (1.0 + r)); },
          {},
          [](int k) { return power_moment(1.0, k); }};
}
inline RadialLaw power_law(double n) {
  return {"power:" + std::to_string(n),
          [n](double r, double omr) {
            const double rim = std::max(0.0, omr * (1.0 + r));
            return n == 0.0 ? 1.0 : std::pow(rim, n);
          },
          {},
          [n](int k) { return power_moment(n, k); }};
}
inline RadialLaw annulus_law(double B) {
  return {"annulus:" + std::to_string(B), [B](double r, double) { return r >= B ? 1.0 : 0.0; },
          B > 0.0 && B < 1.0 ? std::vector<double>{B} : std::vector<double>{},
          [B](int k) { return (1.0 - std::pow(B, k + 1)) / (k + 1); }};
}
// Piecewise linear through (rho[k], sigma[k]); a repeated rho ends one straight run and starts the
// next (a step when the two values differ, a kink otherwise). Constant outside [rho[0],
// rho.back()].
inline RadialLaw piecewise_linear_law(const std::vector<double>& rho,
                                      const std::vector<double>& sigma) {
  if (rho.size() != sigma.size() || rho.size() < 2)
    throw std::invalid_argument("piecewise_linear_law: bad samples");
  std::vector<double> breaks;
  for (double r : rho)
    if (r > 0.0 && r < 1.0 && (breaks.empty() || breaks.back() != r)) breaks.push_back(r);
  auto eval = [rho, sigma](double r, double) {
    if (r <= rho.front()) return sigma.front();
    if (r >= rho.back()) return sigma.back();
    // last k with rho[k] <= r: at a repeated rho this is the second sample (value after).
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(rho.begin(), rho.end(), r) - rho.begin()) - 1;
    const double t = (r - rho[k]) / (rho[k + 1] - rho[k]);
    return sigma[k] + t * (sigma[k + 1] - sigma[k]);
  };
  // Moments piece by piece with 3-point Gauss–Legendre: exact for (linear) * rho^k, k <= 4.
  std::vector<double> edges = {0.0, 1.0};
  edges.insert(edges.end(), breaks.begin(), breaks.end());
  std::sort(edges.begin(), edges.end());
  auto moment = [eval, edges](int k) {
    const double g = std::sqrt(0.6), xg[3] = {-g, 0.0, g}, wg[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
      const double c = 0.5 * (edges[i] + edges[i + 1]), hw = 0.5 * (edges[i + 1] - edges[i]);
      for (int j = 0; j < 3; ++j) {
        const double r = c + hw * xg[j];
        sum += hw * wg[j] * eval(r, 1.0 - r) * std::pow(r, k);
      }
    }
    return sum;
  };
  return {"piecewise-linear", eval, breaks, moment};
}

// ---------------------------------------------------------------------------------------------
// Spots, parameters, results.

struct Grid {
  std::vector<double> x, y;    // strictly increasing
  std::vector<double> sigma0;  // sigma0[j * x.size() + i] at (x[i], y[j])

  // Bilinear inside the cell holding (px, py); zero outside the rectangle.
  double operator()(double px, double py) const {
    if (px < x.front() || px > x.back() || py < y.front() || py > y.back()) return 0.0;
    const std::size_t nx = x.size();
    auto cell = [](const std::vector<double>& g, double p) {
      std::size_t i = static_cast<std::size_t>(std::upper_bound(g.begin(), g.end(), p) - g.begin());
      i = i == 0 ? 0 : i - 1;
      return std::min(i, g.size() - 2);
    };
    const std::size_t i = cell(x, px), j = cell(y, py);
    const double tx = (px - x[i]) / (x[i + 1] - x[i]), ty = (py - y[j]) / (y[j + 1] - y[j]);
    const double s00 = sigma0[j * nx + i], s10 = sigma0[j * nx + i + 1];
    const double s01 = sigma0[(j + 1) * nx + i], s11 = sigma0[(j + 1) * nx + i + 1];
    return (1.0 - ty) * ((1.0 - tx) * s00 + tx * s10) + ty * ((1.0 - tx) * s01 + tx * s11);
  }
};

enum class Shape { Ellipse, Rect, Map };

struct Spot {
  Shape shape = Shape::Ellipse;
  double q = 1.0;                 // ellipse: semi-axis along y; rect: half-width along y
  RadialLaw law = uniform_law();  // ellipse and rect
  Grid grid;                      // map
};

struct Params {
  double f = 1.0, kappa = 1.0, h = 0.0, h_y = 0.0;
};

struct Motion {
  double v_x = 0.0, v_y = 0.0, omega = 0.0, N = 1.0, R = 1.0;
};

struct Result {
  double T_x = 0, T_y = 0, M_z = 0, M_roll = 0, M_tilt = 0, N = 0;
  // The quadrature's error estimate (max over the components) relative to f N, or f N R for
  // the torques.
  double rel_error = 0;
};

namespace detail {

constexpr std::size_t kC = 6;  // T_x, T_y, M_z, N, M_roll, M_tilt with c = f = 1
using V = rq::Vec<kC>;

// A point of a piece [a, b] at s in [0, 1]: u = a + (b - a) S(s), S(s) = s^2 (3 - 2 s), with
// from_a = u - a and to_b = b - u formed without cancellation, and jac = du/ds.
struct PiecePoint {
  double u, from_a, to_b, a, b, jac;
};

inline PiecePoint piece_point(double a, double b, double s) {
  const double step = s * s * (3.0 - 2.0 * s);
  const double back = (1.0 - s) * (1.0 - s) * (1.0 + 2.0 * s);  // 1 - step
  PiecePoint p;
  p.from_a = (b - a) * step;
  p.to_b = (b - a) * back;
  p.u = step <= 0.5 ? a + p.from_a : b - p.to_b;
  p.a = a;
  p.b = b;
  p.jac = (b - a) * 6.0 * s * (1.0 - s);
  return p;
}

// p.u - c, exact when c is an end of the piece (c is an edge whenever it lies inside [a, b]).
inline double offset(const PiecePoint& p, double c) {
  return p.a >= c ? (p.a - c) + p.from_a : (p.b - c) - p.to_b;
}

inline std::vector<std::pair<int, std::pair<double, double>>> pieces(std::vector<double> e) {
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  std::vector<std::pair<int, std::pair<double, double>>> out;
  for (std::size_t i = 0; i + 1 < e.size(); ++i)
    out.push_back({static_cast<int>(i), {e[i], e[i + 1]}});
  return out;
}

// ∫ over the outer pieces between `edges` of ∫ over the inner pieces of line(w) dw du, where
// make_line(PiecePoint outer) returns {inner edges, line}, line(PiecePoint inner) -> V holding
// every Jacobian but du/ds and dw/ds. Both levels use the piece map S and adaptive bisection in s.
template <class MakeLine>
rq::AdaptResult<kC + 2> integrate_nested(std::vector<double> edges, const MakeLine& make_line,
                                         double rel_tol) {
  rel_tol = std::max(rel_tol, 1e-14);
  const auto outer_pieces = pieces(std::move(edges));
  const double inner_tol = 0.05 * rel_tol;
  constexpr std::size_t M = kC + 2;  // values, then the lines' L1 scale and error estimates

  auto outer_eval = [&](int seg, double t0, double t1) {
    const double a = outer_pieces[static_cast<std::size_t>(seg)].second.first;
    const double b = outer_pieces[static_cast<std::size_t>(seg)].second.second;
    auto g = [&](double s) {
      rq::Vec<M> out{};
      const PiecePoint op = piece_point(a, b, s);
      if (op.jac == 0.0) return out;
      const auto made = make_line(op);
      const auto& line = made.second;
      const auto inner_pieces = pieces(made.first);
      auto inner_eval = [&](int sg, double w0, double w1) {
        const double ia = inner_pieces[static_cast<std::size_t>(sg)].second.first;
        const double ib = inner_pieces[static_cast<std::size_t>(sg)].second.second;
        auto f = [&](double si) {
          const PiecePoint ip = piece_point(ia, ib, si);
          if (ip.jac == 0.0) return V{};
          V v = line(ip);
          for (double& c : v) c *= ip.jac;
          return v;
        };
        const rq::Gk21Result<kC> r = rq::gk21<kC>(f, w0, w1);
        rq::Panel<kC> pn{sg, w0, w1, r.value, 0.0, 0.0};
        for (std::size_t c = 0; c < kC; ++c) {
          pn.err = std::max(pn.err, r.err[c]);
          pn.l1 = std::max(pn.l1, r.abs[c]);
        }
        return pn;
      };
      std::vector<std::pair<int, std::pair<double, double>>> init;
      for (const auto& ip : inner_pieces) init.push_back({ip.first, {0.0, 1.0}});
      const rq::AdaptResult<kC> in = rq::adapt<kC>(inner_eval, init, inner_tol, 4000);
      for (std::size_t c = 0; c < kC; ++c) out[c] = op.jac * in.value[c];
      out[kC] = op.jac * in.l1;
      out[kC + 1] = op.jac * in.err;
      return out;
    };
    const rq::Gk21Result<M> r = rq::gk21<M>(g, t0, t1);
    rq::Panel<M> pn{seg, t0, t1, r.value, 0.0, std::fabs(r.value[kC])};
    for (std::size_t c = 0; c < kC; ++c) pn.err = std::max(pn.err, r.err[c]);
    pn.err += std::fabs(r.value[kC + 1]);
    return pn;
  };
  std::vector<std::pair<int, std::pair<double, double>>> init;
  for (const auto& s : outer_pieces) init.push_back({s.first, {0.0, 1.0}});
  return rq::adapt<M>(outer_eval, init, 0.9 * rel_tol, 20000);
}

// The integrand at a point given its position r and its offset u = r - c from the centre of
// rotation (u unused when omega = 0), sigma0 there and the area weight.
struct Kernel {
  double kappa, h, h_y;
  bool spinning;
  double sgn;     // sign of omega
  double ex, ey;  // slip direction when not spinning
  V operator()(double x, double y, double ux, double uy, double s0, double weight) const {
    double dx = ex, dy = ey;
    if (spinning) {
      const double un = std::sqrt(ux * ux + uy * uy);
      if (un == 0.0) return V{};
      dx = -sgn * uy / un;  // v_S = omega z x u
      dy = sgn * ux / un;
    }
    const double sigma = weight * s0 * (1.0 + h * x + h_y * y);
    const double tx = sigma * dx, ty = sigma * kappa * dy;
    return {tx, ty, x * ty - y * tx, sigma, sigma * x, sigma * y};
  }
};

}  // namespace detail

enum class Method {
  Natural,    // ellipse: elliptic-polar about the spot's centre; rect and map: Cartesian
  Cartesian,  // ellipse only: x outer, y inner over |y| <= Q sqrt(1 - x^2) (a cross-check)
};

// The resultants of `spot` under `p` and `m`. rel_tol is relative to ~max(1, kappa) ∫|sigma| dA;
// 1e-12 gives ~1e-12 relative to f N (forces) and f N R (torques).
inline Result spot_reference(const Spot& spot, const Params& p, const Motion& m,
                             double rel_tol = 1e-12, Method method = Method::Natural) {
  using detail::offset;
  using detail::PiecePoint;
  using detail::V;
  constexpr double kPiD = 3.14159265358979323846;
  const double speed = std::hypot(m.v_x, m.v_y);
  const bool spinning = m.omega != 0.0;
  const bool at_rest = speed == 0.0 && !spinning;
  // The centre of rotation in units of R; far away when not spinning (then only the splits use
  // it, and none falls inside the spot).
  const double w = m.omega * m.R;
  const double cx = spinning ? -m.v_y / w : 1e300, cy = spinning ? m.v_x / w : 1e300;
  const detail::Kernel k{p.kappa,
                         p.h,
                         p.h_y,
                         spinning,
                         m.omega > 0.0 ? 1.0 : -1.0,
                         speed > 0.0 ? m.v_x / speed : 1.0,
                         speed > 0.0 ? m.v_y / speed : 0.0};
  const auto& law = spot.law.sigma0;
  std::vector<double> breaks;
  for (double b : spot.law.breaks)
    if (b > 0.0 && b < 1.0) breaks.push_back(b);

  rq::AdaptResult<detail::kC + 2> r;
  if (spot.shape == Shape::Ellipse && method == Method::Natural) {
    const double Q = spot.q;
    // The centre in elliptic-polar coordinates.
    const double cys = cy / Q;
    const double rho_c = spinning ? std::hypot(cx, cys) : 2.0;
    const double t_c = spinning ? std::atan2(cys, cx) : 0.0;
    const double ct = std::cos(t_c), st = std::sin(t_c);
    std::vector<double> edges = {0.0, 1.0};
    if (rho_c > 0.0 && rho_c < 1.0) edges.push_back(rho_c);
    edges.insert(edges.end(), breaks.begin(), breaks.end());
    auto make_line = [&](const PiecePoint& op) {
      const double rho = op.u;
      const double s0 = law(rho, (1.0 - op.b) + op.to_b);
      const double d = offset(op, rho_c);  // rho - rho_c
      const double weight = Q * rho;
      // phi = t - t_c in [-pi, pi]: the direction of r - c jumps at the ends and in the middle.
      auto line = [=, &k](const PiecePoint& ip) -> V {
        const double phi = ip.u;
        const double sh = std::sin(0.5 * phi), ch = std::cos(0.5 * phi);
        const double cphi = 1.0 - 2.0 * sh * sh, sphi = 2.0 * sh * ch;
        const double xs = rho * (ct * cphi - st * sphi);  // t = t_c + phi
        const double ys = rho * (st * cphi + ct * sphi);
        // (r - c) in scaled coordinates, rotated by t_c: (rho cos phi - rho_c, rho sin phi).
        const double ur = d - 2.0 * rho * sh * sh, ut = rho * sphi;
        const double ux = ct * ur - st * ut, uy = Q * (st * ur + ct * ut);
        return k(xs, Q * ys, ux, uy, s0, weight);
      };
      return std::make_pair(std::vector<double>{-kPiD, 0.0, kPiD}, line);
    };
    r = detail::integrate_nested(edges, make_line, rel_tol);
  } else if (spot.shape == Shape::Ellipse) {
    const double Q = spot.q;
    std::vector<double> edges = {-1.0, 0.0, 1.0};
    if (cx > -1.0 && cx < 1.0) edges.push_back(cx);
    for (double b : breaks) {
      edges.push_back(b);
      edges.push_back(-b);
    }
    auto make_line = [&](const PiecePoint& op) {
      const double x = op.u;
      const bool right = op.a >= 0.0;                                                // 0 is an edge
      const double omx = right ? (1.0 - op.b) + op.to_b : (1.0 + op.a) + op.from_a;  // 1 - |x|
      const double Y = Q * std::sqrt(omx * (2.0 - omx));  // Q sqrt(1 - x^2)
      std::vector<double> inner = {-Y, Y};
      if (cy > -Y && cy < Y) inner.push_back(cy);
      for (double b : breaks) {
        const double xb = std::fabs(x);
        if (xb < b) {
          const double yb = Q * std::sqrt((b - xb) * (b + xb));
          inner.push_back(yb);
          inner.push_back(-yb);
        }
      }
      const double dx = offset(op, cx);
      auto line = [=, &k, &law](const PiecePoint& ip) -> V {
        const double y = ip.u;
        // 1 - rho_e^2 = (Y - y)(Y + y)/Q^2, both factors from the piece's ends.
        // Near the centre rho comes from x and y instead (1 - rim cancels there).
        const double ymy = (Y - ip.b) + ip.to_b, ypy = (ip.a + Y) + ip.from_a;
        const double rim = std::max(0.0, ymy * ypy / (Q * Q));
        const double rho =
            rim > 0.5 ? std::hypot(x, y / Q) : std::min(1.0, std::sqrt(std::max(0.0, 1.0 - rim)));
        const double s0 = law(rho, rim / (1.0 + rho));
        return k(x, y, dx, offset(ip, cy), s0, 1.0);
      };
      return std::make_pair(inner, line);
    };
    r = detail::integrate_nested(edges, make_line, rel_tol);
  } else {
    const bool rect = spot.shape == Shape::Rect;
    const Grid& grid = spot.grid;
    const double x0 = rect ? -1.0 : grid.x.front(), x1 = rect ? 1.0 : grid.x.back();
    const double y0 = rect ? -spot.q : grid.y.front(), y1 = rect ? spot.q : grid.y.back();
    std::vector<double> edges = {x0, x1}, inner = {y0, y1};
    if (cx > x0 && cx < x1) edges.push_back(cx);
    if (cy > y0 && cy < y1) inner.push_back(cy);
    if (rect) {
      edges.push_back(0.0);
      for (double b : breaks) {
        edges.push_back(b);
        edges.push_back(-b);
      }
    } else {
      edges.insert(edges.end(), grid.x.begin(), grid.x.end());
      inner.insert(inner.end(), grid.y.begin(), grid.y.end());
    }
    auto make_line = [&](const PiecePoint& op) {
      const double x = op.u;
      const double dx = offset(op, cx);
      double s0 = 0.0;
      if (rect) {
        // |x| and 1 - |x|; 0 is an edge, so a piece lies on one side of it.
        const bool right = op.a >= 0.0;
        const double omx = right ? (1.0 - op.b) + op.to_b : (1.0 + op.a) + op.from_a;
        s0 = law(right ? x : -x, omx);
      }
      auto line = [=, &k, &grid](const PiecePoint& ip) -> V {
        const double y = ip.u;
        return k(x, y, dx, offset(ip, cy), rect ? s0 : grid(x, y), 1.0);
      };
      return std::make_pair(inner, line);
    };
    r = detail::integrate_nested(edges, make_line, rel_tol);
  }

  Result out;
  const double n0 = r.value[3];
  const double force = p.f * m.N / n0, torque = force * m.R;
  if (!at_rest) {
    out.T_x = force * r.value[0];
    out.T_y = force * r.value[1];
    out.M_z = torque * r.value[2];
  }
  out.N = m.N;
  out.M_roll = m.N * m.R * r.value[4] / n0;
  out.M_tilt = m.N * m.R * r.value[5] / n0;
  out.rel_error = r.err / n0;
  return out;
}

}  // namespace frictionid::testing::spot_ref
