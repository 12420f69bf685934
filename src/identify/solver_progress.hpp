// What the local stages (local_stage.cpp, joint_stage.cpp) tell Ceres and take from it: each
// iteration goes to the fit's observer, which may stop the solver, and Ceres' own log stays quiet
// unless the host set glog up.
#pragma once

#include <ceres/iteration_callback.h>
#include <ceres/solver.h>

#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_settings.hpp>

namespace frictionid {

// Reports every Levenberg-Marquardt iteration as local-fit progress of start `start` of
// `starts` (0 of 0 for a joint fit); stops the solver when the observer cancels.
class SolverProgress final : public ceres::IterationCallback {
 public:
  SolverProgress(FitObserver* observer, int start, int starts, int max_iterations)
      : observer_(observer), start_(start), starts_(starts), max_iterations_(max_iterations) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& it) override;

 private:
  FitObserver* observer_;
  int start_, starts_, max_iterations_;
};

// Ceres logs through glog. A host that never set glog up would get its warnings ("Error in
// evaluating the ResidualBlock ...", one per failed step) on stderr, while every failure reaches
// the caller as a FitError or a warning in words; such a host gets only fatal messages.
void quiet_solver_logging();

// Levenberg-Marquardt with the fit's limits and tolerances, quiet, on the calling thread (the
// stages spread their own work over threads); the caller picks the linear solver and adds the
// callbacks. Ceres' projected line search under bounds would cost one more Jacobian per
// iteration; bounds stay enforced by projecting the trust-region step, so it is off.
inline ceres::Solver::Options solver_options(const FitSettings& s) {
  quiet_solver_logging();
  ceres::Solver::Options o;
  o.max_num_line_search_step_size_iterations = 0;
  o.max_num_iterations = s.max_iterations;
  o.function_tolerance = s.function_tolerance;
  o.gradient_tolerance = s.gradient_tolerance;
  o.parameter_tolerance = s.parameter_tolerance;
  o.num_threads = 1;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  return o;
}

}  // namespace frictionid
