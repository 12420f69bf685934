#include "identify/thread_budget.hpp"

#include <algorithm>

#include "identify/row_chunks.hpp"

namespace frictionid {

namespace {
thread_local ThreadBudget* t_budget = nullptr;
}  // namespace

ThreadBudget::ThreadBudget(int threads) : total_(resolve_thread_count(threads)) {}

int ThreadBudget::acquire(int wanted) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const int got = std::clamp(total_ - busy_, 0, std::max(wanted, 0));
  busy_ += got;
  peak_ = std::max(peak_, busy_);
  return got;
}

void ThreadBudget::release(int count) {
  const std::lock_guard<std::mutex> lock(mutex_);
  busy_ -= count;
}

int ThreadBudget::peak() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return peak_;
}

ThreadBudget* current_thread_budget() {
  return t_budget;
}

ThreadBudgetScope::ThreadBudgetScope(ThreadBudget* budget) : previous_(t_budget) {
  t_budget = budget;
}

ThreadBudgetScope::~ThreadBudgetScope() {
  t_budget = previous_;
}

}  // namespace frictionid
