// The maximum likelihood of a two-term variance function (docs/physics.md §8.10, (8.10a)-(8.10c)):
//
//   affine    sigma_i^2 = s_abs^2 + (s_rel y_i)^2  = A (1 + tau y_i^2)
//   additive  sigma_i   = s_abs + s_rel |y_i|       = sqrt(A) (1 + tau |y_i|)
//
// For a fixed ratio tau > 0 the best floor variance A has a closed form, so -2 ln L is a function
// of t = ln tau alone, the profile P(t), whose minimum is the likelihood maximum. One variable
// makes "from any start" checkable: P on a grid of t wide enough that its ends are the one-term
// bounds (tau -> 0: constant; tau -> inf: proportional) to rounding, then a safeguarded Newton
// search on t from each of the grid's best local minima.
#pragma once

#include <vector>

namespace frictionid {

enum class TwoTermForm { Affine, Additive };

struct TwoTermMaximum {
  bool found = false;  // an interior maximum (s_abs, s_rel > 0); otherwise a bound is the maximum
  double s_abs = 0.0, s_rel = 0.0;
  double neg2_loglik = 0.0;  // P at it (8.10a)
  bool converged = false;    // the Newton search ended by its criterion, not its step limit
};

// The best interior stationary point of -2 ln L for residuals e at fitted values y (equal length,
// values of magnitude <= 1: noise_model.cpp works in units of the sample's largest value).
TwoTermMaximum two_term_maximum(TwoTermForm form, const std::vector<double>& y,
                                const std::vector<double>& e);

// The gradient check (8.10c): the decrease of -2 ln L that one Fisher-scoring step from (s_abs,
// s_rel) still promises, 1/2 g' F^-1 g, g the gradient and F the Fisher information in
// log-parameters. A parameter at 0 counts only when moving it inward would descend (there in the
// parameter itself, its logarithm being -inf). 0 at a maximum, up to rounding.
double remaining_gain(TwoTermForm form, double s_abs, double s_rel, const std::vector<double>& y,
                      const std::vector<double>& e);

}  // namespace frictionid
