// The runner: global stage (NLopt, on a subsample) then local stage (Ceres, autodiff, all rows)
// from the best distinct global points, then statistics. Never opens a file.
#pragma once

#include <atomic>
#include <stdexcept>

#include "identify/dataset.hpp"
#include "identify/fit_result.hpp"
#include "identify/fit_settings.hpp"

namespace frictionid {

// A fit that cannot produce a usable result (every start failed, interrupted, no channel).
class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Fitter {
 public:
  explicit Fitter(FitSettings settings) : settings_(std::move(settings)) {}
  const FitSettings& settings() const { return settings_; }

  // Throws std::invalid_argument for settings that do not fit the data, FitError for failure.
  // cancel, when set during the run, stops it at the next evaluation (FitError "interrupted").
  FitResult fit(const Dataset& data, const std::atomic<bool>* cancel = nullptr) const;

 private:
  FitSettings settings_;
};

}  // namespace frictionid
