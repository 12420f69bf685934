// Brute-force reference for the dry-friction resultants (test oracle).
//
// Integrates the local Coulomb law of docs/physics.md §1 directly over the contact disk with nested
// adaptive Gauss–Kronrod (G10K21) quadrature: adaptive in rho, and for every rho node an adaptive
// integral over theta. It deliberately uses no elliptic integrals and no ring reduction, so it is
// an independent check of src/model. Only the C++ standard library is used.
//
// Geometry: the instantaneous centre of rotation r_c = (-v_y, v_x)/omega sits at distance
// eps = |v|/|omega| in direction theta*. The radial integral is split at rho = eps (the ring
// integrals have (rho-eps) ln|rho-eps| terms there) and every angular integral starts at theta*,
// so the near-singular point is at the ends of the angular interval, where bisection resolves it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace frictionid::testing {

struct ReferenceResult {
  double T_x, T_y, M_z;
  double abs_error_estimate;  // bound on max(|dT_x|, |dT_y|, |dM_z|) from the GK estimates
};

namespace ref_quad {

template <std::size_t M>
using Vec = std::array<double, M>;

// QUADPACK qk21: Kronrod nodes (Gauss nodes at odd indices), Kronrod and Gauss weights.
inline constexpr double kXgk[11] = {
    0.995657163025808080735527280689003, 0.973906528517171720077964012084452,
    0.930157491355708226001207180059508, 0.865063366688984510732096688423493,
    0.780817726586416897063717578345042, 0.679409568299024406234327365114874,
    0.562757134668604683339000099272694, 0.433395394129247190799265943165784,
    0.294392862701460198131126603103866, 0.148874338981631210884826001129720,
    0.000000000000000000000000000000000};
inline constexpr double kWgk[11] = {
    0.011694638867371874278064396062192, 0.032558162307964727478818972459390,
    0.054755896574351996031381300244580, 0.075039674810919952767043140916190,
    0.093125454583697605535065465083366, 0.109387158802297641899210590325805,
    0.123491976262065851077208376723050, 0.134709217311473325928054001771707,
    0.142775938577060080797094273138717, 0.147739104901338491374841515972068,
    0.149445554002916905664936468389821};
inline constexpr double kWg[5] = {
    0.066671344308688137593568809893332, 0.149451349150580593145776339657697,
    0.219086362515982043995534934228163, 0.269266719309996355091226921569469,
    0.295524224714752870173892994651338};

template <std::size_t M>
struct Gk21Result {
  Vec<M> value{}, abs{}, err{};  // per component: Kronrod value, integral of |f|, error
};

// One G10K21 panel of a vector-valued f on [a, b], with QUADPACK's error heuristic per component.
template <std::size_t M, class F>
Gk21Result<M> gk21(const F& f, double a, double b) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double centre = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  std::array<Vec<M>, 21> fv;
  fv[20] = f(centre);
  for (int j = 0; j < 10; ++j) {
    const double dx = half * kXgk[j];
    fv[2 * j] = f(centre - dx);
    fv[2 * j + 1] = f(centre + dx);
  }
  Gk21Result<M> out;
  for (std::size_t c = 0; c < M; ++c) {
    double resk = kWgk[10] * fv[20][c];
    double resabs = kWgk[10] * std::fabs(fv[20][c]);
    double resg = 0.0;
    for (int j = 0; j < 10; ++j) {
      const double f1 = fv[2 * j][c], f2 = fv[2 * j + 1][c];
      resk += kWgk[j] * (f1 + f2);
      resabs += kWgk[j] * (std::fabs(f1) + std::fabs(f2));
      if (j % 2 == 1) resg += kWg[j / 2] * (f1 + f2);
    }
    const double mean = 0.5 * resk;
    double resasc = kWgk[10] * std::fabs(fv[20][c] - mean);
    for (int j = 0; j < 10; ++j)
      resasc += kWgk[j] * (std::fabs(fv[2 * j][c] - mean) + std::fabs(fv[2 * j + 1][c] - mean));
    const double ah = std::fabs(half);
    resabs *= ah;
    resasc *= ah;
    double err = std::fabs((resk - resg) * half);
    if (resasc != 0.0 && err != 0.0) {
      const double r = 200.0 * err / resasc;
      err = resasc * std::min(1.0, r * std::sqrt(r));
    }
    // Round-off floor: nothing below 50 ulp of the panel's L1 norm is trustworthy.
    err = std::max(50.0 * kEps * resabs, err);
    out.value[c] = resk * half;
    out.abs[c] = resabs;
    out.err[c] = err;
  }
  return out;
}

