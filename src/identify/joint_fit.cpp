// The joint fit (joint_fit.hpp, docs/physics.md §8.13): the runs' own fits, a common start for
// the shared parameters, the joint local stage and the joint covariance by the Schur complement.
#include <frictionid/joint_fit.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <set>

#include <frictionid/fit_error.hpp>

#include "identify/fit_statistics.hpp"
#include "identify/fitted_run.hpp"
#include "identify/joint_stage.hpp"
#include "identify/local_stage.hpp"
#include "identify/row_chunks.hpp"
#include "identify/statistics.hpp"

namespace frictionid {
namespace {

std::vector<int> shared_indices(const std::vector<std::string>& names) {
  if (names.empty()) throw std::invalid_argument("no shared parameter named");
  std::set<int> out;
  for (const auto& n : names) {
    const auto i = param_index(n);
    if (!i)
      throw std::invalid_argument("unknown parameter '" + n +
                                  "' (f, kappa, h, a, b, m, n, p0, b_tilde)");
    out.insert(*i);
  }
  return {out.begin(), out.end()};
}

// The run's problem with the shared parameters (free in it: check_shared_parameters) first
// among the free ones.
LocalProblem shared_first(const LocalProblem& p, const std::vector<int>& shared) {
  LocalProblem q = p;
  q.free = shared;
  for (int i : p.free)
    if (std::find(shared.begin(), shared.end(), i) == shared.end()) q.free.push_back(i);
  return q;
}

// Inverse-variance weighted mean of the runs' own estimates (plain mean where a run has no
// standard error), clamped into every run's bounds.
double common_start(const std::vector<FittedRun>& fits, int i) {
  double sw = 0.0, swx = 0.0, sum = 0.0;
  bool weighted = true;
  double lo = -HUGE_VAL, hi = HUGE_VAL;
  for (const auto& f : fits) {
    const ParameterEstimate* e = nullptr;
    for (const auto& p : f.result.parameters)
      if (p.name == param_names()[i]) e = &p;
    const double x = f.x[i];
    sum += x;
    if (e && e->std_error && *e->std_error > 0.0) {
      sw += 1.0 / (*e->std_error * *e->std_error);
      swx += x / (*e->std_error * *e->std_error);
    } else {
      weighted = false;
    }
    lo = std::max(lo, f.settings->params[i].lower);
    hi = std::min(hi, f.settings->params[i].upper);
  }
  const double x = weighted && sw > 0.0 ? swx / sw : sum / static_cast<double>(fits.size());
  return std::clamp(x, lo, hi);
}

// Inverse of a symmetric positive definite matrix through its equilibrated eigen-decomposition;
// false when it is singular to working precision.
bool spd_inverse(const Eigen::MatrixXd& h, Eigen::MatrixXd& out) {
  const Eigen::Index n = h.rows();
  if (n == 0) {
    out.resize(0, 0);
    return true;
  }
  Eigen::VectorXd d(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(h(i, i) > 0.0) || !std::isfinite(h(i, i))) return false;
    d[i] = 1.0 / std::sqrt(h(i, i));
  }
  const Eigen::MatrixXd e = d.asDiagonal() * h * d.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(e);
  if (es.info() != Eigen::Success) return false;
  const Eigen::VectorXd ev = es.eigenvalues();
  if (!(ev.minCoeff() > 1e-14 * ev.maxCoeff())) return false;
  out = d.asDiagonal() * es.eigenvectors() * ev.cwiseInverse().asDiagonal() *
        es.eigenvectors().transpose() * d.asDiagonal();
  return true;
}

// Passes on only cancellation, which the runs fitted side by side poll from several threads:
// progress lines of interleaved runs would mean nothing, and observers need not be thread-safe.
class CancelOnlyObserver : public FitObserver {
 public:
  explicit CancelOnlyObserver(const FitObserver* inner) : inner_(inner) {}
  bool cancelled() const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    return inner_ && inner_->cancelled();
  }

 private:
  const FitObserver* inner_;
  mutable std::mutex mutex_;
};

}  // namespace

void check_shared_parameters(const FitSettings& s, const std::vector<std::string>& shared) {
  const std::vector<int> used = s.used_parameters();
  for (int i : shared_indices(shared)) {
    if (std::find(used.begin(), used.end(), i) == used.end())
      throw std::invalid_argument(std::string(param_names()[i]) +
                                  " is not a parameter of its model (" + model_name(s.model) + ")");
    if (s.params[i].fixed)
      throw std::invalid_argument(std::string("shared parameter ") + param_names()[i] +
                                  " is fixed");
  }
}

