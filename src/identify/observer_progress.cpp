#include "identify/observer_progress.hpp"

#include <atomic>
#include <memory>
#include <thread>

#include <frictionid/fit_error.hpp>
#include <frictionid/model/spot_integral_table.hpp>

namespace frictionid {

std::function<bool()> table_progress_check(FitObserver* observer, long budget) {
  struct Count {
    std::atomic<long> points{0};
    long shown = 0;  // the calling thread's
  };
  auto count = std::make_shared<Count>();
  const std::thread::id caller = std::this_thread::get_id();
  return [observer, budget, count, caller] {
    const long n = ++count->points;
    if (observer && std::this_thread::get_id() == caller && n - count->shown >= kTablePointsStep) {
      count->shown = n;
      FitProgress p;
      p.stage = FitStage::ContactTable;
      p.done = n;
      p.total = budget;
      observer->on_progress(p);
    }
    return observer != nullptr && observer->cancelled();
  };
}

RowsProgress::RowsProgress(FitObserver* observer, FitStage stage, long total)
    : observer_(observer), stage_(stage), total_(total) {}

void RowsProgress::at() {
  if (!observer_ || std::this_thread::get_id() != caller_) return;
  const long now = done_.load(std::memory_order_relaxed);
  if (now - shown_ < kRowsStep) return;
  shown_ = now;
  FitProgress p;
  p.stage = stage_;
  p.done = now;
  p.total = total_;
  observer_->on_progress(p);
}

model::ContactSpot observed_spot_for_rows(ModelKind kind, const model::PressureLaw<double>& law,
                                          double q, double n, std::size_t rows,
                                          const model::ContactSpot& spot, int threads,
                                          FitObserver* observer) {
  const std::size_t budget = spot_table_budget(spot, law, rows);
  if (budget == 0) return spot;
  try {
    return spot_with_table_if_bounded(kind, law, q, n, spot, budget,
                                      table_progress_check(observer, static_cast<long>(budget)),
                                      threads);
  } catch (const model::SpotTableBuildStopped&) {
    throw FitError("interrupted");
  }
}

}  // namespace frictionid
