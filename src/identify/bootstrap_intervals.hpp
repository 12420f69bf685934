// Wild bootstrap intervals (docs/physics.md §8.12): replicate data sets y* = y_fit + e v with the
// fit's residuals e and one Rademacher sign v = +-1 per row (so each row keeps its own noise
// level and its channels their correlation), each refitted from the estimate with the same
// weights; percentile 95 % intervals ((B + 1)α-th order statistics) and the standard deviation of
// the refits.
#pragma once

#include <vector>

#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>

#include "identify/local_problem.hpp"

namespace frictionid {

// Runs `replicates` refits spread over lp's threads; replicate b draws its signs from a
// generator seeded by (seed, b) alone, so the intervals do not depend on the thread count.
// Fills ci95_bootstrap and std_error_bootstrap of the free parameters and
// res.bootstrap_replicates (refits that converged to a finite cost).
void add_bootstrap_intervals(const LocalProblem& lp, const ParamVector& x, int replicates,
                             unsigned long long seed, FitResult& res, FitObserver* observer);

// The q-percentile of the sorted refits by the standard bootstrap rule (docs/physics.md §8.12):
// the (B + 1) q-th order statistic (1-based) of B values, linear between neighbouring order
// statistics when (B + 1) q is not an integer, clamped to the smallest and largest value. At
// B = 199 the 2.5 % and 97.5 % points are exactly the 5th and 195th refit.
double bootstrap_percentile(const std::vector<double>& sorted, double q);

// The sign of row `row` in replicate b: +1 or -1, from a counter-based generator.
int rademacher_sign(unsigned long long seed, int replicate, std::size_t row);

}  // namespace frictionid
