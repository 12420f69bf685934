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

#include <cmath>
#include <vector>

namespace frictionid {

enum class TwoTermForm { Affine, Additive };

struct TwoTermMaximum {
  bool found = false;  // an interior maximum (s_abs, s_rel > 0); otherwise a bound is the maximum
  double s_abs = 0.0, s_rel = 0.0;
  double neg2_loglik = 0.0;  // P at it (8.10a)
  bool converged = false;    // the Newton search ended by its criterion, not its step limit
  // Searches left early because they could not end at or below `give_up_above` (below); their
  // basins are not in found/s_abs/s_rel.
  int given_up = 0;
};

// What the search needs of the whole sample, for a caller that has it already: the largest z_i
// and the smallest positive one (z_i = y_i^2 affine, |y_i| additive; HUGE_VAL when there is
// none), and sum e_i^2 in row order.
struct TwoTermRange {
  double z_max = 0.0, z_min = HUGE_VAL, e2 = 0.0;
};
TwoTermRange two_term_range(TwoTermForm form, const std::vector<double>& y,
                            const std::vector<double>& e);

// The best interior stationary point of -2 ln L for residuals e at fitted values y (equal length,
// values of magnitude <= 1: noise_model.cpp works in units of the sample's largest value).
//
// give_up_above (for a caller that only needs to know whether the maximum lies below it): a
// Newton search whose quadratic model, trusted with a wide safety factor, promises no point at
// or below it is left there and counted in given_up. Every search that is not left takes the
// steps it would take without the bound, so a result found at or below give_up_above is the
// one found without it, to the bit.
TwoTermMaximum two_term_maximum(TwoTermForm form, const std::vector<double>& y,
                                const std::vector<double>& e);
TwoTermMaximum two_term_maximum(TwoTermForm form, const std::vector<double>& y,
                                const std::vector<double>& e, const TwoTermRange& range,
                                double give_up_above);

// Whether the grid of two_term_maximum may evaluate four points at a time in AVX2 vectors where
// the processor has AVX2 (and the build is not FRICTIONID_PORTABLE); on unless turned off. Off:
// one point at a time, the same bits. Process-wide; for tests and comparisons.
void allow_profile_lanes(bool allow);

// The gradient check (8.10c): the decrease of -2 ln L that one Fisher-scoring step from (s_abs,
// s_rel) still promises, 1/2 g' F^-1 g, g the gradient and F the Fisher information in
// log-parameters. A parameter at 0 counts only when moving it inward would descend (there in the
// parameter itself, its logarithm being -inf). 0 at a maximum, up to rounding.
double remaining_gain(TwoTermForm form, double s_abs, double s_rel, const std::vector<double>& y,
                      const std::vector<double>& e);

}  // namespace frictionid
