#include "identify/row_chunks.hpp"

#include <algorithm>
#include <atomic>
#include <climits>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "identify/thread_budget.hpp"

namespace frictionid {

int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(std::min(hw, 64u)) : 1;
}

namespace {

// Runs work(0..count-1) on `parts` threads (the caller's among them), each taking the next index;
// on fewer when the calling thread's budget (thread_budget.hpp) has fewer to give.
void run_on_threads(std::size_t count, std::size_t parts,
                    const std::function<void(std::size_t)>& work) {
  ThreadBudget* const budget = current_thread_budget();
  if (budget && parts > 1)
    parts = 1 + static_cast<std::size_t>(budget->acquire(static_cast<int>(
                    std::min<std::size_t>(parts - 1, static_cast<std::size_t>(INT_MAX)))));
  // Given back when the threads have joined, also when work threw.
  struct Release {
    ThreadBudget* budget;
    std::size_t extra;
    ~Release() {
      if (budget && extra > 0) budget->release(static_cast<int>(extra));
    }
  } release{budget, parts > 0 ? parts - 1 : 0};
  if (parts <= 1) {
    for (std::size_t c = 0; c < count; ++c) work(c);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto run = [&] {
    const ThreadBudgetScope scope(budget);  // threads started here draw from the same budget
    for (;;) {
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= count) return;
      try {
        work(c);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next.store(count);
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < parts; ++t) pool.emplace_back(run);
  run();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace

void for_each_chunk(std::size_t count, int threads, const std::function<void(std::size_t)>& work) {
  // A thread costs tens of microseconds to start: not worth it for a few chunks.
  run_on_threads(count,
                 std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count / 4),
                 work);
}

void for_each_task(std::size_t count, int threads, const std::function<void(std::size_t)>& work) {
  run_on_threads(
      count, std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count), work);
}

}  // namespace frictionid
