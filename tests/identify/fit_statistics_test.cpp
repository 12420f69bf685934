#include "identify/fit_statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include <frictionid/fitter.hpp>
#include <frictionid/model_variant.hpp>
#include <frictionid/synthetic_data.hpp>

#include "identify/statistics.hpp"

namespace frictionid::fit_statistics_test {
namespace {

using Law = model::PressureLaw<double>;

// Wide bounds do not make a value far inside them "at its bound" (--bounds f=0.01:1e9 with
// f = 0.9 was flagged when the test was relative to the box width).
TEST(AtBound, IsAnAbsolutePlusRelativeDistanceNotAFractionOfTheBox) {
  EXPECT_FALSE(at_bound(0.9, 0.01, 1e9));
  EXPECT_TRUE(at_bound(0.01, 0.01, 1e9));
  EXPECT_TRUE(at_bound(1e9, 0.01, 1e9));
  EXPECT_TRUE(at_bound(0.01 + 5e-10, 0.01, 1e9));
  EXPECT_FALSE(at_bound(0.01 + 5e-9, 0.01, 1e9));
  EXPECT_TRUE(at_bound(1e4 * (1 - 1e-10), 4.0, 1e4));  // relative near a large bound
  EXPECT_FALSE(at_bound(0.0, -1.0, 1.0));
}

// AIC and BIC against their formulas on a real fit. With sigma columns -2 log L = chi²; with the
// noise model estimated, -2 log L = chi² + sum ln sigma_i^2 and its parameters count in k. The
// sigmas are recomputed here from the reported noise model and the fitted values.
TEST(InformationCriteria, MatchTheirFormulasOnARealFitWithSigmaColumnsAndWithANoiseModel) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.2, 0.1);
  for (bool sigma : {true, false}) {
    const Dataset d = generate_dataset(ModelKind::Seed, law, truth, SyntheticDesign{},
                                       NoiseSpec{0.01, 0.0, sigma}, 9);
    const FitResult r = Fitter(FitSettings::defaults(ModelKind::Seed, law, "hertz")).fit(d);
    const double n = static_cast<double>(r.residuals);
    double k = 6.0, log_det = 0.0;
    ASSERT_EQ(r.residuals, 4 * d.rows());
    for (const auto& cs : r.channel_summaries) {
      ASSERT_EQ(cs.noise.has_value(), !sigma);
      if (!cs.noise) continue;
      k += cs.noise->model == "affine" ? 2 : 1;
      for (double y : r.fitted[static_cast<int>(cs.channel)]) {
        const double s = cs.noise->model == "relative"
                             ? cs.noise->s_rel * std::max(std::fabs(y), cs.noise->floor)
                             : std::hypot(cs.noise->s_abs, cs.noise->s_rel * y);
        log_det += std::log(s * s);
      }
    }
    const double m2ll = r.chi2 + log_det;
    EXPECT_NEAR(r.aic, m2ll + 2 * k, 1e-9 * std::fabs(r.aic)) << "sigma columns " << sigma;
    EXPECT_NEAR(r.bic, m2ll + k * std::log(n), 1e-9 * std::fabs(r.bic))
        << "sigma columns " << sigma;
    EXPECT_FALSE(r.covariance_scaled_by_reduced_chi2);
  }
}

// One sigma for all residuals, estimated from them: -2 log L = n ln(chi²/n) (+ const).
TEST(InformationCriteria, UseNLogChi2OverNWhenOneSigmaIsEstimatedFromTheResiduals) {
  const auto ic = information_criteria(50.0, 200, 3, false);
  EXPECT_NEAR(ic.aic, 200 * std::log(50.0 / 200) + 6, 1e-12);
  EXPECT_NEAR(ic.bic, 200 * std::log(50.0 / 200) + 3 * std::log(200.0), 1e-12);
}

TEST(InformationCriteria, PenaliseEachParameterByTwoAndByLogN) {
  const auto a = information_criteria(100.0, 1000, 3, true);
  const auto b = information_criteria(100.0, 1000, 4, true);
  EXPECT_DOUBLE_EQ(b.aic - a.aic, 2.0);
  EXPECT_DOUBLE_EQ(b.bic - a.bic, std::log(1000.0));
}

