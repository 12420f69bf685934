// Ceres adapter of the joint local stage (joint_stage.hpp). Every run's residual block is
// evaluated before Ceres asks for it, all runs at once on the threads (an EvaluationCallback),
// each into its own slot: the bits do not depend on the thread count, which they would if
// Ceres' own threads summed the blocks' gradients in the order they finish.
#include "identify/joint_stage.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "identify/local_stage.hpp"
#include "identify/normal_equations.hpp"
#include "identify/row_chunks.hpp"
#include "identify/solver_progress.hpp"

namespace frictionid {
namespace {

// The parameter values Ceres moves: one shared block and one own block per run. The own blocks
// lie in one array in run order: Ceres orders the blocks of an elimination group by address,
// and the reduced system's sums follow that order, so addresses from the heap (wherever earlier
// work left room) would make the bits vary from one process to the next.
struct JointState {
  std::vector<double> shared;
  std::vector<double> own_values;
  std::vector<std::size_t> own_begin;  // run r's block: own_values[own_begin[r] ..]
  double* own(std::size_t r) { return own_values.data() + own_begin[r]; }
  const double* own(std::size_t r) const { return own_values.data() + own_begin[r]; }
};

std::size_t own_count(const JointProblem& p, std::size_t r) {
  return p.runs[r].free.size() - p.shared.size();
}

ParamVector point_of(const JointProblem& p, const JointState& z, std::size_t r) {
  ParamVector x = p.start[r];
  const std::size_t ks = p.shared.size();
  for (std::size_t j = 0; j < ks; ++j) x[p.shared[j]] = z.shared[j];
  for (std::size_t j = 0; j < own_count(p, r); ++j) x[p.runs[r].free[ks + j]] = z.own(r)[j];
  return x;
}

// Every run's residuals (and Jacobian) at the current point, computed before Ceres asks.
class RunEvaluations final : public ceres::EvaluationCallback {
 public:
  RunEvaluations(const JointProblem& p, const JointState& z)
      : p_(p), z_(z), forms_(p.runs.size()), sum_sq_(p.runs.size()), good_(p.runs.size()) {}

  void PrepareForEvaluation(bool evaluate_jacobians, bool new_evaluation_point) override {
    if (!new_evaluation_point && (has_jacobians_ || !evaluate_jacobians)) return;
    for_each_chunk(p_.runs.size(), p_.threads, [&](std::size_t r) {
      const ParamVector x = point_of(p_, z_, r);
      if (evaluate_jacobians) {
        NormalEquations ne;
        good_[r] = normal_equations(p_.runs[r], x, ne);
        if (good_[r]) forms_[r] = square_root_form(ne);
      } else {
        sum_sq_[r] = 2.0 * problem_cost(p_.runs[r], x);
        good_[r] = std::isfinite(sum_sq_[r]);
      }
    });
    has_jacobians_ = evaluate_jacobians;
  }

  bool good(std::size_t r) const { return good_[r] != 0; }
  bool has_jacobians() const { return has_jacobians_; }
  const SquareRootForm& form(std::size_t r) const { return forms_[r]; }
  double sum_of_squares(std::size_t r) const { return sum_sq_[r]; }

 private:
  const JointProblem& p_;
  const JointState& z_;
  std::vector<SquareRootForm> forms_;
  std::vector<double> sum_sq_;
  std::vector<char> good_;
  bool has_jacobians_ = false;
};

// Run r's k + 1 residuals [w; rho] over the shared block and (when it has any) its own block.
class RunCost final : public ceres::CostFunction {
 public:
  RunCost(const RunEvaluations& e, std::size_t run, int shared, int own)
      : e_(e), run_(run), shared_(shared), own_(own) {
    set_num_residuals(shared + own + 1);
    mutable_parameter_block_sizes()->push_back(shared);
    if (own > 0) mutable_parameter_block_sizes()->push_back(own);
  }

