#include <frictionid/fitter.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include <frictionid/io/report_writer.hpp>
#include <frictionid/synthetic_data.hpp>
#include "support/matched_digits.hpp"

namespace frictionid::fitter_test {
namespace {

using Law = model::PressureLaw<double>;

using frictionid::test::matched_digits;

std::array<double, kParamCount> truth_params(const Law& law) {
  auto p = default_parameters(law, 0.85, 1.3, 0.12);
  p[kA] = 0.9;
  p[kB] = 20.0;
  p[kM] = 7.0;
  p[kBTilde] = 3.0;
  return p;
}

void expect_recovery(ModelKind kind, const Law& law, const std::array<double, kParamCount>& truth,
                     double digits) {
  const Dataset d = generate_dataset(kind, law, truth, SyntheticDesign{}, NoiseSpec{}, 5);
  const FitResult r = Fitter(FitSettings::defaults(kind, law, "law")).fit(d);
  for (const auto& p : r.parameters) {
    const int i = *param_index(p.name);
    EXPECT_GE(matched_digits(p.value, truth[i]), digits) << p.name << " = " << p.value;
  }
  EXPECT_TRUE(r.solver.converged);
}

TEST(Fitter, NoiseFreeSeedDataRecoversEveryParameterToTenDigitsFromTheBoundsAlone) {
  expect_recovery(ModelKind::Seed, Law::hertz(), truth_params(Law::hertz()), 10.0);
}

TEST(Fitter, NoiseFreeCorrectedDataRecoversEveryParameterToTenDigitsFromTheBoundsAlone) {
  expect_recovery(ModelKind::Corrected, Law::parabolic(), truth_params(Law::parabolic()), 10.0);
}

TEST(Fitter, NoiseFreeExactDataRecoversFrictionTiltAndPressureExponentToEightDigits) {
  const Law law = Law::power(1.7);
  auto truth = default_parameters(law, 0.85, 1.3, 0.12);
  SyntheticDesign design;
  design.rows = 200;
  const Dataset d = generate_dataset(ModelKind::Exact, law, truth, design, NoiseSpec{}, 5);
  FitSettings s =
      FitSettings::defaults(ModelKind::Exact, Law::power(1.0), "law");  // n starts elsewhere
  const FitResult r = Fitter(s).fit(d);
  ASSERT_EQ(r.parameters.size(), 4u);
  for (const auto& p : r.parameters)
    EXPECT_GE(matched_digits(p.value, truth[*param_index(p.name)]), 8.0) << p.name;
}

// With 1 % noise the reported standard errors must be honest: every parameter within 4 of them.
void expect_within_four_standard_errors(ModelKind kind, const Law& law,
                                        const std::array<double, kParamCount>& truth) {
  SyntheticDesign design;
  design.rows = 300;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Dataset d = generate_dataset(kind, law, truth, design, NoiseSpec{0.01, 0.0, false}, seed);
    FitSettings s = FitSettings::defaults(kind, law, "law");
    s.seed = seed;
    const FitResult r = Fitter(s).fit(d);
    for (const auto& p : r.parameters) {
      ASSERT_TRUE(p.std_error.has_value()) << p.name;
      EXPECT_LE(std::fabs(p.value - truth[*param_index(p.name)]), 4.0 * *p.std_error)
          << "seed " << seed << " " << p.name << " = " << p.value << " +- " << *p.std_error;
    }
  }
}

TEST(Fitter, OnePercentNoiseLeavesEveryParameterWithinFourStandardErrorsForTwentySeeds) {
  expect_within_four_standard_errors(ModelKind::Seed, Law::hertz(), truth_params(Law::hertz()));
}

TEST(Fitter, CorrectedModelStandardErrorsAreHonestForTwentySeeds) {
  expect_within_four_standard_errors(ModelKind::Corrected, Law::parabolic(),
                                     truth_params(Law::parabolic()));
}

TEST(Fitter, ExactModelStandardErrorsAreHonestForTwentySeeds) {
  const Law law = Law::hertz();
  expect_within_four_standard_errors(ModelKind::Exact, law,
                                     default_parameters(law, 0.85, 1.3, 0.12));
}

TEST(Fitter, DataWithoutLateralForceOrRollingTorqueNamesHAndBAsUndetermined) {
  const Law law = Law::hertz();
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.channels = {Channel::T_x, Channel::M_z};
  const FitResult r = Fitter(s).fit(d);
  bool warned = false;
  for (const auto& w : r.warnings)
    if (w.find("not determined") != std::string::npos && w.find("h and b") != std::string::npos)
      warned = true;
  EXPECT_TRUE(warned);
  for (const auto& p : r.parameters) {
    if (p.name == "h" || p.name == "b")
      EXPECT_FALSE(p.std_error.has_value()) << p.name;
    else
      EXPECT_TRUE(p.std_error.has_value()) << p.name;
  }
}

TEST(Fitter, AParameterPinnedAtABoundIsFlagged) {
  const Law law = Law::hertz();
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.params[kF].upper = 0.8;  // truth 0.85 lies outside
  const FitResult r = Fitter(s).fit(d);
  for (const auto& p : r.parameters)
    if (p.name == "f") {
      EXPECT_TRUE(p.at_bound);
    }
}

TEST(Fitter, FixedParametersKeepTheirValueAndHaveNoStandardError) {
  const Law law = Law::hertz();
  const auto truth = truth_params(law);
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth, SyntheticDesign{}, NoiseSpec{}, 5);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.params[kKappa].fixed = true;
  s.params[kKappa].initial = truth[kKappa];
  const FitResult r = Fitter(s).fit(d);
  for (const auto& p : r.parameters) {
    if (p.name != "kappa") continue;
    EXPECT_TRUE(p.fixed);
    EXPECT_EQ(p.value, truth[kKappa]);
    EXPECT_FALSE(p.std_error.has_value());
  }
}