// The HC3 sandwich against a direct computation: the whitened residuals of a small sigma-column
// fit, their Jacobian by central differences, leverages, and B M B with Eigen.
TEST(Sandwich, Hc3StandardErrorsMatchADirectComputation) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.2, 0.1);
  SyntheticDesign design;
  design.rows = 40;
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth, design, NoiseSpec{0.02, 0.0, true}, 21);
  const FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "hertz");
  const FitResult fit = Fitter(s).fit(d);
  ParamVector x = default_parameters(law);
  for (const auto& p : fit.parameters) x[*param_index(p.name)] = p.value;
  const std::vector<int> free = model_parameters(ModelKind::Seed, law.kind);

  auto residuals = [&](const ParamVector& at) {
    const ModelEvaluator<double> model(ModelKind::Seed, law, at.data());
    std::vector<double> r;
    for (std::size_t i = 0; i < d.rows(); ++i) {
      const auto p = model({d.v_x[i], d.v_y[i], d.omega[i], d.N[i], d.R[i]});
      const double pred[kChannelCount] = {p.T_x, p.T_y, p.M_z, p.M_roll, p.M_tilt};
      for (Channel c : kAllChannels) {
        if (!d.has_channel(c)) continue;  // a circle's file has no M_tilt
        const int ci = static_cast<int>(c);
        r.push_back((pred[ci] - d.value[ci][i]) / d.sigma[ci][i]);
      }
    }
    return r;
  };
  const std::vector<double> r0 = residuals(x);
  const auto m = static_cast<Eigen::Index>(r0.size()), k = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd J(m, k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const int i = free[static_cast<std::size_t>(j)];
    const double h = 1e-6 * std::max(1.0, std::fabs(x[i]));
    ParamVector up = x, down = x;
    up[i] += h;
    down[i] -= h;
    const auto ru = residuals(up), rd = residuals(down);
    for (Eigen::Index a = 0; a < m; ++a)
      J(a, j) = (ru[static_cast<std::size_t>(a)] - rd[static_cast<std::size_t>(a)]) / (2 * h);
  }
  const Eigen::MatrixXd B = (J.transpose() * J).inverse();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(k, k);
  for (Eigen::Index a = 0; a < m; ++a) {
    const Eigen::RowVectorXd ja = J.row(a);
    const double lev = (ja * B * ja.transpose())(0, 0);
    const double e = r0[static_cast<std::size_t>(a)] / (1.0 - lev);
    M += e * e * ja.transpose() * ja;
  }
  const Eigen::MatrixXd S = B * M * B;
  for (Eigen::Index j = 0; j < k; ++j) {
    const auto* p = fit.parameter(param_names()[free[static_cast<std::size_t>(j)]]);
    ASSERT_TRUE(p && p->std_error_sandwich) << p->name;
    EXPECT_NEAR(*p->std_error_sandwich, std::sqrt(S(j, j)), 1e-5 * std::sqrt(S(j, j))) << p->name;
    // and the model-based one is sqrt(B_jj) (sigma columns: absolute)
    EXPECT_NEAR(*p->std_error, std::sqrt(B(j, j)), 1e-5 * std::sqrt(B(j, j))) << p->name;
  }
}

// Too few observations to estimate a noise model from (at most 2k + 2 for k free parameters):
// where a fitted channel has no sigma column the covariance is the whitened (J^T J)^-1 times the
// reduced chi², whose degrees of freedom are observations - k; with sigma columns on every fitted
// channel it is (J^T J)^-1 as it stands (docs/physics.md (8.4)). Recomputed here from the model:
// residuals whitened by the sigma column, else by the channel's upper median magnitude (§8.2),
// Jacobian by central differences, s² = sum r² / (n - k). One channel without sigma columns makes
// the whitening cancel: s² (J^T J)^-1 of the raw residuals, the textbook least-squares covariance.
struct TinyFit {
  std::vector<Channel> channels;
  std::vector<const char*> free;
  std::size_t rows = 0;
  std::vector<Channel> with_sigma;  // channels that keep their sigma column
};