  bool Evaluate(double const* const* /*parameters*/, double* residuals,
                double** jacobians) const override {
    if (!e_.good(run_)) return false;
    const int k = shared_ + own_;
    if (!e_.has_jacobians()) {
      if (jacobians != nullptr) return false;  // Ceres announced no Jacobians for this point
      std::fill(residuals, residuals + k, 0.0);
      residuals[k] = std::sqrt(e_.sum_of_squares(run_));
      return true;
    }
    const SquareRootForm& f = e_.form(run_);
    for (int i = 0; i < k; ++i) residuals[i] = f.w[i];
    residuals[k] = f.rho;
    if (jacobians == nullptr) return true;
    // Row-major (k + 1) x block-width: the shared columns first, then the run's own.
    const int widths[2] = {shared_, own_};
    for (int b = 0, col0 = 0; b < (own_ > 0 ? 2 : 1); col0 += widths[b], ++b) {
      if (jacobians[b] == nullptr) continue;
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < widths[b]; ++j) jacobians[b][i * widths[b] + j] = f.a(i, col0 + j);
      for (int j = 0; j < widths[b]; ++j) jacobians[b][k * widths[b] + j] = 0.0;
    }
    return true;
  }

 private:
  const RunEvaluations& e_;
  std::size_t run_;
  int shared_, own_;
};

}  // namespace

JointOutcome joint_local_fit(const JointProblem& p, FitObserver* observer) {
  const std::size_t ks = p.shared.size(), runs = p.runs.size();
  if (ks == 0 || runs == 0) throw std::logic_error("joint fit without shared parameters or runs");
  const FitSettings& s0 = *p.runs[0].settings;
  JointState z;
  for (int i : p.shared) z.shared.push_back(p.start[0][i]);
  for (std::size_t r = 0; r < runs; ++r) {
    z.own_begin.push_back(z.own_values.size());
    for (std::size_t j = 0; j < own_count(p, r); ++j)
      z.own_values.push_back(p.start[r][p.runs[r].free[ks + j]]);
  }

  RunEvaluations evaluations(p, z);
  ceres::Problem::Options po;
  po.evaluation_callback = &evaluations;
  ceres::Problem problem(po);
  bool any_own = false;
  for (std::size_t r = 0; r < runs; ++r) {
    const int own = static_cast<int>(own_count(p, r));
    auto* cost = new RunCost(evaluations, r, static_cast<int>(ks), own);
    if (own > 0) {
      problem.AddResidualBlock(cost, nullptr, z.shared.data(), z.own(r));
      any_own = true;
    } else {
      problem.AddResidualBlock(cost, nullptr, z.shared.data());
    }
  }
  // Bounds: the shared ones are the intersection of the runs' boxes.
  for (std::size_t j = 0; j < ks; ++j) {
    double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& run : p.runs) {
      lo = std::max(lo, run.settings->params[p.shared[j]].lower);
      hi = std::min(hi, run.settings->params[p.shared[j]].upper);
    }
    problem.SetParameterLowerBound(z.shared.data(), static_cast<int>(j), lo);
    problem.SetParameterUpperBound(z.shared.data(), static_cast<int>(j), hi);
  }
  for (std::size_t r = 0; r < runs; ++r)
    for (std::size_t j = 0; j < own_count(p, r); ++j) {
      const auto& bound = p.runs[r].settings->params[p.runs[r].free[ks + j]];
      problem.SetParameterLowerBound(z.own(r), static_cast<int>(j), bound.lower);
      problem.SetParameterUpperBound(z.own(r), static_cast<int>(j), bound.upper);
    }

  // One thread: runs are spread over threads by the evaluation callback.
  ceres::Solver::Options o = solver_options(s0);
  if (any_own) {
    // Eliminate the runs' own blocks first (group 0), then solve for the shared block.
    o.linear_solver_type = ceres::DENSE_SCHUR;
    auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
    for (std::size_t r = 0; r < runs; ++r)
      if (own_count(p, r) > 0) ordering->AddElementToGroup(z.own(r), 0);
    ordering->AddElementToGroup(z.shared.data(), 1);
    o.linear_solver_ordering = ordering;
  } else {
    o.linear_solver_type = ceres::DENSE_QR;
  }
  SolverProgress progress(observer, 0, 0, s0.max_iterations);
  o.callbacks.push_back(&progress);
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);

  JointOutcome out;
  for (std::size_t r = 0; r < runs; ++r) out.x.push_back(point_of(p, z, r));
  out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  out.termination = ceres::TerminationTypeToString(summary.termination_type);
  out.converged = summary.termination_type == ceres::CONVERGENCE ||
                  summary.termination_type == ceres::USER_SUCCESS;
  out.linear_solver = ceres::LinearSolverTypeToString(summary.linear_solver_type_used);
  out.cost = summary.final_cost;
  if (!std::isfinite(out.cost) || summary.termination_type == ceres::FAILURE)
    out.cost = std::numeric_limits<double>::infinity();
  return out;
}

}  // namespace frictionid