TEST(Fitter, SameInputAndSeedGiveAByteIdenticalReport) {
  const Law law = Law::hertz();
  const Dataset d = generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{},
                                     NoiseSpec{0.01, 0.0, false}, 9);
  const FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  const std::string a = report_json(Fitter(s).fit(d)).dump(2);
  const std::string b = report_json(Fitter(s).fit(d)).dump(2);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.find("NaN"), std::string::npos);
}

TEST(Fitter, ReportIsByteIdenticalWithOneOrTwoSolverThreads) {
  const Law law = Law::hertz();
  SyntheticDesign design;
  design.rows = 6000;  // several residual blocks, so two threads really split the work
  const Dataset d = generate_dataset(ModelKind::Seed, law, truth_params(law), design,
                                     NoiseSpec{0.01, 0.0, false}, 21);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.global_evaluations = 300;
  s.threads = 1;
  const std::string one = report_json(Fitter(s).fit(d)).dump(2);
  s.threads = 2;
  EXPECT_EQ(report_json(Fitter(s).fit(d)).dump(2), one);
}

// A robust loss must not break down when the residuals vanish (noise-free data): its factor
// and derivative are evaluated without cancellation.
TEST(Fitter, RobustLossesOnNoiseFreeDataConvergeToTheTruth) {
  const Law law = Law::hertz();
  const auto truth = truth_params(law);
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth, SyntheticDesign{}, NoiseSpec{}, 5);
  for (LossKind loss : {LossKind::Huber, LossKind::Cauchy, LossKind::SoftL1}) {
    FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
    s.loss = loss;
    const FitResult r = Fitter(s).fit(d);
    EXPECT_TRUE(r.solver.converged) << r.solver.termination;
    for (const auto& p : r.parameters)
      EXPECT_GE(matched_digits(p.value, truth[*param_index(p.name)]), 9.0) << p.name;
  }
}

