#include <frictionid/model_comparison.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <frictionid/fit_result.hpp>
#include <frictionid/fitter.hpp>
#include <frictionid/synthetic_data.hpp>

namespace frictionid::model_comparison_test {
namespace {

using Law = model::PressureLaw<double>;

// Exact-model data with 0.2 % noise: the closed forms cannot follow the integral model's shape,
// so their residuals ordered by eps form long runs (lag-1 correlation near 1) while the exact
// fit's residuals are noise (near 0), and AIC prefers exact.
TEST(ModelComparison, ClosedFormsLeaveASystematicResidualOnExactDataAndAicPrefersExact) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  SyntheticDesign design;
  design.rows = 400;
  const Dataset d =
      generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{0.002, 0.0, false}, 11);
  const ModelComparison c =
      compare_models(d, {FitSettings::defaults(ModelKind::Seed, law, "law"),
                         FitSettings::defaults(ModelKind::Corrected, law, "law"),
                         FitSettings::defaults(ModelKind::Exact, law, "law")});
  ASSERT_EQ(c.fits.size(), 3u);
  EXPECT_EQ(c.preferred_by_aic, "exact");
  EXPECT_EQ(c.preferred_by_bic, "exact");
  EXPECT_GT(c.delta_aic[0], 100.0);
  EXPECT_GT(c.delta_aic[1], 100.0);
  for (const char* ch : {"T_x", "T_y", "M_z"}) {
    EXPECT_GT(c.residual_autocorrelation[0].at(ch), 0.5) << "seed " << ch;
    EXPECT_LT(std::fabs(c.residual_autocorrelation[2].at(ch)), 0.3) << "exact " << ch;
  }
  EXPECT_GT(c.residual_autocorrelation[1].at("M_z"), 0.5) << "corrected M_z";
  // Under one noise (exact's, the model AIC prefers) the closed forms' chi2 is far above the
  // exact fit's, whatever their own chi2 (each near the number of cells) says.
  EXPECT_EQ(c.common_noise_fit, 2u);
  ASSERT_EQ(c.chi2_common.size(), 3u);
  EXPECT_NEAR(c.chi2_common[2], c.fits[2].chi2, 1e-3 * c.fits[2].chi2);
  EXPECT_GT(c.chi2_common[0], 2 * c.chi2_common[2]);
  EXPECT_GT(c.chi2_common[1], 2 * c.chi2_common[2]);
  // The coefficients implied by the exact fit are those of its (Hertz) pressure at its kappa.
  const double kappa = c.fits[2].parameters[1].value;
  const double r = 15 * M_PI * (1 + kappa) / (32 * kappa);
  EXPECT_NEAR(c.implied_by_exact.at("b"), 25.0, 1e-12);
  EXPECT_NEAR(c.implied_by_exact.at("m"), r * r, 1e-10);
}

// The approximants know the circle only, so the coefficients set beside theirs come from the
// exact fit on the circle, not from an exact fit on an ellipse listed before it.
TEST(ModelComparison, CoefficientsImpliedByExactComeFromTheFitOnTheCircle) {
  const Law law = Law::uniform();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  SyntheticDesign design;
  design.rows = 120;
  const Dataset d = generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{}, 11);
  FitSettings on_ellipse =
      FitSettings::defaults(ModelKind::Exact, law, "law", model::ContactSpot::ellipse(0.5));
  on_ellipse.fix("h_y", 0.0);
  const ModelComparison c =
      compare_models(d, {on_ellipse, FitSettings::defaults(ModelKind::Exact, law, "law")});
  ASSERT_EQ(c.fits.size(), 2u);
  const double kappa = c.fits[1].parameters[1].value;
  EXPECT_NEAR(kappa, 1.15, 1e-8);
  const double r = (1 + kappa) * (4.0 / 3.0) / kappa;  // uniform: (1 + kappa) m2/(kappa m3)
  EXPECT_NEAR(c.implied_by_exact.at("b"), 16.0, 1e-12);
  EXPECT_NEAR(c.implied_by_exact.at("m"), r * r, 1e-9);
}

