// Fits several model variants to the same rows and says which the data support (docs/physics.md §3:
// the closed forms carry shape errors of tens of percent, so this is a real question).
#pragma once

#include <cstddef>
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
  // Lag-1 autocorrelation of each fit's residuals, per channel, whitened by the common noise
  // below, ordered by eps within each curve (slip_curve: rows of one slip direction, spin sign,
  // tilt sign, load and radius; coarser when fewer than half the rows share their curve: spin
  // sign, tilt sign and direction to 10 degrees) and pooled over the curves: near 0 for a model
  // that explains the shape, near 1 for a systematic (shape) misfit.
  std::vector<std::map<std::string, double>> residual_autocorrelation;
  // Each fit estimates its own noise, so its own chi2 is close to the number of cells whatever
  // the fit: chi2 values of different fits are not comparable. chi2_common[k] is fit k's sum of
  // squared residuals divided by one sigma per row for every fit: that of the fit preferred by
  // AIC (fit_sigma), fits[common_noise_fit].
  std::vector<double> chi2_common;
  std::size_t common_noise_fit = 0;
};

// The sigma per row that fit r divided channel c's residuals by (docs/physics.md §8.2, §8.10):
// the sigma column when the file has one, else the channel's estimated noise model at the
// row's fitted value (floored at 1e-15 of the largest |fitted|, as the fit does), else the
// channel's fixed scale. NaN in rows that do not measure c; empty when c was not fitted.
std::vector<double> fit_sigma(const FitResult& r, const Dataset& d, Channel c);

// The rows whose collapsed channels share one curve of eps: one slip direction atan2(v_y, v_x)
// (micro-radians), spin sign and tilt sign. At a fixed curve every kinematic state is fixed by
// eps up to scale, so the model's collapsed values depend on eps alone, whatever the spot,
// pressure or tilt.
struct SlipCurve {
  long long direction = 0;  // atan2(v_y, v_x) in micro-radians
  int spin = 1;             // sgn omega (+1 for omega = 0)
  int tilt = 1;             // the row's tilt sign
  bool operator<(const SlipCurve& o) const {
    return direction != o.direction ? direction < o.direction
           : spin != o.spin         ? spin < o.spin
                                    : tilt < o.tilt;
  }
  bool operator==(const SlipCurve& o) const {
    return direction == o.direction && spin == o.spin && tilt == o.tilt;
  }
};
SlipCurve slip_curve(const Dataset& d, std::size_t row);

// The slip angle of the row after the mirror images collapse_factor divides out, in degrees:
// atan2(sgn(omega) v_y, |v_x|), in [-90, 90], rounded to 1e-6 degrees. Rows at one mirrored angle
// fall on one collapsed curve when the model has those mirror symmetries (native tilt along +x, no
// sideways tilt, a spot symmetric about both axes).
double mirrored_slip_angle_deg(const Dataset& d, std::size_t row);

// Divides a channel by its load scale (N, or N R for torques) and its parity sign: sgn v_x for
// T_x, sgn omega for T_y and M_z, 1 for M_roll and M_tilt. These are the signs the model's two
// mirror images take (docs/physics.md (2.14)-(2.15)): y -> -y ((v_x, v_y, omega) -> (v_x, -v_y,
// -omega) turns T_y and M_z over) and the point reflection ((v, omega) -> (-v, -omega) turns
// T_x, T_y and M_z over). Together they take every row to v_x >= 0, omega >= 0 at the slip
// angle mirrored_slip_angle_deg; rows of one slip_curve keep one factor's sign, so a collapsed
// curve never changes sign from row to row. For plots and residual-run statistics.
double collapse_factor(const Dataset& d, Channel c, std::size_t row);

// Throws like Fitter::fit. Same data, whitening scales and rows for every model.
ModelComparison compare_models(const Dataset& data, const std::vector<FitSettings>& settings,
                               FitObserver* observer = nullptr);

}  // namespace frictionid
