#include "identify/row_predictions.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <vector>

#include <frictionid/fit_error.hpp>

#include "identify/observer_progress.hpp"
#include "identify/row_chunks.hpp"

namespace frictionid {

namespace {

// Rows a thread takes at a time: small enough that 64 rows already keep two threads busy, large
// enough that taking them costs nothing beside a row (~1 us on the circle).
constexpr std::size_t kPredictionRows = 16;

}  // namespace

void predict_rows(const ModelEvaluator<double>& model, std::size_t rows,
                  const std::function<model::Kinematics(std::size_t)>& kinematics,
                  const std::function<void(std::size_t, const model::Resultants<double>&)>& store,
                  int threads, FitObserver* observer) {
  const std::size_t parts = (rows + kPredictionRows - 1) / kPredictionRows;
  // The first failing row's error, so that the message does not depend on the threads either.
  std::vector<std::exception_ptr> errors(parts);
  std::atomic<bool> stopped{false};
  RowsProgress progress(observer, FitStage::ModelRows, static_cast<long>(rows));
  for_each_chunk(parts, resolve_thread_count(threads), [&](std::size_t part) {
    if (stopped.load(std::memory_order_relaxed)) return;
    if (observer && observer->cancelled()) {
      stopped = true;
      return;
    }
    progress.at();
    const std::size_t begin = part * kPredictionRows, end = std::min(rows, begin + kPredictionRows);
    try {
      for (std::size_t i = begin; i < end; ++i) store(i, model(kinematics(i)));
    } catch (...) {
      errors[part] = std::current_exception();
    }
    progress.done(end - begin);
  });
  if (stopped) throw FitError("interrupted");
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace frictionid