// Physics.md §3: with the coefficients the pressure law implies, the seed's T_par differs from
// the exact one only in shape, t_seed = eps/sqrt(eps^2 + a) against the Hertz closed form of
// §2, t = 3/(16 eps) [(4 eps^2 - eps^4) A + (eps^2 + 2) W]. Fitting f alone to exact T_x data
// must leave exactly that ratio as the residual: measured/fitted = t/(c t_seed) at every row,
// with one constant c = f_fit/f_true, a dip of ~14 % near eps = 0.9 against both ends.
TEST(ModelComparison, SeedFitToExactDataLeavesThePredictedShapeResidual) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  SyntheticDesign design;
  design.rows = 400;
  design.eps_min = 1e-3;
  design.eps_max = 1e3;
  const Dataset d = generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{}, 3);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.channels = {Channel::T_x};
  const double a = std::pow(8.0 / (3.0 * M_PI), 2);  // (2 m1/m0)^2 for Hertz
  for (int i : {kKappa, kH, kA, kB, kM}) s.params[i].fixed = true;
  s.params[kA].initial = a;
  const FitResult r = Fitter(s).fit(d);
  const double c = r.parameters[0].value / truth[kF];
  double dip = 1.0, dip_eps = 0.0, low_end = 0.0, high_end = 0.0;
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const double eps = r.eps[i];
    const double A = std::asin(std::min(1.0, 1.0 / eps)),
                 W = std::sqrt(std::max(0.0, eps * eps - 1));
    const double t_exact =
        3.0 / (16.0 * eps) * ((4 * eps * eps - std::pow(eps, 4)) * A + (eps * eps + 2) * W);
    const double t_seed = eps / std::sqrt(eps * eps + a);
    const double predicted = t_exact / (c * t_seed);  // measured / fitted
    const double got = d.value[0][i] / r.fitted[0][i];
    ASSERT_NEAR(got, predicted, 1e-9) << "eps " << eps;
    const double shape = c * t_seed / t_exact;  // the approximant against the exact shape
    if (shape < dip) dip = shape, dip_eps = eps;
    if (eps < 2e-3) low_end = shape;
    if (eps > 5e2) high_end = shape;
  }
  EXPECT_NEAR(low_end / c, 1.0, 1e-3);  // both ends: slopes matched (a from the law)
  EXPECT_NEAR(high_end / c, 1.0, 1e-3);
  EXPECT_NEAR(dip / c, 1.0 - 0.139, 0.005);  // tens of percent in between (docs/physics.md §3)
  EXPECT_GT(dip_eps, 0.6);
  EXPECT_LT(dip_eps, 1.3);
}

// Slip in several directions: the force direction alone (T_x, T_y, no M_z) fixes kappa.
TEST(ModelComparison, SlipInSeveralDirectionsIdentifiesKappaWithoutTorque) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.6, 0.0);
  SyntheticDesign design;
  design.rows = 300;
  design.slip_angles = {0.0, 0.5, 1.0, 1.4};
  const Dataset d =
      generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{0.005, 0.0, false}, 4);
  FitSettings s = FitSettings::defaults(ModelKind::Exact, law, "law");
  s.channels = {Channel::T_x, Channel::T_y};
  s.params[kH].fixed = true;  // no torque channel carries the tilt's own signature here
  s.params[kH].initial = 0.0;
  const FitResult r = Fitter(s).fit(d);
  const ParameterEstimate& kappa = r.parameters[1];
  ASSERT_EQ(kappa.name, "kappa");
  ASSERT_TRUE(kappa.std_error.has_value());
  EXPECT_LT(*kappa.std_error, 0.01);
  EXPECT_LE(std::fabs(kappa.value - 1.6), 4 * *kappa.std_error);
}

