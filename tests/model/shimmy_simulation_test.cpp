// The towed wheel (docs/physics.md §10): the first slip phase against an independent classical
// Runge–Kutta integration of the equations written out again with the uniform disk's closed forms
// (std::comp_ellint_*, not src/model); the energy balance (10.6) in every phase; rest reached in
// bounded steps; the cohesion test (10.3) against the uniform disk's known limits; the Keldysh
// constraint kept; rows of the dense output at k dt.
#include <frictionid/model/shimmy_simulation.hpp>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <frictionid/model/exact_model.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/ring_integral_table.hpp>
#include <frictionid/model/spot_model.hpp>

namespace shimmy_simulation_test {
namespace {

using namespace frictionid::model;

constexpr double kF = 0.8;

ShimmyWheel test_wheel(bool rigid = false) {
  ShimmyWheel w;
  w.V = 10.0;
  w.caster = 0.1;
  w.J = 0.5;
  w.k_psi = 2000.0;
  w.c_psi = 1.0;
  w.m_y = 20.0;
  w.k_y = 2e5;
  w.c_y = 50.0;
  w.rigid_lateral = rigid;
  w.N = 1000.0;
  w.R = 0.05;
  return w;
}

// The friction's derivative along the kinematics, as the application layer gives it: the model
// with dual-number velocities (docs/physics.md §10.8).
using Dual = ceres::Jet<double, 1>;

template <typename Model>
ContactForces dual_slope(const Model& model, const Kinematics& k, const Kinematics& dk) {
  const Resultants<Dual> r = model(kinematics_along<Dual>(k, dk));
  return {r.T_x.v[0], r.T_y.v[0], r.M_z.v[0]};
}

// Values by the radial quadrature, derivatives from the ring-integral table.
struct UniformExact {
  ExactModel<double> model{{kF, 1.0, 0.0}, PressureLaw<double>::uniform()};
  ExactModel<Dual> dual{{Dual(kF), Dual(1.0), Dual(0.0)},
                        PressureLaw<Dual>::uniform(),
                        std::make_shared<const RingIntegralTable>(PressureLaw<double>::uniform())};
  Resultants<double> operator()(const Kinematics& k) const { return model(k); }
  ContactForces slip_slope(const Kinematics& k, const Kinematics& dk) const {
    return dual_slope(dual, k, dk);
  }
};

// The second implementation: the equations of motion (10.1)-(10.2) written out again as the
// issue states them, integrated by classical RK4 with a fixed small step. The friction is the
// same model (it is not what is tested here). z = (y, y', psi, psi').
using Z = std::array<double, 4>;
Z reference_rate(const ShimmyWheel& w, const Z& z) {
  static const UniformExact friction;
  const double u = -w.V * std::sin(z[2]) + z[1] * std::cos(z[2]) - w.caster * z[3];
  const Resultants<double> r = friction(Kinematics{0.0, u, z[3], w.N, w.R});
  const double ydd =
      (-w.k_y * z[0] - w.c_y * z[1] - r.T_x * std::sin(z[2]) - r.T_y * std::cos(z[2])) / w.m_y;
  const double pdd = (-w.k_psi * z[2] - w.c_psi * z[3] + w.caster * r.T_y - r.M_z) / w.J;
  return {z[1], ydd, z[3], pdd};
}

Z rk4(const ShimmyWheel& w, Z z, double t0, double t1, double h) {
  const int n = static_cast<int>(std::ceil((t1 - t0) / h));
  const double dt = (t1 - t0) / n;
  for (int i = 0; i < n; ++i) {
    const Z k1 = reference_rate(w, z);
    Z a;
    for (int j = 0; j < 4; ++j) a[j] = z[j] + 0.5 * dt * k1[j];
    const Z k2 = reference_rate(w, a);
    for (int j = 0; j < 4; ++j) a[j] = z[j] + 0.5 * dt * k2[j];
    const Z k3 = reference_rate(w, a);
    for (int j = 0; j < 4; ++j) a[j] = z[j] + dt * k3[j];
    const Z k4 = reference_rate(w, a);
    for (int j = 0; j < 4; ++j) z[j] += dt / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return z;
}

TEST(Shimmy, FirstSlipPhaseMatchesAnIndependentRungeKuttaIntegration) {
  const ShimmyWheel w = test_wheel();
  ShimmySettings set;
  set.duration = 0.2;
  set.rtol = set.atol = 1e-12;
  set.record = true;
  set.output_step = 1e-3;
  std::vector<ShimmyRow> rows;
  const ShimmyStart start{0.002, 0.0, 0.05, 0.0};
  const ShimmyRun run = simulate_shimmy(UniformExact{}, w, start, set,
                                        [&](const ShimmyRow& r) { rows.push_back(r); });
  ASSERT_GT(run.first_switch, 0.01);
  // Compare while the slip is well away from its zero (where its direction turns on a time scale
  // that a fixed step cannot follow).
  Z z{start.y, start.y_dot, start.psi, start.psi_dot};
  double t = 0.0;
  int compared = 0;
  for (const ShimmyRow& r : rows) {
    if (r.t >= run.first_switch) break;
    z = rk4(w, z, t, r.t, 2e-6);
    t = r.t;
    const double u = -w.V * std::sin(z[2]) + z[1] * std::cos(z[2]) - w.caster * z[3];
    if (std::hypot(u, w.R * z[3]) < 1e-3 * run.scales.slip) break;
    EXPECT_NEAR(r.y, z[0], 1e-8 * run.scales.y) << r.t;
    EXPECT_NEAR(r.y_dot, z[1], 1e-8 * run.scales.y_dot) << r.t;
    EXPECT_NEAR(r.psi, z[2], 1e-8 * run.scales.psi) << r.t;
    EXPECT_NEAR(r.psi_dot, z[3], 1e-8 * run.scales.psi_dot) << r.t;
    ++compared;
  }
  EXPECT_GT(compared, 10);
}

TEST(Shimmy, JacobianMatchesFiniteDifferencesOfTheRates) {
  // Every entry of d(rate)/d(state) against central differences of shimmy_rate with the
  // friction of the perturbed state's own slip direction, elastic and rigid strut, at slips
  // from large to near the stiff limit.
  const UniformExact fr;
  const auto forces = [&](const ShimmyWheel& w, const ShimmyState& x) {
    const auto s = spot_slip(w, x);
    const Resultants<double> r = fr(Kinematics{0.0, s[0], x[kSPsiDot], w.N, w.R});
    return ContactForces{r.T_x, r.T_y, r.M_z};
  };
  for (bool rigid : {false, true}) {
    const ShimmyWheel w = test_wheel(rigid);
    const ShimmyLimitCurve curve(fr, w.N, w.R, 64);
    for (double size : {1.0, 1e-2, 1e-4}) {
      ShimmyState x{};
      x[kSY] = rigid ? 0.0 : 2e-4;
      x[kSPsi] = 0.03;
      x[kSYDot] = rigid ? 0.0 : w.V * std::tan(x[kSPsi]) + 0.4 * size;
      x[kSPsiDot] = -3.0 * size;
      const auto s = spot_slip(w, x);
      const ContactForces F = forces(w, x);
      const OdeMatrix<7> J = shimmy_jacobian(w, x, F, curve.slope(fr, std::atan2(s[1], s[0])));
      const std::array<double, 4> dth = slip_direction_gradient(w, x);
      const std::array<double, 4> typical{1e-3, 1.0, 0.1, 1.0};
      for (std::size_t j = 0; j < 4; ++j) {
        if (rigid && j < 2) continue;
        // A step that turns the slip by about 1e-5 rad at most.
        const double d = 1e-5 / (std::fabs(dth[j]) + 1.0 / typical[j]);
        ShimmyState a = x, b = x;
        a[j] += d;
        b[j] -= d;
        const ShimmyState ra = shimmy_rate(w, a, forces(w, a));
        const ShimmyState rb = shimmy_rate(w, b, forces(w, b));
        for (std::size_t i = 0; i < 7; ++i) {
          if (rigid && i < 2) continue;
          const double fd = (ra[i] - rb[i]) / (2.0 * d);
          // Truncation (1e-10 relative for a turn of 1e-5) and the rounding of the rates.
          const double noise = 1e-13 * (std::fabs(ra[i]) + std::fabs(rb[i])) / d;
          EXPECT_NEAR(J[i][j], fd, 1e-6 * std::fabs(fd) + noise + 1e-12)
              << "rigid " << rigid << " size " << size << " d rate[" << i << "]/d x[" << j << "]";
        }
      }
    }
  }
}

double balance_error(const ShimmyRun& r) {
  const double W = r.final[kSContactWork], D = r.final[kSDamping];
  const double size = std::max({std::fabs(r.energy_initial), std::fabs(r.energy_final),
                                std::fabs(W), std::fabs(D), std::fabs(r.final[kSFriction])});
  return std::fabs((r.energy_final - r.energy_initial) - (W - D)) / size;
}

TEST(Shimmy, EnergyBalanceClosesThroughSlipAndStickPhases) {
  for (bool rigid : {false, true}) {
    ShimmySettings set;
    set.duration = 1.0;
    const ShimmyRun run = simulate_shimmy(UniformExact{}, test_wheel(rigid), {0.0, 0.0, 0.05, 0.0},
                                          set, [](const ShimmyRow&) {});
    EXPECT_LT(balance_error(run), 1e-8) << rigid;
    EXPECT_GE(run.final[kSFriction], 0.0);
    EXPECT_GT(run.final[kSDamping], 0.0);
    if (!rigid) {
      EXPECT_GT(run.stick_phases, 0);  // the balance is tested across phases
    }
  }
}

TEST(Shimmy, FrictionDissipationNeverDecreases) {
  ShimmySettings set;
  set.duration = 0.5;
  double last = 0.0;
  for (double T : {0.05, 0.1, 0.2, 0.5}) {
    set.duration = T;
    const ShimmyRun run = simulate_shimmy(UniformExact{}, test_wheel(), {0.0, 0.0, 0.05, 0.0}, set,
                                          [](const ShimmyRow&) {});
    EXPECT_GE(run.final[kSFriction], last - 1e-12) << T;
    last = run.final[kSFriction];
  }
}

TEST(Shimmy, RigidStrutComesToRestInBoundedSteps) {
  ShimmySettings set;
  set.duration = 5.0;
  const ShimmyRun run = simulate_shimmy(UniformExact{}, test_wheel(true), {0.0, 0.0, 0.05, 0.0},
                                        set, [](const ShimmyRow&) {});
  EXPECT_EQ(run.outcome, ShimmyOutcome::Rest);
  EXPECT_TRUE(run.in_stick);
  EXPECT_DOUBLE_EQ(run.t_end, 5.0);
  EXPECT_EQ(run.final[kSPsi], 0.0);
  EXPECT_LT(run.steps + run.rejected, 100000);
  EXPECT_FALSE(run.step_limit);
}

// A heavier wheel at low speed: after its first oscillations the contact creeps at its
// friction limit, |s| about 1e-4 of its scale for most of the run (docs/physics.md §10.8).
ShimmyWheel creeping_wheel() {
  ShimmyWheel w = test_wheel();
  w.V = 3.0;
  w.N = 2000.0;
  w.c_psi = 2.0;
  w.c_y = 100.0;
  return w;
}

TEST(Shimmy, ImplicitStepsFollowTheCreepAtTheFrictionLimitWithFewSteps) {
  ShimmySettings set;
  set.duration = 0.5;
  set.record = true;
  set.output_step = 0.05;
  std::vector<ShimmyRow> rows[2];
  ShimmyRun runs[2];
  for (int k = 0; k < 2; ++k) {
    set.stiff_switching = k == 1;
    runs[k] = simulate_shimmy(UniformExact{}, creeping_wheel(), {0.0, 0.0, 0.05, 0.0}, set,
                              [&](const ShimmyRow& r) { rows[k].push_back(r); });
  }
  EXPECT_EQ(runs[0].implicit_steps, 0);
  EXPECT_GT(runs[1].implicit_steps, 0);
  // The explicit steps are held at the friction's stability limit through the creep.
  EXPECT_LT(20 * (runs[1].steps + runs[1].rejected), runs[0].steps + runs[0].rejected);
  ASSERT_EQ(rows[0].size(), rows[1].size());
  for (std::size_t i = 0; i < rows[0].size(); ++i) {
    EXPECT_NEAR(rows[1][i].psi, rows[0][i].psi, 1e-6 * runs[0].scales.psi) << rows[0][i].t;
    EXPECT_NEAR(rows[1][i].y, rows[0][i].y, 1e-6 * runs[0].scales.y) << rows[0][i].t;
  }
  for (const ShimmyRun& r : runs) EXPECT_LT(balance_error(r), 1e-8);
}

TEST(Shimmy, ASmallStickThresholdFollowsTheCreepInsteadOfChargingImpulses) {
  // With implicit steps the slip can be followed down to 1e-8 of its scale: the impulses of
  // the projections and seeds fall with the threshold, at a bounded number of steps.
  ShimmySettings set;
  set.duration = 1.0;
  set.stick_threshold = 1e-8;
  const ShimmyRun run = simulate_shimmy(UniformExact{}, creeping_wheel(), {0.0, 0.0, 0.05, 0.0},
                                        set, [](const ShimmyRow&) {});
  EXPECT_FALSE(run.step_limit);
  EXPECT_LT(run.steps + run.rejected, 10000);
  EXPECT_GT(run.stick_phases, 1);
  EXPECT_LT(std::fabs(run.impulse_work), 1e-6 * run.energy_initial);
  EXPECT_LT(balance_error(run), 1e-8);
}

TEST(Shimmy, OnAnEllipseTheCreepEndsHoldingWithoutChatter) {
  // The same creep on an elliptic spot (Hertz, aspect 0.6): the limit curve samples theta = pi,
  // pure sliding with a spin at rounding level, where the ellipse's rays once returned zero
  // forces; the cohesion test then saw a hole in the limit set and the run chattered through
  // 550,000 slip starts (docs/physics.md §9.3, far centres).
  // Values by the ray integration, derivatives from the spot's table.
  struct EllipseExact {
    SpotModel<double> model{SpotParams<double>{kF, 1.0, 0.0, 0.0, 0.6},
                            PressureLaw<double>::hertz(), ContactSpot::ellipse(0.6)};
    SpotModel<Dual> dual{SpotParams<Dual>{Dual(kF), Dual(1.0), Dual(0.0), Dual(0.0), Dual(0.6)},
                         PressureLaw<Dual>::hertz(), tabulated(ContactSpot::ellipse(0.6))};
    static ContactSpot tabulated(ContactSpot s) {
      s.table = std::make_shared<const SpotIntegralTable>(s, PressureLaw<double>::hertz(), 0.6);
      return s;
    }
    Resultants<double> operator()(const Kinematics& k) const { return model(k); }
    ContactForces slip_slope(const Kinematics& k, const Kinematics& dk) const {
      return dual_slope(dual, k, dk);
    }
  };
  ShimmySettings set;
  set.duration = 1.0;
  set.max_steps = 100000;
  const ShimmyRun run = simulate_shimmy(EllipseExact{}, creeping_wheel(), {0.0, 0.0, 0.05, 0.0},
                                        set, [](const ShimmyRow&) {});
  EXPECT_FALSE(run.step_limit);
  EXPECT_LT(run.slip_starts, 20);
  EXPECT_LT(std::fabs(run.impulse_work), 1e-5 * run.energy_initial);
  EXPECT_LT(balance_error(run), 1e-8);
  EXPECT_EQ(run.cycle.detail, DurationDetail::Holding);
}

TEST(Shimmy, ExactFrictionIsNormalToItsLimitCurve) {
  // Maximal dissipation (docs/physics.md §10.3): with kappa = 1 the curve (T_y, M_z/R)(theta)
  // turns perpendicular to the slip direction d(theta), G'(theta).d(theta) = 0, so that the
  // load W = G(theta) lies where the support in direction d(theta) is attained.
  const UniformExact fr;
  const ShimmyWheel w = test_wheel();
  const ShimmyLimitCurve curve(fr, w.N, w.R, 64);
  for (int i = 0; i < 97; ++i) {
    const double th = 2.0 * M_PI * (i + 0.37) / 97.0;
    const ContactForces g = curve.slope(fr, th);
    const double along = g.T_y * std::cos(th) + g.M_z / w.R * std::sin(th);
    EXPECT_LT(std::fabs(along), 1e-7 * std::hypot(g.T_y, g.M_z / w.R) + 1e-9 * w.N) << th;
  }
}

TEST(Shimmy, CohesionTestAgainstTheUniformDisksLimits) {
  // Uniform disk: pure sliding carries f N, pure spin (2/3) f N R; the limit set holds what is
  // inside and nothing outside.
  const ShimmyWheel w = test_wheel();
  const UniformExact fr;
  const ShimmyLimitCurve curve(fr, w.N, w.R);
  const double T = kF * w.N, M = 2.0 / 3.0 * kF * w.N * w.R;
  EXPECT_GT(curve.margin(fr, {0.0, 0.0, 0.0}).value, 0.0);
  EXPECT_GT(curve.margin(fr, {0.0, 0.99 * T, 0.0}).value, 0.0);
  EXPECT_LT(curve.margin(fr, {0.0, 1.01 * T, 0.0}).value, 0.0);
  EXPECT_GT(curve.margin(fr, {0.0, 0.0, -0.99 * M}).value, 0.0);
  EXPECT_LT(curve.margin(fr, {0.0, 0.0, -1.01 * M}).value, 0.0);
  // The margin is at most the reserve along theta = 0 (the support f N less the load); the
  // curved boundary leaves less in a direction between.
  const double half = curve.margin(fr, {0.0, 0.5 * T, 0.0}).value;
  EXPECT_GT(half, 0.0);
  EXPECT_LE(half, 0.5 * T * (1.0 + 1e-12));
  // A load inside sticks the wheel at s = 0: a start at psi = 0 with a displaced strut whose
  // constraint loads are inside stays at rest.
  ShimmySettings set;
  set.duration = 0.5;
  ShimmyWheel still = w;
  still.caster = 0.0;
  const ShimmyRun run =
      simulate_shimmy(fr, still, {0.2 * T / w.k_y, 0.0, 0.0, 0.0}, set, [](const ShimmyRow&) {});
  EXPECT_EQ(run.outcome, ShimmyOutcome::Rest);
  EXPECT_EQ(run.steps, 0);
  // One outside it slides.
  const ShimmyRun slides =
      simulate_shimmy(fr, still, {2.0 * T / w.k_y, 0.0, 0.0, 0.0}, set, [](const ShimmyRow&) {});
  EXPECT_GT(slides.steps, 0);
  EXPECT_GT(slides.final[kSFriction], 0.0);
}

TEST(Shimmy, NonholonomicBaselineKeepsTheNoSlipConstraint) {
  ShimmySettings set;
  set.duration = 0.3;
  set.law = ShimmyContactLaw::Nonholonomic;
  set.record = true;
  set.output_step = 1e-3;
  const ShimmyWheel w = test_wheel();
  double worst = 0.0;
  std::size_t rows = 0;
  const ShimmyRun run =
      simulate_shimmy(UniformExact{}, w, {0.0, 0.0, 0.05, 0.0}, set, [&](const ShimmyRow& r) {
        worst = std::max(worst, std::fabs(r.u_y));
        EXPECT_EQ(r.M_z, 0.0);
        ++rows;
      });
  EXPECT_LT(worst, 1e-7 * run.scales.slip);
  EXPECT_LT(balance_error(run), 1e-8);
  EXPECT_EQ(rows, 301u);
}

TEST(Shimmy, RowsFallExactlyOnMultiplesOfTheOutputStep) {
  ShimmySettings set;
  set.duration = 0.25;
  set.record = true;
  set.output_step = 0.01;
  std::vector<double> times;
  simulate_shimmy(UniformExact{}, test_wheel(), {0.0, 0.0, 0.05, 0.0}, set,
                  [&](const ShimmyRow& r) { times.push_back(r.t); });
  ASSERT_EQ(times.size(), 26u);
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(times[k], static_cast<double>(k) * 0.01);
}

TEST(ShimmyOutcome, CyclesAreClassifiedByTheirAmplitudes) {
  const auto extremes = [](double ratio) {
    std::vector<PsiExtreme> e;
    double a = 0.1;
    for (int k = 0; k < 12; ++k) {
      e.push_back({0.05 * k, (k % 2 ? -a : a)});
      a *= std::sqrt(ratio);  // per half cycle
    }
    return e;
  };
  const CycleEstimate steady = classify_cycles(extremes(1.0), 1e-3);
  EXPECT_EQ(steady.outcome, ShimmyOutcome::LimitCycle);
  EXPECT_NEAR(steady.amplitude, 0.1, 1e-12);
  EXPECT_NEAR(steady.frequency, 10.0, 1e-9);  // period 0.1 s
  EXPECT_EQ(classify_cycles(extremes(1.2), 1e-3).outcome, ShimmyOutcome::Growing);
  const CycleEstimate decaying = classify_cycles(extremes(0.8), 1e-3);
  EXPECT_EQ(decaying.outcome, ShimmyOutcome::Duration);
  EXPECT_EQ(decaying.detail, DurationDetail::Decaying);
  EXPECT_NEAR(decaying.growth, -0.2, 1e-12);
  EXPECT_EQ(steady.detail, DurationDetail::None);
  std::vector<PsiExtreme> few = extremes(0.8);
  few.resize(5);
  EXPECT_EQ(classify_cycles(few, 1e-3).detail, DurationDetail::FewCycles);
  // Alternately growing and shrinking: neither a limit cycle, nor growing, nor decaying.
  std::vector<PsiExtreme> beat = extremes(1.0);
  for (std::size_t k = 0; k < beat.size(); ++k) beat[k].psi *= 1.0 + 0.05 * ((k / 2) % 2);
  EXPECT_EQ(classify_cycles(beat, 1e-3).detail, DurationDetail::Irregular);
}

TEST(ShimmyOutcome, ARunThatEndsHoldingTheForkOffCentreSaysSo) {
  // Low speed: the oscillation dies out and the contact holds the fork at a small psi != 0
  // while the strut drifts at V tan psi (docs/physics.md §10.5).
  ShimmySettings set;
  set.duration = 1.0;
  const ShimmyRun run = simulate_shimmy(UniformExact{}, creeping_wheel(), {0.0, 0.0, 0.05, 0.0},
                                        set, [](const ShimmyRow&) {});
  ASSERT_EQ(run.outcome, ShimmyOutcome::Duration);
  ASSERT_TRUE(run.in_stick);
  EXPECT_NE(run.final[kSPsi], 0.0);
  EXPECT_EQ(run.cycle.detail, DurationDetail::Holding);
}

}  // namespace
}  // namespace shimmy_simulation_test
