// The RODAS step (include/frictionid/model/rosenbrock_rodas.hpp): its order on a smooth problem
// whose solution is known, its damping of an infinitely stiff mode (L-stability), its error
// estimate's order, and its continuous extension against the exact solution between the ends.
#include <frictionid/model/rosenbrock_rodas.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace rosenbrock_rodas_test {
namespace {

using namespace frictionid::model;

// The rotating oscillator y1' = -y2, y2' = y1, exact solution (cos t, sin t), with a component
// y3' = -lambda (y3 - y1^2) that is stiff for large lambda and acts on nothing else.
struct Stiff {
  double lambda;
  OdeVector<double, 3> operator()(double, const OdeVector<double, 3>& y) const {
    return {-y[1], y[0], -lambda * (y[2] - y[0] * y[0])};
  }
  OdeMatrix<3> jacobian(const OdeVector<double, 3>& y) const {
    OdeMatrix<3> J{};
    J[0][1] = -1.0;
    J[1][0] = 1.0;
    J[2][0] = 2.0 * lambda * y[0];
    J[2][2] = -lambda;
    return J;
  }
};

// Integrates to t = 1 with n equal steps; returns the error of (y1, y2) against (cos, sin).
double global_error(const Stiff& f, int n) {
  OdeVector<double, 3> y{1.0, 0.0, 1.0};
  const double h = 1.0 / n;
  for (int i = 0; i < n; ++i) {
    const RodasStep<3> s = rodas_step<3>(f, i * h, y, f(0.0, y), f.jacobian(y), h);
    y = s.y1;
  }
  return std::hypot(y[0] - std::cos(1.0), y[1] - std::sin(1.0));
}

TEST(Rodas, ConvergesWithOrderFourOnANonStiffProblem) {
  const Stiff f{1.0};
  const double e1 = global_error(f, 20), e2 = global_error(f, 40);
  const double order = std::log2(e1 / e2);
  EXPECT_GT(order, 3.8);
  EXPECT_LT(order, 4.3);
  EXPECT_LT(e2, 1e-7);
}

TEST(Rodas, KeepsItsOrderWhereOneModeIsStiff) {
  // lambda h up to 1e8: an explicit method would need h < 3e-8.
  const Stiff f{1e9};
  const double e1 = global_error(f, 20), e2 = global_error(f, 40);
  EXPECT_GT(std::log2(e1 / e2), 3.5);
  EXPECT_LT(e2, 1e-7);
}

TEST(Rodas, DampsAnInfinitelyStiffModeInOneStep) {
  // y3 far from its slow manifold y3 = y1^2: one step of lambda h = 1e12 lands on it.
  const Stiff f{1e12};
  const OdeVector<double, 3> y{1.0, 0.0, 5.0};
  const RodasStep<3> s = rodas_step<3>(f, 0.0, y, f(0.0, y), f.jacobian(y), 0.1);
  ASSERT_TRUE(s.ok);
  // From 4 off the manifold to within the step's own local error (h^5 ~ 1e-5 of y1).
  EXPECT_NEAR(s.y1[2], s.y1[0] * s.y1[0], 1e-7);
}

TEST(Rodas, ErrorEstimateShrinksLikeTheEmbeddedOrder) {
  const Stiff f{1.0};
  const OdeVector<double, 3> y{1.0, 0.0, 1.0};
  const auto est = [&](double h) {
    const RodasStep<3> s = rodas_step<3>(f, 0.0, y, f(0.0, y), f.jacobian(y), h);
    return std::hypot(s.error[0], s.error[1]);
  };
  // The local error of the 3rd-order solution is O(h^4).
  EXPECT_NEAR(std::log2(est(0.02) / est(0.01)), 4.0, 0.3);
}

TEST(Rodas, ContinuousExtensionIsExactAtTheEndsAndThirdOrderBetween) {
  const Stiff f{1.0};
  const OdeVector<double, 3> y{1.0, 0.0, 1.0};
  const auto mid_error = [&](double h) {
    const RodasStep<3> s = rodas_step<3>(f, 0.0, y, f(0.0, y), f.jacobian(y), h);
    EXPECT_EQ(s.at(0.0)[0], y[0]);
    EXPECT_EQ(s.at(h)[1], s.y1[1]);
    const auto m = s.at(0.4 * h);
    return std::hypot(m[0] - std::cos(0.4 * h), m[1] - std::sin(0.4 * h));
  };
  // Local error of a 3rd-order interpolant: O(h^4).
  EXPECT_GT(std::log2(mid_error(0.04) / mid_error(0.02)), 3.6);
  EXPECT_LT(mid_error(0.02), 1e-8);
}

TEST(Rodas, LuSolvesSystemsThatNeedRowSwapsAtEveryStep) {
  // A matrix whose pivots move at every column, as I/(gamma h) - J of a stiff coupled system:
  // the residual of the solution must be at rounding level.
  OdeMatrix<5> a{};
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 5; ++j)
      a[i][j] =
          std::sin(1.0 + 3.0 * i + 7.0 * j) * std::pow(10.0, static_cast<double>((4 * i + j) % 5));
  const OdeMatrix<5> original = a;
  std::array<std::size_t, 5> pivot{};
  ASSERT_TRUE(detail::lu_factor(a, pivot));
  int swaps = 0;
  for (std::size_t k = 0; k < 5; ++k) swaps += pivot[k] != k;
  EXPECT_GE(swaps, 2);
  const OdeVector<double, 5> b{1.0, -2.0, 3.0, -4.0, 5.0};
  OdeVector<double, 5> x = b;
  detail::lu_solve(a, pivot, x);
  for (std::size_t i = 0; i < 5; ++i) {
    double r = -b[i], size = std::fabs(b[i]);
    for (std::size_t j = 0; j < 5; ++j) {
      r += original[i][j] * x[j];
      size += std::fabs(original[i][j] * x[j]);
    }
    EXPECT_LT(std::fabs(r), 1e-14 * size) << i;
  }
}

TEST(Rodas, ReportsASingularMatrix) {
  // I/(gamma h) - J is singular for J = I/(gamma h).
  const double h = 0.5;
  OdeMatrix<1> J{};
  J[0][0] = 1.0 / (0.25 * h);
  const auto f = [](double, const OdeVector<double, 1>& y) { return y; };
  const RodasStep<1> s = rodas_step<1>(f, 0.0, {1.0}, {1.0}, J, h);
  EXPECT_FALSE(s.ok);
}

}  // namespace
}  // namespace rosenbrock_rodas_test
