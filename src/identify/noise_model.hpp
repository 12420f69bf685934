// Per-channel noise models (docs/physics.md §8.10): the variance of a channel's measurement as a
// function of its fitted value,
//
//   constant   sigma_i^2 = s_abs^2
//   relative   sigma_i^2 = s_rel^2 max(|y_i|, floor)^2     floor = 1e-3 RMS(y): no infinite weight
//   affine     sigma_i^2 = s_abs^2 + s_rel^2 y_i^2          (absolute and relative, in quadrature)
//   additive   sigma_i   = s_abs + s_rel |y_i|              (a floor plus a proportional part)
//
// estimated from residuals e_i at fitted values y_i by maximum likelihood of e_i ~ N(0, sigma_i^2)
// (closed forms for the one-term models, a profile search for the two-term ones), and chosen by
// BIC when the kind is Auto.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <frictionid/fit_settings.hpp>

namespace frictionid {

struct ChannelNoise {
  NoiseModelKind kind = NoiseModelKind::Constant;  // Constant, Relative, Affine or Additive
  double s_abs = 0.0, s_rel = 0.0;
  double floor = 0.0;        // the relative model's smallest |y|
  double neg2_loglik = 0.0;  // sum of log(sigma_i^2) + e_i^2/sigma_i^2 at the estimate
  double bic = 0.0;          // neg2_loglik + (parameters) ln n
  // Why a two-term estimate may not be the likelihood maximum (its gradient check failed);
  // empty when it is.
  std::string problem;
};

// The number of parameters of a noise model of this kind: 2 for affine and additive, else 1.
int noise_parameters(NoiseModelKind kind);

// sigma_i of a channel with noise n at fitted value y.
double noise_sigma(const ChannelNoise& n, double y);

// Estimates the noise of one channel from its fitted values and residuals (equal length, >= 2).
// kind Auto fits all four and keeps the smallest BIC. dof_factor >= 1 scales the variances to
// correct the residuals' shrinkage by the fitted parameters (n / (n - k) for k parameters).
// Auto estimates a two-term form in full only where it may beat the best BIC before it
// (docs/physics.md §8.10): the choice and the estimate are those of estimating all four.
// Takes the vectors by value: a caller that moves them in saves their copies.
// Auto chooses among the two-term forms only for a channel of at least this many rows; below,
// between constant and relative.
inline constexpr std::size_t kTwoTermNoiseRows = 20;

ChannelNoise estimate_channel_noise(std::vector<double> fitted, std::vector<double> residual,
                                    NoiseModelKind kind, double dof_factor = 1.0);

// "constant", "relative", "affine", "additive", "columns", "auto".
const char* noise_model_name(NoiseModelKind kind);

}  // namespace frictionid