void expect_covariance_from_jacobian(const TinyFit& t) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.2, 0.1);
  SyntheticDesign design;
  design.rows = t.rows;
  Dataset d = generate_dataset(ModelKind::Seed, law, truth, design, NoiseSpec{0.02, 0.0, true}, 5);
  for (int c = 0; c < kChannelCount; ++c)
    if (std::find(t.with_sigma.begin(), t.with_sigma.end(), static_cast<Channel>(c)) ==
        t.with_sigma.end())
      d.sigma[c].clear();
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "hertz");
  s.channels = t.channels;
  for (const char* name : {"f", "kappa", "h", "a", "b", "m"})
    if (std::find_if(t.free.begin(), t.free.end(),
                     [&](const char* f) { return std::string(f) == name; }) == t.free.end())
      s.fix(name, truth[*param_index(name)]);
  const FitResult r = Fitter(s).fit(d);
  const std::size_t n = t.channels.size() * t.rows, k = t.free.size();
  ASSERT_LE(n, 2 * k + 2) << "the tiny-data path needs at most 2k + 2 observations";
  ASSERT_EQ(r.residuals, n);

  // Whitening per channel, independent of the program: sigma column, else median |value|.
  const bool all_sigma = t.with_sigma.size() >= t.channels.size();
  std::array<double, kChannelCount> median{};
  for (Channel c : t.channels) {
    std::vector<double> m;
    for (double v : d.value[static_cast<int>(c)]) m.push_back(std::fabs(v));
    std::sort(m.begin(), m.end());
    median[static_cast<int>(c)] = m[m.size() / 2];
  }
  ParamVector x = default_parameters(law);
  for (const auto& p : r.parameters) x[*param_index(p.name)] = p.value;
  auto residuals = [&](const ParamVector& at) {
    const ModelEvaluator<double> model(ModelKind::Seed, law, at.data());
    std::vector<double> out;
    for (std::size_t i = 0; i < d.rows(); ++i) {
      const auto p = model({d.v_x[i], d.v_y[i], d.omega[i], d.N[i], d.R[i]});
      const double pred[kChannelCount] = {p.T_x, p.T_y, p.M_z, p.M_roll};
      for (Channel c : t.channels) {
        const int ci = static_cast<int>(c);
        const double w = d.has_sigma(c) ? d.sigma[ci][i] : median[ci];
        out.push_back((pred[ci] - d.value[ci][i]) / w);
      }
    }
    return out;
  };
  const std::vector<double> r0 = residuals(x);
  const auto m = static_cast<Eigen::Index>(r0.size()), kk = static_cast<Eigen::Index>(k);
  Eigen::MatrixXd J(m, kk);
  for (Eigen::Index j = 0; j < kk; ++j) {
    const int i = *param_index(t.free[static_cast<std::size_t>(j)]);
    const double h = 1e-6 * std::max(1.0, std::fabs(x[i]));
    ParamVector up = x, down = x;
    up[i] += h;
    down[i] -= h;
    const auto ru = residuals(up), rd = residuals(down);
    for (Eigen::Index a = 0; a < m; ++a)
      J(a, j) = (ru[static_cast<std::size_t>(a)] - rd[static_cast<std::size_t>(a)]) / (2 * h);
  }
  double ss = 0.0;
  for (double e : r0) ss += e * e;
  const double s2 = all_sigma ? 1.0 : ss / static_cast<double>(n - k);
  const Eigen::MatrixXd cov = s2 * (J.transpose() * J).inverse();

  EXPECT_EQ(r.covariance_scaled_by_reduced_chi2, !all_sigma);
  EXPECT_NEAR(r.chi2, ss, 1e-9 * ss);
  for (Eigen::Index j = 0; j < kk; ++j) {
    const auto* p = r.parameter(t.free[static_cast<std::size_t>(j)]);
    ASSERT_TRUE(p && p->std_error) << t.free[static_cast<std::size_t>(j)];
    EXPECT_NEAR(*p->std_error, std::sqrt(cov(j, j)), 1e-5 * std::sqrt(cov(j, j))) << p->name;
  }
}

TEST(Covariance, OnTooFewRowsForANoiseModelIsSSquaredTimesJtJInverseWithNMinusKDof) {
  // T_x = f N t(eps; a) alone (docs/physics.md §3), f and a free: 4 rows <= k + 2 = 4 for the
  // channel, 2 degrees of freedom.
  expect_covariance_from_jacobian({{Channel::T_x}, {"f", "a"}, 4, {}});
  // T_x and M_z, f, a and m free: 4 rows per channel <= 3 + 2, 8 observations, 5 degrees of
  // freedom; whitened per channel.
  expect_covariance_from_jacobian({{Channel::T_x, Channel::M_z}, {"f", "a", "m"}, 4, {}});
}

