// frictionid simulate through the built executable (FRICTIONID_EXE, set by ctest): the JSON
// summary, the trajectory CSV and exit code 2 on invalid options.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_command.hpp"

namespace simulate_test {
namespace {

namespace fs = std::filesystem;

using RunResult = frictionid::test::SplitResult;

RunResult run(const std::string& args) {
  return frictionid::test::run_frictionid_split(args);
}

TEST(CliSimulate, UniformDiskPrintsTheSummaryAndWritesTheTrajectory) {
  const fs::path d =
      fs::temp_directory_path() / ("frictionid_cli_simulate_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  const fs::path csv = d / "traj.csv";
  const RunResult r =
      run("simulate --model exact --pressure uniform --param f=0.3 --inertia-ratio 0.5 --v0 2 "
          "--omega0 5 --mass 2 --R 0.5 --output " +
          csv.string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"model", "pressure", "parameters", "inertia_ratio", "N", "eps0",
                          "eps_final", "eps_fixed_point", "t_stop_slide", "t_stop_spin", "steps",
                          "rejected_steps", "distance", "rotation", "stopped", "trajectory_rows"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_NEAR(j["eps_final"].get<double>(), 0.6530018, 1e-6);
  EXPECT_NEAR(j["eps_fixed_point"].get<double>(), 0.65300178920560, 1e-12);
  const double ts = j["t_stop_slide"].get<double>();
  EXPECT_NEAR(j["t_stop_spin"].get<double>(), ts, 1e-9 * ts);
  EXPECT_NEAR(j["N"].get<double>(), 2 * 9.81, 1e-12);
  EXPECT_TRUE(j["stopped"].get<bool>());

  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("t,v_x,v_y,omega,eps,T_x,T_y,M_z", 0), 0u) << header;
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, j["trajectory_rows"].get<std::size_t>());
  EXPECT_GT(rows, 10u);
  fs::remove_all(d);
}

TEST(CliSimulate, SeedModelAndSlipAngleRun) {
  const RunResult r =
      run("simulate --model seed --pressure hertz --param f=0.5,kappa=1.5 --inertia-ratio 0.5 "
          "--v0 1 --omega0 -3 --slip-angle 30");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["slip_angle_final_deg"].get<double>(), 0.0, 1e-3);
  EXPECT_GT(j["steps"].get<long>(), 0);
}

TEST(CliSimulate, InvalidOptionsExitWithCodeTwoAndOneLine) {
  for (const char* args :
       {"simulate", "simulate --inertia-ratio 0", "simulate --inertia-ratio -1",
        "simulate --inertia-ratio abc", "simulate --inertia-ratio nan",
        "simulate --inertia-ratio 0.5 --v0 0 --omega0 0", "simulate --inertia-ratio 0.5 --mass 0",
        "simulate --inertia-ratio 0.5 --v0 -1", "simulate --inertia-ratio 0.5 --tol 0",
        "simulate --inertia-ratio 0.5 --model foo", "simulate --inertia-ratio 0.5 --N -3"}) {
    const RunResult r = run(args);
    EXPECT_EQ(r.code, 2) << args << ": " << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args << ": " << r.out;
  }
}

TEST(CliSimulate, ASpeedWhoseEnergyOverflowsIsExitTwoWithTheTrueReason) {
  for (const char* args : {"simulate --inertia-ratio 0.5 --v0 1e300",
                           "simulate --inertia-ratio 0.5 --v0 1 --omega0 1e200 --R 1"}) {
    const RunResult r = run(args);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("overflows"), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(r.err.find("must be moving"), std::string::npos) << args << ": " << r.err;
  }
  // Just below the limit the body is simulated.
  const RunResult ok = run("simulate --inertia-ratio 0.5 --v0 1e150");
  EXPECT_EQ(ok.code, 0) << ok.err;
}

}  // namespace
}  // namespace simulate_test