template <std::size_t M>
struct Panel {
  int seg;
  double a, b;
  Vec<M> value;
  double err;  // error estimate (norm over the components that matter)
  double l1;   // contribution to the scale the tolerance is relative to
};

template <std::size_t M>
struct AdaptResult {
  Vec<M> value{};
  double err = 0.0;
  double l1 = 0.0;
};

// Global adaptive bisection: always split the panel with the largest error until the summed error
// is <= rel_tol * summed l1. eval(seg, a, b) returns a Panel<M>.
template <std::size_t M, class Eval>
AdaptResult<M> adapt(const Eval& eval,
                     const std::vector<std::pair<int, std::pair<double, double>>>& init,
                     double rel_tol, std::size_t max_panels) {
  std::vector<Panel<M>> panels;
  std::vector<std::size_t> heap;  // indices of splittable panels, max-heap on err
  auto less = [&panels](std::size_t i, std::size_t j) { return panels[i].err < panels[j].err; };
  double err_sum = 0.0, l1_sum = 0.0;
  for (const auto& s : init) {
    panels.push_back(eval(s.first, s.second.first, s.second.second));
    err_sum += panels.back().err;
    l1_sum += panels.back().l1;
    heap.push_back(panels.size() - 1);
  }
  std::make_heap(heap.begin(), heap.end(), less);
  auto resum = [&] {
    err_sum = 0.0;
    l1_sum = 0.0;
    for (const auto& p : panels) {
      err_sum += p.err;
      l1_sum += p.l1;
    }
  };
  while (true) {
    if (err_sum <= rel_tol * l1_sum) {
      resum();  // running sums drift; confirm before stopping
      if (err_sum <= rel_tol * l1_sum) break;
    }
    if (heap.empty() || panels.size() >= max_panels) break;
    std::pop_heap(heap.begin(), heap.end(), less);
    const std::size_t i = heap.back();
    heap.pop_back();
    const Panel<M> p = panels[i];
    const double mid = 0.5 * (p.a + p.b);
    if (!(p.a < mid && mid < p.b)) continue;  // cannot bisect further; its error stays counted
    Panel<M> left = eval(p.seg, p.a, mid);
    Panel<M> right = eval(p.seg, mid, p.b);
    err_sum += left.err + right.err - p.err;
    l1_sum += left.l1 + right.l1 - p.l1;
    panels[i] = left;
    heap.push_back(i);
    std::push_heap(heap.begin(), heap.end(), less);
    panels.push_back(right);
    heap.push_back(panels.size() - 1);
    std::push_heap(heap.begin(), heap.end(), less);
  }
  AdaptResult<M> out;
  for (const auto& p : panels) {
    for (std::size_t c = 0; c < M; ++c) out.value[c] += p.value[c];
    out.err += p.err;
    out.l1 += p.l1;
  }
  return out;
}

template <std::size_t N>
struct DiskResult {
  Vec<N> value{};
  double abs_error = 0.0;  // outer GK error (max over components) + integrated inner errors
  double scale = 0.0;      // integral over the disk of max_i |f_i|; rel_tol refers to this
};

