// Self-test of the contact-spot oracle (spot_reference.hpp) against what is known without it: the
// circle model of src/model for Q = 1, a second parametrisation of the ellipse, closed forms for
// pure sliding, the load moments, pure spin on an ellipse, and a uniform rectangle at any centre of
// rotation. Each test prints the worst error it saw, relative to f N (forces, M_z / R) or N
// (M_roll / R, M_tilt / R).
#include <frictionid/model/exact_model.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace spot_reference_selftest {
namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;
namespace fm = frictionid::model;

using sc::centre_of_pressure;
using sc::describe;
using sc::ellipse;
using sc::friction_error;
using sc::kPi;
using sc::moment_error;
using sc::random_motion;
using sc::random_params;
using sc::rect;
using sc::sample_map;
using sc::Worst;

// ---------------------------------------------------------------------------------------------

TEST(SpotReference, EllipseWithQ1MatchesTheCircleModel) {
  sc::Uniform u(0x0c1c1e);
  Worst worst{"ellipse Q=1 vs exact_resultants_by_quadrature"};
  int i = 0;
  for (const sc::LawCase& lc : sc::law_cases()) {
    for (int rep = 0; rep < 6; ++rep, ++i) {
      sr::Params p = random_params(u, 1.0);
      p.h_y = 0.0;
      const sr::Motion m = random_motion(u, i, 5);
      const sr::Spot s = ellipse(1.0, lc.ref);
      const sr::Result ref = sr::spot_reference(s, p, m);
      const fm::Kinematics k{m.v_x, m.v_y, m.omega, m.N, m.R};
      const auto c = fm::exact_resultants_by_quadrature<double>({p.f, p.kappa, p.h}, lc.law, k);
      const sr::Result circle{c.T_x, c.T_y, c.M_z, c.M_roll, 0.0, c.N, 0.0};
      SCOPED_TRACE(describe(s, lc.name, p, m));
      const double e = friction_error(ref, circle, p, m);
      const double em = moment_error(ref, circle, m);
      worst.add(std::max(e, em));
      EXPECT_LT(e, 1e-10);
      EXPECT_LT(em, 1e-12);
      EXPECT_LT(ref.rel_error, 1e-11);
    }
  }
}

TEST(SpotReference, CartesianAndEllipticPolarParametrisationsAgreeOnEllipses) {
  sc::Uniform u(0xe111a5);
  Worst worst{"ellipse elliptic-polar vs Cartesian"};
  int i = 0;
  for (const sc::LawCase& lc : sc::law_cases()) {
    for (int rep = 0; rep < 3; ++rep, ++i) {
      const double q = u.log_in(0.3, 3.0);
      const sr::Params p = random_params(u, q);
      const sr::Motion m = random_motion(u, i, 6);
      const sr::Spot s = ellipse(q, lc.ref);
      const sr::Result a = sr::spot_reference(s, p, m);
      const sr::Result b = sr::spot_reference(s, p, m, 1e-12, sr::Method::Cartesian);
      SCOPED_TRACE(describe(s, lc.name, p, m));
      const double e = std::max(friction_error(a, b, p, m), moment_error(a, b, m));
      worst.add(e);
      EXPECT_LT(e, 1e-11);
    }
  }
}

TEST(SpotReference, PureSlidingGivesFNDTimesTheSlipDirectionAndTheTiltTorque) {
  sc::Uniform u(0x511de);
  Worst worst{"pure sliding vs f N D v/|v|, M_z = f (kappa e_y M_roll - e_x M_tilt)"};
  std::vector<std::pair<sr::Spot, std::string>> spots;
  for (const sc::LawCase& lc : sc::law_cases()) {
    spots.push_back({ellipse(u.log_in(0.3, 3.0), lc.ref), lc.name});
    spots.push_back({rect(u.log_in(0.3, 3.0), lc.ref), lc.name});
  }
  spots.push_back({sample_map(), "map"});
  for (const auto& [s, name] : spots) {
    const sr::Params p = random_params(u, s.shape == sr::Shape::Map ? 1.0 : s.q);
    sr::Motion m = random_motion(u, 1, 5);  // omega = 0
    const double speed = std::hypot(m.v_x, m.v_y), ex = m.v_x / speed, ey = m.v_y / speed;
    const sr::Result r = sr::spot_reference(s, p, m);
    const auto [xc, yc] = centre_of_pressure(s, p);
    const double F = p.f * m.N;
    const double mz = F * m.R * (p.kappa * ey * xc - ex * yc);
    SCOPED_TRACE(describe(s, name, p, m));
    const sr::Result expected{F * ex, F * p.kappa * ey, mz, 0, 0, m.N, 0};
    const double e = friction_error(r, expected, p, m);
    worst.add(e);
    EXPECT_LT(e, 1e-13);
  }
}

