// Profile-likelihood intervals (docs/physics.md §8.12): for each free parameter, the cost
// minimised over the others as the parameter is moved away from its estimate, and where that
// profile has risen by t(0.975, dof)^2 (times the reduced chi² when the covariance is scaled).
// Asymmetric where the model is not linear in the parameter, like lmfit's conf_interval.
#pragma once

#include <string>
#include <vector>

#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>

#include "identify/local_problem.hpp"

namespace frictionid {

// Fills ci95_profile and profile_closed of every free parameter with a standard error, and a
// warning for each side that does not close inside the bounds. lp is the problem the statistics
// were taken on (weighted by the noise model where there is one), x its optimum.
// With `only`, just the parameters named there.
void add_profile_intervals(const LocalProblem& lp, const ParamVector& x, FitResult& res,
                           FitObserver* observer, const std::vector<std::string>* only = nullptr);

// A pair of parameters beyond this |correlation| is strongly correlated: a warning says so, and
// their profile intervals are computed whatever the interval method (§8.12).
inline constexpr double kStrongCorrelation = 0.99;

// The parameters, in report order, with |correlation| > kStrongCorrelation to another one.
std::vector<std::string> strongly_correlated_parameters(const FitResult& res);

// The profile of parameter i through x at value v: the cost (1/2 sum of squares) with i held at
// v and the other free parameters refitted from `warm`. +inf where the refit fails.
double profile_cost(const LocalProblem& lp, int i, double v, ParamVector& warm,
                    FitObserver* observer);

}  // namespace frictionid
