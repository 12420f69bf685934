// A joint fit of several runs in which some parameters are common to all runs and the rest are
// each run's own (`frictionid batch --shared kappa,h`, docs/physics.md §8.13): e.g. runs at
// several loads that share the tilt kappa and the pressure offset h but differ in friction f.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>

namespace frictionid {

struct JointRunInput {
  std::string label;
  const Dataset* data = nullptr;  // must outlive the call
  FitSettings settings;           // the run's settings (model, law, fixes, bounds, noise model)
};

struct JointRunResult {
  std::string label;
  FitResult separate;  // the run's own fit, which the joint fit starts from and whitens with
  // Every parameter the run's model reads at the joint optimum, the shared ones included, with
  // standard errors and ci95 from the joint covariance. Sandwich, profile and bootstrap
  // intervals are those of the separate fit only and are absent here.
  std::vector<ParameterEstimate> parameters;
  double cost = 0.0;  // the run's share of the joint cost
  double chi2 = 0.0;  // the run's chi², without the loss
  std::size_t observations = 0;
  double dof = 0.0;  // observations - own free parameters - its share of the shared ones
  double reduced_chi2 = 0.0;
};

struct JointFitResult {
  std::vector<ParameterEstimate> shared;  // the shared parameters, in canonical order
  std::vector<JointRunResult> runs;       // in the order given
  double cost = 0.0, chi2 = 0.0;
  std::size_t observations = 0, free_parameters = 0;
  std::size_t dof = 0;
  double reduced_chi2 = 0.0;
  int iterations = 0;
  bool converged = false;
  std::string termination;  // Ceres' termination type
  std::string linear_solver;
  double time_s = 0.0;
};

// Throws std::invalid_argument when `shared` is empty, names an unknown parameter, or one that
// the model of `s` does not read or that `s` holds fixed.
void check_shared_parameters(const FitSettings& s, const std::vector<std::string>& shared);

// Fits every run alone (Fitter), then all runs together: the shared parameters are one value
// for all runs, every other free parameter is the run's own. The rows keep the whitening of
// their run's own fit (its noise model or sigma columns), so the joint covariance is absolute.
// Throws std::invalid_argument, before any fit, where check_shared_parameters fails for a run
// (naming the run); FitError when a run's own fit or the joint fit
// fails (the message names the first such run) or the observer cancels. With at least as many
// runs as threads the runs' own fits go one per thread, and meanwhile the observer is asked only
// cancelled(), from those threads one at a time; the result does not depend on `threads`.
JointFitResult fit_joint(const std::vector<JointRunInput>& runs,
                         const std::vector<std::string>& shared, int threads = 0,
                         FitObserver* observer = nullptr);

}  // namespace frictionid
