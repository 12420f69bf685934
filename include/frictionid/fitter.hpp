// The runner: global stage (NLopt, on a subsample) then local stage (Ceres, autodiff, all rows)
// from the best distinct global points, then statistics and warnings. Never opens a file, never
// writes to a stream: progress, diagnostics and cancellation go through a FitObserver.
#pragma once

#include <frictionid/dataset.hpp>
#include <frictionid/fit_error.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>

namespace frictionid {

class Fitter {
 public:
  explicit Fitter(FitSettings settings) : settings_(std::move(settings)) {}
  const FitSettings& settings() const { return settings_; }

  // Fits the data. Throws std::invalid_argument for settings that FitSettings::validate rejects
  // or that do not fit the data (no rows, no measured channel), FitError for a failed or
  // cancelled fit. The observer (may be null) sees progress and diagnostics and can cancel.
  FitResult fit(const Dataset& data, FitObserver* observer = nullptr) const;

 private:
  FitSettings settings_;
};

}  // namespace frictionid
