// The thread budget bounds the busy threads of nested loops, and a loop's results do not depend
// on how many threads the budget let it have.
#include "identify/thread_budget.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <thread>
#include <vector>

#include "identify/row_chunks.hpp"

namespace frictionid::thread_budget_test {
namespace {

// Counts the threads inside `work` at once and keeps the most seen.
struct Concurrency {
  std::atomic<int> now{0}, most{0};
  void enter() {
    const int n = ++now;
    int m = most.load();
    while (n > m && !most.compare_exchange_weak(m, n)) {
    }
    // Long enough for the other threads of the loop to arrive.
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  void leave() { --now; }
};

// Outer tasks, each running an inner chunked loop: the shape of a batch of fits, or of a fit
// whose statistics start per-channel tasks.
void nested_loops(Concurrency& c) {
  for_each_task(4, 4, [&](std::size_t) {
    for_each_chunk(64, 8, [&](std::size_t) {
      c.enter();
      c.leave();
    });
  });
}

TEST(ThreadBudget, NestedLoopsWithoutABudgetRunMoreThreadsThanTheyWouldBeGiven) {
  Concurrency c;
  nested_loops(c);
  EXPECT_GT(c.most.load(), 2);  // what the budget is for: 4 outer x up to 8 inner
}

TEST(ThreadBudget, NestedLoopsUnderABudgetOfTwoNeverRunMoreThanTwoThreads) {
  Concurrency c;
  ThreadBudget budget(2);
  {
    const ThreadBudgetScope scope(&budget);
    nested_loops(c);
  }
  EXPECT_LE(c.most.load(), 2);
  EXPECT_EQ(budget.peak(), 2);      // and it does use the two
  EXPECT_EQ(budget.acquire(5), 1);  // every thread given back: one besides the caller's
}

TEST(ThreadBudget, ABudgetOfOneRunsEveryLoopOnTheCallersThread) {
  ThreadBudget budget(1);
  const ThreadBudgetScope scope(&budget);
  const auto caller = std::this_thread::get_id();
  std::atomic<int> elsewhere{0};
  for_each_task(8, 8, [&](std::size_t) {
    for_each_chunk(100, 8, [&](std::size_t) {
      if (std::this_thread::get_id() != caller) ++elsewhere;
    });
  });
  EXPECT_EQ(elsewhere.load(), 0);
}

TEST(ThreadBudget, ChunkResultsAreTheSameWhateverTheBudget) {
  std::vector<double> x(256 * 40);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 / (1.0 + static_cast<double>(i) * 0.37);
  auto sum = [&](int budget_threads) {
    ThreadBudget budget(budget_threads);
    const ThreadBudgetScope scope(&budget);
    std::vector<double> part(chunk_count(x.size()));
    for_each_chunk(part.size(), 8, [&](std::size_t c) {
      const auto b = x.begin() + static_cast<std::ptrdiff_t>(c * kChunkRows);
      part[c] = std::accumulate(b, b + kChunkRows, 0.0);
    });
    return std::accumulate(part.begin(), part.end(), 0.0);
  };
  EXPECT_EQ(sum(1), sum(2));
  EXPECT_EQ(sum(1), sum(8));
}

TEST(ThreadBudget, AnExceptionInALoopGivesItsThreadsBack) {
  ThreadBudget budget(3);
  const ThreadBudgetScope scope(&budget);
  EXPECT_THROW(for_each_task(6, 3,
                             [](std::size_t k) {
                               if (k == 2) throw std::runtime_error("task 2");
                             }),
               std::runtime_error);
  EXPECT_EQ(budget.acquire(10), 2);
}

}  // namespace
}  // namespace frictionid::thread_budget_test
