// Self-test of the brute-force reference integrator against results known without the ring
// reduction: exact pure-sliding / pure-spin resultants, closed forms of docs/physics.md §2
// (evaluated in long double, where they are well conditioned), large-eps series, and the power
// balance of §5.
#include "model/reference_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace reference_integrator_selftest {
namespace {

using frictionid::testing::reference_resultants;
using frictionid::testing::ReferenceResult;
namespace rq = frictionid::testing::ref_quad;

constexpr double kPi = 3.14159265358979323846;
constexpr long double kPiL = 3.14159265358979323846264338327950288L;
constexpr double kTol = 1e-12;  // relative to N0 = ∫sigma0 dS

// Power law sigma0 = (1 - rho^2)^n: uniform n = 0, Hertz n = 0.5, parabolic n = 1.
struct Law {
  std::string name;
  double n;
  std::function<double(double)> sigma0() const {
    const double e = n;
    return [e](double rho) { return std::pow(std::max(0.0, 1.0 - rho * rho), e); };
  }
  // m_k = ∫_0^1 sigma0 rho^k drho = B((k+1)/2, n+1) / 2
  double moment(int k) const { return 0.5 * std::beta(0.5 * (k + 1), n + 1.0); }
  double n0() const { return 2.0 * kPi * moment(1); }
};

const std::vector<Law>& laws() {
  static const std::vector<Law> l = {{"uniform", 0.0}, {"hertz", 0.5}, {"power0.1", 0.1}};
  return l;
}

// (1) Pure sliding: T = N0 D v/|v|, M_z = h kappa pi m3 sin(alpha).
TEST(ReferenceIntegrator, PureSlidingIsExact) {
  for (const Law& law : laws()) {
    const double n0 = law.n0(), m3 = law.moment(3);
    for (double kappa : {1.0, 0.6, 1.8}) {
      for (double h : {0.0, 0.35, -0.2}) {
        for (double alpha : {0.0, 0.7, 2.5, -1.9}) {
          const double speed = 2.3;
          const ReferenceResult r = reference_resultants(
              law.sigma0(), kappa, h, speed * std::cos(alpha), speed * std::sin(alpha), 0.0);
          SCOPED_TRACE(law.name + " kappa=" + std::to_string(kappa) + " h=" + std::to_string(h) +
                       " alpha=" + std::to_string(alpha));
          EXPECT_NEAR(r.T_x, n0 * std::cos(alpha), kTol * n0);
          EXPECT_NEAR(r.T_y, n0 * kappa * std::sin(alpha), kTol * n0);
          EXPECT_NEAR(r.M_z, h * kappa * kPi * m3 * std::sin(alpha), kTol * n0);
        }
      }
    }
  }
}

// (2) Pure spin: e = sgn(omega) e_theta, so T_x = 0, T_y = sgn kappa h pi m2,
// M_z = sgn pi (1 + kappa) m2 (= 2 pi m2 for kappa = 1).
TEST(ReferenceIntegrator, PureSpin) {
  for (const Law& law : laws()) {
    const double n0 = law.n0(), m2 = law.moment(2);
    {
      const ReferenceResult r = reference_resultants(law.sigma0(), 1.0, 0.0, 0.0, 0.0, 1.3);
      SCOPED_TRACE(law.name + " isotropic");
      EXPECT_NEAR(r.T_x, 0.0, kTol * n0);
      EXPECT_NEAR(r.T_y, 0.0, kTol * n0);
      EXPECT_NEAR(r.M_z, 2.0 * kPi * m2, kTol * n0);
    }
    for (double kappa : {0.6, 1.0, 1.8}) {
      for (double h : {0.4, -0.25}) {
        for (double omega : {1.5, -0.7}) {
          const double s = omega > 0 ? 1.0 : -1.0;
          const ReferenceResult r = reference_resultants(law.sigma0(), kappa, h, 0.0, 0.0, omega);
          SCOPED_TRACE(law.name + " kappa=" + std::to_string(kappa) + " h=" + std::to_string(h) +
                       " omega=" + std::to_string(omega));
          EXPECT_NEAR(r.T_x, 0.0, kTol * n0);
          EXPECT_NEAR(r.T_y, s * kappa * h * kPi * m2, kTol * n0);
          EXPECT_NEAR(r.M_z, s * kPi * (1.0 + kappa) * m2, kTol * n0);
        }
      }
    }
  }
}

TEST(ReferenceIntegrator, NoMotionGivesZeros) {
  const ReferenceResult r = reference_resultants([](double) { return 1.0; }, 1.3, 0.2, 0, 0, 0);
  EXPECT_EQ(r.T_x, 0.0);
  EXPECT_EQ(r.T_y, 0.0);
  EXPECT_EQ(r.M_z, 0.0);
  EXPECT_EQ(r.abs_error_estimate, 0.0);
}

// eps values covering centre inside / on / just off / outside the rim, including exact rings.
const std::vector<double> kEps = {1e-3, 0.1, 0.5, 0.9, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.1, 2.0, 10.0};

// (3) Uniform pressure, kappa = 1, h = 0, v along +x, omega = 1: T_x / pi = t(eps).
long double uniform_t(long double e) {
  if (e == 1.0L) return 8.0L / (3.0L * kPiL);  // (1 - e^2) K -> 0, E(1) = 1
  if (e < 1.0L) {
    const long double K = std::comp_ellint_1l(e), E = std::comp_ellint_2l(e);
    return 4.0L / (3.0L * kPiL * e) * ((1 + e * e) * E - (1 - e) * (1 + e) * K);
  }
  const long double K = std::comp_ellint_1l(1 / e), E = std::comp_ellint_2l(1 / e);
  return 4.0L / (3.0L * kPiL) * ((e * e + 1) * E - (e - 1) * (e + 1) * K);
}

long double uniform_mhat(long double e) {
  if (e == 1.0L) return 4.0L / (3.0L * kPiL);
  if (e < 1.0L) {
    const long double K = std::comp_ellint_1l(e), E = std::comp_ellint_2l(e);
    return 2.0L / (3.0L * kPiL) * ((4 - 2 * e * e) * E - (1 - e) * (1 + e) * K);
  }
  const long double K = std::comp_ellint_1l(1 / e), E = std::comp_ellint_2l(1 / e);
  return 1.0L / (6.0L * kPiL * e) *
         ((16 * e * e - 8 * e * e * e * e) * E + (e - 1) * (e + 1) * (8 * e * e - 12) * K);
}

TEST(ReferenceIntegrator, UniformClosedForm) {
  const auto uniform = [](double) { return 1.0; };
  std::vector<double> eps = kEps;
  eps.push_back(1e3);  // t is still well conditioned there in long double
  for (double e : eps) {
    const ReferenceResult r = reference_resultants(uniform, 1.0, 0.0, e, 0.0, 1.0);
    SCOPED_TRACE("eps=" + std::to_string(e));
    const double t = static_cast<double>(uniform_t(e));
    EXPECT_NEAR(r.T_x / kPi, t, kTol);
    EXPECT_NEAR(r.T_y, 0.0, kTol * kPi);
    if (e <= 10.0) {  // m-hat's closed form cancels catastrophically for large eps
      // M0 = pi (1 + kappa) m2 = 2 pi / 3
      EXPECT_NEAR(r.M_z, 2.0 * kPi / 3.0 * static_cast<double>(uniform_mhat(e)), kTol * kPi);
    }
    EXPECT_LE(std::fabs(r.T_x - kPi * t), r.abs_error_estimate + 1e-15 * kPi);
  }
}

// Hertz closed forms (docs/physics.md §2) with kappa != 1 and tilt: T_x = F0 t, T_y = h kappa F0 p,
// M_z = M0 [2 mhat + (kappa - 1)(2 m1/m2) p] / (1 + kappa); F0 = 2 pi/3, m1 = 1/3, m2 = pi/16.
TEST(ReferenceIntegrator, HertzClosedForms) {
  const Law hertz{"hertz", 0.5};
  const double kappa = 1.4, h = 0.3;
  const double m1 = 1.0 / 3.0, m2 = kPi / 16.0, f0 = 2.0 * kPi / 3.0;
  const double m0 = kPi * (1.0 + kappa) * m2;
  for (double e : kEps) {
    const long double el = e;
    const long double A = e >= 1.0 ? std::asin(1.0L / el) : kPiL / 2;
    const long double W = e > 1.0 ? std::sqrt((el - 1) * (el + 1)) : 0.0L;
    const long double e2 = el * el, e4 = e2 * e2;
    const double t = static_cast<double>(3.0L / (16.0L * el) * ((4 * e2 - e4) * A + (e2 + 2) * W));
    const double mh =
        static_cast<double>(((8 - 8 * e2 + 3 * e4) * A + 3 * (2 - e2) * W) / (4.0L * kPiL));
    const double p =
        static_cast<double>((3 * (8 - 4 * e2 + e4) * A + (8 + 10 * e2 - 3 * e4) * W / e2) / 128.0L);
    const ReferenceResult r = reference_resultants(hertz.sigma0(), kappa, h, e, 0.0, 1.0);
    SCOPED_TRACE("eps=" + std::to_string(e));
    EXPECT_NEAR(r.T_x, f0 * t, kTol * f0);
    EXPECT_NEAR(r.T_y, h * kappa * f0 * p, kTol * f0);
    EXPECT_NEAR(r.M_z, m0 * (2 * mh + (kappa - 1) * (2 * m1 / m2) * p) / (1 + kappa), kTol * f0);
  }
}

// Large eps, kappa = 1, h = 0, v = (eps, 0), omega = 1, a = 1/eps: expanding the integrand in a
// and integrating over theta gives
//   T_x = 2 pi m1 - pi a^2 m3 / 2 - 3 pi a^4 m5 / 32 - 5 pi a^6 m7 / 128 + O(a^8)
//   M_z = pi (a m3 + a^3 m5 / 8 + 3 a^5 m7 / 64) + O(a^7).
TEST(ReferenceIntegrator, LargeEpsSeries) {
  for (const Law& law : laws()) {
    const double n0 = law.n0();
    const double m1 = law.moment(1), m3 = law.moment(3), m5 = law.moment(5), m7 = law.moment(7);
    for (double e : {1e3, 1e4, 1e6}) {
      const double a = 1.0 / e;
      const ReferenceResult r = reference_resultants(law.sigma0(), 1.0, 0.0, e, 0.0, 1.0);
      SCOPED_TRACE(law.name + " eps=" + std::to_string(e));
      const double tx = 2 * kPi * m1 - kPi * a * a * m3 / 2 - 3 * kPi * std::pow(a, 4) * m5 / 32 -
                        5 * kPi * std::pow(a, 6) * m7 / 128;
      const double mz = kPi * (a * m3 + std::pow(a, 3) * m5 / 8 + 3 * std::pow(a, 5) * m7 / 64);
      EXPECT_NEAR(r.T_x, tx, kTol * n0);
      EXPECT_NEAR(r.T_y, 0.0, kTol * n0);
      EXPECT_NEAR(r.M_z, mz, kTol * n0);
      EXPECT_NEAR(r.M_z / mz, 1.0, 1e-9);  // M_z ~ 1/eps is tiny; check it relatively as well
    }
  }
}

// (4) Power balance (docs/physics.md §5): T.v + M_z omega = ∫ sigma (v_S . D v_S)/|v_S| dS, the
// right side integrated separately, with v_S formed directly in x-y coordinates.
TEST(ReferenceIntegrator, PowerBalance) {
  struct Case {
    double kappa, h, vx, vy, omega;
  };
  const std::vector<Case> cases = {
      {1.0, 0.0, 0.5, 0.0, 1.0},  {1.0, 0.3, 0.3, -0.4, 1.0},   {1.0, -0.2, -0.6, 0.8, -1.0},
      {0.7, 0.25, 0.2, 0.7, 2.0}, {1.6, 0.4, 1.2, -0.9, -0.8},  {2.5, -0.3, 1e-3, 0.0, 1.0},
      {0.5, 0.1, 0.0, 1.0, 1.0},  {1.0, 0.5, 30.0, 40.0, 0.05},
  };
  for (const Law& law : laws()) {
    const auto sigma0 = law.sigma0();
    for (const Case& c : cases) {
      const ReferenceResult r = reference_resultants(sigma0, c.kappa, c.h, c.vx, c.vy, c.omega);
      const rq::SingularPoint sp = rq::singular_point(c.vx, c.vy, c.omega);
      auto make_ring = [&](double rho) {
        const double s0 = sigma0(rho);
        return [=](double phi) -> rq::Vec<1> {
          const double th = sp.theta_star + phi;
          const double x = rho * std::cos(th), y = rho * std::sin(th);
          const double wx = c.vx - c.omega * y, wy = c.vy + c.omega * x;
          const double w = std::sqrt(wx * wx + wy * wy);
          if (w == 0.0) return {0.0};
          return {s0 * (1 + c.h * x) * (wx * wx + c.kappa * wy * wy) / w};
        };
      };
      const auto rhs = rq::integrate_disk<1>(make_ring, sp.eps, 1e-12);
      const double lhs = r.T_x * c.vx + r.T_y * c.vy + r.M_z * c.omega;
      const double scale =
          law.n0() * (std::hypot(c.vx, c.vy) + std::fabs(c.omega)) * std::max(1.0, c.kappa);
      SCOPED_TRACE(law.name + " kappa=" + std::to_string(c.kappa) + " v=(" + std::to_string(c.vx) +
                   "," + std::to_string(c.vy) + ") omega=" + std::to_string(c.omega));
      EXPECT_NEAR(lhs, rhs.value[0], kTol * scale);
    }
  }
}

// Mirror y -> -y maps (v_x, v_y, omega) to (v_x, -v_y, -omega) and (T_x, T_y, M_z) to
// (T_x, -T_y, -M_z); the singular direction moves, so the quadrature path differs.
TEST(ReferenceIntegrator, MirrorSymmetry) {
  for (const Law& law : laws()) {
    const double n0 = law.n0();
    const ReferenceResult a = reference_resultants(law.sigma0(), 1.7, 0.3, 0.35, 0.25, 0.9);
    const ReferenceResult b = reference_resultants(law.sigma0(), 1.7, 0.3, 0.35, -0.25, -0.9);
    SCOPED_TRACE(law.name);
    EXPECT_NEAR(a.T_x, b.T_x, kTol * n0);
    EXPECT_NEAR(a.T_y, -b.T_y, kTol * n0);
    EXPECT_NEAR(a.M_z, -b.M_z, kTol * n0);
    EXPECT_GT(std::fabs(a.T_y), 0.1 * n0);  // non-trivial case
  }
}

// The 2-D engine on smooth and endpoint-singular integrands with known values.
TEST(ReferenceIntegrator, DiskEngine) {
  for (double eps : {0.0, 1e-3, 0.5, 1.0, 3.0}) {
    // ∫ exp(x) dS over the unit disk = 2 pi I1(1); phi measured from an arbitrary direction.
    auto exp_ring = [](double rho) {
      return [rho](double phi) -> rq::Vec<1> { return {std::exp(rho * std::cos(phi + 0.4))}; };
    };
    const auto r = rq::integrate_disk<1>(exp_ring, eps, 1e-12);
    EXPECT_NEAR(r.value[0], 2 * kPi * std::cyl_bessel_i(1.0, 1.0), 1e-12 * r.scale) << eps;
    // ∫ (1 - rho^2)^0.1 dS = pi / 1.1
    auto pow_ring = [](double rho) {
      const double s = std::pow(std::max(0.0, 1 - rho * rho), 0.1);
      return [s](double) -> rq::Vec<1> { return {s}; };
    };
    const auto p = rq::integrate_disk<1>(pow_ring, eps, 1e-12);
    EXPECT_NEAR(p.value[0], kPi / 1.1, 1e-12 * p.scale) << eps;
    EXPECT_LE(p.abs_error, 1e-12 * p.scale) << eps;
  }
}

}  // namespace
}  // namespace reference_integrator_selftest
