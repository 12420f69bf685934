#include "identify/normal_equations.hpp"

#include <gtest/gtest.h>

#include <random>

namespace frictionid::normal_equations_test {
namespace {

NormalEquations from_rows(const Eigen::MatrixXd& j, const Eigen::VectorXd& r) {
  return {j.transpose() * j, j.transpose() * r, r.squaredNorm()};
}

// The square-root form must reproduce what Levenberg-Marquardt uses of the tall problem: the
// cost, the gradient, J^T J, and the linearised cost |r + J d|^2 for any step d.
void expect_same_problem(const Eigen::MatrixXd& j, const Eigen::VectorXd& r, double tol) {
  const SquareRootForm f = square_root_form(from_rows(j, r));
  const double scale = (j.transpose() * j).norm();
  EXPECT_LE((f.a.transpose() * f.a - j.transpose() * j).norm(), tol * scale);
  EXPECT_LE((f.a.transpose() * f.w - j.transpose() * r).norm(), tol * j.norm() * r.norm() + 1e-300);
  EXPECT_NEAR(f.w.squaredNorm() + f.rho * f.rho, r.squaredNorm(), tol * r.squaredNorm());
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n01;
  for (int t = 0; t < 5; ++t) {
    Eigen::VectorXd d(j.cols());
    for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = n01(rng);
    const double tall = (r + j * d).squaredNorm();
    const double small = (f.w + f.a * d).squaredNorm() + f.rho * f.rho;
    EXPECT_NEAR(small, tall, tol * (tall + r.squaredNorm()));
  }
}

TEST(NormalEquations, SquareRootFormKeepsCostGradientAndGaussNewtonMatrix) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd j(500, 6);
  Eigen::VectorXd r(500);
  for (Eigen::Index i = 0; i < j.rows(); ++i) {
    r[i] = n01(rng);
    for (Eigen::Index k = 0; k < j.cols(); ++k) j(i, k) = n01(rng) * std::pow(10.0, k - 3.0);
  }
  expect_same_problem(j, r, 1e-12);
}

TEST(NormalEquations, RankDeficientJacobianGetsAZeroRowAndStillTheSameCost) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd j(300, 4);
  Eigen::VectorXd r(300);
  for (Eigen::Index i = 0; i < j.rows(); ++i) {
    r[i] = n01(rng);
    j(i, 0) = n01(rng);
    j(i, 1) = n01(rng);
    j(i, 2) = 2.0 * j(i, 0) - j(i, 1);  // a combination the rows cannot resolve
    j(i, 3) = 0.0;                      // a parameter no row depends on
  }
  const SquareRootForm f = square_root_form(from_rows(j, r));
  int zero_rows = 0;
  for (Eigen::Index i = 0; i < f.a.rows(); ++i) zero_rows += f.a.row(i).norm() == 0.0;
  EXPECT_EQ(zero_rows, 2);
  expect_same_problem(j, r, 1e-10);
}

TEST(NormalEquations, ResidualsInTheRangeOfTheJacobianLeaveNoRemainder) {
  Eigen::MatrixXd j = Eigen::MatrixXd::Random(50, 3);
  const Eigen::VectorXd r = j * Eigen::Vector3d(0.5, -2.0, 1.0);
  const SquareRootForm f = square_root_form(from_rows(j, r));
  EXPECT_LE(f.rho, 1e-6 * r.norm());
  EXPECT_NEAR(f.w.norm(), r.norm(), 1e-12 * r.norm());
}

// A second view of the rank-deficient case: the minimum-norm Gauss-Newton step of the small
// problem, solved by a complete orthogonal decomposition, is the tall problem's minimum-norm
// step, -pinv(J) r, even with a null direction that is not along one parameter.
TEST(NormalEquations, RankDeficientSquareRootFormGivesTheTallProblemsMinimumNormStep) {
  std::mt19937_64 rng(29);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd j(200, 5);
  Eigen::VectorXd r(200);
  for (Eigen::Index i = 0; i < j.rows(); ++i) {
    r[i] = n01(rng);
    for (Eigen::Index k = 0; k < 3; ++k) j(i, k) = n01(rng);
    j(i, 3) = j(i, 0) + 0.5 * j(i, 2);   // null direction (1, 0, 0.5, -1, 0)
    j(i, 4) = -3.0 * j(i, 1) + j(i, 2);  // and (0, -3, 1, 0, -1)
  }
  const SquareRootForm f = square_root_form(from_rows(j, r));
  const Eigen::VectorXd tall = -j.completeOrthogonalDecomposition().solve(r);
  const Eigen::VectorXd small = -f.a.completeOrthogonalDecomposition().solve(f.w);
  EXPECT_LE((small - tall).norm(), 1e-9 * tall.norm()) << small.transpose() << "\n"
                                                       << tall.transpose();
}

}  // namespace
}  // namespace frictionid::normal_equations_test
