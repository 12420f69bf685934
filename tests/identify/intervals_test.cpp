// Interval methods beyond the covariance: profile likelihood, wild bootstrap, and the covariance
// itself on a problem linear in its one free parameter.
#include "identify/bootstrap_intervals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <frictionid/fitter.hpp>
#include <frictionid/synthetic_data.hpp>

#include "identify/statistics.hpp"

namespace frictionid::intervals_test {
namespace {

using Law = model::PressureLaw<double>;

Dataset small_data(bool sigma_columns, std::uint64_t seed, std::size_t rows = 120) {
  const Law law = Law::hertz();
  SyntheticDesign design;
  design.rows = rows;
  return generate_dataset(ModelKind::Seed, law, default_parameters(law, 0.9, 1.2, 0.1), design,
                          NoiseSpec{0.02, 0.0, sigma_columns}, seed);
}

// The profile interval against a brute-force scan: at each v on a fine grid an independent fit
// with f fixed at v gives the profile cost; the interval ends where it crosses the threshold.
TEST(ProfileIntervals, MatchABruteForceScanOfTheProfiledCost) {
  const Law law = Law::hertz();
  const Dataset d = small_data(true, 4);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "hertz");
  s.intervals = IntervalMethod::Profile;
  const FitResult r = Fitter(s).fit(d);
  const ParameterEstimate* f = r.parameter("f");
  ASSERT_TRUE(f && f->ci95_profile && f->std_error);
  const double threshold =
      r.cost + 0.5 * std::pow(student_t_quantile(0.975, static_cast<double>(r.dof)), 2);
  auto profile = [&](double v) {
    FitSettings held = s;
    held.intervals = IntervalMethod::Model;
    held.global = false;
    for (const auto& p : r.parameters) held.start(p.name, p.value);
    held.fix("f", v);
    return Fitter(held).fit(d).cost;
  };
  for (int side : {-1, 1}) {
    const double step = 0.02 * *f->std_error;
    double inside = f->value, c_inside = r.cost;
    bool crossed = false;
    for (int k = 1; k < 400 && !crossed; ++k) {
      const double v = f->value + side * k * step;
      const double c = profile(v);
      if (c > threshold) {
        const double crossing = inside + (v - inside) * (threshold - c_inside) / (c - c_inside);
        EXPECT_NEAR((*f->ci95_profile)[side < 0 ? 0 : 1], crossing, 0.01 * *f->std_error);
        crossed = true;
        continue;
      }
      inside = v;
      c_inside = c;
    }
    EXPECT_TRUE(crossed) << "side " << side;
  }
  // Near linear here: the profile interval is close to the covariance's.
  EXPECT_NEAR((*f->ci95_profile)[0], (*f->ci95)[0], 0.1 * *f->std_error);
  EXPECT_NEAR((*f->ci95_profile)[1], (*f->ci95)[1], 0.1 * *f->std_error);
}

TEST(ProfileIntervals, ASideThatReachesTheBoundIsSaidToBeOpen) {
  const Law law = Law::hertz();
  const Dataset d = small_data(true, 5);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "hertz");
  s.intervals = IntervalMethod::Profile;
  const FitResult free_fit = Fitter(s).fit(d);
  const double f = free_fit.parameter("f")->value, se = *free_fit.parameter("f")->std_error;
  s.bound("f", f - 0.5 * se, 5.0);  // the lower side cannot close inside this bound
  const FitResult r = Fitter(s).fit(d);
  const ParameterEstimate* p = r.parameter("f");
  ASSERT_TRUE(p->ci95_profile);
  EXPECT_FALSE(p->profile_closed[0]);
  EXPECT_TRUE(p->profile_closed[1]);
  EXPECT_EQ((*p->ci95_profile)[0], f - 0.5 * se);
  bool warned = false;
  for (const auto& w : r.warnings)
    warned |= w.find("profile of f does not close inside its lower bound") != std::string::npos;
  EXPECT_TRUE(warned);
}

FitResult bootstrap_fit(const Dataset& d, unsigned long long seed, int threads) {
  FitSettings s = FitSettings::defaults(ModelKind::Seed, Law::hertz(), "hertz");
  s.bootstrap = 60;
  s.seed = seed;
  s.threads = threads;
  return Fitter(s).fit(d);
}

TEST(BootstrapIntervals, AreReproducibleForASeedAndIndependentOfTheThreadCount) {
  const Dataset d = small_data(false, 6);
  const FitResult a = bootstrap_fit(d, 3, 1), b = bootstrap_fit(d, 3, 2),
                  c = bootstrap_fit(d, 4, 2);
  EXPECT_EQ(a.bootstrap_replicates, 60);
  for (const auto& p : a.parameters) {
    ASSERT_TRUE(p.ci95_bootstrap) << p.name;
    EXPECT_EQ(*p.ci95_bootstrap, *b.parameter(p.name)->ci95_bootstrap) << p.name;
    EXPECT_EQ(*p.std_error_bootstrap, *b.parameter(p.name)->std_error_bootstrap) << p.name;
    EXPECT_NE(*p.std_error_bootstrap, *c.parameter(p.name)->std_error_bootstrap) << p.name;
  }
}

// On data the model describes, the bootstrap's spread estimates the same standard error as the
// covariance (within its own sampling error, ~1/sqrt(2 * 60) = 9 %, allowed 3 times).
TEST(BootstrapIntervals, StandardErrorsAgreeWithTheCovarianceOnWellSpecifiedData) {
  const FitResult r = bootstrap_fit(small_data(false, 7, 600), 1, 0);
  for (const auto& p : r.parameters) {
    ASSERT_TRUE(p.std_error && p.std_error_bootstrap) << p.name;
    EXPECT_NEAR(*p.std_error_bootstrap / *p.std_error, 1.0, 0.3) << p.name;
    EXPECT_LT((*p.ci95_bootstrap)[0], p.value);
    EXPECT_GT((*p.ci95_bootstrap)[1], p.value);
  }
}

