// A finished single fit together with the problem it ended on: the whitened rows, free
// parameters and optimum that a joint fit over several runs (joint_fit.hpp) starts from.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>

#include "identify/local_problem.hpp"

namespace frictionid {

struct FittedRun {
  FitResult result;
  std::unique_ptr<FitSettings> settings;  // what problem.settings points at
  // The estimated noise model's sigmas (problem.rows.sigma points here); null when no noise
  // model was estimated. problem's rows point at the caller's dataset, which must outlive this.
  std::unique_ptr<std::array<std::vector<double>, kChannelCount>> noise_sigma;
  LocalProblem problem;  // whitened as the statistics saw it
  ParamVector x{};       // the optimum
};

// Fitter::fit, keeping the final problem. Throws as Fitter::fit does.
FittedRun fit_keeping_problem(const FitSettings& s, const Dataset& data, FitObserver* observer);

}  // namespace frictionid
