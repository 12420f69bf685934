// What the local stages (local_stage.cpp, joint_stage.cpp) tell Ceres and take from it: each
// iteration goes to the fit's observer, which may stop the solver, and Ceres' own log stays quiet
// unless the host set glog up.
#pragma once

#include <ceres/iteration_callback.h>

#include <frictionid/fit_observer.hpp>

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

}  // namespace frictionid
