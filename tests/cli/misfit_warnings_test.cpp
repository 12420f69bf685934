// A wrong fit does not say "No warnings": a channel the model misses is named as a misfit, even
// when an estimated noise model absorbs the misfit into its noise (reduced chi2 near 1).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

namespace misfit_warnings_test {
namespace {

using frictionid::test::read_file;
using frictionid::test::ScratchDir;

std::string warnings_of(const std::string& report_dir) {
  const auto j = nlohmann::json::parse(read_file(report_dir + "/report.json"));
  std::string all;
  for (const auto& w : j["warnings"]) all += w.get<std::string>() + "\n";
  return all;
}

// Lateral slip in every direction, exact-model data with 1 % noise.
void lateral_data(const ScratchDir& d) {
  const auto r = frictionid::test::run_frictionid(
      "generate --model exact --param f=0.9,kappa=1.15,h=0.08 --slip-angles 0,30,60,-30 "
      "--rows 2000 --noise 0.01 --seed 4 --output " +
      d / "lateral.csv");
  ASSERT_EQ(r.code, 0) << r.out;
}

TEST(MisfitWarnings, AFitMissingTheLateralSlipColumnSaysItExplainsNoneOfTy) {
  const ScratchDir d("misfit_lateral");
  lateral_data(d);
  // v_y under a name the reader does not take for it: the lateral slip is read as 0.
  std::string text = read_file(d / "lateral.csv");
  text.replace(text.find("v_y"), 3, "lateral_speed");
  std::ofstream(d / "no_vy.csv") << text;
  const auto r = frictionid::test::run_frictionid("fit " + d / "no_vy.csv" +
                                                  " --model exact --report " + d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(warnings_of(d / "out").find("of the variation of T_y"), std::string::npos)
      << warnings_of(d / "out");
  // The residuals keep one sign over stretches of each sweep: the runs test names the misfit.
  EXPECT_NE(warnings_of(d / "out").find("residuals of T_y have structure against eps"),
            std::string::npos)
      << warnings_of(d / "out");
}

TEST(MisfitWarnings, ACorrectFitOfLateralSlipHasNoUnexplainedChannel) {
  const ScratchDir d("misfit_correct");
  lateral_data(d);
  const auto r = frictionid::test::run_frictionid("fit " + d / "lateral.csv" +
                                                  " --model exact --report " + d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(warnings_of(d / "out").find("of the variation of"), std::string::npos)
      << warnings_of(d / "out");
  EXPECT_EQ(warnings_of(d / "out").find("beyond 6 sigma"), std::string::npos);
  EXPECT_EQ(warnings_of(d / "out").find("have structure against eps"), std::string::npos)
      << warnings_of(d / "out");
}

TEST(MisfitWarnings, MostRowsBeyondSixSigmaAreAMisfitNotOutliers) {
  // The seed model on exact-model data with 1 % sigma columns: its closed forms miss T_x by
  // far more than the stated noise.
  const ScratchDir d("misfit_seed");
  const auto r = frictionid::test::run_frictionid("fit " + std::string(FRICTIONID_SOURCE_DIR) +
                                                  "/data/example_hertz.csv --model seed " +
                                                  "--report " + d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string w = warnings_of(d / "out");
  const auto t_x = w.find("rows of T_x");
  ASSERT_NE(t_x, std::string::npos) << w;
  const std::string line = w.substr(t_x, w.find('\n', t_x) - t_x);
  EXPECT_NE(line.find("the model misses this channel"), std::string::npos) << line;
  EXPECT_EQ(line.find("looks like an outlier"), std::string::npos) << line;
}

}  // namespace
}  // namespace misfit_warnings_test