TEST(SpotReference, MRollAndMTiltEqualTheClosedFormLoadMoments) {
  sc::Uniform u(0x303e);
  Worst worst{"M_roll, M_tilt vs closed-form moments"};
  std::vector<std::pair<sr::Spot, std::string>> spots;
  for (const sc::LawCase& lc : sc::law_cases()) {
    spots.push_back({ellipse(u.log_in(0.3, 3.0), lc.ref), lc.name});
    spots.push_back({rect(u.log_in(0.3, 3.0), lc.ref), lc.name});
  }
  spots.push_back({sample_map(), "map"});
  int i = 0;
  for (const auto& [s, name] : spots) {
    const sr::Params p = random_params(u, s.shape == sr::Shape::Map ? 1.0 : s.q);
    const sr::Motion m = random_motion(u, i++, 4);
    const sr::Result r = sr::spot_reference(s, p, m);
    const auto [xc, yc] = centre_of_pressure(s, p);
    SCOPED_TRACE(describe(s, name, p, m));
    const sr::Result expected{0, 0, 0, m.N * m.R * xc, m.N * m.R * yc, m.N, 0};
    const double e = moment_error(r, expected, m);
    worst.add(e);
    EXPECT_LT(e, 1e-13);
    EXPECT_EQ(r.N, m.N);
  }
}

// The hardest geometry for the elliptic-polar rule: the centre of rotation on or within 1e-8 of
// the rim, where the rim singularity of Hertz meets the jump of the slip direction.
TEST(SpotReference, ParametrisationsAgreeWhenTheCentreOfRotationSitsOnTheRim) {
  Worst worst{"ellipse elliptic-polar vs Cartesian, centre on the rim"};
  const std::vector<sc::LawCase> all = sc::law_cases();
  for (const sc::LawCase& lc : {all[1], all[6], all[7]}) {  // hertz, annulus:0.75, table
    for (double q : {0.3, 2.7}) {
      for (double d : {0.0, 1e-8, -1e-8, -1e-4}) {
        for (double angle : {0.3, 1.5707963267948966}) {
          // c = (-v_y, v_x)/omega at elliptic radius 1 + d
          const double cx = (1 + d) * std::cos(angle), cy = q * (1 + d) * std::sin(angle);
          const double omega = 1.3;
          const sr::Motion m{cy * omega, -cx * omega, omega, 1.0, 1.0};
          const sr::Params p{1.0, 1.7, 0.3, 0.2 / q};
          const sr::Spot s = ellipse(q, lc.ref);
          const sr::Result a = sr::spot_reference(s, p, m);
          const sr::Result b = sr::spot_reference(s, p, m, 1e-12, sr::Method::Cartesian);
          SCOPED_TRACE(describe(s, lc.name, p, m));
          const double e = friction_error(a, b, p, m);
          worst.add(e);
          EXPECT_LT(e, 1e-11);
          EXPECT_LT(a.rel_error, 1e-11);
        }
      }
    }
  }
}

TEST(SpotReference, RectWithUniformLawEqualsTheUniformMapOnTheSameRectangle) {
  sc::Uniform u(0x3ec7);
  Worst worst{"rect uniform vs uniform map"};
  for (int i = 0; i < 12; ++i) {
    const double q = u.log_in(0.3, 3.0);
    const sr::Params p = random_params(u, q);
    const sr::Motion m = random_motion(u, i, 6);
    const sr::Spot r = rect(q, sr::uniform_law());
    sr::Spot map;
    map.shape = sr::Shape::Map;
    map.grid.x = {-1.0, -0.35, 0.2, 1.0};
    map.grid.y = {-q, -0.1 * q, 0.6 * q, q};
    map.grid.sigma0.assign(16, 1.0);
    const sr::Result a = sr::spot_reference(r, p, m), b = sr::spot_reference(map, p, m);
    SCOPED_TRACE(describe(r, "uniform", p, m));
    const double e = std::max(friction_error(a, b, p, m), moment_error(a, b, m));
    worst.add(e);
    EXPECT_LT(e, 1e-11);
  }
}

