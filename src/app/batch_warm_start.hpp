// `batch --warm-start`: every run but the first starts its local fit from the first run's
// parameters instead of running the global stage, which is most of a small fit's cost
// (docs/design.md §4.5). A cheap check guards it: the warm fit must converge and fit every channel
// about as closely as the first run fits its own; otherwise the run gets the full search, and its
// row is then the single fit's, bit for bit.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>

namespace frictionid::app {

struct WarmStart {
  std::string label;                                        // the run it comes from
  std::vector<std::pair<std::string, double>> values;       // its fitted parameters
  std::array<std::optional<double>, kChannelCount> misfit;  // channel_misfit per fitted channel
};

// A warm start from a successful fit of the run `label`.
WarmStart warm_start_from(const std::string& label, const FitResult& r);

// A fitted channel's RMSE relative to the spread of its data, sqrt(1 - R^2): comparable between
// runs of one campaign whatever their loads and noise model (a fit's whitening scale is its noise
// estimate, which a wrong basin inflates too), and far larger in a wrong basin than in the right.
std::optional<double> channel_misfit(const FitResult& r, Channel c);

// How much worse than the first run's a warm fit may fit a channel before the run falls back to
// the full search: noise levels differ between runs, a wrong basin by an order of magnitude.
inline constexpr double kWarmMisfitRatio = 2.0;

// The local fit from the warm start with settings `s` (the global stage skipped), or nullopt
// when it failed or fails the check: then the caller fits with `s` as given.
std::optional<FitResult> fit_warm(const FitSettings& s, const WarmStart& warm, const Dataset& data,
                                  FitObserver* observer);

}  // namespace frictionid::app
