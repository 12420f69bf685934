#include "identify/local_stage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <frictionid/synthetic_data.hpp>

namespace frictionid::local_stage_test {
namespace {

using Law = model::PressureLaw<double>;

struct Fixture {
  Dataset data;
  FitSettings settings;
  LocalProblem problem;
  ParamVector truth{};
};

// Rows in several slip directions, all four channels, 1 % noise; free = every model parameter.
void make(Fixture& f, ModelKind kind, const Law& law, std::size_t rows, LossKind loss,
          std::vector<double> slip_angles = {0.0, 0.4, 1.2, -2.0}) {
  f.settings.model = kind;
  f.settings.law = law;
  f.settings.params = default_parameter_settings(law);
  f.settings.loss = loss;
  f.settings.loss_scale = 1.5;
  f.truth = default_parameters(law, 0.85, 1.3, 0.12);
  SyntheticDesign design;
  design.rows = rows;
  design.slip_angles = slip_angles;
  f.data = generate_dataset(kind, law, f.truth, design, NoiseSpec{0.01, 0.0, false}, 17);
  f.problem.rows.data = &f.data;
  f.problem.rows.channels = {Channel::T_x, Channel::T_y, Channel::M_z, Channel::M_roll};
  f.problem.rows.scale = {2000.0, 100.0, 50.0, 10.0};
  f.problem.rows.begin = 0;
  f.problem.rows.end = f.data.rows();
  f.problem.settings = &f.settings;
  f.problem.free = model_parameters(kind, law.kind);
  f.problem.threads = 1;
}

std::vector<double> residuals_at(const Fixture& f, const ParamVector& x) {
  std::vector<double> r(f.problem.rows.residual_count());
  EXPECT_TRUE(evaluate_residuals(f.problem.rows, f.settings.model, f.settings.law, f.settings.loss,
                                 f.settings.loss_scale, x.data(), r.data()));
  return r;
}

// J^T J, J^T r and r^T r of the autodiff pass against a Jacobian by central differences of the
// plain-double residuals.
void expect_normal_equations_match_differences(ModelKind kind, const Law& law, LossKind loss,
                                               std::vector<double> slip_angles = {0.0, 0.4, 1.2,
                                                                                  -2.0}) {
  Fixture f;
  make(f, kind, law, 300, loss, slip_angles);
  ParamVector x = f.truth;
  for (int i : f.problem.free) x[i] *= 1.03;  // off the optimum: J^T r is not small
  const std::size_t k = f.problem.free.size();
  const std::vector<double> r = residuals_at(f, x);
  Eigen::MatrixXd j(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(k));
  for (std::size_t c = 0; c < k; ++c) {
    const int i = f.problem.free[c];
    const double h = 1e-6 * std::max(std::fabs(x[i]), 1e-2);
    ParamVector up = x, down = x;
    up[i] += h;
    down[i] -= h;
    const auto ru = residuals_at(f, up), rd = residuals_at(f, down);
    for (std::size_t m = 0; m < r.size(); ++m)
      j(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(c)) = (ru[m] - rd[m]) / (2 * h);
  }
  const Eigen::Map<const Eigen::VectorXd> rv(r.data(), static_cast<Eigen::Index>(r.size()));
  NormalEquations ne;
  ASSERT_TRUE(normal_equations(f.problem, x, ne));
  const Eigen::MatrixXd jtj = j.transpose() * j;
  const Eigen::VectorXd jtr = j.transpose() * rv;
  for (Eigen::Index a = 0; a < jtj.rows(); ++a) {
    for (Eigen::Index b = 0; b < jtj.cols(); ++b)
      EXPECT_NEAR(ne.jtj(a, b), jtj(a, b), 1e-6 * std::sqrt(jtj(a, a) * jtj(b, b)))
          << a << "," << b;
    EXPECT_NEAR(ne.jtr[a], jtr[a], 1e-6 * std::sqrt(jtj(a, a)) * rv.norm()) << a;
  }
  EXPECT_NEAR(ne.rtr, rv.squaredNorm(), 1e-12 * rv.squaredNorm());
}

TEST(LocalStage, SeedNormalEquationsMatchCentralDifferences) {
  expect_normal_equations_match_differences(ModelKind::Seed, Law::hertz(), LossKind::None);
}

// Slip along x only: the rows go four at a time through the packet pass.
TEST(LocalStage, SeedAndCorrectedPacketPassesMatchCentralDifferences) {
  expect_normal_equations_match_differences(ModelKind::Seed, Law::hertz(), LossKind::None, {0.0});
  expect_normal_equations_match_differences(ModelKind::Corrected, Law::power(1.7), LossKind::None,
                                            {0.0});
}

// The packet passes (AVX2) against the row-by-row passes on the same rows (allow_row_packets),
// for the normal equations, the cost, the Jacobian's factor and the HC3 meat: the
// sum of squares of all four passes to the bit, J^T J and J^T r to rounding (the lanes are summed
// apart). Rows of slip along x in both directions, with and without spin, a sigma column,
// unmeasured values, and a few oblique rows between them.
TEST(LocalStage, PacketPassAgreesWithTheRowByRowPass) {
  if (!row_packets_available()) GTEST_SKIP() << "no packet pass in this build or on this processor";
  for (ModelKind kind : {ModelKind::Seed, ModelKind::Corrected}) {
    Fixture f;
    make(f, kind, Law::hertz(), 2003, LossKind::None, {0.0});
    Dataset& d = f.data;
    for (std::size_t i = 0; i < d.rows(); ++i) {
      if (i % 3 == 1) d.v_x[i] = -d.v_x[i];  // slip along -x
      if (i % 97 == 5) d.v_y[i] = 0.01;      // oblique: the scalar path
      if (i % 89 == 7) d.omega[i] = 0.0;     // pure sliding
      if (i % 83 == 9) d.v_x[i] = 0.0;       // pure spin
      if (i % 13 == 3) d.present[static_cast<int>(Channel::M_z)][i] = 0;
    }
    d.sigma[static_cast<int>(Channel::T_y)].assign(d.rows(), 0.0);
    for (std::size_t i = 0; i < d.rows(); ++i)
      d.sigma[static_cast<int>(Channel::T_y)][i] = 2.0 + 0.01 * static_cast<double>(i % 31);
    ParamVector x = f.truth;
    for (int i : f.problem.free) x[i] *= 0.97;
    f.problem.threads = 2;
    NormalEquations packed, scalar;
    ASSERT_TRUE(normal_equations(f.problem, x, packed));
    const double packed_cost = problem_cost(f.problem, x);
    const Eigen::MatrixXd bread = packed.jtj.inverse();
    const auto packed_factor = jacobian_factor(f.problem, x);
    const auto packed_meat = sandwich_meat(f.problem, x, bread);
    allow_row_packets(false);
    ASSERT_TRUE(normal_equations(f.problem, x, scalar));
    const double scalar_cost = problem_cost(f.problem, x);
    const auto scalar_factor = jacobian_factor(f.problem, x);
    const auto scalar_meat = sandwich_meat(f.problem, x, bread);
    allow_row_packets(true);
    // The Jacobian's triangular factor and the sandwich's meat see the same rows.
    ASSERT_TRUE(packed_factor && scalar_factor && packed_meat && scalar_meat);
    EXPECT_EQ(packed_factor->cost, scalar_factor->cost);
    const Eigen::MatrixXd rtr_p = packed_factor->r.transpose() * packed_factor->r;
    const Eigen::MatrixXd rtr_s = scalar_factor->r.transpose() * scalar_factor->r;
    for (Eigen::Index a = 0; a < rtr_s.rows(); ++a)
      for (Eigen::Index b = 0; b < rtr_s.cols(); ++b) {
        const double scale = std::sqrt(rtr_s(a, a) * rtr_s(b, b));
        EXPECT_NEAR(rtr_p(a, b), rtr_s(a, b), 1e-13 * scale);
        EXPECT_NEAR((*packed_meat)(a, b), (*scalar_meat)(a, b),
                    1e-12 * std::sqrt((*scalar_meat)(a, a) * (*scalar_meat)(b, b)));
      }
    EXPECT_EQ(packed.rtr, scalar.rtr);
    EXPECT_EQ(packed.rtr, 2.0 * packed_cost);
    EXPECT_EQ(packed_cost, scalar_cost);
    for (Eigen::Index a = 0; a < packed.jtj.rows(); ++a) {
      for (Eigen::Index b = 0; b < packed.jtj.cols(); ++b)
        EXPECT_NEAR(packed.jtj(a, b), scalar.jtj(a, b),
                    1e-13 * std::sqrt(scalar.jtj(a, a) * scalar.jtj(b, b)));
      EXPECT_NEAR(packed.jtr[a], scalar.jtr[a], 1e-13 * std::sqrt(scalar.jtj(a, a) * scalar.rtr));
    }
  }
}

// The global stage's cost with each packet's geometry formed once: problem_cost's bits, on rows
// of every kind (packets, oblique rows between them, unmeasured values, a sigma column), for
// both closed forms, a robust loss (no packets) and the exact model.
TEST(LocalStage, RepeatedCostIsProblemCostToTheBit) {
  struct Case {
    ModelKind kind;
    LossKind loss;
  };
  for (const Case& k :
       {Case{ModelKind::Seed, LossKind::None}, Case{ModelKind::Corrected, LossKind::None},
        Case{ModelKind::Seed, LossKind::Cauchy}, Case{ModelKind::Exact, LossKind::None}}) {
    Fixture f;
    make(f, k.kind, Law::hertz(), 1001, k.loss, {0.0});
    Dataset& d = f.data;
    for (std::size_t i = 0; i < d.rows(); ++i) {
      if (i % 3 == 1) d.v_x[i] = -d.v_x[i];
      if (i % 37 == 5) d.v_y[i] = 0.01;
      if (i % 41 == 7) d.omega[i] = 0.0;
      if (i % 13 == 3) d.present[static_cast<int>(Channel::M_z)][i] = 0;
    }
    d.sigma[static_cast<int>(Channel::T_y)].assign(d.rows(), 0.0);
    for (std::size_t i = 0; i < d.rows(); ++i)
      d.sigma[static_cast<int>(Channel::T_y)][i] = 2.0 + 0.01 * static_cast<double>(i % 31);
    f.problem.rows.begin = 3;  // a problem on part of the rows, chunks not at row 0
    const RepeatedCost cost(f.problem);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> scale(0.8, 1.2);
    for (int trial = 0; trial < 20; ++trial) {
      ParamVector x = f.truth;
      for (int i : f.problem.free) x[i] *= scale(rng);
      EXPECT_EQ(cost(x), problem_cost(f.problem, x)) << static_cast<int>(k.kind) << " " << trial;
    }
  }
}

TEST(LocalStage, CorrectedNormalEquationsWithHuberLossMatchCentralDifferences) {
  expect_normal_equations_match_differences(ModelKind::Corrected, Law::parabolic(),
                                            LossKind::Huber);
}

TEST(LocalStage, ExactNormalEquationsWithFreePressureExponentMatchCentralDifferences) {
  expect_normal_equations_match_differences(ModelKind::Exact, Law::power(1.5), LossKind::Cauchy);
}

TEST(LocalStage, TriangularFactorHasTheGaussNewtonMatrixOfTheRows) {
  Fixture f;
  make(f, ModelKind::Seed, Law::hertz(), 2000, LossKind::None);
  NormalEquations ne;
  ASSERT_TRUE(normal_equations(f.problem, f.truth, ne));
  const auto jf = jacobian_factor(f.problem, f.truth);
  ASSERT_TRUE(jf.has_value());
  const Eigen::MatrixXd rtr = jf->r.transpose() * jf->r;
  for (Eigen::Index a = 0; a < rtr.rows(); ++a)
    for (Eigen::Index b = 0; b < rtr.cols(); ++b)
      EXPECT_NEAR(rtr(a, b), ne.jtj(a, b), 1e-12 * std::sqrt(ne.jtj(a, a) * ne.jtj(b, b)));
  EXPECT_NEAR(2.0 * jf->cost, ne.rtr, 1e-13 * ne.rtr);
  EXPECT_NEAR(problem_cost(f.problem, f.truth), jf->cost, 1e-13 * jf->cost);
}

TEST(LocalStage, ThreadCountDoesNotChangeASingleBit) {
  Fixture f;
  make(f, ModelKind::Seed, Law::hertz(), 5000, LossKind::SoftL1);
  NormalEquations one, three;
  ASSERT_TRUE(normal_equations(f.problem, f.truth, one));
  const auto factor_one = jacobian_factor(f.problem, f.truth);
  const double cost_one = problem_cost(f.problem, f.truth);
  f.problem.threads = 3;
  ASSERT_TRUE(normal_equations(f.problem, f.truth, three));
  EXPECT_TRUE(one.jtj == three.jtj);
  EXPECT_TRUE(one.jtr == three.jtr);
  EXPECT_EQ(one.rtr, three.rtr);
  EXPECT_TRUE(factor_one->r == jacobian_factor(f.problem, f.truth)->r);
  EXPECT_EQ(cost_one, problem_cost(f.problem, f.truth));
}

// Ceres takes a trial point's cost from either pass (local_stage.cpp keeps the autodiff pass's
// normal equations for the Jacobian request that follows): they must agree to the last bit, with
// sigma columns, unmeasured values and a robust loss on the way, or the trajectory would depend on
// which pass ran.
TEST(LocalStage, AutodiffPassGivesTheSameSumOfSquaresAsThePlainPassToTheBit) {
  for (LossKind loss : {LossKind::None, LossKind::Cauchy}) {
    Fixture f;
    make(f, ModelKind::Seed, Law::hertz(), 3000, loss);
    f.data.sigma[static_cast<int>(Channel::T_y)].assign(f.data.rows(), 0.0);
    for (std::size_t i = 0; i < f.data.rows(); ++i)
      f.data.sigma[static_cast<int>(Channel::T_y)][i] = 3.0 + 0.001 * static_cast<double>(i % 97);
    for (std::size_t i = 0; i < f.data.rows(); i += 7) {
      f.data.present[static_cast<int>(Channel::M_z)][i] = 0;
      f.data.value[static_cast<int>(Channel::M_z)][i] = std::nan("");
    }
    ParamVector x = f.truth;
    for (int i : f.problem.free) x[i] *= 1.02;
    for (int threads : {1, 2}) {
      f.problem.threads = threads;
      NormalEquations ne;
      ASSERT_TRUE(normal_equations(f.problem, x, ne));
      EXPECT_EQ(ne.rtr, 2.0 * problem_cost(f.problem, x)) << threads;
    }
  }
}

TEST(LocalStage, LevenbergMarquardtReachesTheOptimumOfNoiseFreeRowsFromANearbyStart) {
  Fixture f;
  make(f, ModelKind::Seed, Law::hertz(), 1000, LossKind::None);
  f.data =
      generate_dataset(ModelKind::Seed, f.settings.law, f.truth, SyntheticDesign{}, NoiseSpec{}, 4);
  f.problem.rows.end = f.data.rows();
  ParamVector start = f.truth;
  for (int i : f.problem.free) start[i] *= 0.9;
  const LocalOutcome out = local_fit(f.problem, start, nullptr, 1, 1);
  EXPECT_TRUE(out.converged) << out.termination;
  for (int i : f.problem.free) EXPECT_NEAR(out.x[i], f.truth[i], 1e-9 * f.truth[i]) << i;
  EXPECT_LT(out.cost, 1e-20);
}

TEST(LocalStage, ANonFiniteModelFailsThePassInsteadOfReturningNaN) {
  Fixture f;
  make(f, ModelKind::Seed, Law::hertz(), 300, LossKind::None);
  f.data.N[123] = std::nan("");  // loaders reject this; the pass must not swallow it either
  NormalEquations ne;
  EXPECT_FALSE(normal_equations(f.problem, f.truth, ne));
  EXPECT_FALSE(jacobian_factor(f.problem, f.truth).has_value());
  EXPECT_FALSE(std::isfinite(problem_cost(f.problem, f.truth)));
}

}  // namespace
}  // namespace frictionid::local_stage_test