namespace {

// 1. Every run alone: its optimum and the whitening its noise model gives. With at least as many
// runs as threads, one run per thread (a fit's bits do not depend on its thread count); the first
// failing run in input order is the one reported, whatever the schedule.
std::vector<FittedRun> fit_runs_alone(const std::vector<JointRunInput>& inputs, int workers,
                                      bool parallel_runs, FitObserver* observer) {
  for (const auto& in : inputs)
    if (in.data == nullptr) throw std::invalid_argument("run " + in.label + ": no data");
  std::vector<FittedRun> fits(inputs.size());
  std::vector<std::exception_ptr> failed(inputs.size());
  CancelOnlyObserver cancel_only(observer);
  FitObserver* run_observer = parallel_runs && workers > 1 ? &cancel_only : observer;
  for_each_task(inputs.size(), parallel_runs ? workers : 1, [&](std::size_t r) {
    const JointRunInput& in = inputs[r];
    FitSettings s = in.settings;
    s.threads = parallel_runs ? 1 : workers;
    try {
      fits[r] = fit_keeping_problem(s, *in.data, run_observer);
    } catch (const FitError& e) {
      failed[r] = std::make_exception_ptr(FitError("run " + in.label + ": " + e.what()));
    } catch (const std::invalid_argument& e) {
      failed[r] =
          std::make_exception_ptr(std::invalid_argument("run " + in.label + ": " + e.what()));
    }
  });
  if (observer && observer->cancelled()) throw FitError("interrupted");
  for (const auto& f : failed)
    if (f) std::rethrow_exception(f);
  return fits;
}

// 2. One problem over all runs, the shared parameters first, from their common start.
JointProblem joint_problem(const std::vector<FittedRun>& fits, const std::vector<int>& shared,
                           int workers, bool parallel_runs) {
  JointProblem jp;
  jp.shared = shared;
  jp.threads = parallel_runs ? workers : 1;
  std::vector<double> start(shared.size());
  for (std::size_t j = 0; j < shared.size(); ++j) start[j] = common_start(fits, shared[j]);
  for (const FittedRun& fit : fits) {
    jp.runs.push_back(shared_first(fit.problem, shared));
    jp.runs.back().threads = parallel_runs ? 1 : workers;
    ParamVector x = fit.x;
    for (std::size_t j = 0; j < shared.size(); ++j) x[shared[j]] = start[j];
    jp.start.push_back(x);
  }
  return jp;
}

// 3. The joint covariance: H = sum of the runs' J^T J, with the runs' own blocks eliminated
// (the Schur complement on the shared block).
struct JointCovariance {
  std::vector<Eigen::MatrixXd> h;            // each run's J^T J, shared parameters first
  std::vector<Eigen::MatrixXd> own_inverse;  // each run's own block, inverted
  Eigen::MatrixXd shared;                    // the shared parameters' covariance
  bool determined = true;
};

JointCovariance joint_covariance(const JointProblem& jp, const JointOutcome& joint) {
  const auto kse = static_cast<Eigen::Index>(jp.shared.size());
  const std::size_t runs = jp.runs.size();
  JointCovariance c;
  c.h.resize(runs);
  c.own_inverse.resize(runs);
  std::vector<char> good(runs, 1);
  for_each_chunk(runs, jp.threads, [&](std::size_t r) {
    NormalEquations ne;
    good[r] = normal_equations(jp.runs[r], joint.x[r], ne);
    c.h[r] = ne.jtj;
  });
  if (std::any_of(good.begin(), good.end(), [](char g) { return g == 0; }))
    throw FitError("the model is not finite at the joint optimum");
  Eigen::MatrixXd schur = Eigen::MatrixXd::Zero(kse, kse);
  for (std::size_t r = 0; r < runs; ++r) {
    const Eigen::Index ko = c.h[r].rows() - kse;
    const Eigen::MatrixXd hss = c.h[r].topLeftCorner(kse, kse);
    const Eigen::MatrixXd hsp = c.h[r].topRightCorner(kse, ko);
    if (!spd_inverse(c.h[r].bottomRightCorner(ko, ko), c.own_inverse[r])) {
      c.determined = false;
      continue;
    }
    schur += hss - hsp * c.own_inverse[r] * hsp.transpose();
  }
  c.determined = c.determined && spd_inverse(schur, c.shared);
  return c;
}

// 4. The shared estimates and every run's own, their costs and chi², at the joint optimum.
JointFitResult joint_result(const std::vector<JointRunInput>& inputs, std::vector<FittedRun>& fits,
                            const JointProblem& jp, const JointOutcome& joint,
                            const JointCovariance& c) {
  const std::vector<int>& shared = jp.shared;
  const std::size_t ks = shared.size();
  const auto kse = static_cast<Eigen::Index>(ks);
  JointFitResult out;
  out.iterations = joint.iterations;
  out.converged = joint.converged;
  out.termination = joint.termination;
  out.linear_solver = joint.linear_solver;
  out.free_parameters = ks;
  for (std::size_t r = 0; r < fits.size(); ++r) {
    for (const auto& cs : fits[r].result.channel_summaries) out.observations += cs.rows;
    out.free_parameters += jp.runs[r].free.size() - ks;
  }
  out.dof = out.observations > out.free_parameters ? out.observations - out.free_parameters : 0;
  const double tq = out.dof > 0 ? student_t_quantile(0.975, static_cast<double>(out.dof)) : 0.0;
  const FitSettings& s0 = *fits[0].settings;
  for (std::size_t j = 0; j < ks; ++j) {
    const auto je = static_cast<Eigen::Index>(j);
    out.shared.push_back(parameter_estimate(
        s0, shared[j], joint.x[0][shared[j]],
        c.determined ? std::optional<double>(c.shared(je, je)) : std::nullopt, tq));
  }

  for (std::size_t r = 0; r < fits.size(); ++r) {
    JointRunResult run;
    run.label = inputs[r].label;
    const LocalProblem& p = jp.runs[r];
    const ParamVector& x = joint.x[r];
    const Eigen::Index ko = c.h[r].rows() - kse;
    Eigen::MatrixXd cov_pp;
    if (c.determined) {
      // Cov_pp = H_pp^-1 + H_pp^-1 H_ps Cov_ss H_sp H_pp^-1
      const Eigen::MatrixXd g = c.own_inverse[r] * c.h[r].topRightCorner(kse, ko).transpose();
      cov_pp = c.own_inverse[r] + g * c.shared * g.transpose();
    }
    for (int i : p.used) {
      const auto at = std::find(p.free.begin(), p.free.end(), i) - p.free.begin();
      std::optional<double> var;
      if (c.determined && at < static_cast<long>(p.free.size()))
        var = at < kse ? c.shared(at, at) : cov_pp(at - kse, at - kse);
      run.parameters.push_back(parameter_estimate(*p.settings, i, x[i], var, tq));
    }
    run.cost = problem_cost(p, x);
    run.chi2 = plain_chi2(p, x);
    for (const auto& cs : fits[r].result.channel_summaries) run.observations += cs.rows;
    run.dof = static_cast<double>(run.observations) - static_cast<double>(ko) -
              static_cast<double>(ks) / static_cast<double>(fits.size());
    run.reduced_chi2 =
        run.dof > 0.0 ? run.chi2 / run.dof : std::numeric_limits<double>::quiet_NaN();
    out.cost += run.cost;
    out.chi2 += run.chi2;
    run.separate = std::move(fits[r].result);
    out.runs.push_back(std::move(run));
  }
  out.reduced_chi2 = out.dof > 0 ? out.chi2 / static_cast<double>(out.dof)
                                 : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace

JointFitResult fit_joint(const std::vector<JointRunInput>& inputs,
                         const std::vector<std::string>& shared_names, int threads,
                         FitObserver* observer) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const std::vector<int> shared = shared_indices(shared_names);
  if (inputs.empty()) throw std::invalid_argument("a joint fit needs at least one run");
  for (const auto& in : inputs) {
    try {
      check_shared_parameters(in.settings, shared_names);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("run " + in.label + ": " + e.what());
    }
  }
  const int workers = resolve_thread_count(threads);
  const bool parallel_runs = inputs.size() >= static_cast<std::size_t>(workers);
  std::vector<FittedRun> fits = fit_runs_alone(inputs, workers, parallel_runs, observer);
  const JointProblem jp = joint_problem(fits, shared, workers, parallel_runs);
  const JointOutcome joint = joint_local_fit(jp, observer);
  if (observer && observer->cancelled()) throw FitError("interrupted");
  if (!std::isfinite(joint.cost))
    throw FitError("the joint fit failed (" + joint.termination + ")");
  JointFitResult out = joint_result(inputs, fits, jp, joint, joint_covariance(jp, joint));
  out.time_s = std::chrono::duration<double>(clock::now() - t0).count();
  return out;
}

}  // namespace frictionid