TEST(Covariance, OnTooFewRowsWithSigmaColumnsOnSomeChannelsIsStillScaledByTheReducedChi2) {
  expect_covariance_from_jacobian(
      {{Channel::T_x, Channel::M_z}, {"f", "a", "m"}, 4, {Channel::T_x}});
}

TEST(Covariance, OnTooFewRowsWithSigmaColumnsOnEveryChannelIsNotRescaled) {
  expect_covariance_from_jacobian({{Channel::T_x}, {"f", "a"}, 5, {Channel::T_x}});
  expect_covariance_from_jacobian(
      {{Channel::T_x, Channel::M_z}, {"f", "a", "m"}, 4, {Channel::T_x, Channel::M_z}});
}

}  // namespace
}  // namespace frictionid::fit_statistics_test

namespace frictionid::fit_statistics_test {
namespace {

FitResult fit_exact_rows(std::size_t rows, bool sigma_columns) {
  using Law = model::PressureLaw<double>;
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  SyntheticDesign design;
  design.rows = rows;
  const Dataset d = generate_dataset(ModelKind::Exact, law, truth, design,
                                     NoiseSpec{0.01, 0.0, sigma_columns}, 3);
  FitSettings s = FitSettings::defaults(ModelKind::Exact, law, "hertz");
  s.global_evaluations = 500;
  return Fitter(s).fit(d);
}

// The t quantile of each interval, read back from it.
double interval_t(const ParameterEstimate& e) {
  return ((*e.ci95)[1] - e.value) / *e.std_error;
}

// Sigma columns are known: every interval uses t(0.975, n - k).
TEST(IntervalDof, SigmaColumnsKeepNMinusK) {
  const FitResult r = fit_exact_rows(8, true);
  const double t = student_t_quantile(0.975, static_cast<double>(r.dof));
  for (const auto& e : r.parameters)
    if (e.std_error) {
      EXPECT_NEAR(interval_t(e), t, 1e-9 * t) << e.name;
    }
}

// Each channel's sigma estimated from its 8 rows: the intervals' degrees of freedom are fewer
// than n - k = 29 (Satterthwaite over the channels), never more, and on 600 rows per
// channel close to n - k.
TEST(IntervalDof, EstimatedNoiseOnFewRowsWidensTheIntervals) {
  const FitResult small = fit_exact_rows(8, false);
  ASSERT_GT(small.noise_iterations, 0);
  const double t_nk = student_t_quantile(0.975, static_cast<double>(small.dof));
  for (const auto& e : small.parameters) {
    ASSERT_TRUE(e.std_error) << e.name;
    // Fewer than n - k: t(0.975, 29) = 2.045, t(0.975, 20) = 2.086.
    EXPECT_GT(interval_t(e), 1.01 * t_nk) << e.name;
  }
  const FitResult large = fit_exact_rows(600, false);
  const double t_large = student_t_quantile(0.975, static_cast<double>(large.dof));
  for (const auto& e : large.parameters) {
    EXPECT_GE(interval_t(e), t_large * (1 - 1e-12)) << e.name;
    EXPECT_LT(interval_t(e), t_large * 1.002) << e.name;
  }
  EXPECT_GT(t_nk, 0.0);
}

// Rows per channel, not cells, decide whether a noise model is estimated: 5 rows of 4 channels
// (20 cells) with 3 free parameters leave the fixed scales and one pooled sigma.
TEST(IntervalDof, TooFewRowsPerChannelPoolOneSigma) {
  const FitResult r = fit_exact_rows(5, false);
  EXPECT_EQ(r.noise_iterations, 0);
  EXPECT_TRUE(r.covariance_scaled_by_reduced_chi2);
  const double t = student_t_quantile(0.975, static_cast<double>(r.dof));
  for (const auto& e : r.parameters)
    if (e.std_error) {
      EXPECT_NEAR(interval_t(e), t, 1e-9 * t) << e.name;
    }
}

}  // namespace
}  // namespace frictionid::fit_statistics_test
