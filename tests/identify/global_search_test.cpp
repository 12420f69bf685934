#include "identify/global_search.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace frictionid::global_search_test {
namespace {

// Two basins: a shallow one near (-2, -2) and the global minimum 0 at (1.5, 0.5).
double two_basins(const double* z) {
  const double a = (z[0] - 1.5) * (z[0] - 1.5) + (z[1] - 0.5) * (z[1] - 0.5);
  const double b = (z[0] + 2) * (z[0] + 2) + (z[1] + 2) * (z[1] + 2);
  return std::min(a, 0.3 + b);
}

GlobalSearchProblem problem() {
  GlobalSearchProblem p;
  p.lower = {-4.0, -4.0};
  p.upper = {4.0, 4.0};
  p.objective = two_basins;
  return p;
}

TEST(GlobalSearch, EveryAlgorithmPutsItsBestStartInTheDeeperBasin) {
  for (const auto& algorithm : global_algorithms()) {
    const auto out = global_search(problem(), algorithm, 1500, 7, 3);
    ASSERT_FALSE(out.starts.empty()) << algorithm;
    EXPECT_TRUE(out.failure.empty()) << algorithm << ": " << out.failure;
    EXPECT_NEAR(out.starts[0][0], 1.5, 0.3) << algorithm;
    EXPECT_NEAR(out.starts[0][1], 0.5, 0.3) << algorithm;
    EXPECT_LE(out.evaluations, 1500) << algorithm;
  }
}

TEST(GlobalSearch, StartsAreSortedAndAtLeastATenthOfTheBoxApart) {
  const auto out = global_search(problem(), "crs2", 2000, 3, 4);
  ASSERT_GE(out.starts.size(), 2u);
  for (std::size_t i = 1; i < out.starts.size(); ++i) {
    EXPECT_LE(out.start_values[i - 1], out.start_values[i]);
    for (std::size_t j = 0; j < i; ++j) {
      const double d = std::max(std::fabs(out.starts[i][0] - out.starts[j][0]),
                                std::fabs(out.starts[i][1] - out.starts[j][1]));
      EXPECT_GE(d, 0.1 * 8.0) << i << " " << j;
    }
  }
}

TEST(GlobalSearch, SameSeedSameStartsAnotherSeedOtherPoints) {
  const auto a = global_search(problem(), "crs2", 800, 11, 3);
  const auto b = global_search(problem(), "crs2", 800, 11, 3);
  const auto c = global_search(problem(), "crs2", 800, 12, 3);
  EXPECT_EQ(a.starts, b.starts);
  EXPECT_EQ(a.start_values, b.start_values);
  EXPECT_NE(a.starts, c.starts);
}

// NLopt refusing the problem must not escape as an exception: the fitter falls back to its
// initial values and warns.
TEST(GlobalSearch, ANloptFailureIsReportedNotThrown) {
  GlobalSearchProblem p = problem();
  p.lower = {1.0, 1.0};
  p.upper = {-1.0, -1.0};  // an empty box
  GlobalSearchOutcome out;
  EXPECT_NO_THROW(out = global_search(p, "crs2", 100, 1, 2));
  EXPECT_FALSE(out.failure.empty());
}

}  // namespace
}  // namespace frictionid::global_search_test
