#include <frictionid/joint_fit.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include <frictionid/fitter.hpp>
#include <frictionid/synthetic_data.hpp>

#include "identify/fitted_run.hpp"
#include "identify/joint_stage.hpp"
#include "support/matched_digits.hpp"

namespace frictionid::joint_fit_test {
namespace {

using Law = model::PressureLaw<double>;

using frictionid::test::matched_digits;

// A campaign of runs at several loads that share kappa and h, each with its own friction f
// (the common physical case: load-dependent friction on one tire).
struct Campaign {
  std::vector<Dataset> data;
  std::vector<std::array<double, kParamCount>> truth;
  std::vector<JointRunInput> inputs() const {
    std::vector<JointRunInput> out;
    for (std::size_t r = 0; r < data.size(); ++r)
      out.push_back({"load" + std::to_string(r), &data[r],
                     FitSettings::defaults(ModelKind::Seed, Law::hertz(), "hertz")});
    return out;
  }
};

Campaign campaign(std::size_t runs, double noise, std::uint64_t seed, std::size_t rows = 300) {
  Campaign c;
  for (std::size_t r = 0; r < runs; ++r) {
    auto truth = default_parameters(Law::hertz(), 0.7 + 0.1 * static_cast<double>(r), 1.3, 0.12);
    SyntheticDesign design;
    design.rows = rows;
    design.loads = {2000.0 + 1500.0 * static_cast<double>(r)};
    c.data.push_back(generate_dataset(ModelKind::Seed, Law::hertz(), truth, design,
                                      NoiseSpec{noise, 0.0, false}, seed * 100 + r));
    c.truth.push_back(truth);
  }
  return c;
}

const ParameterEstimate& find(const std::vector<ParameterEstimate>& ps, const std::string& n) {
  return *std::find_if(ps.begin(), ps.end(), [&](const auto& p) { return p.name == n; });
}

TEST(JointFit, NoiseFreeRunsWithCommonKappaAndHAndPerLoadFRecoverEveryParameterToTenDigits) {
  const Campaign c = campaign(3, 0.0, 1);
  const JointFitResult j = fit_joint(c.inputs(), {"h", "kappa"});
  ASSERT_EQ(j.shared.size(), 2u);
  EXPECT_EQ(j.shared[0].name, "kappa");  // canonical order, whatever order was asked
  EXPECT_GE(matched_digits(j.shared[0].value, 1.3), 10.0) << j.shared[0].value;
  EXPECT_GE(matched_digits(j.shared[1].value, 0.12), 10.0) << j.shared[1].value;
  ASSERT_EQ(j.runs.size(), 3u);
  for (std::size_t r = 0; r < 3; ++r) {
    ASSERT_EQ(j.runs[r].parameters.size(), 6u);
    for (const auto& p : j.runs[r].parameters)
      EXPECT_GE(matched_digits(p.value, c.truth[r][*param_index(p.name)]), 10.0)
          << "run " << r << " " << p.name << " = " << p.value;
    EXPECT_EQ(find(j.runs[r].parameters, "kappa").value, j.shared[0].value);
  }
  EXPECT_TRUE(j.converged) << j.termination;
  EXPECT_EQ(j.linear_solver, "DENSE_SCHUR");
}

// The joint solver itself, not the runs' own fits: from a start 10-20 % off in the shared and
// the own parameters it returns to the truth.
TEST(JointStage, FromAPerturbedStartTheSchurSolverReturnsToTheTruthToTenDigits) {
  const Campaign c = campaign(3, 0.0, 2);
  std::vector<FittedRun> fits;
  JointProblem jp;
  jp.shared = {kKappa, kH};
  for (std::size_t r = 0; r < 3; ++r) {
    fits.push_back(fit_keeping_problem(
        FitSettings::defaults(ModelKind::Seed, Law::hertz(), "hertz"), c.data[r], nullptr));
    LocalProblem p = fits.back().problem;
    p.free = {kKappa, kH, kF, kA, kB, kM};
    jp.runs.push_back(p);
    ParamVector x = c.truth[r];
    x[kKappa] *= 1.1;
    x[kH] *= 0.8;
    x[kF] *= 0.95;
    x[kM] *= 1.1;
    jp.start.push_back(x);
  }
  jp.start[1][kKappa] = jp.start[2][kKappa] = jp.start[0][kKappa];
  jp.start[1][kH] = jp.start[2][kH] = jp.start[0][kH];
  const JointOutcome o = joint_local_fit(jp, nullptr);
  ASSERT_TRUE(std::isfinite(o.cost));
  for (std::size_t r = 0; r < 3; ++r)
    for (int i : jp.runs[r].free)
      EXPECT_GE(matched_digits(o.x[r][i], c.truth[r][i]), 10.0)
          << "run " << r << " " << param_names()[i] << " = " << o.x[r][i];
}

// The Schur-complement covariance against the inverse of the whole joint Gauss-Newton matrix,
// assembled densely from every run's J^T J at the joint optimum.
TEST(JointFit, StandardErrorsEqualTheInverseOfTheWholeJointGaussNewtonMatrix) {
  const Campaign c = campaign(3, 0.01, 3, 200);
  const auto inputs = c.inputs();
  const JointFitResult j = fit_joint(inputs, {"kappa", "h"}, 1);
  // Rebuild each run's final problem at the joint optimum (the same whitening: the own fit).
  const std::size_t ks = 2, ko = 4, k = ks + 3 * ko;
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(k, k);
  for (std::size_t r = 0; r < 3; ++r) {
    FittedRun f = fit_keeping_problem(inputs[r].settings, c.data[r], nullptr);
    LocalProblem p = f.problem;
    p.free = {kKappa, kH, kF, kA, kB, kM};
    ParamVector x = f.x;
    for (const auto& e : j.runs[r].parameters) x[*param_index(e.name)] = e.value;
    NormalEquations ne;
    ASSERT_TRUE(normal_equations(p, x, ne));
    const Eigen::Index o = static_cast<Eigen::Index>(ks + r * ko);
    h.topLeftCorner(2, 2) += ne.jtj.topLeftCorner(2, 2);
    h.block(0, o, 2, 4) += ne.jtj.topRightCorner(2, 4);
    h.block(o, 0, 4, 2) += ne.jtj.bottomLeftCorner(4, 2);
    h.block(o, o, 4, 4) += ne.jtj.bottomRightCorner(4, 4);
  }
  const Eigen::MatrixXd cov = h.inverse();
  EXPECT_NEAR(*j.shared[0].std_error / std::sqrt(cov(0, 0)), 1.0, 1e-7);
  EXPECT_NEAR(*j.shared[1].std_error / std::sqrt(cov(1, 1)), 1.0, 1e-7);
  const char* own[] = {"f", "a", "b", "m"};
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t q = 0; q < ko; ++q) {
      const auto d = static_cast<Eigen::Index>(ks + r * ko + q);
      EXPECT_NEAR(*find(j.runs[r].parameters, own[q]).std_error / std::sqrt(cov(d, d)), 1.0, 1e-7)
          << "run " << r << " " << own[q];
    }
}

// Four runs pooled: the shared kappa's standard error is below every run's own, the estimate
// stays within four of them, and over replicates it scatters less than the runs' own estimates.
TEST(JointFit, SharedParametersAreMorePreciseThanSeparateFitsAndTheirErrorsHonest) {
  double joint_sq = 0.0, separate_sq = 0.0;
  int separate_n = 0;
  const int replicates = 6;
  for (int rep = 1; rep <= replicates; ++rep) {
    const Campaign c = campaign(4, 0.01, 10 + rep, 200);
    const JointFitResult j = fit_joint(c.inputs(), {"kappa", "h"});
    const ParameterEstimate& kappa = j.shared[0];
    ASSERT_TRUE(kappa.std_error);
    EXPECT_LE(std::fabs(kappa.value - 1.3), 4.0 * *kappa.std_error) << "replicate " << rep;
    joint_sq += (kappa.value - 1.3) * (kappa.value - 1.3);
    for (const auto& run : j.runs) {
      const ParameterEstimate& own = find(run.separate.parameters, "kappa");
      ASSERT_TRUE(own.std_error);
      EXPECT_LT(*kappa.std_error, *own.std_error) << run.label;
      separate_sq += (own.value - 1.3) * (own.value - 1.3);
      ++separate_n;
      // The per-run f keeps its own value: within four standard errors of its truth.
      const ParameterEstimate& f = find(run.parameters, "f");
      ASSERT_TRUE(f.std_error);
      EXPECT_LE(std::fabs(f.value - find(run.separate.parameters, "f").value), 4.0 * *f.std_error);
    }
  }
  EXPECT_LT(std::sqrt(joint_sq / replicates), std::sqrt(separate_sq / separate_n));
}

TEST(JointFit, TheResultDoesNotDependOnTheThreadCount) {
  const Campaign c = campaign(3, 0.01, 4, 200);
  const JointFitResult one = fit_joint(c.inputs(), {"kappa", "h"}, 1);
  const JointFitResult two = fit_joint(c.inputs(), {"kappa", "h"}, 2);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t i = 0; i < one.runs[r].parameters.size(); ++i) {
      EXPECT_EQ(one.runs[r].parameters[i].value, two.runs[r].parameters[i].value);
      EXPECT_EQ(one.runs[r].parameters[i].std_error, two.runs[r].parameters[i].std_error);
    }
  EXPECT_EQ(one.cost, two.cost);
}