// Integral over the unit disk of f(rho, phi) dS, dS = rho drho dphi, phi in [-pi, pi].
// make_ring(rho) returns a callable phi -> Vec<N> (per-rho work, e.g. sigma0, is done once).
// The radial integral is split at rho = eps when 0 < eps < 1; each piece [a, b] is mapped by
// rho = a + (b - a) t^2 (3 - 2 t), which softens endpoint singularities (pressure (1-rho^2)^n at
// rho = 1, the kink at rho = eps) on both ends. The caller chooses phi = 0 at the singular
// direction so the near-singular point of every ring sits at the ends of [-pi, 0] and [0, pi].
template <std::size_t N, class MakeRing>
DiskResult<N> integrate_disk(const MakeRing& make_ring, double eps, double rel_tol,
                             const std::vector<double>& breakpoints = {}) {
  constexpr double kTwoPi = 6.283185307179586476925286766559;
  // Below ~1e-13 the 50-ulp floor per panel makes the tolerance unreachable.
  rel_tol = std::max(rel_tol, 1e-13);
  const double inner_tol = 0.1 * rel_tol;  // inner errors may use 10% of the budget
  // [-pi, 0] and [0, pi]: the singular direction phi = 0 is an end of both pieces, where
  // floating-point resolution in phi is unlimited (unlike at phi = 2 pi).
  const std::vector<std::pair<int, std::pair<double, double>>> inner_init = {
      {0, {-0.5 * kTwoPi, 0.0}}, {0, {0.0, 0.5 * kTwoPi}}};

  // Also split at the pressure law's breakpoints (steps, kinks): a Gauss rule across a jump
  // converges only algebraically however far the bisection goes.
  std::vector<double> edges = {0.0, 1.0};
  if (eps > 0.0 && eps < 1.0) edges.push_back(eps);
  for (double b : breakpoints)
    if (b > 0.0 && b < 1.0) edges.push_back(b);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<std::pair<double, double>> segs;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) segs.push_back({edges[i], edges[i + 1]});

  // Outer integrand in t: N values, then the rings' L1 scale and their error estimates.
  constexpr std::size_t M = N + 2;
  auto outer_eval = [&](int seg, double t0, double t1) {
    const double a = segs[seg].first, b = segs[seg].second;
    auto g = [&](double t) {
      // min: rounding must not push rho past b (pressure laws may be undefined beyond rho = 1)
      const double rho = std::min(b, a + (b - a) * (t * t * (3.0 - 2.0 * t)));
      const double w = rho * (b - a) * 6.0 * t * (1.0 - t);  // rho * drho/dt
      Vec<M> out{};
      if (w == 0.0) return out;
      const auto ring = make_ring(rho);
      auto inner_eval = [&](int s, double p0, double p1) {
        const Gk21Result<N> r = gk21<N>(ring, p0, p1);
        Panel<N> p{s, p0, p1, r.value, 0.0, 0.0};
        for (std::size_t c = 0; c < N; ++c) {
          p.err = std::max(p.err, r.err[c]);
          p.l1 = std::max(p.l1, r.abs[c]);
        }
        return p;
      };
      const AdaptResult<N> in = adapt<N>(inner_eval, inner_init, inner_tol, 2000);
      for (std::size_t c = 0; c < N; ++c) out[c] = w * in.value[c];
      out[N] = w * in.l1;
      out[N + 1] = w * in.err;
      return out;
    };
    const Gk21Result<M> r = gk21<M>(g, t0, t1);
    Panel<M> p{seg, t0, t1, r.value, 0.0, std::fabs(r.value[N])};
    for (std::size_t c = 0; c < N; ++c) p.err = std::max(p.err, r.err[c]);
    p.err += std::fabs(r.value[N + 1]);
    return p;
  };

  std::vector<std::pair<int, std::pair<double, double>>> outer_init;
  for (int s = 0; s < static_cast<int>(segs.size()); ++s) {
    outer_init.push_back({s, {0.0, 0.5}});
    outer_init.push_back({s, {0.5, 1.0}});
  }
  const AdaptResult<M> res = adapt<M>(outer_eval, outer_init, 0.9 * rel_tol, 4000);
  DiskResult<N> out;
  for (std::size_t c = 0; c < N; ++c) out.value[c] = res.value[c];
  out.abs_error = res.err;
  out.scale = res.l1;
  return out;
}

// Position of the instantaneous centre: distance eps and direction theta* (omega != 0).
struct SingularPoint {
  double eps;
  double theta_star;
};

inline SingularPoint singular_point(double v_x, double v_y, double omega) {
  if (omega == 0.0) return {std::numeric_limits<double>::infinity(), 0.0};
  const double cx = -v_y / omega, cy = v_x / omega;
  return {std::hypot(cx, cy), std::atan2(cy, cx)};
}

}  // namespace ref_quad

