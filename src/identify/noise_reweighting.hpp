// Fits with an estimated noise model (docs/physics.md §8.10): alternate between estimating each
// channel's variance function from the residuals and refitting with the rows weighted by it,
// until the noise parameters settle. The covariance of the result is then absolute.
#pragma once

#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>

#include "identify/local_stage.hpp"

namespace frictionid {

// An estimated sigma is floored at this share of the channel's RMS fitted value: a channel whose
// residuals lie below it (a noise-free channel, residuals at rounding) is treated as exact to
// that level (docs/physics.md §8.10).
inline constexpr double kNoiseFreeSigma = 1e-6;

// Whether channel c's noise is estimated (rather than taken from its sigma column).
bool noise_estimated(const FitSettings& s, const Dataset& data, Channel c);

// Whether some channel whose noise would be estimated has k + 2 rows or fewer (k free
// parameters): a channel's noise is estimated from its own rows, so then none is, and the fixed
// scales stay with one sigma pooled over all cells (docs/physics.md §8.10).
bool noise_pooled(const FitSettings& s, const Dataset& data,
                  const std::vector<ChannelSummary>& channels, std::size_t free);

struct NoiseRefinement {
  // The noise model's sigma of every row of each estimated channel (empty for the others, whose
  // sigma columns stay): ResidualRows::sigma of the final problem.
  std::array<std::vector<double>, kChannelCount> sigma;
  LocalOutcome fit;      // the last local fit, weighted by `sigma`
  double log_det = 0.0;  // sum over observations of ln sigma_i^2 of the estimated channels
  int parameters = 0;    // noise parameters estimated
};

// Starting from the fit `start` of lp (whitened by fixed channel scales), reweights until the
// noise converges. Fills res.channel_summaries' noise, scale and scale_source, and
// res.noise_iterations. Throws FitError when a refit fails or the observer cancels.
NoiseRefinement refine_noise(const LocalProblem& lp, const LocalOutcome& start, FitResult& res,
                             FitObserver* observer);

}  // namespace frictionid
