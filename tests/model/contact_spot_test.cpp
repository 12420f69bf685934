// The production spot model (spot_model.hpp) on ellipses, rectangles and pressure maps, against
// the independent 2-D oracle (spot_reference.hpp, itself checked in spot_reference_selftest.cpp)
// and against what holds without it: the circle model at Q = 1, the friction bound, rect = map,
// and pure sliding in closed form. The comparison tests print the worst error they saw.
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/exact_model.hpp>
#include <frictionid/model/spot_model.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace contact_spot_test {
namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;
namespace fm = frictionid::model;

using sc::centre_of_pressure;
using sc::describe;
using sc::friction_error;
using sc::kPi;
using sc::moment_error;
using sc::random_motion;
using sc::random_params;
using sc::Worst;

// One spot in both descriptions: the oracle's and the production model's.
struct Case {
  std::string law_name;
  sr::Spot ref;
  fm::ContactSpot spot;
  fm::PressureLaw<double> law = fm::PressureLaw<double>::uniform();  // ignored for a map
};

Case ellipse_case(double q, const sc::LawCase& lc) {
  return {lc.name, sc::ellipse(q, lc.ref), fm::ContactSpot::ellipse(q), lc.law};
}
Case rect_case(double q, const sc::LawCase& lc) {
  return {lc.name, sc::rect(q, lc.ref), fm::ContactSpot::rect(q), lc.law};
}
Case map_case(const sr::Grid& g, const std::string& name) {
  sr::Spot s;
  s.shape = sr::Shape::Map;
  s.grid = g;
  auto m = std::make_shared<fm::PressureMap>();
  m->x = g.x;
  m->y = g.y;
  m->sigma0 = g.sigma0;
  m->source = name;
  return {name, s, fm::ContactSpot::pressure_map(m)};
}

// A random grid: 3..7 lines along x over about [-1.3, 1.3], 3..6 along y over about [-1.5, 1.5],
// samples in [0, 1.5] with about one in six zero (never all zero).
sr::Grid random_grid(sc::Uniform& u) {
  auto lines = [&u](std::size_t n, double lo, double hi) {
    std::vector<double> w(n - 1);
    double sum = 0.0;
    for (double& x : w) sum += (x = u.in(0.3, 1.0));
    std::vector<double> out = {lo};
    for (std::size_t k = 0; k + 2 < n; ++k) out.push_back(out.back() + (hi - lo) * w[k] / sum);
    out.push_back(hi);
    return out;
  };
  sr::Grid g;
  g.x = lines(3 + u.index(5), -u.in(0.5, 1.3), u.in(0.5, 1.3));
  g.y = lines(3 + u.index(4), -u.in(0.3, 1.5), u.in(0.3, 1.5));
  for (std::size_t k = 0; k < g.x.size() * g.y.size(); ++k)
    g.sigma0.push_back(u.u01() < 1.0 / 6 ? 0.0 : u.in(0.05, 1.5));
  g.sigma0[g.sigma0.size() / 2] = 1.0;
  return g;
}

// Parameters with 1 + h x + h_y y > 0 on the spot: sqrt(h^2 + (h_y Q)^2) < 1 on an ellipse,
// |h| + |h_y| Q < 1 on a rectangle, |h| X + |h_y| Y < 1 on a map spanning |x| <= X, |y| <= Y.
sr::Params params_for(sc::Uniform& u, const Case& c) {
  if (c.ref.shape != sr::Shape::Map) return random_params(u, c.ref.q);
  const sr::Grid& g = c.ref.grid;
  sr::Params p = random_params(u, 1.0);
  p.h /= std::max(-g.x.front(), g.x.back());
  p.h_y /= std::max(-g.y.front(), g.y.back());
  return p;
}

fm::SpotParams<double> production_params(const sr::Params& p, const Case& c) {
  return {p.f, p.kappa, p.h, p.h_y, c.ref.shape == sr::Shape::Map ? 1.0 : c.ref.q};
}

