// Statistics of a finished fit (docs/physics.md §8): covariance from the whitened Jacobian,
// standard errors and intervals, correlation, chi², information criteria, per-channel RMSE and
// R², and the per-row predictions for plots.
#pragma once

#include <optional>
#include <vector>

#include <frictionid/fit_result.hpp>

#include <Eigen/Core>

#include "identify/local_problem.hpp"

namespace frictionid {

// What an estimated noise model adds to the likelihood: sum of ln sigma_i^2 over the
// observations, and its parameters.
struct NoiseTerms {
  double log_det = 0.0;
  int parameters = 0;
};

// What the warnings need beyond FitResult, per free parameter in lp.free's order.
struct FitStatisticsDetail {
  // The covariance of the free parameters as the standard errors use it (scaled by the reduced
  // chi² where res says so); rows and columns of undetermined parameters are 0.
  Eigen::MatrixXd covariance;
  std::vector<bool> determined;
  // The HC3 variance a correct noise model leads one to expect, sum_i q_il (times the reduced
  // chi² where the covariance is scaled), and the degrees of freedom of its chi² approximation,
  // (sum_i q_il)^2 / sum_i q_il^2 (Satterthwaite; see sandwich_meat). Absent without HC3.
  std::vector<std::optional<double>> sandwich_expected, sandwich_dof;
  // The degrees of freedom of each parameter's interval, (8.6a): n - k, or fewer where the
  // channels' noise was estimated.
  std::vector<double> interval_dof;
};

// Fills res.parameters, correlation, cost, chi2, dof, reduced_chi2, aic, bic, the channel
// summaries' rmse and r2, eps and fitted. Returns the free parameters the data do not determine.
// Throws FitError when the model is not finite at x. Fills `detail` when given.
std::vector<int> add_fit_statistics(const LocalProblem& lp, const ParamVector& x,
                                    const ParamVector& start, const NoiseTerms& noise,
                                    FitResult& res, FitStatisticsDetail* detail = nullptr);

// chi² of the problem at x without the loss (the cost keeps the loss's robustification).
double plain_chi2(const LocalProblem& lp, const ParamVector& x);

// Parameter i of the settings at `value`: bounds, fixed, at_bound and, where the variance is
// given, finite and not negative, its standard error and value -/+ tq * stderr as ci95.
ParameterEstimate parameter_estimate(const FitSettings& s, int i, double value,
                                     std::optional<double> variance, double tq);

// Whether x sits on a bound: within 1e-9 (1 + |bound|) of it, an absolute-plus-relative distance
// that does not grow with the width of the box.
bool at_bound(double x, double lower, double upper);

// AIC and BIC of a least-squares fit with k free parameters and n observations. With known
// sigmas (absolute_sigma) -2 log L = chi² + const, so AIC = chi² + 2k, BIC = chi² + k ln n;
// with one sigma estimated from the residuals -2 log L = n ln(chi²/n) + const. An estimated
// noise model adds its sum of ln sigma_i^2 to -2 log L and its parameters to k (noise).
struct InformationCriteria {
  double aic = 0.0, bic = 0.0;
};
InformationCriteria information_criteria(double chi2, std::size_t n, std::size_t k,
                                         bool absolute_sigma, const NoiseTerms& noise = {});

}  // namespace frictionid