// sigma0 = law(|x|) with a continuous piecewise-linear law is bilinear on a grid through its kinks
// (and x = 0): the rect then equals that map, law, spin, tilt and all.
TEST(SpotReference, RectWithAKinkedLinearLawEqualsTheMapThroughItsKinks) {
  sc::Uniform u(0x3ec8);
  Worst worst{"rect kinked linear law vs map"};
  const std::vector<double> rho = {0.0, 0.3, 0.3, 0.7, 0.7, 1.0};
  const std::vector<double> sig = {1.0, 0.8, 0.8, 0.3, 0.3, 0.6};
  const sr::RadialLaw law = sr::piecewise_linear_law(rho, sig);
  for (int i = 0; i < 10; ++i) {
    const double q = u.log_in(0.3, 3.0);
    const sr::Params p = random_params(u, q);
    const sr::Motion m = random_motion(u, i, 5);
    const sr::Spot r = rect(q, law);
    sr::Spot map;
    map.shape = sr::Shape::Map;
    map.grid.x = {-1.0, -0.7, -0.3, 0.0, 0.3, 0.7, 1.0};
    map.grid.y = {-q, q};
    for (int j = 0; j < 2; ++j)
      for (double x : map.grid.x)
        map.grid.sigma0.push_back(law.sigma0(std::fabs(x), 1.0 - std::fabs(x)));
    const sr::Result a = sr::spot_reference(r, p, m), b = sr::spot_reference(map, p, m);
    SCOPED_TRACE(describe(r, law.name, p, m));
    const double e = std::max(friction_error(a, b, p, m), moment_error(a, b, m));
    worst.add(e);
    EXPECT_LT(e, 1e-11);
  }
}

// ∫_0^b sqrt(a^2 + s^2) ds, odd in b.
double H(double a, double b) {
  if (a == 0.0) return 0.5 * b * std::fabs(b);
  return 0.5 * (b * std::hypot(a, b) + a * a * std::asinh(b / std::fabs(a)));
}
// ∫_0^a ∫_0^b sqrt(x^2 + y^2) dy dx, odd in a and in b.
double F(double a, double b) {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double x = std::fabs(a), y = std::fabs(b), d = std::hypot(x, y);
  const double v =
      (2 * x * y * d + x * x * x * std::asinh(y / x) + y * y * y * std::asinh(x / y)) / 6;
  return (a > 0) == (b > 0) ? v : -v;
}

// Uniform pressure, no tilt: with u = r - c, ∫u_x/|u| dA and ∫|u| dA over a rectangle are sums of
// corner terms, so T (any kappa) and M_z (kappa = 1) are known for any centre of rotation c.
TEST(SpotReference, UniformRectangleMatchesTheClosedFormAtAnyCentreOfRotation) {
  sc::Uniform u(0xc105ed);
  Worst worst{"uniform rect vs corner-sum closed form"};
  // Random centres, then centres on a corner, on an edge, and 1e-9 inside or outside a corner
  // (in units of the half-sides).
  const std::vector<std::pair<double, double>> fixed = {
      {1.0, 1.0},   {-1.0, 1.0},          {1.0, 0.3},
      {-0.4, -1.0}, {1 + 1e-9, 1 + 1e-9}, {1 - 1e-9, -1 + 1e-9}};
  for (int i = 0; i < 16 + static_cast<int>(fixed.size()); ++i) {
    const double q = u.log_in(0.3, 3.0);
    sr::Params p{u.in(0.1, 1.2), i % 2 == 0 ? 1.0 : u.log_in(0.4, 2.5), 0.0, 0.0};
    sr::Motion m = random_motion(u, i + 2, 100);  // spinning
    if (i == 3) m.v_x = m.v_y = 0.0;
    if (i >= 16) {  // c = (-v_y, v_x)/(omega R)
      const auto [fx, fy] = fixed[static_cast<std::size_t>(i - 16)];
      m.v_x = fy * q * m.omega * m.R;
      m.v_y = -fx * m.omega * m.R;
    }
    const double w = m.omega * m.R, cx = -m.v_y / w, cy = m.v_x / w;
    const double a0 = -1.0 - cx, a1 = 1.0 - cx, b0 = -q - cy, b1 = q - cy;
    const double Ix = H(a1, b1) - H(a1, b0) - H(a0, b1) + H(a0, b0);
    const double Iy = H(b1, a1) - H(b1, a0) - H(b0, a1) + H(b0, a0);
    const double J = F(a1, b1) - F(a1, b0) - F(a0, b1) + F(a0, b0);
    const double sgn = m.omega > 0 ? 1.0 : -1.0, c = p.f * m.N / (4.0 * q);
    const sr::Spot s = rect(q, sr::uniform_law());
    const sr::Result r = sr::spot_reference(s, p, m);
    SCOPED_TRACE(describe(s, "uniform", p, m));
    const double F0 = p.f * m.N;
    double e = std::max(std::fabs(r.T_x + c * sgn * Iy), std::fabs(r.T_y - c * sgn * p.kappa * Ix));
    if (p.kappa == 1.0)
      e = std::max(e, std::fabs(r.M_z - c * m.R * sgn * (J + cx * Ix + cy * Iy)) / m.R);
    worst.add(e / F0);
    EXPECT_LT(e / F0, 1e-12);
  }
}