sr::Result production(const Case& c, const sr::Params& p, const sr::Motion& m) {
  const fm::Kinematics k{m.v_x, m.v_y, m.omega, m.N, m.R};
  const fm::Resultants<double> r =
      fm::spot_resultants<double>(production_params(p, c), c.law, c.spot, k);
  return {r.T_x, r.T_y, r.M_z, r.M_roll, r.M_tilt, r.N, 0.0};
}

// Case i of the random sweep: ellipse, rect and map in turn, the laws in turn (with their steps:
// annulus:0.4, annulus:0.75 and a table with a step), Q log-uniform in [0.3, 3].
Case sweep_case(sc::Uniform& u, int i) {
  static const std::vector<sc::LawCase> laws = sc::law_cases();
  const sc::LawCase& lc = laws[static_cast<std::size_t>(i / 3) % laws.size()];
  switch (i % 3) {
    case 0:
      return ellipse_case(u.log_in(0.3, 3.0), lc);
    case 1:
      return rect_case(u.log_in(0.3, 3.0), lc);
    default:
      return map_case(random_grid(u), "random map " + std::to_string(i));
  }
}

// ---------------------------------------------------------------------------------------------

// 240 random cases; eps = |v|/(|omega| R) log-uniform in [0.05, 6], random slip direction and spin
// sign, every tenth case pure spin (v = 0) and every tenth pure sliding (omega = 0).
TEST(ContactSpot, MatchesTheTwoDimensionalOracleOnEllipsesRectanglesAndMapsTo1e9) {
  sc::Uniform u(0x5b07c0de);
  Worst force{"production vs oracle, forces / (f N)"};
  Worst torque{"production vs oracle, M_z / (f N R)"};
  Worst moments{"production vs oracle, M_roll, M_tilt / (N R)"};
  Worst oracle{"oracle's own error estimate / (f N)"};
  double t_oracle = 0.0, t_model = 0.0;
  int n = 0;
  for (int i = 0; i < 240; ++i) {
    const Case c = sweep_case(u, i);
    const sr::Params p = params_for(u, c);
    const sr::Motion m = random_motion(u, i, 10);
    const auto t0 = std::chrono::steady_clock::now();
    const sr::Result ref = sr::spot_reference(c.ref, p, m);
    const auto t1 = std::chrono::steady_clock::now();
    const sr::Result got = production(c, p, m);
    const auto t2 = std::chrono::steady_clock::now();
    t_oracle += std::chrono::duration<double>(t1 - t0).count();
    t_model += std::chrono::duration<double>(t2 - t1).count();
    SCOPED_TRACE("case " + std::to_string(i) + ": " + describe(c.ref, c.law_name, p, m));
    const double F = p.f * m.N, M = F * m.R;
    const double ef = std::max(std::fabs(got.T_x - ref.T_x), std::fabs(got.T_y - ref.T_y)) / F;
    const double et = std::fabs(got.M_z - ref.M_z) / M;
    const double em = moment_error(got, ref, m);
    force.add(ef);
    torque.add(et);
    moments.add(em);
    oracle.add(ref.rel_error);
    EXPECT_LT(ef, 1e-9);
    EXPECT_LT(et, 1e-9);
    EXPECT_LT(em, 1e-9);
    EXPECT_EQ(got.N, m.N);
    EXPECT_LT(ref.rel_error, 1e-11);  // the oracle converged
    ++n;
  }
  EXPECT_EQ(n, 240);
  std::cout << "[ timing   ] " << n << " cases: oracle " << t_oracle << " s, production " << t_model
            << " s\n";
}

