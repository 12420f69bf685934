#include "identify/statistics.hpp"

#include <gtest/gtest.h>

#include <random>

namespace frictionid::statistics_test {
namespace {

// Reference quantiles: t_{0.975} for 1, 2, 10, 30 degrees of freedom (standard tables) and the
// normal limit; t_1 is the Cauchy quantile tan(pi (p - 1/2)).
TEST(Statistics, StudentTQuantileMatchesTabulatedValues) {
  EXPECT_NEAR(student_t_quantile(0.975, 1), std::tan(M_PI * 0.475), 1e-9);
  EXPECT_NEAR(student_t_quantile(0.975, 2), 4.302652729749464, 1e-9);
  EXPECT_NEAR(student_t_quantile(0.975, 10), 2.228138851986274, 1e-9);
  EXPECT_NEAR(student_t_quantile(0.975, 30), 2.042272456301238, 1e-9);
  EXPECT_NEAR(student_t_quantile(0.975, 1e7), 1.959963984540054, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.025, 10), -student_t_quantile(0.975, 10), 1e-12);
  // dof = 2 has the closed form t = (2p - 1) sqrt(2 / (1 - (2p - 1)^2)).
  const double p = 0.9, x = 2 * p - 1;
  EXPECT_NEAR(student_t_quantile(p, 2), x * std::sqrt(2 / (1 - x * x)), 1e-10);
}

TEST(Statistics, FullRankCovarianceIsTheInverseOfTheNormalMatrix) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> z;
  Eigen::MatrixXd J(50, 4);
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 4; ++j) J(i, j) = z(rng) * std::pow(10.0, j);  // mixed column scales
  const auto c = covariance_from_jacobian(J);
  const Eigen::MatrixXd expect = (J.transpose() * J).inverse();
  EXPECT_LT((c.covariance - expect).norm() / expect.norm(), 1e-10);
  for (bool d : c.determined) EXPECT_TRUE(d);
  EXPECT_TRUE(c.null_directions.empty());
}

// Columns 1 and 3 enter only as a sum (like h and kappa in T_y): both are undetermined,
// the others keep their covariance.
TEST(Statistics, RankDeficientJacobianNamesTheColumnsOfTheNullDirection) {
  std::mt19937_64 rng(4);
  std::normal_distribution<double> z;
  Eigen::MatrixXd J(40, 4);
  for (int i = 0; i < 40; ++i) {
    J(i, 0) = z(rng);
    J(i, 1) = z(rng);
    J(i, 2) = z(rng);
    J(i, 3) = 2.0 * J(i, 1);
  }
  const auto c = covariance_from_jacobian(J);
  EXPECT_TRUE(c.determined[0]);
  EXPECT_FALSE(c.determined[1]);
  EXPECT_TRUE(c.determined[2]);
  EXPECT_FALSE(c.determined[3]);
  ASSERT_EQ(c.null_directions.size(), 1u);
  EXPECT_EQ(c.null_directions[0], (std::vector<int>{1, 3}));
}

TEST(Statistics, IncompleteBetaMatchesClosedForms) {
  // I_x(1, b) = 1 - (1 - x)^b and I_x(a, 1) = x^a.
  for (double x : {0.1, 0.5, 0.9}) {
    EXPECT_NEAR(regularized_incomplete_beta(x, 1.0, 3.5), 1 - std::pow(1 - x, 3.5), 1e-13);
    EXPECT_NEAR(regularized_incomplete_beta(x, 2.5, 1.0), std::pow(x, 2.5), 1e-13);
  }
}

}  // namespace
}  // namespace frictionid::statistics_test
