// The search for the optimum: the global stage over the bounds box on a subsample, local fits
// from its best distinct points, and the best of them refined on all rows.
#pragma once

#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>

#include "identify/local_stage.hpp"

namespace frictionid {

struct SearchOutcome {
  LocalOutcome best;  // the final local fit, on all rows
  ParamVector start;  // the point the winning local fit started from
};

// Fills res.global and, where the global stage failed, a warning. Throws FitError when every
// local fit failed or the observer cancelled.
SearchOutcome search_optimum(const LocalProblem& lp, const ParamVector& initial, FitResult& res,
                             FitObserver* observer);

}  // namespace frictionid