TEST(BootstrapIntervals, RademacherSignsAreBalancedAndDifferBySeedReplicateAndRow) {
  int sum = 0, same_seed = 0;
  for (std::size_t i = 0; i < 20000; ++i) {
    sum += rademacher_sign(9, 0, i);
    same_seed += rademacher_sign(9, 0, i) == rademacher_sign(10, 0, i);
  }
  EXPECT_LT(std::abs(sum), 4 * std::sqrt(20000.0));
  EXPECT_NEAR(same_seed, 10000, 4 * std::sqrt(5000.0));
}

// The percentile reads order statistics, not values: with the k-th of B sorted refits equal to
// k^2 the (B + 1) q-th order statistic is recognisable from its value.
std::vector<double> squares(int b) {
  std::vector<double> v;
  for (int k = 1; k <= b; ++k) v.push_back(static_cast<double>(k) * k);
  return v;
}

TEST(BootstrapPercentile, IsThe5thAnd195thOf199Refits) {
  const std::vector<double> v = squares(199);
  EXPECT_EQ(bootstrap_percentile(v, 0.025), 5.0 * 5.0);
  EXPECT_EQ(bootstrap_percentile(v, 0.975), 195.0 * 195.0);
}

TEST(BootstrapPercentile, InterpolatesBetweenOrderStatisticsWhenBPlus1TimesAlphaIsNotAnInteger) {
  std::vector<double> ranks(99);
  for (int k = 1; k <= 99; ++k) ranks[k - 1] = k;
  EXPECT_DOUBLE_EQ(bootstrap_percentile(ranks, 0.025), 2.5);
  EXPECT_DOUBLE_EQ(bootstrap_percentile(ranks, 0.975), 97.5);
  const std::vector<double> v = squares(99);  // halfway between the 2nd and 3rd, 97th and 98th
  EXPECT_DOUBLE_EQ(bootstrap_percentile(v, 0.025), (4.0 + 9.0) / 2);
  EXPECT_DOUBLE_EQ(bootstrap_percentile(v, 0.975), (97.0 * 97.0 + 98.0 * 98.0) / 2);
  EXPECT_EQ(bootstrap_percentile(squares(999), 0.025), 25.0 * 25.0);
  EXPECT_EQ(bootstrap_percentile(squares(999), 0.975), 975.0 * 975.0);
}

TEST(BootstrapPercentile, IsClampedToTheSmallestAndLargestRefit) {
  const std::vector<double> v = squares(19);  // (B + 1) q = 0.5 and 19.5
  EXPECT_EQ(bootstrap_percentile(v, 0.025), 1.0);
  EXPECT_EQ(bootstrap_percentile(v, 0.975), 19.0 * 19.0);
  EXPECT_EQ(bootstrap_percentile({7.0}, 0.025), 7.0);
  EXPECT_EQ(bootstrap_percentile({7.0}, 0.975), 7.0);
  EXPECT_THROW(bootstrap_percentile({}, 0.5), std::invalid_argument);
}

// M_roll = h N R m3/(2 m1) is linear in h: fitting h alone to M_roll is a weighted linear
// regression through the origin, whose estimate and variance have closed forms. With sigma
// columns Var = 1/sum(x^2/sigma^2); with a constant noise model estimated from the residuals
// Var = s^2/sum(x^2), s^2 = sum(e^2)/(n - 1) (the n/(n - k) factor, k = 1).
TEST(Covariance, OfAProblemLinearInItsParameterMatchesTheClosedForm) {
  const Law law = Law::hertz();
  const auto moments = model::law_moments(law);
  const double rho = moments[3] / (2 * moments[1]);
  for (bool sigma : {true, false}) {
    const Dataset d = small_data(sigma, 8, 200);
    FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "hertz");
    s.channels = {Channel::M_roll};
    for (const char* name : {"f", "kappa", "a", "b", "m"}) s.fix(name, s.parameter(name).initial);
    s.noise_model = sigma ? NoiseModelKind::Columns : NoiseModelKind::Constant;
    const FitResult r = Fitter(s).fit(d);
    const int c = static_cast<int>(Channel::M_roll);
    double sxx = 0, sxy = 0;
    std::vector<double> x(d.rows());
    for (std::size_t i = 0; i < d.rows(); ++i) {
      x[i] = d.N[i] * d.R[i] * rho;
      const double w = sigma ? 1.0 / (d.sigma[c][i] * d.sigma[c][i]) : 1.0;
      sxx += w * x[i] * x[i];
      sxy += w * x[i] * d.value[c][i];
    }
    const double h = sxy / sxx;
    double var = 1.0 / sxx;
    if (!sigma) {
      double see = 0;
      for (std::size_t i = 0; i < d.rows(); ++i) see += std::pow(d.value[c][i] - h * x[i], 2);
      var = see / (static_cast<double>(d.rows()) - 1) / sxx;
    }
    const ParameterEstimate* p = r.parameter("h");
    EXPECT_NEAR(p->value, h, 1e-9 * std::fabs(h)) << "sigma columns " << sigma;
    EXPECT_NEAR(*p->std_error, std::sqrt(var), 1e-6 * std::sqrt(var)) << "sigma columns " << sigma;
  }
}

}  // namespace
}  // namespace frictionid::intervals_test
