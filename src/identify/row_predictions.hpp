// A model's resultants at many rows on several threads (eval, generate): each row is computed by
// itself, from the same evaluator, so the values are the same bits on any number of threads.
#pragma once

#include <cstddef>
#include <functional>

#include <frictionid/fit_observer.hpp>
#include <frictionid/model/kinematics.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid {

// store(i, model(kinematics(i))) for every i in [0, rows), on up to `threads` threads (0: every
// hardware thread; fewer when the calling thread's budget has fewer, thread_budget.hpp). store is
// called from those threads, once per row: it must write only row i's own slots. A row of a
// non-circular spot integrated by itself costs 6-600 us, so the rows go out a few at a time. A row
// that throws ends its part, and the first such row's error is rethrown, whichever thread met
// another first. The observer (may be null) hears the rows done (FitStage::ModelRows, every
// kRowsStep of observer_progress.hpp, from the calling thread) and is asked between parts
// whether to cancel, which ends the pass with FitError("interrupted").
void predict_rows(const ModelEvaluator<double>& model, std::size_t rows,
                  const std::function<model::Kinematics(std::size_t)>& kinematics,
                  const std::function<void(std::size_t, const model::Resultants<double>&)>& store,
                  int threads, FitObserver* observer = nullptr);

}  // namespace frictionid
