// Shared inputs of the contact-spot tests: a seeded uniform generator that does not depend on the
// standard library's distributions, and the pressure laws in two independent descriptions, the
// production PressureLaw and the oracle's RadialLaw (spot_reference.hpp).
#pragma once

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model/spot_model.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "model/spot_reference.hpp"

namespace frictionid::testing::spot_cases {

// Uniform numbers from the raw 64-bit output of std::mt19937_64 (whose sequence the standard
// fixes), mapped by hand: the same cases on every standard library.
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : g_(seed) {}
  double u01() { return static_cast<double>(g_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double in(double a, double b) { return a + (b - a) * u01(); }
  double log_in(double a, double b) { return std::exp(in(std::log(a), std::log(b))); }
  double sign() { return u01() < 0.5 ? -1.0 : 1.0; }
  std::size_t index(std::size_t n) {
    return std::min(n - 1, static_cast<std::size_t>(u01() * static_cast<double>(n)));
  }

 private:
  std::mt19937_64 g_;
};

struct LawCase {
  std::string name;
  spot_ref::RadialLaw ref;
  model::PressureLaw<double> law;
};

// Piecewise linear with kinks at 0.3 and 0.8 and a step up at 0.55. Each run has two samples, so
// the production table's monotone cubic interpolates it as the same straight lines; the last
// value is not 0, so no rim factor is fitted.
inline LawCase kinked_step_table() {
  const std::vector<double> rho = {0.0, 0.3, 0.3, 0.55, 0.55, 0.8, 0.8, 1.0};
  const std::vector<double> sig = {1.0, 0.8, 0.8, 0.5, 1.2, 0.9, 0.9, 0.2};
  return {"table(kinks 0.3, 0.8; step 0.55)", spot_ref::piecewise_linear_law(rho, sig),
          model::PressureLaw<double>::tabulated(
              std::make_shared<const model::PressureTable>(rho, sig))};
}

// A smooth profile times (1 - rho^2)^gamma sampled at `samples` equal steps: its interpolant
// kinks at every sample (gamma > 0: the table fits its own rim exponent).
inline model::PressureLaw<double> sampled_table(int samples, double gamma) {
  std::vector<double> rho, sig;
  for (int i = 0; i < samples; ++i) {
    const double r = i / static_cast<double>(samples - 1);
    rho.push_back(r);
    sig.push_back(std::pow(1.0 - r * r, gamma) * (1.0 + 0.3 * std::sin(7.0 * r)));
  }
  return model::PressureLaw<double>::tabulated(
      std::make_shared<const model::PressureTable>(rho, sig));
}

// A table law's product rule against the cuts at every sample, for one law (case k) and spot of
// aspect q: the largest difference of any channel over the centres, relative to A0, each one
// beyond 1e-12 a failure naming the case. Product, Cuts: integrators of (cx, cy) with
// uses_product_rule().
struct SampledCase {
  int samples;
  double gamma;
};
inline const std::vector<SampledCase>& sampled_cases() {
  static const std::vector<SampledCase> cases = {
      {201, 0.0}, {201, 0.5}, {101, 1.5}, {80, 0.5}, {1001, 0.5}};
  return cases;
}
template <typename Product, typename Cuts>
double product_rule_difference(const Product& product, const Cuts& cuts,
                               const std::vector<std::array<double, 2>>& centres, double A0,
                               const SampledCase& k, double q) {
  const std::string what = std::to_string(k.samples) + " samples, gamma " +
                           std::to_string(k.gamma) + ", q " + std::to_string(q);
  EXPECT_TRUE(product.uses_product_rule()) << what;
  EXPECT_FALSE(cuts.uses_product_rule()) << what;
  double worst = 0.0;
  for (const auto& c : centres) {
    const auto got = product(c[0], c[1]).channels(), want = cuts(c[0], c[1]).channels();
    for (std::size_t j = 0; j < got.size(); ++j) {
      const double e = std::fabs(got[j] - want[j]) / A0;
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-12) << what << ", channel " << j << " at (" << c[0] << ", " << c[1] << ")";
    }
  }
  return worst;
}

inline std::vector<LawCase> law_cases() {
  using L = model::PressureLaw<double>;
  return {{"uniform", spot_ref::uniform_law(), L::uniform()},
          {"hertz", spot_ref::hertz_law(), L::hertz()},
          {"parabolic", spot_ref::parabolic_law(), L::parabolic()},
          {"power:0.3", spot_ref::power_law(0.3), L::power(0.3)},
          {"power:1.7", spot_ref::power_law(1.7), L::power(1.7)},
          {"annulus:0.4", spot_ref::annulus_law(0.4), L::annulus(0.4)},
          {"annulus:0.75", spot_ref::annulus_law(0.75), L::annulus(0.75)},
          kinked_step_table()};
}

inline constexpr double kPi = 3.14159265358979323846;

struct Worst {
  std::string what;
  double err = 0.0;
  void add(double e) { err = std::max(err, e); }
  ~Worst() { std::cout << "[ worst    ] " << what << ": " << err << "\n"; }
};

inline std::string describe(const spot_ref::Spot& s, const std::string& law,
                            const spot_ref::Params& p, const spot_ref::Motion& m) {
  std::ostringstream o;
  o.precision(17);
  o << (s.shape == spot_ref::Shape::Ellipse ? "ellipse"
        : s.shape == spot_ref::Shape::Rect  ? "rect"
                                            : "map")
    << ":" << s.q << " " << law << " f=" << p.f << " kappa=" << p.kappa << " h=" << p.h
    << " h_y=" << p.h_y << " v=(" << m.v_x << "," << m.v_y << ") omega=" << m.omega << " N=" << m.N
    << " R=" << m.R;
  return o.str();
}

// Random friction parameters with 1 + h x + h_y y > 0 on the spot (|h| + |h_y| Q_max < 0.9).
inline spot_ref::Params random_params(Uniform& u, double y_extent) {
  spot_ref::Params p;
  p.f = u.in(0.1, 1.2);
  p.kappa = u.log_in(0.4, 2.5);
  const double budget = 0.9 * u.u01();
  const double share = u.u01();
  p.h = u.sign() * budget * share;
  p.h_y = u.sign() * budget * (1.0 - share) / y_extent;
  return p;
}

// eps = |v|/(|omega| R) log-uniform in [0.05, 6], random slip direction and spin sign; every
// `every`-th case pure spin (v = 0) and the next one pure sliding (omega = 0).
inline spot_ref::Motion random_motion(Uniform& u, int i, int every = 7) {
  spot_ref::Motion m;
  m.N = u.in(1.0, 300.0);
  m.R = u.log_in(0.01, 2.0);
  const double omega = u.sign() * u.log_in(0.2, 5.0);
  const double eps = u.log_in(0.05, 6.0), alpha = u.in(-kPi, kPi);
  const double v = eps * std::fabs(omega) * m.R;
  m.v_x = v * std::cos(alpha);
  m.v_y = v * std::sin(alpha);
  m.omega = omega;
  if (i % every == 0) m.v_x = m.v_y = 0.0;
  if (i % every == 1) m.omega = 0.0;
  return m;
}

// Errors of a against b relative to f N (forces) and f N R (torques), and N R for the moments.
inline double friction_error(const spot_ref::Result& a, const spot_ref::Result& b,
                             const spot_ref::Params& p, const spot_ref::Motion& m) {
  const double F = p.f * m.N, M = F * m.R;
  return std::max(
      {std::fabs(a.T_x - b.T_x) / F, std::fabs(a.T_y - b.T_y) / F, std::fabs(a.M_z - b.M_z) / M});
}
inline double moment_error(const spot_ref::Result& a, const spot_ref::Result& b,
                           const spot_ref::Motion& m) {
  return std::max(std::fabs(a.M_roll - b.M_roll), std::fabs(a.M_tilt - b.M_tilt)) / (m.N * m.R);
}

// Moves the centre of rotation c = (-v_y, v_x)/(omega R) to scale (cos t, q sin t), on the rim
// of the ellipse of aspect q scaled by `scale`; omega is kept (1 where it was 0).
inline void centre_on_ellipse(spot_ref::Motion& m, double q, double t, double scale) {
  const double w = (m.omega != 0.0 ? m.omega : 1.0) * m.R;
  m.omega = w / m.R;
  m.v_x = scale * q * std::sin(t) * w;
  m.v_y = -scale * std::cos(t) * w;
}

// The model on the oracle's ellipse (every row integrated, no table) against the oracle:
// friction_error and moment_error.
struct OracleErrors {
  double friction, moment;
};
inline OracleErrors ellipse_vs_oracle(const spot_ref::Spot& ref,
                                      const model::PressureLaw<double>& law,
                                      const spot_ref::Params& p, const spot_ref::Motion& m) {
  const model::Kinematics k{m.v_x, m.v_y, m.omega, m.N, m.R};
  const model::Resultants<double> r = model::spot_resultants<double>(
      {p.f, p.kappa, p.h, p.h_y, ref.q}, law, model::ContactSpot::ellipse(ref.q), k);
  const spot_ref::Result got{r.T_x, r.T_y, r.M_z, r.M_roll, r.M_tilt, r.N, 0.0};
  const spot_ref::Result want = spot_ref::spot_reference(ref, p, m);
  return {friction_error(got, want, p, m), moment_error(got, want, m)};
}

inline spot_ref::Spot ellipse(double q, const spot_ref::RadialLaw& law) {
  spot_ref::Spot s;
  s.shape = spot_ref::Shape::Ellipse;
  s.q = q;
  s.law = law;
  return s;
}
inline spot_ref::Spot rect(double q, const spot_ref::RadialLaw& law) {
  spot_ref::Spot s = ellipse(q, law);
  s.shape = spot_ref::Shape::Rect;
  return s;
}
// A map on [-1.1, 0.9] x [-0.8, 0.7] with some structure: a bump, a slope, a zero corner.
inline spot_ref::Spot sample_map() {
  spot_ref::Spot s;
  s.shape = spot_ref::Shape::Map;
  s.grid.x = {-1.1, -0.6, -0.05, 0.3, 0.9};
  s.grid.y = {-0.8, -0.2, 0.35, 0.7};
  for (double y : s.grid.y)
    for (double x : s.grid.x)
      s.grid.sigma0.push_back(std::max(0.0, 1.2 - x * x - 1.5 * y * y + 0.3 * x));
  s.grid.sigma0[0] = 0.0;
  return s;
}

// Moments ∫ sigma0 (1 + h x + h_y y) {1, x, y} dA of a map, cell by cell with the 2-point
// Gauss–Legendre rule, exact for the bilinear interpolant times x^2 or y^2.
struct MapMoments {
  double n0, mx, my;
};
inline MapMoments grid_moments(const spot_ref::Grid& g, double h, double h_y) {
  const double d = 0.5 / std::sqrt(3.0), nodes[2] = {0.5 - d, 0.5 + d};
  MapMoments out{0, 0, 0};
  const std::size_t nx = g.x.size();
  for (std::size_t j = 0; j + 1 < g.y.size(); ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const double wx = g.x[i + 1] - g.x[i], wy = g.y[j + 1] - g.y[j];
      for (double tx : nodes)
        for (double ty : nodes) {
          const double s = (1 - tx) * (1 - ty) * g.sigma0[j * nx + i] +
                           tx * (1 - ty) * g.sigma0[j * nx + i + 1] +
                           (1 - tx) * ty * g.sigma0[(j + 1) * nx + i] +
                           tx * ty * g.sigma0[(j + 1) * nx + i + 1];
          const double x = g.x[i] + tx * wx, y = g.y[j] + ty * wy;
          const double w = 0.25 * wx * wy * s * (1.0 + h * x + h_y * y);
          out.n0 += w;
          out.mx += w * x;
          out.my += w * y;
        }
    }
  return out;
}

// Centre of pressure (X_c, Y_c) in units of R from closed-form moments.
inline std::pair<double, double> centre_of_pressure(const spot_ref::Spot& s,
                                                    const spot_ref::Params& p) {
  const double Q = s.q;
  switch (s.shape) {
    case spot_ref::Shape::Ellipse: {
      // N0 = 2 pi Q m1, ∫sigma x = h pi Q m3, ∫sigma y = h_y pi Q^3 m3
      const double r = s.law.moment(3) / (2.0 * s.law.moment(1));
      return {p.h * r, p.h_y * Q * Q * r};
    }
    case spot_ref::Shape::Rect:
      // N0 = 4 Q m0, ∫sigma x = 4 Q h m2, ∫sigma y = 4 m0 h_y Q^3/3
      return {p.h * s.law.moment(2) / s.law.moment(0), p.h_y * Q * Q / 3.0};
    case spot_ref::Shape::Map: {
      const MapMoments mm = grid_moments(s.grid, p.h, p.h_y);
      return {mm.mx / mm.n0, mm.my / mm.n0};
    }
  }
  return {0.0, 0.0};
}

}  // namespace frictionid::testing::spot_cases