// Pure spin about the centre of an ellipse: with x = rho cos t, y = Q rho sin t and
// g(t) = sqrt(cos^2 t + Q^2 sin^2 t), c = N/(2 pi Q m1),
//   T_x = -s f c h_y Q^3 m2 ∫sin^2/g,  T_y = s f c kappa h Q m2 ∫cos^2/g,
//   M_z = s f c Q m2 R ∫(kappa cos^2 + Q^2 sin^2)/g   (t over a period; trapezoid rule).
TEST(SpotReference, PureSpinOnAnEllipseMatchesOneDimensionalIntegrals) {
  sc::Uniform u(0x5915);
  Worst worst{"pure spin on an ellipse vs 1-D integrals"};
  for (const sc::LawCase& lc : sc::law_cases()) {
    for (double q : {0.35, 1.0, 2.2}) {
      const sr::Params p = random_params(u, q);
      sr::Motion m = random_motion(u, 0, 7);  // v = 0
      const int n = 1024;
      double A1 = 0, A2 = 0, A3 = 0;
      for (int j = 0; j < n; ++j) {
        const double t = 2 * kPi * j / n, cs = std::cos(t), sn = std::sin(t);
        const double g = std::sqrt(cs * cs + q * q * sn * sn);
        A1 += sn * sn / g;
        A2 += cs * cs / g;
        A3 += (p.kappa * cs * cs + q * q * sn * sn) / g;
      }
      A1 *= 2 * kPi / n;
      A2 *= 2 * kPi / n;
      A3 *= 2 * kPi / n;
      const double m1 = lc.ref.moment(1), m2 = lc.ref.moment(2);
      const double s = m.omega > 0 ? 1.0 : -1.0, c = p.f * m.N / (2 * kPi * q * m1);
      const sr::Result expected{-s * c * p.h_y * q * q * q * m2 * A1,
                                s * c * p.kappa * p.h * q * m2 * A2,
                                s * c * q * m2 * A3 * m.R,
                                0,
                                0,
                                m.N,
                                0};
      const sr::Spot sp = ellipse(q, lc.ref);
      const sr::Result r = sr::spot_reference(sp, p, m);
      SCOPED_TRACE(describe(sp, lc.name, p, m));
      const double e = friction_error(r, expected, p, m);
      worst.add(e);
      EXPECT_LT(e, 1e-12);
    }
  }
}

TEST(SpotReference, AtRestThereIsNoFrictionButTheLoadMomentsRemain) {
  const sr::Params p{0.5, 1.3, 0.2, -0.1};
  const sr::Motion m{0.0, 0.0, 0.0, 10.0, 0.5};
  for (const sr::Spot& s :
       {ellipse(0.7, sr::hertz_law()), rect(1.4, sr::annulus_law(0.3)), sample_map()}) {
    const sr::Result r = sr::spot_reference(s, p, m);
    const auto [xc, yc] = centre_of_pressure(s, p);
    EXPECT_EQ(r.T_x, 0.0);
    EXPECT_EQ(r.T_y, 0.0);
    EXPECT_EQ(r.M_z, 0.0);
    EXPECT_NEAR(r.M_roll, m.N * m.R * xc, 1e-13 * m.N * m.R);
    EXPECT_NEAR(r.M_tilt, m.N * m.R * yc, 1e-13 * m.N * m.R);
  }
}

}  // namespace
}  // namespace spot_reference_selftest
