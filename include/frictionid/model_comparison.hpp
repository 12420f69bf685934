// Fits several model variants to the same rows and says which the data support (docs/physics.md §3:
// the closed forms carry shape errors of tens of percent, so this is a real question).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>

namespace frictionid {

struct ModelComparison {
  std::vector<FitResult> fits;  // in the order of the settings given
  std::string preferred_by_aic, preferred_by_bic;
  std::vector<double> delta_aic, delta_bic;  // relative to the best, per fit
  // Closed-form coefficients implied by the exact fit's pressure shape and kappa (physics §3);
  // empty when no exact fit was compared.
  std::map<std::string, double> implied_by_exact;
  // Lag-1 autocorrelation of each fit's whitened residuals ordered by eps, per channel: near 0
  // for a model that explains the shape, near 1 for a systematic (shape) misfit.
  std::vector<std::map<std::string, double>> residual_autocorrelation;
};

// Divides a channel by its load scale (N, or N R for torques) and its parity sign (sign of v_x
// for T_x, of omega for T_y and M_z), so rows at every load and spin sign fall on one curve of
// eps in the aligned case: for plots and residual-run statistics.
double collapse_factor(const Dataset& d, Channel c, std::size_t row);

// Throws like Fitter::fit. Same data, whitening scales and rows for every model.
ModelComparison compare_models(const Dataset& data, const std::vector<FitSettings>& settings,
                               FitObserver* observer = nullptr);

}  // namespace frictionid
