// Statistics that do not exist are null, with a warning that says why, never a number.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

namespace undefined_statistics_test {
namespace {

using frictionid::test::read_file;
using frictionid::test::ScratchDir;

TEST(UndefinedStatistics, AFitWithNoDegreeOfFreedomHasANullReducedChi2AndSaysWhy) {
  const ScratchDir d("undefined_statistics");
  // Three rows of one channel for the exact model's three free parameters.
  std::ifstream example(std::string(FRICTIONID_SOURCE_DIR) + "/data/example_hertz.csv");
  std::ofstream three(d / "three.csv");
  std::string line;
  for (int i = 0; i < 4 && std::getline(example, line); ++i) three << line << "\n";
  three.close();
  const auto r = frictionid::test::run_frictionid("fit " + d / "three.csv" +
                                                  " --model exact --channels T_x "
                                                  "--noise-model constant --report " +
                                                  d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("reduced chi2 undefined (dof 0)"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(read_file(d / "out/report.json"));
  EXPECT_EQ(j["statistics"]["dof"], 0);
  EXPECT_TRUE(j["statistics"]["reduced_chi2"].is_null()) << j["statistics"].dump();
  bool said = false;
  for (const auto& w : j["warnings"])
    said = said || w.get<std::string>().find("no degree of freedom") != std::string::npos;
  EXPECT_TRUE(said) << j["warnings"].dump();
  for (const auto& [name, p] : j["parameters"].items()) EXPECT_TRUE(p["stderr"].is_null()) << name;
}

TEST(UndefinedStatistics, ConstantChannelsNameTheRealCauseNotAMissingChannel) {
  const ScratchDir d("constant_channels");
  std::ofstream(d / "const.csv") << "v_x,omega,N,R,T_x\n0.1,1,100,0.05,5\n0.2,1,100,0.05,5\n"
                                    "0.3,1,100,0.05,5\n0.4,1,100,0.05,5\n";
  const auto r =
      frictionid::test::run_frictionid("fit " + d / "const.csv" + " --report " + d / "out");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("every measured value of T_x is the same"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("no requested channel is measured"), std::string::npos) << r.out;
}

// A sigma too large to weigh anything (1/sigma^2 underflows to 0) leaves its channel with zero
// weight: it must not be listed as fitted, nor count in the degrees of freedom, and a warning
// says why.
TEST(UndefinedStatistics, AChannelWhoseSigmaGivesNoWeightLeavesTheFitAndSaysWhy) {
  const ScratchDir d("weightless_channel");
  std::ifstream example(std::string(FRICTIONID_SOURCE_DIR) + "/data/example_hertz.csv");
  std::ofstream out(d / "data.csv");
  std::string line;
  std::getline(example, line);
  ASSERT_EQ(line.find("v_x,v_y,omega,N,R,T_x,T_y,M_z,M_roll,sigma_T_x,sigma_T_y,"), 0u) << line;
  out << line << "\n";
  std::size_t rows = 0;
  while (std::getline(example, line)) {  // sigma_T_y, the 11th field, becomes 1e300
    std::size_t at = 0;
    for (int comma = 0; comma < 10; ++comma) at = line.find(',', at) + 1;
    out << line.substr(0, at) << "1e300" << line.substr(line.find(',', at)) << "\n";
    ++rows;
  }
  out.close();
  const auto fit = [&](const std::string& file, const std::string& dir) {
    const auto r = frictionid::test::run_frictionid("fit " + d / file +
                                                    " --model seed --channels T_x,T_y "
                                                    "--noise-model columns --report " +
                                                    d / dir);
    EXPECT_EQ(r.code, 0) << r.out;
    return std::make_pair(r.out, nlohmann::json::parse(read_file(d / (dir + "/report.json"))));
  };
  const auto [said, j] = fit("data.csv", "out");
  EXPECT_NE(said.find("channel T_y left the fit"), std::string::npos) << said;
  EXPECT_EQ(j["channels"], nlohmann::json::array({"T_x"})) << j["channels"].dump();
  bool warned = false;
  for (const auto& w : j["warnings"])
    warned = warned || w.get<std::string>().find(
                           "T_y left the fit: its sigma column gives every "
                           "row zero weight") != std::string::npos;
  EXPECT_TRUE(warned) << j["warnings"].dump();
  // The degrees of freedom are T_x's rows less the free parameters, as without T_y at all.
  const auto only = frictionid::test::run_frictionid(
      "fit " + d / "data.csv" + " --model seed --channels T_x --noise-model columns --report " +
      d / "only");
  ASSERT_EQ(only.code, 0) << only.out;
  const auto k = nlohmann::json::parse(read_file(d / "only/report.json"));
  EXPECT_EQ(j["statistics"]["dof"], k["statistics"]["dof"]);
  EXPECT_LT(j["statistics"]["dof"].get<double>(), static_cast<double>(rows));
}

TEST(UndefinedStatistics, SigmaColumnsThatWeighNothingAreAnErrorNamingThem) {
  const ScratchDir d("weightless_channels");
  std::ofstream(d / "big.csv") << "v_x,omega,N,R,T_x,sigma_T_x\n0.1,1,100,0.05,5,1e200\n"
                                  "0.2,1,100,0.05,6,1e200\n0.3,1,100,0.05,7,1e200\n";
  const auto r = frictionid::test::run_frictionid("fit " + d / "big.csv" +
                                                  " --model exact --report " + d / "out");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("sigma columns of T_x give every row zero weight"), std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace undefined_statistics_test
