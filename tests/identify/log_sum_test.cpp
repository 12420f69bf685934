#include "identify/log_sum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace frictionid::log_sum_test {
namespace {

// Sum of std::log in long double: the reference the block sum is held to.
long double reference(const std::vector<double>& xs) {
  long double s = 0.0L;
  for (double x : xs) s += std::log(static_cast<long double>(x));
  return s;
}

double block_sum(const std::vector<double>& xs) {
  LogSum s;
  for (double x : xs) s.add(x);
  return s.sum();
}

TEST(LogSum, EqualsTheSumOfLogsOverTheWholeNormalRangeToRounding) {
  std::mt19937_64 rng(3);
  for (int n : {1, 31, 32, 33, 1000, 100001}) {
    std::uniform_real_distribution<double> exponent(-1000.0, 1000.0);
    std::vector<double> xs(static_cast<std::size_t>(n));
    long double magnitude = 0.0L;
    for (double& x : xs) {
      x = std::pow(2.0, exponent(rng));
      magnitude += std::fabs(std::log(static_cast<long double>(x)));
    }
    const long double ref = reference(xs);
    // Summing n rounded logs in double errs by up to about n ulp of the running sum.
    EXPECT_LE(std::fabs(static_cast<long double>(block_sum(xs)) - ref),
              4e-16L * magnitude + 1e-300L)
        << n;
  }
}

TEST(LogSum, IsExactForPowersOfTwoAndOne) {
  std::vector<double> xs(1000, 1.0);
  EXPECT_EQ(block_sum(xs), 0.0);
  for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = std::ldexp(1.0, static_cast<int>(i % 7) - 3);
  // Exponents -3..3, 142 full cycles plus -3..2: sum -3; one ulp of ln 2 times 3 at most.
  EXPECT_NEAR(block_sum(xs), -3.0 * std::log(2.0), 4e-16 * 3.0);
}

TEST(LogSum, TakesSubnormalsOneByOneAndSignalsZeroNegativeAndInfinityAsLogDoes) {
  const double sub = std::numeric_limits<double>::denorm_min() * 12345.0;
  EXPECT_NEAR(block_sum({sub, 2.0, sub}), 2.0 * std::log(sub) + std::log(2.0), 1e-12);
  EXPECT_EQ(block_sum({1.5, 0.0, 3.0}), -HUGE_VAL);
  EXPECT_TRUE(std::isnan(block_sum({1.5, -2.0})));
  EXPECT_EQ(block_sum({1.5, HUGE_VAL}), HUGE_VAL);
  EXPECT_TRUE(std::isnan(block_sum({1.5, std::nan("")})));
  EXPECT_EQ(block_sum({}), 0.0);
}

}  // namespace
}  // namespace frictionid::log_sum_test
