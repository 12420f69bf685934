#include "identify/solver_progress.hpp"

#include <glog/logging.h>

#include <mutex>

namespace frictionid {

ceres::CallbackReturnType SolverProgress::operator()(const ceres::IterationSummary& it) {
  if (!observer_) return ceres::SOLVER_CONTINUE;
  FitProgress p;
  p.stage = FitStage::LocalFit;
  p.done = it.iteration;
  p.total = max_iterations_;
  p.start = start_;
  p.starts = starts_;
  p.cost = it.cost;
  observer_->on_progress(p);
  return observer_->cancelled() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
}

void quiet_solver_logging() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (!google::IsGoogleLoggingInitialized()) FLAGS_minloglevel = google::GLOG_FATAL;
  });
}

}  // namespace frictionid
