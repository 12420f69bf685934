// Start values and bounds are honoured or rejected, never ignored or changed silently (issue
// case B5): --param without --no-global, a --param outside the bounds and a --fix outside
// --bounds are errors that name the option (exit 2), and nothing is written.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/run_command.hpp"

namespace start_and_bounds_test {
namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string err;
};

class StartAndBounds : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("FRICTIONID_EXE")) GTEST_SKIP() << "FRICTIONID_EXE not set";
    dir_ = fs::temp_directory_path() / ("frictionid_b5_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  // `frictionid fit` of the example with extra arguments (shell words, none quoted).
  Result fit(const std::string& extra) {
    const std::string cmd =
        "exec '" + std::string(std::getenv("FRICTIONID_EXE")) + "' fit '" +
        (fs::path(FRICTIONID_SOURCE_DIR) / "data" / "example_hertz.csv").string() +
        "' --model seed --report '" + (dir_ / "rep").string() + "' " + extra + " 2>&1 >/dev/null";
    const auto r = frictionid::test::run_command(cmd);
    return {r.code, r.out};
  }
  void expect_error(const std::string& extra, const std::string& says) {
    const Result r = fit(extra);
    EXPECT_EQ(r.code, 2) << extra << "\n" << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << extra << "\n" << r.err;
    EXPECT_TRUE(fs::is_empty(dir_)) << extra << " wrote something";
  }
  fs::path dir_;
};

TEST_F(StartAndBounds, ParamWithoutNoGlobalIsAnErrorNotIgnored) {
  expect_error("--param f=0.7", "only --no-global uses");
}

TEST_F(StartAndBounds, ParamOutsideGivenBoundsIsAnErrorNotClamped) {
  expect_error("--no-global --param f=5 --bounds f=0.1:2", "--param f=5 lies outside f's bounds");
}

TEST_F(StartAndBounds, ParamOutsideTheDefaultBoundsSaysTheyAreTheDefaults) {
  expect_error("--no-global --param f=50", "(the defaults)");
}

TEST_F(StartAndBounds, FixOutsideItsBoundsIsAnError) {
  expect_error("--fix f=5 --bounds f=0.1:2", "--fix f=5 lies outside --bounds f=0.1:2");
}

TEST_F(StartAndBounds, ParamInsideTheBoundsWithNoGlobalIsTheReportedStart) {
  const Result r = fit("--no-global --starts 1 --param f=0.7 --bounds f=0.1:2");
  ASSERT_EQ(r.code, 0) << r.err;
  std::FILE* f = std::fopen((dir_ / "rep" / "report.json").c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::string json;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) json.append(buf, n);
  std::fclose(f);
  EXPECT_NE(json.find("\"initial\": 0.7,"), std::string::npos);
}

}  // namespace
}  // namespace start_and_bounds_test
