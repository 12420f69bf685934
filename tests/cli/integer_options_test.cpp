// Counts and seeds on the command line (issue cases A6 and B6): a negative value, one past the
// type or past the documented limit is an error naming the option (exit 2) before anything is
// allocated or written, never a wrapped, clamped or aliased value.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/memory_cap.hpp"
#include "support/run_command.hpp"

namespace integer_options_test {
namespace {

namespace fs = std::filesystem;

const std::string kExample =
    (fs::path(FRICTIONID_SOURCE_DIR) / "data" / "example_hertz.csv").string();

struct Result {
  int code;
  std::string err;
};

// Runs FRICTIONID_EXE with the arguments (shell words, none quoted) and a 1 GB memory cap, so
// that an allocation from a wrapped count fails fast instead of eating the machine.
Result run(const std::string& args) {
  const char* exe = std::getenv("FRICTIONID_EXE");
  const std::string cmd = frictionid::test::memory_cap_prefix(1000) + "exec '" +
                          std::string(exe ? exe : "frictionid") + "' " + args + " 2>&1 >/dev/null";
  const auto r = frictionid::test::run_command(cmd);
  return {r.code, r.out};
}

class IntegerOptions : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("FRICTIONID_EXE")) GTEST_SKIP() << "FRICTIONID_EXE not set";
    out_ = fs::temp_directory_path() / ("frictionid_int_" + std::to_string(::getpid()));
    fs::remove_all(out_);
    fs::create_directories(out_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(out_, ec);
  }
  void expect_rejected(const std::string& args, const std::string& option,
                       const std::string& reason) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(option + ": got"), std::string::npos) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(fs::is_empty(out_)) << args << " left files behind";
  }
  std::string generate() const {
    return "generate --model seed --output " + (out_ / "g.csv").string();
  }
  std::string fit() const { return "fit " + kExample + " --report " + (out_ / "rep").string(); }
  fs::path out_;
};

TEST_F(IntegerOptions, NegativeRowsAreRejectedBeforeAnyAllocation) {
  expect_rejected(generate() + " --rows -1", "--rows", "negative");
}

TEST_F(IntegerOptions, RowsPastTheLimitAreRejected) {
  expect_rejected(generate() + " --rows 10000001", "--rows", "too large");
  expect_rejected(generate() + " --rows 0", "--rows", "too small");
}

TEST_F(IntegerOptions, NegativeSeedsAreRejected) {
  expect_rejected(generate() + " --seed -1", "--seed", "negative");
  expect_rejected(fit() + " --seed -1", "--seed", "negative");
}

TEST_F(IntegerOptions, ASeedPastSixtyFourBitsIsRejectedNotClamped) {
  expect_rejected(generate() + " --seed 18446744073709551616", "--seed", "too large");
}

TEST_F(IntegerOptions, AFitSeedPastThirtyTwoBitsIsRejectedInsteadOfAliasingAnother) {
  expect_rejected(fit() + " --seed 4294967297", "--seed", "from 0 to 4294967295");
}

TEST_F(IntegerOptions, ANegativeGlobalSubsampleIsRejected) {
  expect_rejected(fit() + " --global-subsample -1", "--global-subsample", "negative");
}

}  // namespace
}  // namespace integer_options_test
