// Warnings of a finished fit, in words a user can act on.
#pragma once

#include <vector>

#include <frictionid/fit_result.hpp>

#include "identify/local_problem.hpp"

namespace frictionid {

// Appends to res.warnings: no convergence, channels that are zero in every row, residuals that
// grow with the signal, noise estimates short of their likelihood maximum, undetermined and
// strongly correlated parameters, parameters at a bound, and what the data ranges and the pressure
// law say about the closed forms' coefficients.
void add_fit_warnings(const LocalProblem& lp, const ParamVector& x,
                      const std::vector<int>& undetermined, FitResult& res);

}  // namespace frictionid
