// The Dormand–Prince integrator and the sliding–spinning body (docs/physics.md §4): convergence
// order on known ODEs, the terminal ratio eps of the uniform disk against an independent root of
// the closed forms (std::comp_ellint_*, not src/model) and the literature value 0.653 (Farkas,
// Bartels, Unger & Wolf, PRL 90, 248302, 2003), simultaneous stops, energy decay, and the pure
// sliding / pure spinning stop times in closed form.
#include <frictionid/model/sliding_spinning_body.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include <frictionid/model/approximants.hpp>
#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/dormand_prince.hpp>
#include <frictionid/model/exact_model.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/pressure_table.hpp>

namespace sliding_spinning_body_test {
namespace {

using namespace frictionid::model;

using V2 = OdeVector<double, 2>;

// Harmonic oscillator y'' = -y: y = (cos t, -sin t).
V2 oscillator(double, const V2& y) {
  return {y[1], -y[0]};
}

double fixed_step_error(int steps, double t_end) {
  V2 y{1.0, 0.0};
  const double h = t_end / steps;
  double t = 0.0;
  V2 f = oscillator(t, y);
  for (int i = 0; i < steps; ++i) {
    const auto s = dopri5_step(oscillator, t, y, f, h);
    y = s.y;
    f = s.f_end;
    t += h;
  }
  return std::hypot(y[0] - std::cos(t_end), y[1] + std::sin(t_end));
}

TEST(DormandPrince, GlobalErrorIsFifthOrder) {
  const double e1 = fixed_step_error(10, 2.0), e2 = fixed_step_error(20, 2.0),
               e3 = fixed_step_error(40, 2.0);
  EXPECT_NEAR(std::log2(e1 / e2), 5.0, 0.3) << e1 << " " << e2;
  EXPECT_NEAR(std::log2(e2 / e3), 5.0, 0.3) << e2 << " " << e3;
}

TEST(DormandPrince, EmbeddedErrorEstimateIsOfTheFourthOrderSolution) {
  // The local error of the 4th-order solution is O(h^5).
  const V2 y{1.0, 0.0};
  const V2 f = oscillator(0.0, y);
  double prev = 0.0;
  for (double h : {0.4, 0.2, 0.1}) {
    const auto s = dopri5_step(oscillator, 0.0, y, f, h);
    const double est = std::hypot(s.error[0], s.error[1]);
    if (prev > 0.0) {
      EXPECT_NEAR(std::log2(prev / est), 5.0, 0.35) << h;
    }
    prev = est;
  }
}

TEST(DormandPrince, AdaptiveDriverMeetsItsToleranceAndStopsWhenTold) {
  // y' = -2 t y, y = exp(-t^2), until t >= 3.
  using V1 = OdeVector<double, 1>;
  OdeSettings s;
  s.rtol = 1e-9;
  s.atol = 1e-12;
  double worst = 0.0;
  const auto stats =
      dopri5_integrate([](double t, const V1& y) { return V1{-2.0 * t * y[0]}; }, 0.0, V1{1.0}, s,
                       [&](double t, const V1& y, const V1&) {
                         worst = std::max(worst, std::fabs(y[0] - std::exp(-t * t)));
                         return t < 3.0;
                       });
  EXPECT_TRUE(stats.stopped_by_observer);
  EXPECT_LT(worst, 1e-8);
  EXPECT_GT(stats.accepted, 10);
  EXPECT_LT(stats.accepted, 400);
}

// --- the body ---------------------------------------------------------------------------------

// Physics §2 closed forms for the uniform law, kappa = 1, written with std::comp_ellint_1/2
// (modulus k): t(eps) and m-hat(eps).
double uniform_t(double e) {
  if (e <= 1.0) {
    const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    return 4.0 / (3.0 * M_PI * e) * ((1 + e * e) * E - (1 - e * e) * K);
  }
  const double K = std::comp_ellint_1(1.0 / e), E = std::comp_ellint_2(1.0 / e);
  return 4.0 / (3.0 * M_PI) * ((e * e + 1) * E - (e * e - 1) * K);
}
double uniform_mhat(double e) {
  if (e <= 1.0) {
    const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    return 2.0 / (3.0 * M_PI) * ((4 - 2 * e * e) * E - (1 - e * e) * K);
  }
  const double K = std::comp_ellint_1(1.0 / e), E = std::comp_ellint_2(1.0 / e);
  const double e2 = e * e;
  return 1.0 / (6.0 * M_PI * e) * ((16 * e2 - 8 * e2 * e2) * E + (e2 - 1) * (8 * e2 - 12) * K);
}

// Root of t(eps)/eps = mu_M m-hat(eps)/i (mu_M = 2/3) by bisection: the terminal ratio.
double uniform_terminal_eps(double inertia_ratio) {
  const auto G = [&](double e) {
    return uniform_t(e) / e - (2.0 / 3.0) * uniform_mhat(e) / inertia_ratio;
  };
  double lo = 0.05, hi = 5.0;
  EXPECT_LT(G(lo), 0.0);
  EXPECT_GT(G(hi), 0.0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (G(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct ExactFriction {
  ExactModel<double> model;
  Resultants<double> operator()(const Kinematics& k) const { return model(k); }
};

ExactFriction exact_friction(PressureLaw<double> law, double f = 1.0, double kappa = 1.0) {
  return {ExactModel<double>({f, kappa, 0.0}, std::move(law))};
}

BodyProperties disk() {
  BodyProperties b;
  b.mass = 2.0;
  b.inertia_ratio = 0.5;
  b.R = 0.1;
  b.N = 2.0 * 9.81;
  return b;
}

TEST(SlidingSpinningBody, UniformDiskReachesTheIndependentFixedPointAndTheLiteratureValue) {
  const double eps_star = uniform_terminal_eps(0.5);
  EXPECT_NEAR(eps_star, 0.653, 5e-4);  // Farkas et al. 2003
  const auto friction = exact_friction(PressureLaw<double>::uniform(), 0.3);
  for (double eps0 : {0.05, 1.0, 20.0}) {
    const BodyInitialState init{eps0 * 0.1 * 10.0, 0.0, 10.0};
    const BodySimulation sim =
        simulate_sliding_spinning_body(friction, disk(), init, BodySimulationSettings{});
    ASSERT_TRUE(sim.stopped) << eps0;
    EXPECT_NEAR(sim.eps_final, eps_star, 1e-4) << eps0;
    EXPECT_NEAR(sim.eps_final, eps_star, 1e-7) << eps0;  // what the default settings give
    EXPECT_LT(sim.stats.accepted, 500) << eps0;
  }
  // The model-based root finder agrees with the closed-form root.
  const auto roots = eps_fixed_points(friction, disk(), 0.0);
  ASSERT_EQ(roots.size(), 1u);
  EXPECT_TRUE(roots[0].stable);
  EXPECT_NEAR(roots[0].eps, eps_star, 1e-12);
}

TEST(SlidingSpinningBody, SlidingAndSpinningStopTogether) {
  const auto friction = exact_friction(PressureLaw<double>::uniform(), 0.5);
  const BodySimulation sim =
      simulate_sliding_spinning_body(friction, disk(), {0.3, 0.0, 20.0}, BodySimulationSettings{});
  ASSERT_TRUE(sim.stopped);
  EXPECT_GT(sim.t_stop_slide, 0.0);
  EXPECT_NEAR(sim.t_stop_slide, sim.t_stop_spin, 1e-10 * sim.t_stop_slide);
  EXPECT_NEAR(sim.t_end, sim.t_stop_slide, 1e-9 * sim.t_stop_slide);
}

TEST(SlidingSpinningBody, EnergyDecreasesMonotonically) {
  for (const auto& law : {PressureLaw<double>::uniform(), PressureLaw<double>::hertz()}) {
    const auto friction = exact_friction(law, 0.4, 1.0);
    const BodySimulation sim = simulate_sliding_spinning_body(friction, disk(), {0.5, 0.2, -15.0},
                                                              BodySimulationSettings{});
    ASSERT_TRUE(sim.stopped);
    ASSERT_GT(sim.trajectory.size(), 20u);
    EXPECT_NEAR(sim.trajectory.front().energy, sim.energy_initial, 1e-12);
    for (std::size_t i = 1; i < sim.trajectory.size(); ++i) {
      const double e = sim.trajectory[i].energy, prev = sim.trajectory[i - 1].energy;
      if (prev > 1e-250) {
        EXPECT_LT(e, prev) << i;
      } else {
        EXPECT_LE(e, prev) << i;  // the last row may lie far below (underflow to 0)
      }
    }
    EXPECT_LT(sim.trajectory.back().energy, 1e-20 * sim.energy_initial);
  }
}

TEST(SlidingSpinningBody, PureSlidingAndPureSpinningStopAtTheClosedFormTimes) {
  const double f = 0.25, g = 9.81;
  const auto friction = exact_friction(PressureLaw<double>::uniform(), f);
  const BodyProperties b = disk();
  // Pure sliding: T = f N, t = v0 M_b/(f N).
  const auto slide = simulate_sliding_spinning_body(friction, b, {1.5, 0.0, 0.0}, {});
  EXPECT_NEAR(slide.t_stop_slide, 1.5 / (f * g), 1e-9 * slide.t_stop_slide);
  EXPECT_EQ(slide.t_stop_spin, 0.0);
  EXPECT_NEAR(slide.distance, 1.5 * 1.5 / (2 * f * g), 1e-9);
  // Pure spinning: M_z = (2/3) f N R (uniform), t = I omega0/M_z.
  const auto spin = simulate_sliding_spinning_body(friction, b, {0.0, 0.0, 30.0}, {});
  const double t_spin = 0.5 * b.mass * b.R * b.R * 30.0 / ((2.0 / 3.0) * f * b.N * b.R);
  EXPECT_NEAR(spin.t_stop_spin, t_spin, 1e-9 * t_spin);
  EXPECT_EQ(spin.t_stop_slide, 0.0);
  EXPECT_NEAR(spin.rotation, 30.0 * t_spin / 2.0, 1e-9 * 30.0 * t_spin);
}

TEST(SlidingSpinningBody, SeedApproximantsPredictADifferentTerminalRatio) {
  // Seed/corrected without tilt: 1/sqrt(eps^2 + a) = (mu_M/i)/sqrt(1 + m eps^2), so
  // eps*^2 = ((mu_M/i)^2 a - 1)/(m - (mu_M/i)^2) = 7/48 for the uniform disk (a = 1, m = 64/9).
  const auto law = PressureLaw<double>::uniform();
  const LawMoments<double> mo = law_moments(law);
  const auto c = coefficients(mo, 1.0);
  const ApproximantShape<double> shape = approximant_shape(mo);
  for (const auto form : {ApproximantForm::Seed, ApproximantForm::Corrected}) {
    const ApproximantParams<double> p{
        1.0, 1.0, 0.0, c.a, form == ApproximantForm::Seed ? c.b : c.b_tilde, c.m, c.p0};
    const auto friction = [&](const Kinematics& k) {
      return approximant_resultants(form, p, shape, k);
    };
    const auto sim = simulate_sliding_spinning_body(friction, disk(), {0.5, 0.0, 10.0}, {});
    ASSERT_TRUE(sim.stopped);
    EXPECT_NEAR(sim.eps_final, std::sqrt(7.0 / 48.0), 1e-4);
    EXPECT_NEAR(sim.t_stop_slide, sim.t_stop_spin, 1e-10 * sim.t_stop_slide);
    EXPECT_GT(uniform_terminal_eps(0.5) - sim.eps_final, 0.25);
  }
}

TEST(SlidingSpinningBody, RingOnUniformPressureLetsSlidingDieFirst) {
  // i = 1 with uniform pressure: d ln(eps)/dt < 0 for every eps, so eps -> 0, no fixed point.
  const auto friction = exact_friction(PressureLaw<double>::uniform());
  BodyProperties b = disk();
  b.inertia_ratio = 1.0;
  EXPECT_TRUE(eps_fixed_points(friction, b, 0.0).empty());
  const auto sim = simulate_sliding_spinning_body(friction, b, {1.0, 0.0, 10.0}, {});
  ASSERT_TRUE(sim.stopped);
  EXPECT_LT(sim.eps_final, 1e-5);
  EXPECT_NEAR(sim.t_stop_slide, sim.t_stop_spin, 1e-9 * sim.t_stop_spin);
}

TEST(SlidingSpinningBody, RimPressureApproachesTheThinRingLimit) {
  // sigma0 = rho^20 (tabulated, 2001 samples), i = 1: the terminal ratio 0.92976441047 comes from
  // an independent scipy quadrature of the ring kernels (experiments/terminal_motion).
  std::vector<double> rho, sigma;
  for (int i = 0; i <= 2000; ++i) {
    rho.push_back(i / 2000.0);
    sigma.push_back(std::pow(i / 2000.0, 20));
  }
  const auto law =
      PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(rho, sigma));
  const auto friction = exact_friction(law);
  BodyProperties b = disk();
  b.inertia_ratio = 1.0;
  const auto sim = simulate_sliding_spinning_body(friction, b, {1.0, 0.0, 10.0}, {});
  ASSERT_TRUE(sim.stopped);
  EXPECT_NEAR(sim.eps_final, 0.92976441047, 1e-6);
}

TEST(SlidingSpinningBody, AnisotropicSlipTurnsToTheLowFrictionAxis) {
  // kappa = 2: the force -f N t D e pulls the slip direction towards x, where the fixed point of
  // slip along x applies.
  const auto friction = exact_friction(PressureLaw<double>::hertz(), 0.5, 2.0);
  const double a = 40.0 * M_PI / 180.0;
  const auto sim = simulate_sliding_spinning_body(friction, disk(),
                                                  {0.4 * std::cos(a), 0.4 * std::sin(a), 8.0}, {});
  ASSERT_TRUE(sim.stopped);
  EXPECT_NEAR(sim.slip_angle_final, 0.0, 1e-6);
  const auto roots = eps_fixed_points(friction, disk(), 0.0);
  ASSERT_FALSE(roots.empty());
  EXPECT_NEAR(sim.eps_final, roots[0].eps, 1e-5);
  EXPECT_NEAR(sim.t_stop_slide, sim.t_stop_spin, 1e-9 * sim.t_stop_spin);
}

TEST(SlidingSpinningBody, RejectsABodyAtRestOrWithoutInertia) {
  const auto friction = exact_friction(PressureLaw<double>::uniform());
  EXPECT_THROW(simulate_sliding_spinning_body(friction, disk(), {0.0, 0.0, 0.0}, {}),
               std::invalid_argument);
  BodyProperties b = disk();
  b.inertia_ratio = 0.0;
  EXPECT_THROW(simulate_sliding_spinning_body(friction, b, {1.0, 0.0, 1.0}, {}),
               std::invalid_argument);
}

}  // namespace
}  // namespace sliding_spinning_body_test
