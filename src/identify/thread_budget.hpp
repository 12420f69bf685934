// One bound on the busy threads of a whole call (a fit, a batch, a Python fit): whatever asks for
// threads inside it (the passes over the rows, the CSV reader's parts, the report's plots, the
// bootstrap, the batch's runs) takes them from the same budget, so that `--threads N` or Dask's
// one thread per worker is the total and no layer multiplies it by its own count.
//
// The budget travels with the thread: a call installs it for its thread (ThreadBudgetScope),
// and every thread that for_each_chunk / for_each_task (row_chunks.hpp) starts inherits it, so
// no signature between the call and the innermost loop names it. Results never depend on how
// many threads a loop gets (row_chunks.hpp), so a loop that finds the budget spent simply runs
// on the threads it has.
#pragma once

#include <mutex>

namespace frictionid {

class ThreadBudget {
 public:
  // `threads` busy threads at most, the installing thread among them; 0: every hardware thread.
  explicit ThreadBudget(int threads);
  ThreadBudget(const ThreadBudget&) = delete;
  ThreadBudget& operator=(const ThreadBudget&) = delete;

  int total() const { return total_; }

  // Takes up to `wanted` more threads and returns how many it got (0 when the budget is spent).
  int acquire(int wanted);
  void release(int count);

  // The most threads that were busy at once (the installing thread counts as one).
  int peak() const;

 private:
  mutable std::mutex mutex_;
  int total_;
  int busy_ = 1;
  int peak_ = 1;
};

// The budget of the calling thread, or null when none is installed (then a loop takes the thread
// count it is given, as before budgets existed).
ThreadBudget* current_thread_budget();

// Installs `budget` for the calling thread until the scope ends (the previous one is restored).
class ThreadBudgetScope {
 public:
  explicit ThreadBudgetScope(ThreadBudget* budget);
  ~ThreadBudgetScope();
  ThreadBudgetScope(const ThreadBudgetScope&) = delete;
  ThreadBudgetScope& operator=(const ThreadBudgetScope&) = delete;

 private:
  ThreadBudget* previous_;
};

}  // namespace frictionid
