// Runs the built executable (path from FRICTIONID_EXE, set by ctest) on valid and invalid input
// and checks output and exit codes.
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
#include <iterator>
#include <string>
#include "support/run_command.hpp"

namespace cli_test {
namespace {

namespace fs = std::filesystem;

using RunResult = frictionid::test::CommandResult;

RunResult run(const std::string& args) {
  return frictionid::test::run_frictionid(args);
}

fs::path temp_dir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("frictionid_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(Cli, CoefficientsForHertzPrintTheClosedFormValues) {
  const RunResult r = run("coefficients --pressure hertz");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["a"].get<double>(), std::pow(8.0 / (3.0 * M_PI), 2), 1e-14);
  EXPECT_NEAR(j["b"].get<double>(), 25.0, 1e-12);
  EXPECT_NEAR(j["mu_M"].get<double>(), 3.0 * M_PI / 16.0, 1e-15);
  EXPECT_TRUE(j["consistency"]["all"].get<bool>());
  for (const char* key : {"m0", "m1", "m2", "m3", "m", "b_tilde", "p0", "M_roll_per_hNR"})
    EXPECT_TRUE(j.contains(key)) << key;
}

TEST(Cli, CoefficientsTableFormatIsForPeople) {
  const RunResult r = run("coefficients --pressure parabolic --format table");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("0.5625"), std::string::npos);  // a = 9/16
}

TEST(Cli, BadPressureLawKappaOrExponentExitWithCodeTwoAndOneLine) {
  for (const char* args :
       {"coefficients --pressure foo", "coefficients --kappa 0", "coefficients --kappa -1",
        "coefficients --pressure power:-1", "coefficients --pressure power:abc",
        "coefficients --kappa abc", "coefficients --pressure table:/nonexistent/file.csv",
        "coefficients --pressure power:0 --kappa 1e-300"}) {  // m would overflow
    const RunResult r = run(args);
    EXPECT_EQ(r.code, 2) << args << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
  }
}

TEST(Cli, BadPressureTableNamesFileLineAndColumn) {
  const fs::path d = temp_dir("table");
  std::ofstream(d / "t.csv") << "rho,sigma0\n0,1\n0.5,0.8\n0.4,0.5\n";
  const RunResult r = run("coefficients --pressure table:" + (d / "t.csv").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("t.csv:4:1"), std::string::npos) << r.out;
  fs::remove_all(d);
}

TEST(Cli, EvalPrintsTheResultantsAsJson) {
  const RunResult r =
      run("eval --model exact --pressure hertz --param f=0.8,kappa=1.2,h=0.1 "
          "--vx 0.3 --omega 2 --R 0.1 --N 1000");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  // M_roll = h N R m3/(2 m1) = 0.1 * 1000 * 0.1 * 0.2 for Hertz.
  EXPECT_NEAR(j["M_roll"].get<double>(), 2.0, 1e-12);
  EXPECT_EQ(j["N"].get<double>(), 1000.0);
  EXPECT_GT(j["T_x"].get<double>(), 0.0);
  EXPECT_LT(j["T_x"].get<double>(), 0.8 * 1000.0);
}

TEST(Cli, GenerateThenFitRecoversTheTruthAndWritesTheReport) {
  const fs::path d = temp_dir("fit");
  const std::string csv = (d / "data.csv").string();
  RunResult g =
      run("generate --model seed --pressure hertz --param f=0.85,kappa=1.3,h=0.12 --rows 300 "
          "--output " +
          csv + " --truth " + (d / "truth.json").string());
  ASSERT_EQ(g.code, 0) << g.out;
  const RunResult f = run("fit " + csv + " --model seed --report " + (d / "rep").string());
  ASSERT_EQ(f.code, 0) << f.out;
  std::ifstream in(d / "rep" / "report.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_NEAR(j["parameters"]["f"]["value"].get<double>(), 0.85, 1e-9);
  EXPECT_NEAR(j["parameters"]["h"]["value"].get<double>(), 0.12, 1e-9);
  EXPECT_TRUE(fs::exists(d / "rep" / "report.md"));
  fs::remove_all(d);
}

TEST(Cli, FitOnAMissingFileOrUnknownParameterFailsWithoutAReport) {
  const fs::path d = temp_dir("bad");
  RunResult r = run("fit /nonexistent.csv --model seed --report " + (d / "rep").string());
  EXPECT_EQ(r.code, 2) << r.out;
  const std::string csv = (d / "x.csv").string();
  ASSERT_EQ(run("generate --model seed --rows 20 --output " + csv).code, 0);
  r = run("fit " + csv + " --model seed --fix n=1 --report " + (d / "rep").string());
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("no parameter 'n'"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(d / "rep"));
  fs::remove_all(d);
}

// "--fix ''" must not silently mean "nothing fixed".
TEST(Cli, EmptyOptionValuesAreRejectedNotIgnored) {
  const fs::path d = temp_dir("empty");
  const std::string csv = (d / "x.csv").string(), rep = (d / "rep").string();
  ASSERT_EQ(run("generate --model seed --rows 20 --output " + csv).code, 0);
  for (const std::string opt :
       {"--fix ''", "--bounds ''", "--param ''", "--columns ''", "--channels=", "--pressure ''"}) {
    const RunResult r = run("fit " + csv + " --model seed " + opt + " --report " + rep);
    EXPECT_EQ(r.code, 2) << opt << ": " << r.out;
    EXPECT_NE(r.out.find("empty argument"), std::string::npos) << opt << ": " << r.out;
    EXPECT_FALSE(fs::exists(rep)) << opt;
  }
  EXPECT_EQ(run("eval --model seed --vx 1 --omega 1 --param ''").code, 2);
  fs::remove_all(d);
}

}  // namespace

