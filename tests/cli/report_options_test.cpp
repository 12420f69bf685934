// --plot-x and --color-by of `fit`, and extra columns through `eval`, run on the built executable.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include "support/run_command.hpp"

namespace report_options_test {
namespace {

namespace fs = std::filesystem;

using RunResult = frictionid::test::CommandResult;

RunResult run(const std::string& args) {
  return frictionid::test::run_frictionid(args);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Generated rows with two extra columns appended: a number per row and a run label.
class ReportOptions : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("frictionid_report_options_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const std::string plain = (dir_ / "plain.csv").string();
    const RunResult g =
        run("generate --model seed --param f=0.8,kappa=1.2,h=0.1 --rows 60 "
            "--output " +
            plain);
    ASSERT_EQ(g.code, 0) << g.out;
    std::istringstream in(slurp(plain));
    std::ofstream out(dir_ / "data.csv");
    std::string line;
    std::getline(in, line);
    out << line << ",camber,run\n";
    for (int i = 0; std::getline(in, line); ++i)
      out << line << "," << (i % 5) * 0.5 << "," << (i % 2 ? "left" : "right") << "\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(ReportOptions, PlotXAndColorByShapeTheReport) {
  const RunResult f = run("fit " + (dir_ / "data.csv").string() + " --model seed --report " +
                          (dir_ / "rep").string() + " --plot-x camber --color-by run");
  ASSERT_EQ(f.code, 0) << f.out;
  EXPECT_TRUE(fs::exists(dir_ / "rep" / "x_camber_T_x.svg"));
  const std::string html = slurp(dir_ / "rep" / "report.html");
  EXPECT_NE(html.find(">run = left</text>"), std::string::npos);
  EXPECT_NE(html.find(">run = right</text>"), std::string::npos);
}

TEST_F(ReportOptions, AnUnknownPlotColumnFailsBeforeTheFit) {
  const RunResult f = run("fit " + (dir_ / "data.csv").string() + " --model seed --report " +
                          (dir_ / "rep").string() + " --plot-x slip_angle");
  EXPECT_EQ(f.code, 2) << f.out;
  EXPECT_NE(f.out.find("--plot-x slip_angle: no such column"), std::string::npos) << f.out;
  EXPECT_FALSE(fs::exists(dir_ / "rep" / "report.json"));
}

TEST_F(ReportOptions, EvalCarriesExtraColumnsIntoThePredictions) {
  const RunResult e =
      run("eval --model seed --param f=0.8,kappa=1.2,h=0.1 --input " +
          (dir_ / "data.csv").string() + " --output " + (dir_ / "pred.csv").string());
  ASSERT_EQ(e.code, 0) << e.out;
  std::istringstream in(slurp(dir_ / "pred.csv"));
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_NE(header.find(",camber,run,"), std::string::npos) << header;
  EXPECT_NE(first.find(",0,right,"), std::string::npos) << first;  // row 0's values
}

}  // namespace
}  // namespace report_options_test
