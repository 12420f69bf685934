// A table build's stop check that also counts its points for a FitObserver: the build asks it
// before every point, from any of its threads (spot_integral_table.hpp), and it reports
// FitStage::ContactTable every kTablePointsStep points (model_variant.hpp) from the thread that
// made it only, as FitObserver promises; the count is everyone's. A fit's row cache, eval and
// generate build their tables with it.
#pragma once

#include <functional>

#include <frictionid/fit_observer.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid {

// True when the observer (may be null: never) asks to cancel. `budget`: the points the build
// may compute, reported as the stage's total.
std::function<bool()> table_progress_check(FitObserver* observer, long budget);

// spot_for_rows (model_variant.hpp) with its table's build reported to the observer and
// cancelled by it (FitError("interrupted")): eval's and generate's pass over their rows.
model::ContactSpot observed_spot_for_rows(ModelKind kind, const model::PressureLaw<double>& law,
                                          double q, double n, std::size_t rows,
                                          const model::ContactSpot& spot, int threads,
                                          FitObserver* observer);

}  // namespace frictionid