namespace {

TEST(Cli, CompareWritesSideBySideReportsAndPrefersTheGeneratingModel) {
  const fs::path d = temp_dir("compare");
  const std::string csv = (d / "data.csv").string();
  ASSERT_EQ(run("generate --model exact --pressure hertz --param f=0.9,kappa=1.2,h=0.1 --rows 200 "
                "--noise 0.002 --output " +
                csv)
                .code,
            0);
  const RunResult r = run("compare " + csv + " --pressure hertz --report " + (d / "cmp").string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(d / "cmp" / "compare.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["preferred_by_aic"], "exact");
  EXPECT_EQ(j["models"].size(), 3u);
  for (const char* m : {"seed", "corrected", "exact"})
    EXPECT_TRUE(fs::exists(d / "cmp" / m / "report.json")) << m;
  EXPECT_TRUE(fs::exists(d / "cmp" / "compare.md"));
  fs::remove_all(d);
}

// Replaces field `column` (0-based) of data line `line` (1-based, the header is line 1).
std::string with_field(const std::string& csv, std::size_t line, std::size_t column,
                       const std::string& value) {
  std::string out;
  std::size_t start = 0, n = 0;
  while (start < csv.size()) {
    const std::size_t end = csv.find('\n', start);
    std::string l = csv.substr(start, end - start);
    if (++n == line) {
      std::size_t b = 0;
      for (std::size_t k = 0; k < column; ++k) b = l.find(',', b) + 1;
      const std::size_t e = l.find(',', b);
      l = l.substr(0, b) + value + (e == std::string::npos ? "" : l.substr(e));
    }
    out += l + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// A failed fit says why in frictionid's own words and names the row; the solver's log (glog's
// "Logging before InitGoogleLogging", "Error in evaluating the ResidualBlock") stays silent.
TEST(Cli, AFitThatFailsNamesTheRowAndPrintsNoSolverLog) {
  const fs::path dir = temp_dir("fail_row");
  const std::string csv = read_text(fs::path(FRICTIONID_SOURCE_DIR) / "data/example_hertz.csv");
  const auto header = csv.substr(0, csv.find('\n'));
  std::size_t sigma_col = 0;
  for (std::size_t b = 0, k = 0;; ++k) {
    const std::size_t e = header.find(',', b);
    if (header.substr(b, e - b) == "sigma_T_x") {
      sigma_col = k;
      break;
    }
    ASSERT_NE(e, std::string::npos) << "no sigma_T_x column";
    b = e + 1;
  }
  std::ofstream(dir / "d.csv") << with_field(csv, 10, sigma_col, "1e-300");
  const RunResult r =
      run("fit " + (dir / "d.csv").string() + " --model seed --report " + (dir / "rep").string());
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("line 10"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("channel T_x"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("InitGoogleLogging"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("ResidualBlock"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

// One wild value does not switch its channel off in silence: the report names its row.
TEST(Cli, AnOutlierRowIsNamedInTheReport) {
  const fs::path dir = temp_dir("outlier");
  ASSERT_EQ(run("generate --model seed --pressure hertz --param f=0.9,kappa=1.2,h=0.1 --rows 400 "
                "--noise 0.01 --seed 5 --output " +
                (dir / "d.csv").string())
                .code,
            0);
  std::ofstream(dir / "o.csv") << with_field(read_text(dir / "d.csv"), 42, 5, "1e12");
  const RunResult r =
      run("fit " + (dir / "o.csv").string() + " --model seed --report " + (dir / "rep").string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(read_text(dir / "rep" / "report.json"));
  bool named = false;
  for (const auto& w : j["warnings"])
    named |= w.get<std::string>().find("at line 42 (T_x = 1e+12") != std::string::npos &&
             w.get<std::string>().find("outlier") != std::string::npos;
  EXPECT_TRUE(named) << j["warnings"].dump(2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cli_test
