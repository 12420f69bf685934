// Progress on a FitObserver from passes that run on several threads: FitObserver promises its
// calls on one thread, so a pass reports from the thread that started it only, with counts that
// are everyone's. A table's build (every kTablePointsStep points, model_variant.hpp) and a pass
// over rows (every kRowsStep rows) report so: a fit's row cache (spot_cache.hpp), eval and
// generate (row_predictions.hpp).
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>

#include <frictionid/fit_observer.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid {

inline constexpr long kRowsStep = 1024;

// A table build's stop check that also counts its points: the build asks it before every
// point, from any of its threads (spot_integral_table.hpp), and it reports FitStage::ContactTable
// with `budget` (the points the build may compute) as the total. True when the observer (may be
// null: never) asks to cancel.
std::function<bool()> table_progress_check(FitObserver* observer, long budget);

// The rows done of a pass, reported as `stage` every kRowsStep rows. Make it on the thread that
// runs the pass; each part of the pass calls at() before it starts and done() after it ends.
class RowsProgress {
 public:
  RowsProgress(FitObserver* observer, FitStage stage, long total);
  void at();
  void done(std::size_t rows) { done_ += static_cast<long>(rows); }

 private:
  FitObserver* observer_;
  FitStage stage_;
  long total_;
  std::thread::id caller_ = std::this_thread::get_id();
  std::atomic<long> done_{0};
  long shown_ = 0;  // the caller's
};

// spot_for_rows (model_variant.hpp) with its table's build reported to the observer and
// cancelled by it (FitError("interrupted")): eval's and generate's pass over their rows.
model::ContactSpot observed_spot_for_rows(ModelKind kind, const model::PressureLaw<double>& law,
                                          double q, double n, std::size_t rows,
                                          const model::ContactSpot& spot, int threads,
                                          FitObserver* observer);

}  // namespace frictionid
