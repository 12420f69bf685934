// Statistics that do not exist are null, with a warning that says why, never a number.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

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

}  // namespace
