#include <frictionid/fit_settings.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <frictionid/fitter.hpp>
#include <frictionid/synthetic_data.hpp>

namespace frictionid::fit_settings_test {
namespace {

using Law = model::PressureLaw<double>;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The reason validate() gives, or "" when it accepts the settings.
std::string rejection(const FitSettings& s) {
  std::string why;
  return s.validate(&why) ? std::string() : why;
}

// The message of the std::invalid_argument a fit with these settings throws ("" when it runs).
std::string fit_rejection(const FitSettings& s) {
  const Dataset d = generate_dataset(ModelKind::Seed, Law::hertz(),
                                     default_parameters(Law::hertz(), 0.9, 1.2, 0.1),
                                     SyntheticDesign{}, NoiseSpec{}, 1);
  try {
    Fitter(s).fit(d);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

TEST(FitSettings, DefaultConstructedSettingsAreValidAndFit) {
  EXPECT_EQ(rejection(FitSettings{}), "");
  EXPECT_EQ(fit_rejection(FitSettings{}), "");
}

TEST(FitSettings, DefaultsForEveryModelAndLawAreValid) {
  for (ModelKind m : {ModelKind::Seed, ModelKind::Corrected, ModelKind::Exact})
    for (const Law& law : {Law::uniform(), Law::hertz(), Law::parabolic(), Law::power(1.7)})
      EXPECT_EQ(rejection(FitSettings::defaults(m, law, "law")), "") << model_name(m);
}

TEST(FitSettings, ZeroGlobalSubsampleIsRejectedWithAMessageNotACrash) {
  FitSettings s;
  s.global_subsample = 0;
  EXPECT_TRUE(contains(rejection(s), "global_subsample")) << rejection(s);
  EXPECT_TRUE(contains(fit_rejection(s), "global_subsample")) << fit_rejection(s);
}

TEST(FitSettings, EmptyBoundsAreRejectedNamingTheParameter) {
  FitSettings s;
  s.bound("kappa", 2.0, 2.0);
  EXPECT_TRUE(contains(rejection(s), "bounds of kappa")) << rejection(s);
  EXPECT_TRUE(contains(fit_rejection(s), "bounds of kappa"));
}

TEST(FitSettings, InvertedBoundsAreRejectedNamingTheParameter) {
  FitSettings s;
  s.bound("f", 2.0, 0.5);
  EXPECT_TRUE(contains(rejection(s), "bounds of f")) << rejection(s);
}

TEST(FitSettings, NonFiniteBoundsAreRejected) {
  FitSettings s;
  s.bound("h", -1.0, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(contains(rejection(s), "finite")) << rejection(s);
  s.bound("h", std::nan(""), 1.0);
  EXPECT_FALSE(rejection(s).empty());
}

TEST(FitSettings, UnknownParameterNamesThrowNamingTheName) {
  FitSettings s;
  for (const char* name : {"mu", "F", "", "kappa "}) {
    try {
      s.fix(name, 0.3);
      ADD_FAILURE() << "accepted '" << name << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE(contains(e.what(), "unknown parameter '" + std::string(name) + "'"));
    }
  }
  EXPECT_THROW(s.bound("alpha", 0, 1), std::invalid_argument);
  EXPECT_THROW(s.start("beta", 1), std::invalid_argument);
}

TEST(FitSettings, AFixedValueOutsideItsBoundsIsRejected) {
  FitSettings s;
  s.bound("f", 0.1, 2.0).fix("f", 5.0);
  EXPECT_TRUE(contains(rejection(s), "f is fixed at 5")) << rejection(s);
}

TEST(FitSettings, LogScaledParametersNeedAPositiveLowerBound) {
  FitSettings s;
  s.bound("kappa", 0.0, 2.0);
  EXPECT_TRUE(contains(rejection(s), "kappa must stay > 0")) << rejection(s);
}

TEST(FitSettings, SearchAndSolverLimitsAreChecked) {
  auto why = [](auto change) {
    FitSettings s;
    change(s);
    return rejection(s);
  };
  EXPECT_TRUE(contains(why([](FitSettings& s) { s.starts = 0; }), "starts"));
  EXPECT_TRUE(
      contains(why([](FitSettings& s) { s.global_evaluations = 3; }), "global_evaluations"));
  EXPECT_TRUE(contains(why([](FitSettings& s) { s.global_algorithm = "annealing"; }),
                       "unknown global algorithm 'annealing'"));
  EXPECT_TRUE(contains(why([](FitSettings& s) { s.max_iterations = 0; }), "max_iterations"));
  EXPECT_TRUE(contains(why([](FitSettings& s) { s.threads = -1; }), "threads"));
  EXPECT_TRUE(contains(why([](FitSettings& s) { s.function_tolerance = -1; }), "tolerance"));
  EXPECT_TRUE(contains(why([](FitSettings& s) {
                         s.loss = LossKind::Huber;
                         s.loss_scale = 0;
                       }),
                       "loss scale"));
  EXPECT_TRUE(contains(why([](FitSettings& s) {
                         s.channels = {Channel::T_x, Channel::T_x};
                       }),
                       "listed twice"));
  // Without the global stage its budget does not matter.
  EXPECT_EQ(why([](FitSettings& s) {
              s.global = false;
              s.global_subsample = 0;
            }),
            "");
}

TEST(FitSettings, ABadPressureLawIsRejected) {
  FitSettings s;
  s.law = Law::power(-1.0);
  EXPECT_TRUE(contains(rejection(s), "exponent")) << rejection(s);
  s.law = Law::tabulated(nullptr);
  EXPECT_TRUE(contains(rejection(s), "table")) << rejection(s);
}

TEST(FitSettings, ParametersAreReachedByName) {
  FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz");
  s.fix("kappa", 1.0).bound("f", 0.2, 1.5).start("h", 0.05);
  EXPECT_TRUE(s.params[kKappa].fixed);
  EXPECT_EQ(s.params[kKappa].initial, 1.0);
  EXPECT_EQ(s.params[kF].lower, 0.2);
  EXPECT_EQ(s.params[kF].upper, 1.5);
  EXPECT_EQ(s.parameter("h").initial, 0.05);
}

TEST(FitSettings, NoiseModelNamesRoundTripAndUnknownNamesAreRejected) {
  for (NoiseModelKind k :
       {NoiseModelKind::Auto, NoiseModelKind::Constant, NoiseModelKind::Relative,
        NoiseModelKind::Affine, NoiseModelKind::Additive, NoiseModelKind::Columns})
    EXPECT_EQ(parse_noise_model_kind(noise_model_kind_name(k)), k) << noise_model_kind_name(k);
  EXPECT_STREQ(noise_model_kind_name(NoiseModelKind::Additive), "additive");
  for (const char* bad : {"", "Additive", "affine ", "add", "sigma"})
    EXPECT_FALSE(parse_noise_model_kind(bad)) << bad;
}

}  // namespace
}  // namespace frictionid::fit_settings_test
