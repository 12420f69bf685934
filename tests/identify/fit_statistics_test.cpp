#include "identify/fit_statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include <frictionid/fitter.hpp>
#include <frictionid/synthetic_data.hpp>

namespace frictionid {
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
      const double pred[kChannelCount] = {p.T_x, p.T_y, p.M_z, p.M_roll};
      for (int c = 0; c < kChannelCount; ++c)
        r.push_back((pred[c] - d.value[c][i]) / d.sigma[c][i]);
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

}  // namespace
}  // namespace frictionid