// Nearly pure sliding: the centre of rotation eps = v/(|omega| R) = 1e3 to 1e16 spot radii away
// (a rig's spin at the level of its noise, or the towed wheel's slip direction at theta = pi,
// where omega = sin(pi)/R is a rounding error). Every spot kind and law in turn, kappa, h and
// h_y random, the slip direction and spin sign random; the same 1e-9 as the sweep above.
TEST(ContactSpot, NearlyPureSlidingMatchesTheOracleHoweverFarTheCentreOfRotation) {
  sc::Uniform u(0xfa7ce27e);
  Worst force{"far centre: production vs oracle, forces / (f N)"};
  Worst torque{"far centre: production vs oracle, M_z / (f N R)"};
  const double eps_values[] = {1e3, 3e4, 1e6, 1e9, 1e12, 1e16};
  for (int i = 0; i < 36; ++i) {
    const Case c = sweep_case(u, i);
    const sr::Params p = params_for(u, c);
    const double eps = eps_values[(i / 3) % 6];  // every spot kind at every distance
    const double alpha = u.in(0.0, 2.0 * M_PI), v = u.in(0.5, 2.0);
    sr::Motion m;
    m.R = u.in(0.02, 0.2);
    m.N = u.in(100.0, 5000.0);
    m.v_x = v * std::cos(alpha);
    m.v_y = v * std::sin(alpha);
    m.omega = (u.u01() < 0.5 ? -1.0 : 1.0) * v / (eps * m.R);
    const sr::Result ref = sr::spot_reference(c.ref, p, m);
    const sr::Result got = production(c, p, m);
    SCOPED_TRACE("case " + std::to_string(i) + ": " + describe(c.ref, c.law_name, p, m));
    const double F = p.f * m.N, M = F * m.R;
    const double ef = std::max(std::fabs(got.T_x - ref.T_x), std::fabs(got.T_y - ref.T_y)) / F;
    const double et = std::fabs(got.M_z - ref.M_z) / M;
    force.add(ef);
    torque.add(et);
    EXPECT_LT(ef, 1e-9);
    EXPECT_LT(et, 1e-9);
    EXPECT_LT(ref.rel_error, 1e-11);
  }
}

// The ellipse integrator at Q = 1 against the ring-reduced circle model (no h_y there).
TEST(ContactSpot, EllipseWithQ1EqualsTheCircleModelTo1e12) {
  sc::Uniform u(0xc11c1e);
  Worst exact{"ellipse Q=1 vs ExactModel"};
  Worst quad{"ellipse Q=1 vs exact_resultants_by_quadrature"};
  int i = 0;
  for (const sc::LawCase& lc : sc::law_cases()) {
    for (int rep = 0; rep < 8; ++rep, ++i) {
      const Case c = ellipse_case(1.0, lc);
      sr::Params p = random_params(u, 1.0);
      p.h_y = 0.0;
      const sr::Motion m = random_motion(u, i, 8);
      const sr::Result got = production(c, p, m);
      const fm::Kinematics k{m.v_x, m.v_y, m.omega, m.N, m.R};
      const fm::Resultants<double> e = fm::ExactModel<double>({p.f, p.kappa, p.h}, lc.law)(k);
      const fm::Resultants<double> q =
          fm::exact_resultants_by_quadrature<double>({p.f, p.kappa, p.h}, lc.law, k);
      const sr::Result es{e.T_x, e.T_y, e.M_z, e.M_roll, 0.0, e.N, 0.0};
      const sr::Result qs{q.T_x, q.T_y, q.M_z, q.M_roll, 0.0, q.N, 0.0};
      SCOPED_TRACE(describe(c.ref, c.law_name, p, m));
      const double de = std::max(friction_error(got, es, p, m), moment_error(got, es, m));
      const double dq = std::max(friction_error(got, qs, p, m), moment_error(got, qs, m));
      exact.add(de);
      quad.add(dq);
      EXPECT_LT(de, 1e-12);
      EXPECT_LT(dq, 1e-12);
    }
  }
}

TEST(ContactSpot, FrictionForceNeverExceedsFMaxOneKappaTimesN) {
  sc::Uniform u(0xb0b0);
  Worst ratio{"max |T| / (f max(1, kappa) N)"};
  for (int i = 0; i < 300; ++i) {
    const Case c = sweep_case(u, i);
    const sr::Params p = params_for(u, c);
    const sr::Motion m = random_motion(u, i, 10);
    const sr::Result got = production(c, p, m);
    const double bound = p.f * std::max(1.0, p.kappa) * m.N;
    const double r = std::hypot(got.T_x, got.T_y) / bound;
    ratio.add(r);
    SCOPED_TRACE(describe(c.ref, c.law_name, p, m));
    EXPECT_LE(r, 1.0 + 1e-14);
  }
}

