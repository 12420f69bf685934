// Warnings of a finished fit, in words a user can act on.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <frictionid/fit_result.hpp>

#include "identify/fit_statistics.hpp"
#include "identify/local_problem.hpp"

namespace frictionid {

// Appends to res.warnings: no convergence, channels that are zero in every row, residuals that
// grow with the signal, noise estimates short of their likelihood maximum, undetermined and
// strongly correlated parameters, parameters at a bound, and what the data ranges and the pressure
// law say about the closed forms' coefficients.
// `detail` (from add_fit_statistics) gives the covariance and the sandwich's expected spread;
// without it the sandwich and law comparisons use the standard errors alone.
void add_fit_warnings(const LocalProblem& lp, const ParamVector& x,
                      const std::vector<int>& undetermined, FitResult& res,
                      const FitStatisticsDetail* detail = nullptr);

// The standard error of c - c_law(kappa), a fitted coefficient's gap to the value the pressure
// law implies at the fitted kappa, by the delta method: var c + slope² var kappa
// - 2 slope cov(c, kappa), slope = d c_law/d kappa. Without kappa's variance (kappa fixed) the
// coefficient's alone. nullopt when the variance is not positive.
std::optional<double> law_gap_std_error(double var_coefficient, std::optional<double> var_kappa,
                                        std::optional<double> cov_coefficient_kappa, double slope);

// The Wald-Wolfowitz runs test over groups of residuals, each in its order: runs of one sign
// counted in every group, their expectation and variance given each group's counts of positive
// and negative residuals summed (zeros skipped, groups of fewer than 2 left out), and
// z = (runs - expected)/sqrt(variance) (0 when the variance is 0).
struct RunsTest {
  std::size_t rows = 0;
  double runs = 0.0, expected = 0.0, variance = 0.0, z = 0.0;
};
RunsTest residual_runs(const std::vector<std::vector<double>>& groups);

// The 0.1 % (p = 0.001) or 99.9 % (p = 0.999) quantile of chi² with nu degrees of freedom
// (Wilson-Hilferty).
double chi2_quantile(double p, double nu);
inline constexpr double kNormalQuantile999 = 3.090232306167813;

// Whether HC3's variance, as a ratio to what a correct noise model makes it expect (§8.11), is
// evidence against the noise model: the standard errors differ by more than 25 % and the ratio
// lies outside the central 99.8 % of chi²_nu/nu.
bool sandwich_disagrees(double ratio, double nu);

}  // namespace frictionid