// More rows than the global subsample: the starts are fitted on the subsample and the best is
// refined on all rows, which must still reach the optimum of all rows.
TEST(Fitter, LargeDataRefinesTheBestSubsampleFitOnAllRows) {
  const Law law = Law::hertz();
  const auto truth = truth_params(law);
  SyntheticDesign design;
  design.rows = 5000;
  const Dataset d = generate_dataset(ModelKind::Seed, law, truth, design, NoiseSpec{}, 8);
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.global_subsample = 300;
  const FitResult r = Fitter(s).fit(d);
  EXPECT_TRUE(r.global.local_fits_on_subsample);
  EXPECT_EQ(r.global.subsample_rows, 295u);  // every 17th row
  EXPECT_TRUE(r.solver.converged);
  for (const auto& p : r.parameters)
    EXPECT_GE(matched_digits(p.value, truth[*param_index(p.name)]), 10.0) << p.name;
}

// A model that is not finite for every parameter value (here a row whose load is NaN, which the
// CSV loader would reject) must end in FitError, never in a report with NaN in it.
TEST(Fitter, ANonFiniteModelAtEveryStartIsAFitErrorNotAResult) {
  const Law law = Law::hertz();
  Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  d.N[17] = std::nan("");
  for (bool global : {true, false}) {
    FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
    s.global = global;
    EXPECT_THROW(Fitter(s).fit(d), FitError) << "global stage " << global;
  }
}

TEST(Fitter, RequestedChannelThatNoRowMeasuresIsReportedNotFitted) {
  const Law law = Law::hertz();
  Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  for (auto& p : d.present[static_cast<int>(Channel::M_roll)]) p = 0;
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.channels = {Channel::T_x, Channel::T_y, Channel::M_z, Channel::M_roll};
  const FitResult r = Fitter(s).fit(d);
  EXPECT_EQ(r.channels.size(), 3u);
  bool warned = false;
  for (const auto& w : r.warnings) warned |= w.find("M_roll") != std::string::npos;
  EXPECT_TRUE(warned);
}

// The failed fit says where the model stopped being finite, so the user can find the row.
TEST(Fitter, AFitErrorNamesTheFirstRowAndChannelWhereTheModelIsNotFinite) {
  const Law law = Law::hertz();
  Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  d.line.resize(d.rows());
  for (std::size_t i = 0; i < d.rows(); ++i) d.line[i] = i + 2;  // a header on line 1
  d.source = "rig.csv";
  d.N[17] = std::nan("");
  FitSettings s = FitSettings::defaults(ModelKind::Seed, law, "law");
  s.global = false;
  try {
    Fitter(s).fit(d);
    ADD_FAILURE() << "no FitError";
  } catch (const FitError& e) {
    EXPECT_NE(std::string(e.what()).find("line 19 of rig.csv, channel T_x"), std::string::npos)
        << e.what();
  }
}

// Records what the fit reports and cancels after a given number of progress calls.
class CountingObserver : public FitObserver {
 public:
  explicit CountingObserver(int cancel_after) : cancel_after_(cancel_after) {}
  void on_progress(const FitProgress& p) override {
    ++calls;
    if (p.stage == FitStage::GlobalSearch) ++global_calls;
    if (p.stage == FitStage::LocalFit) ++local_calls;
  }
  void on_log(const std::string& line) override { logs += line; }
  bool cancelled() const override { return cancel_after_ >= 0 && calls >= cancel_after_; }
  int calls = 0, global_calls = 0, local_calls = 0;
  std::string logs;

 private:
  int cancel_after_;
};

TEST(Fitter, TheObserverSeesBothStagesAndTheSolverReport) {
  const Law law = Law::hertz();
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  CountingObserver observer(-1);
  Fitter(FitSettings::defaults(ModelKind::Seed, law, "law")).fit(d, &observer);
  EXPECT_GT(observer.global_calls, 0);
  EXPECT_GT(observer.local_calls, 0);
  EXPECT_NE(observer.logs.find("Solver Summary"), std::string::npos);
}