TEST(JointFit, AFailingRunIsReportedByItsLabelTheFirstInInputOrderOnAnyThreadCount) {
  Campaign c = campaign(4, 0.01, 6, 100);
  for (std::size_t r : {1u, 3u})  // nothing measured: no fit
    for (auto& p : c.data[r].present) std::fill(p.begin(), p.end(), std::uint8_t{0});
  for (int threads : {1, 2, 4}) {
    try {
      fit_joint(c.inputs(), {"kappa"}, threads);
      ADD_FAILURE() << "no error on " << threads << " threads";
    } catch (const std::exception& e) {
      EXPECT_EQ(std::string(e.what()).rfind("run load1: ", 0), 0u) << e.what();
    }
  }
}

// Cancels once the runs' own fits have begun, polled from whichever threads fit them.
class CancelAfter : public FitObserver {
 public:
  explicit CancelAfter(int polls) : left_(polls) {}
  bool cancelled() const override { return --left_ < 0; }

 private:
  mutable std::atomic<int> left_;
};

TEST(JointFit, ACancelledObserverStopsTheRunsFittedSideBySideWithInterrupted) {
  const Campaign c = campaign(4, 0.01, 7, 200);
  CancelAfter observer(3);
  try {
    fit_joint(c.inputs(), {"kappa"}, 2, &observer);
    ADD_FAILURE() << "not interrupted";
  } catch (const FitError& e) {
    EXPECT_NE(std::string(e.what()).find("interrupted"), std::string::npos) << e.what();
  }
}

TEST(JointFit, AnUnknownFixedOrUnreadSharedParameterIsRejectedNamingIt) {
  const Campaign c = campaign(2, 0.0, 5, 100);
  auto inputs = c.inputs();
  EXPECT_THROW(fit_joint(inputs, {}), std::invalid_argument);
  try {
    fit_joint(inputs, {"kapa"});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'kapa'"), std::string::npos) << e.what();
  }
  inputs[1].settings.fix("h", 0.12);
  try {
    fit_joint(inputs, {"h"});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("run load1: shared parameter h is fixed"),
              std::string::npos)
        << e.what();
  }
  try {
    fit_joint(c.inputs(), {"p0"});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("p0 is not a parameter of its model"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace frictionid::joint_fit_test
