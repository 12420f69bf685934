// --output that is not a regular file (issue cases A1 and C5), through the built executable: a
// FIFO, /dev/stdout, a symlink and the shell's process substitution >(cmd) get the data, and
// none of them is replaced by a regular file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include "support/scratch_dir.hpp"

namespace output_targets_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;

class OutputTargets : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("FRICTIONID_EXE")) GTEST_SKIP() << "FRICTIONID_EXE not set";
    dir_ = fs::temp_directory_path() / ("frictionid_outputs_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  // Runs a bash script in dir_ with $F set to the executable; returns its exit status.
  int bash(const std::string& script) {
    const std::string cmd = "cd '" + dir_.string() + "' && F='" + std::getenv("FRICTIONID_EXE") +
                            "' bash -c '" + script + "' 2>err";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string generate(const std::string& output) const {
    return "$F generate --model seed --rows 7 --output " + output;
  }
  fs::path dir_;
};

TEST_F(OutputTargets, AFifoGetsTheRowsAndStaysAFifo) {
  ASSERT_EQ(bash("mkfifo out.csv; cat out.csv > got.csv & " + generate("out.csv") + "; wait"), 0)
      << read_file(dir_ / "err");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(dir_ / "out.csv")));
  EXPECT_EQ(
      std::count(std::istreambuf_iterator<char>(std::ifstream(dir_ / "got.csv").rdbuf()), {}, '\n'),
      8);
}

TEST_F(OutputTargets, ProcessSubstitutionGetsTheRows) {
  ASSERT_EQ(bash(generate(">(cat > got.csv)") + "; sleep 0.5"), 0) << read_file(dir_ / "err");
  EXPECT_EQ(read_file(dir_ / "got.csv").rfind("v_x,", 0), 0u);
}

TEST_F(OutputTargets, DevStdoutIsWrittenInPlace) {
  ASSERT_EQ(bash(generate("/dev/stdout") + " > got.csv"), 0) << read_file(dir_ / "err");
  EXPECT_EQ(read_file(dir_ / "got.csv").rfind("v_x,", 0), 0u);
}

TEST_F(OutputTargets, DevStdoutUnderAnAppendingRedirectionKeepsWhatTheFileHeld) {
  ASSERT_EQ(bash("printf \"precious\\n\" > log.txt; " + generate("/dev/stdout") + " >> log.txt"), 0)
      << read_file(dir_ / "err");
  const std::string log = read_file(dir_ / "log.txt");
  EXPECT_EQ(log.rfind("precious\nv_x,", 0), 0u) << log;
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 9);
}

TEST_F(OutputTargets, TwoRunsAppendingToDevStdoutLeaveBothOutputs) {
  ASSERT_EQ(
      bash(generate("/dev/stdout") + " >> log.txt; " + generate("/dev/stdout") + " >> log.txt"), 0)
      << read_file(dir_ / "err");
  const std::string log = read_file(dir_ / "log.txt");
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 16) << log;
}

TEST_F(OutputTargets, ASymlinkToProcSelfFdOneWritesToTheCapturedStdoutItself) {
  // The group's stdout is one open file: replacing got.csv by name would leave the group
  // writing "after" into a deleted file, and a reader of the descriptor with nothing.
  ASSERT_EQ(bash("ln -s /proc/self/fd/1 link; { " + generate("link") + "; echo after; } > got.csv"),
            0)
      << read_file(dir_ / "err");
  const std::string got = read_file(dir_ / "got.csv");
  EXPECT_EQ(got.rfind("v_x,", 0), 0u) << got;
  EXPECT_EQ(std::count(got.begin(), got.end(), '\n'), 9) << got;
  EXPECT_NE(got.find("\nafter\n"), std::string::npos) << got;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "link")));
}

TEST_F(OutputTargets, ASymlinkKeepsItsLinkAndItsTargetGetsTheRows) {
  ASSERT_EQ(bash("echo old > target.csv; ln -s target.csv link.csv; " + generate("link.csv")), 0)
      << read_file(dir_ / "err");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
  EXPECT_EQ(read_file(dir_ / "target.csv").rfind("v_x,", 0), 0u);
}

}  // namespace
}  // namespace output_targets_test
