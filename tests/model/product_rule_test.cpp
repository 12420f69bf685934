// The product rule of product_rule.hpp: its weights integrate every polynomial F of degree below
// their number against a piecewise polynomial weight exactly, on the dyadic parts whose weights
// DyadicProductRule stores and on deeper ones it computes when asked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/product_rule.hpp>

namespace fm = frictionid::model;

namespace product_rule_test {
namespace {

// A weight of `count` quartic pieces over [0, 1] between random breakpoints, with random
// coefficients (of either sign, as a table law's slope has).
std::vector<fm::PolynomialPiece> random_pieces(int count, std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0.0, 1.0), c(-1.0, 1.0);
  std::vector<double> cuts = {0.0, 1.0};
  while (static_cast<int>(cuts.size()) < count + 1) cuts.push_back(u(g));
  std::sort(cuts.begin(), cuts.end());
  std::vector<fm::PolynomialPiece> out;
  for (int k = 0; k < count; ++k)
    out.push_back({cuts[static_cast<std::size_t>(k)],
                   cuts[static_cast<std::size_t>(k + 1)],
                   {c(g), c(g), c(g), c(g), c(g)}});
  return out;
}

}  // namespace

TEST(DyadicProductRule, IntegratesEveryPolynomialBelowItsPointsAgainstThePiecewiseWeightExactly) {
  std::mt19937_64 g(7);
  const std::vector<fm::PolynomialPiece> pieces = random_pieces(37, g);
  const double lo = 0.125, hi = 0.875;
  const fm::DyadicProductRule rule(pieces, lo, hi, 4);
  std::uniform_real_distribution<double> c(-1.0, 1.0);
  // Levels 0-7 are stored, 9 and 11 computed on demand.
  for (int level : {0, 2, 5, 7, 9, 11})
    for (int n : {8, 20, 48}) {
      const long k = (1L << level) / 3;
      const double s0 = rule.part_lo(level, k), s1 = rule.part_hi(level, k);
      ASSERT_LT(s0, s1);
      // F = sum_j a_j T_j(x) of degree n - 1 in the part's coordinate x in [-1, 1], evaluated
      // at x itself on both sides (F' reaches ~n^3: recomputing x from s would cost digits).
      std::vector<double> a(static_cast<std::size_t>(n));
      for (double& v : a) v = c(g);
      auto F = [&](double x) {
        double t0 = 1.0, t1 = x, sum = a[0] + a[1] * x;
        for (int j = 2; j < n; ++j) {
          const double t2 = 2.0 * x * t1 - t0;
          sum += a[static_cast<std::size_t>(j)] * t2;
          t0 = t1;
          t1 = t2;
        }
        return sum;
      };
      const double mid = 0.5 * (s0 + s1), half = 0.5 * (s1 - s0);
      // Reference: Gauss–Legendre of 30 points in x on each piece within the part, exact for
      // w F (degree <= 4 + 47).
      double want = 0.0, scale = 0.0;
      for (const fm::PolynomialPiece& p : pieces) {
        const double a0 = std::max(-1.0, (p.a - mid) / half),
                     b0 = std::min(1.0, (p.b - mid) / half);
        if (!(b0 > a0)) continue;
        for (const fm::QuadratureNode& q : fm::gauss_legendre_rule(30)) {
          const double x = a0 + (b0 - a0) * q.from_left;
          const double v = q.weight * (b0 - a0) * half * p(mid + half * x) * F(x);
          want += v;
          scale += std::fabs(v);
        }
      }
      double scratch[fm::kMostProductPoints];
      const double* W = rule.weights(level, k, n, scratch);
      const double* x = fm::chebyshev_points(n);
      double got = 0.0;
      for (int i = 0; i < n; ++i) got += W[i] * F(x[i]);
      EXPECT_NEAR(got, want, 1e-13 * scale) << "level " << level << ", " << n << " points";
    }
}

TEST(DyadicProductRule, RulesOfTheSameWeightShareTheirStoredWeights) {
  // A fit makes an integrator, hence a rule, for every model it evaluates: the weights (16 ms
  // for 201 samples) are computed once per weight.
  std::mt19937_64 g(11);
  const std::vector<fm::PolynomialPiece> pieces = random_pieces(201, g);
  const fm::DyadicProductRule a(pieces, 0.0, 1.0, 4, -0.5), b(pieces, 0.0, 1.0, 4, -0.5);
  double sa[fm::kMostProductPoints], sb[fm::kMostProductPoints];
  EXPECT_EQ(a.weights(5, 7, 24, sa), b.weights(5, 7, 24, sb));
  // Another weight, or the same one with another rim factor, has weights of its own.
  std::vector<fm::PolynomialPiece> other = pieces;
  other[100].c[2] += 1e-3;
  const fm::DyadicProductRule c(other, 0.0, 1.0, 4, -0.5), d(pieces, 0.0, 1.0, 4, 0.5);
  double sc[fm::kMostProductPoints], sd[fm::kMostProductPoints];
  const double* wa = a.weights(0, 0, 24, sa);
  const double* wc = c.weights(0, 0, 24, sc);
  const double* wd = d.weights(0, 0, 24, sd);
  EXPECT_NE(wa, wc);
  EXPECT_NE(wa, wd);
  double differ_c = 0.0, differ_d = 0.0;
  for (int i = 0; i < 24; ++i) {
    differ_c = std::max(differ_c, std::fabs(wa[i] - wc[i]));
    differ_d = std::max(differ_d, std::fabs(wa[i] - wd[i]));
  }
  EXPECT_GT(differ_c, 0.0);
  EXPECT_GT(differ_d, 0.0);
}
}  // namespace product_rule_test
