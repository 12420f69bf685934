// The spot integrals of a fit's rows, computed once before the search (model/spot_integral_cache
// .hpp): the exact model on a non-circular spot integrates ~60 us per row, and a fit evaluates
// every row dozens of times with the same aspect and pressure shape.
#pragma once

#include <memory>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_settings.hpp>
#include <frictionid/model/spot_integral_cache.hpp>

#include "identify/observer_progress.hpp"

namespace frictionid {

// The integrals of every spinning row at the settings' q and exponent n (their initial values),
// or nullptr when nothing can be cached: the circle, another model, or n free (its integrals
// change at every step). With q free they serve the global stage, which holds q at its start
// (fit_search.cpp); the local stage's models, whose q moves, integrate. Spread over `threads`.
// The observer (may be null) is asked to cancel before every point of a table and between
// chunks of rows, and a true answer ends the build with FitError("interrupted"); it hears the
// table's points (FitStage::ContactTable, every kTablePointsStep of model_variant.hpp) and the
// rows done (FitStage::ContactRows, every kRowsStep of observer_progress.hpp), in the calling
// thread.
std::shared_ptr<const model::SpotIntegralCache> spot_cache_for_rows(const Dataset& data,
                                                                    const FitSettings& s,
                                                                    int threads,
                                                                    FitObserver* observer);

}  // namespace frictionid