TEST(ContactSpot, RectWithUniformLawEqualsTheUniformMapOnTheSameRectangle) {
  sc::Uniform u(0x3ec7a9);
  Worst worst{"rect uniform vs uniform map (production)"};
  const sc::LawCase uniform = sc::law_cases().front();
  for (int i = 0; i < 40; ++i) {
    const double q = u.log_in(0.3, 3.0);
    const Case r = rect_case(q, uniform);
    sr::Grid g;
    g.x = i % 2 ? std::vector<double>{-1.0, 1.0} : std::vector<double>{-1.0, -0.2, 0.45, 1.0};
    g.y = i % 2 ? std::vector<double>{-q, q} : std::vector<double>{-q, 0.3 * q, q};
    g.sigma0.assign(g.x.size() * g.y.size(), i % 4 == 0 ? 2.5 : 1.0);  // any scale
    const Case map = map_case(g, "uniform map");
    const sr::Params p = random_params(u, q);
    const sr::Motion m = random_motion(u, i, 10);
    const sr::Result a = production(r, p, m), b = production(map, p, m);
    SCOPED_TRACE(describe(r.ref, "uniform", p, m));
    const double e = std::max(friction_error(a, b, p, m), moment_error(a, b, m));
    worst.add(e);
    EXPECT_LT(e, 1e-10);
  }
}

// omega = 0: v_S = v everywhere, so T = f N D v/|v| and
// M_z = f ∫sigma (kappa x e_y - y e_x) dA = f N R (kappa X_c e_y - Y_c e_x), e = v/|v|, with the
// centre of pressure (X_c, Y_c) R of the tilted pressure from closed-form moments.
TEST(ContactSpot, PureSlidingGivesFNDTimesTheSlipDirectionAndTheTiltTorque) {
  sc::Uniform u(0x51d1);
  Worst force{"pure sliding, T vs f N D v/|v|"};
  Worst torque{"pure sliding, M_z vs f N R (kappa X_c e_y - Y_c e_x)"};
  std::vector<Case> cases;
  for (const sc::LawCase& lc : sc::law_cases()) {
    cases.push_back(ellipse_case(u.log_in(0.3, 3.0), lc));
    cases.push_back(rect_case(u.log_in(0.3, 3.0), lc));
  }
  for (int i = 0; i < 4; ++i) cases.push_back(map_case(random_grid(u), "random map"));
  for (const Case& c : cases) {
    for (int rep = 0; rep < 3; ++rep) {
      const sr::Params p = params_for(u, c);
      const sr::Motion m = random_motion(u, 1, 10);  // omega = 0
      const double speed = std::hypot(m.v_x, m.v_y), ex = m.v_x / speed, ey = m.v_y / speed;
      const sr::Result got = production(c, p, m);
      const auto [xc, yc] = centre_of_pressure(c.ref, p);
      const double F = p.f * m.N, M = F * m.R;
      SCOPED_TRACE(describe(c.ref, c.law_name, p, m));
      const double ef =
          std::max(std::fabs(got.T_x - F * ex), std::fabs(got.T_y - F * p.kappa * ey)) / F;
      const double et = std::fabs(got.M_z - M * (p.kappa * xc * ey - yc * ex)) / M;
      force.add(ef);
      torque.add(et);
      EXPECT_LT(ef, 1e-13);
      EXPECT_LT(et, 1e-13);
      EXPECT_NEAR(got.M_roll, m.N * m.R * xc, 1e-13 * m.N * m.R);
      EXPECT_NEAR(got.M_tilt, m.N * m.R * yc, 1e-13 * m.N * m.R);
    }
  }
}

}  // namespace
}  // namespace contact_spot_test