// Resistance resultants (docs/physics.md §1 sign convention) for R = 1, c = 1, f = 1:
//   sigma = sigma0(rho) (1 + h rho cos theta), v_Sigma = (v_x - omega y, v_y + omega x),
//   T = ∫ sigma D v_Sigma/|v_Sigma| dS, M_z = ∫ sigma (r x D v_Sigma/|v_Sigma|)_z dS, D = diag(1,
//   kappa).
// rel_tol is relative to ∫ max(|integrand components|) dS (~ max(1, kappa) (1 + |h|) N0);
// values below 1e-13 are clamped. breakpoints: the rho where sigma0 or its derivative jumps.
// rim_only: sigma0 is a delta on rho = 1 (the ring law), so only the ring rho = 1 is integrated,
// with weight sigma0(1).
inline ReferenceResult reference_resultants(const std::function<double(double)>& sigma0,
                                            double kappa, double h, double v_x, double v_y,
                                            double omega, double rel_tol = 1e-12,
                                            const std::vector<double>& breakpoints = {},
                                            bool rim_only = false) {
  const double speed = std::hypot(v_x, v_y);
  if (speed == 0.0 && omega == 0.0) return {0.0, 0.0, 0.0, 0.0};
  const ref_quad::SingularPoint sp = ref_quad::singular_point(v_x, v_y, omega);
  const double cs = std::cos(sp.theta_star), ss = std::sin(sp.theta_star);
  const double sgn = omega > 0.0 ? 1.0 : -1.0;
  const double ex0 = v_x / speed, ey0 = v_y / speed;  // only used when omega == 0

  auto make_ring = [&](double rho) {
    const double s0 = sigma0(rho);
    const double d = rho - sp.eps;  // exact near the singular ring (Sterbenz)
    return [=](double phi) -> ref_quad::Vec<3> {
      const double sh = std::sin(0.5 * phi), ch = std::cos(0.5 * phi);
      const double cphi = 1.0 - 2.0 * sh * sh, sphi = 2.0 * sh * ch;
      const double x = rho * (cs * cphi - ss * sphi);  // theta = theta* + phi
      const double y = rho * (ss * cphi + cs * sphi);
      double ex = ex0, ey = ey0;
      if (omega != 0.0) {
        // u = r - r_c in the frame rotated by theta*; rho cos(phi) - eps written without
        // cancellation near the instantaneous centre.
        const double ur = d - 2.0 * rho * sh * sh;
        const double ut = rho * sphi;
        const double ux = cs * ur - ss * ut, uy = ss * ur + cs * ut;
        const double un = std::sqrt(ux * ux + uy * uy);
        if (un == 0.0) return {0.0, 0.0, 0.0};
        ex = -sgn * uy / un;  // v_Sigma = omega e3 x u
        ey = sgn * ux / un;
      }
      const double sigma = s0 * (1.0 + h * x);
      const double dx = sigma * ex, dy = sigma * kappa * ey;
      return {dx, dy, x * dy - y * dx};
    };
  };

  if (rim_only) {
    const auto ring = make_ring(1.0);
    auto eval = [&](int seg, double p0, double p1) {
      const ref_quad::Gk21Result<3> g = ref_quad::gk21<3>(ring, p0, p1);
      ref_quad::Panel<3> p{seg, p0, p1, g.value, 0.0, 0.0};
      for (std::size_t c = 0; c < 3; ++c) {
        p.err = std::max(p.err, g.err[c]);
        p.l1 = std::max(p.l1, g.abs[c]);
      }
      return p;
    };
    const double pi = 3.141592653589793238462643383279502884;
    const auto r = ref_quad::adapt<3>(eval, {{0, {-pi, 0.0}}, {0, {0.0, pi}}},
                                      std::max(rel_tol, 1e-13), 20000);
    return {r.value[0], r.value[1], r.value[2], r.err};
  }
  const auto r =
      ref_quad::integrate_disk<3>(make_ring, omega == 0.0 ? 2.0 : sp.eps, rel_tol, breakpoints);
  return {r.value[0], r.value[1], r.value[2], r.abs_error};
}

}  // namespace frictionid::testing