TEST(Fitter, AnObserverThatCancelsStopsTheFitWithInterrupted) {
  const Law law = Law::hertz();
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  for (int after : {1, 3}) {
    CountingObserver observer(after);
    try {
      Fitter(FitSettings::defaults(ModelKind::Seed, law, "law")).fit(d, &observer);
      ADD_FAILURE() << "not cancelled";
    } catch (const FitError& e) {
      EXPECT_STREQ(e.what(), "interrupted");
    }
    EXPECT_LE(observer.calls, after + 1);  // stops at the next check
  }
}

// With sigma columns a channel that is zero in every row is fitted and said to be zero, not taken
// for noise growing with the signal (its residuals equal the predictions: rank correlation 1).
TEST(Fitter, AChannelThatIsZeroInEveryRowGetsItsOwnWarningNotTheGrowthWarning) {
  const Law law = Law::hertz();
  Dataset d = generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{},
                               NoiseSpec{0.01, 0.0, true}, 5);
  for (auto& v : d.value[static_cast<int>(Channel::T_y)]) v = 0.0;
  for (auto& v : d.sigma[static_cast<int>(Channel::T_y)]) v = 1.0;
  const FitResult r = Fitter(FitSettings::defaults(ModelKind::Seed, law, "law")).fit(d);
  bool zero = false, growth_names_ty = false;
  for (const auto& w : r.warnings) {
    zero |= w.find("every measured value of T_y is zero") != std::string::npos;
    growth_names_ty |= w.find("grow with the measured magnitude") != std::string::npos &&
                       w.find("T_y") != std::string::npos;
  }
  EXPECT_TRUE(zero);
  EXPECT_FALSE(growth_names_ty);
}

// Without sigma columns the noise of a channel that never varies cannot be estimated: it is left
// out of the fit, with a warning, and its rows do not count as observations.
TEST(Fitter, AConstantChannelIsLeftOutOfTheFitAndOfTheDegreesOfFreedom) {
  const Law law = Law::hertz();
  Dataset d = generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{},
                               NoiseSpec{0.01, 0.0, false}, 5);
  const FitResult all = Fitter(FitSettings::defaults(ModelKind::Seed, law, "law")).fit(d);
  for (auto& v : d.value[static_cast<int>(Channel::T_y)]) v = 0.0;
  const FitResult r = Fitter(FitSettings::defaults(ModelKind::Seed, law, "law")).fit(d);
  EXPECT_EQ(r.channels, (std::vector<Channel>{Channel::T_x, Channel::M_z, Channel::M_roll}));
  EXPECT_EQ(r.residuals, all.residuals - d.rows());
  EXPECT_EQ(r.dof, r.residuals - 6);
  bool warned = false;
  for (const auto& w : r.warnings)
    warned |= w.find("every measured value of T_y is the same") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(Fitter, ResultsAreFoundByParameterName) {
  const Law law = Law::hertz();
  const auto truth = truth_params(law);
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth, SyntheticDesign{}, NoiseSpec{}, 5);
  const FitResult r = Fitter(FitSettings::defaults(ModelKind::Seed, law, "law")).fit(d);
  EXPECT_EQ(r.model_kind, ModelKind::Seed);
  ASSERT_NE(r.parameter("kappa"), nullptr);
  EXPECT_GE(matched_digits(r.parameter("kappa")->value, truth[kKappa]), 10.0);
  EXPECT_EQ(r.parameter("n"), nullptr);  // the seed model has no exponent
}

TEST(Fitter, AFitOnTheCircleNamesItsContactCircle) {
  const Law law = Law::hertz();
  const Dataset d =
      generate_dataset(ModelKind::Seed, law, truth_params(law), SyntheticDesign{}, NoiseSpec{}, 5);
  const FitResult r =
      Fitter(FitSettings::defaults(ModelKind::Seed, law, "law", model::ContactSpot::circle()))
          .fit(d);
  EXPECT_EQ(r.contact, "circle");
}

}  // namespace
}  // namespace frictionid::fitter_test