// Aligned slip only (v_y = 0) with no tilt: T_x does not depend on kappa at all (physics §5),
// and T_y = 0, so without M_z the data cannot say anything about kappa.
TEST(ModelComparison, AlignedSlipWithoutTorqueLeavesKappaUndetermined) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.6, 0.0);
  SyntheticDesign design;
  design.rows = 200;
  const Dataset d = generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{}, 4);
  FitSettings s = FitSettings::defaults(ModelKind::Exact, law, "law");
  s.channels = {Channel::T_x};
  s.params[kH].fixed = true;
  s.params[kH].initial = 0.0;
  const FitResult r = Fitter(s).fit(d);
  EXPECT_FALSE(r.parameters[1].std_error.has_value());
}

// Measured loads: every row its own N (1e-9 apart), so no two rows share a curve of one load.
// The residual runs are then taken along coarser curves, and the closed form's shape misfit
// still shows as a lag-1 correlation near 1.
TEST(ModelComparison, ResidualRunsSurviveALoadThatDiffersOnEveryRow) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  SyntheticDesign design;
  design.rows = 300;
  Dataset d =
      generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{0.002, 0.0, false}, 11);
  for (std::size_t i = 0; i < d.rows(); ++i) d.N[i] *= 1 + 1e-9 * static_cast<double>(i);
  const ModelComparison c =
      compare_models(d, {FitSettings::defaults(ModelKind::Seed, law, "law"),
                         FitSettings::defaults(ModelKind::Exact, law, "law")});
  EXPECT_GT(c.residual_autocorrelation[0].at("T_x"), 0.5);
  EXPECT_LT(std::fabs(c.residual_autocorrelation[1].at("T_x")), 0.3);
}

// fit_sigma gives the sigma per row that the fit divided by: with an estimated noise model its
// chi2 is the fit's own.
TEST(ModelComparison, FitSigmaIsTheSigmaTheFitDividedBy) {
  const Law law = Law::hertz();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  SyntheticDesign design;
  design.rows = 300;
  const Dataset d =
      generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{0.01, 0.0, false}, 5);
  const FitResult r = Fitter(FitSettings::defaults(ModelKind::Exact, law, "law")).fit(d);
  double chi2 = 0.0;
  for (const auto& cs : r.channel_summaries) {
    ASSERT_TRUE(cs.noise.has_value()) << channel_name(cs.channel);
    const int ci = static_cast<int>(cs.channel);
    const std::vector<double> sigma = fit_sigma(r, d, cs.channel);
    ASSERT_EQ(sigma.size(), d.rows());
    for (std::size_t i = 0; i < d.rows(); ++i)
      if (d.present[ci][i]) chi2 += std::pow((d.value[ci][i] - r.fitted[ci][i]) / sigma[i], 2);
  }
  // The fit's sigma came from the fitted values one reweighting step earlier.
  EXPECT_NEAR(chi2, r.chi2, 1e-3 * r.chi2);
}

// Rows of one curve share a slip direction, spin sign and tilt sign; the mirrored slip angle
// takes both spin signs of a lateral slip to +-90 degrees and slipping backwards to v_x >= 0.
TEST(ModelComparison, SlipCurvesAndMirroredAngles) {
  Dataset d;
  d.v_x = {1.0, 2.0, 1.0, 0.0, 0.0, -1.0};
  d.v_y = {0.0, 0.0, 0.0, 1.0, 1.0, 1.0};
  d.omega = {2.0, 5.0, -2.0, 2.0, -2.0, -2.0};
  EXPECT_EQ(slip_curve(d, 0), slip_curve(d, 1));
  EXPECT_FALSE(slip_curve(d, 0) == slip_curve(d, 2));
  EXPECT_FALSE(slip_curve(d, 3) == slip_curve(d, 4));
  EXPECT_EQ(mirrored_slip_angle_deg(d, 0), 0.0);
  EXPECT_EQ(mirrored_slip_angle_deg(d, 2), 0.0);
  EXPECT_EQ(mirrored_slip_angle_deg(d, 3), 90.0);
  EXPECT_EQ(mirrored_slip_angle_deg(d, 4), -90.0);
  EXPECT_EQ(mirrored_slip_angle_deg(d, 5), -45.0);
}

}  // namespace
}  // namespace frictionid::model_comparison_test
