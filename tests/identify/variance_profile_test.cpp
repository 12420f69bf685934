#include "identify/variance_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <frictionid/synthetic_data.hpp>

#include "support/noise_brute_force.hpp"

namespace frictionid::variance_profile_test {
namespace {

// Fitted values log-spread over two decades (in units of the largest, as noise_model.cpp calls
// the search) and residuals of a two-term sigma.
struct Sample {
  std::vector<double> y, e;
};
Sample sample(TwoTermForm form, double s_abs, double s_rel, std::size_t n, std::uint64_t seed) {
  NormalStream g(seed);
  Sample s;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = (i % 2 ? -1.0 : 1.0) * 0.01 * std::pow(100.0, static_cast<double>(i) / n);
    const double sd =
        form == TwoTermForm::Affine ? std::hypot(s_abs, s_rel * y) : s_abs + s_rel * std::fabs(y);
    s.y.push_back(y);
    s.e.push_back(sd * g.next());
  }
  return s;
}

test::TwoTerm brute(TwoTermForm form) {
  return form == TwoTermForm::Affine ? test::TwoTerm::Affine : test::TwoTerm::Additive;
}

TEST(VarianceProfile, TheSearchFindsTheInteriorMaximumAndReportsItsLikelihood) {
  for (TwoTermForm form : {TwoTermForm::Affine, TwoTermForm::Additive}) {
    const Sample s = sample(form, 0.002, 0.02, 400, 3);
    const TwoTermMaximum m = two_term_maximum(form, s.y, s.e);
    ASSERT_TRUE(m.found);
    EXPECT_TRUE(m.converged);
    const double rows = test::two_term_neg2_loglik(brute(form), m.s_abs, m.s_rel, s.y, s.e);
    EXPECT_NEAR(m.neg2_loglik, rows, 1e-9 * std::fabs(rows));
    const auto bf = test::brute_force_maximum(brute(form), s.y, s.e);
    EXPECT_LE(rows, bf.neg2_loglik + 1e-6);
  }
}

// give_up_above: a search that ends at or below it is the search without it, to the bit; one
// that cannot reach it is left (given_up), and what it finds is not reported.
TEST(VarianceProfile, ABoundToBeatLeavesOnlySearchesThatCannotReachIt) {
  for (TwoTermForm form : {TwoTermForm::Affine, TwoTermForm::Additive}) {
    const Sample s = sample(form, 0.002, 0.02, 400, 3);
    const TwoTermMaximum m = two_term_maximum(form, s.y, s.e);
    ASSERT_TRUE(m.found);
    EXPECT_EQ(m.given_up, 0);
    const TwoTermRange range = two_term_range(form, s.y, s.e);
    for (double above : {0.0, 1.0, 100.0}) {
      const TwoTermMaximum b = two_term_maximum(form, s.y, s.e, range, m.neg2_loglik + above);
      EXPECT_EQ(b.given_up, 0);
      EXPECT_EQ(b.found, m.found);
      EXPECT_EQ(b.s_abs, m.s_abs);
      EXPECT_EQ(b.s_rel, m.s_rel);
      EXPECT_EQ(b.neg2_loglik, m.neg2_loglik);
      EXPECT_EQ(b.converged, m.converged);
    }
    const TwoTermMaximum below = two_term_maximum(form, s.y, s.e, range, m.neg2_loglik - 50.0);
    EXPECT_GT(below.given_up, 0);
    EXPECT_FALSE(below.found);
  }
}

// The grid four points at a time (AVX2, where there is) and one at a time place the same starts:
// the same bits, also with a row whose fitted value is not finite (one log at a time there).
TEST(VarianceProfile, TheGridInVectorLanesGivesTheSameMaximum) {
  for (TwoTermForm form : {TwoTermForm::Affine, TwoTermForm::Additive})
    for (std::size_t n : {30u, 400u, 9000u})
      for (bool nan_row : {false, true}) {
        Sample s = sample(form, 0.002, 0.02, n, 7 + n);
        if (nan_row) s.y[n / 2] = std::nan("");
        TwoTermMaximum m[2];
        for (int lanes = 0; lanes < 2; ++lanes) {
          allow_profile_lanes(lanes == 1);
          m[lanes] = two_term_maximum(form, s.y, s.e);
        }
        allow_profile_lanes(true);
        EXPECT_EQ(m[0].found, m[1].found);
        EXPECT_EQ(m[0].s_abs, m[1].s_abs);
        EXPECT_EQ(m[0].s_rel, m[1].s_rel);
        EXPECT_EQ(m[0].converged, m[1].converged);
        if (!nan_row) {
          EXPECT_TRUE(m[0].found) << n;
          EXPECT_EQ(m[0].neg2_loglik, m[1].neg2_loglik);
        }
      }
}

TEST(VarianceProfile, NoResidualsOrNoFittedValuesLeaveOnlyTheBounds) {
  const std::vector<double> y = {0.5, -1.0, 0.2}, zeros = {0.0, 0.0, 0.0};
  EXPECT_FALSE(two_term_maximum(TwoTermForm::Affine, y, zeros).found);
  EXPECT_FALSE(two_term_maximum(TwoTermForm::Additive, zeros, y).found);
}

// At the maximum the gradient check promises nothing; a step away from it, about the quadratic
// rise of -2 ln L there (a tenth of a unit of ln s_abs).
TEST(VarianceProfile, RemainingGainIsZeroAtTheMaximumAndPositiveAwayFromIt) {
  for (TwoTermForm form : {TwoTermForm::Affine, TwoTermForm::Additive}) {
    const Sample s = sample(form, 0.002, 0.02, 400, 4);
    const TwoTermMaximum m = two_term_maximum(form, s.y, s.e);
    ASSERT_TRUE(m.found);
    EXPECT_LT(remaining_gain(form, m.s_abs, m.s_rel, s.y, s.e), 1e-9);
    const double away = remaining_gain(form, 1.1 * m.s_abs, m.s_rel, s.y, s.e);
    const double rise = test::two_term_neg2_loglik(brute(form), 1.1 * m.s_abs, m.s_rel, s.y, s.e) -
                        test::two_term_neg2_loglik(brute(form), m.s_abs, m.s_rel, s.y, s.e);
    EXPECT_GT(away, 0.3 * rise);
    EXPECT_LT(away, 3.0 * rise);
  }
}

// On a bound the check counts the bound parameter only when moving it inward descends: purely
// proportional noise at s_abs = 0 passes; noise with a floor, forced to the constant bound, does
// not.
TEST(VarianceProfile, RemainingGainCountsABoundParameterOnlyWhenMovingItInwardDescends) {
  for (TwoTermForm form : {TwoTermForm::Affine, TwoTermForm::Additive}) {
    const Sample p = sample(form, 0.0, 0.02, 400, 5);
    double r2 = 0.0;
    for (std::size_t i = 0; i < p.y.size(); ++i) r2 += (p.e[i] / p.y[i]) * (p.e[i] / p.y[i]);
    EXPECT_LT(remaining_gain(form, 0.0, std::sqrt(r2 / 400.0), p.y, p.e), 1e-9);
    const Sample a = sample(form, 0.002, 0.02, 400, 6);
    double e2 = 0.0;
    for (double v : a.e) e2 += v * v;
    EXPECT_GT(remaining_gain(form, std::sqrt(e2 / 400.0), 0.0, a.y, a.e), 1.0);
  }
}

}  // namespace
}  // namespace frictionid::variance_profile_test
