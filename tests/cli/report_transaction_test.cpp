// The report stage through the built executable (FRICTIONID_EXE): the report directory is
// replaced as a whole (README "Reliability"), a second run into it waits or, with --no-wait,
// fails clearly; Ctrl-C at any instant ends with exit 130 and the earlier report intact.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include "support/scratch_dir.hpp"

namespace report_transaction_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;

const fs::path kExample = fs::path(FRICTIONID_SOURCE_DIR) / "data" / "example_hertz.csv";

struct Child {
  pid_t pid = -1;
  fs::path err;  // its stderr
};

// Starts `frictionid fit` of the example into `report`; env entries are "NAME=value".
Child start_fit(const fs::path& report, const fs::path& err, std::vector<std::string> extra = {},
                const std::vector<std::string>& env = {}) {
  const char* exe = std::getenv("FRICTIONID_EXE");
  std::vector<std::string> args = {exe ? exe : "frictionid",
                                   "fit",
                                   kExample.string(),
                                   "--no-global",
                                   "--starts",
                                   "1",
                                   "--channels",
                                   "T_x",
                                   "--report",
                                   report.string()};
  for (auto& e : extra) args.push_back(e);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (const auto& e : env) ::putenv(const_cast<char*>(e.c_str()));
    const int null_fd = ::open("/dev/null", O_WRONLY);
    const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(null_fd, STDOUT_FILENO);
    ::dup2(err_fd, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return {pid, err};
}

int wait_exit(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int run_fit(const fs::path& report, const fs::path& err, std::vector<std::string> extra = {},
            const std::vector<std::string>& env = {}) {
  return wait_exit(start_fit(report, err, std::move(extra), env).pid);
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool exe_set() {
  return std::getenv("FRICTIONID_EXE") != nullptr;
}

TEST(ReportTransaction, TheReportIsASymlinkToOneCompleteDirectoryAndNothingElseStays) {
  if (!exe_set()) GTEST_SKIP() << "FRICTIONID_EXE not set";
  ScratchDir s("symlink");
  const fs::path report = s.path() / "out" / "rep";
  ASSERT_EQ(run_fit(report, s.path() / "err"), 0) << read_file(s.path() / "err");
  ASSERT_EQ(run_fit(report, s.path() / "err", {"--fix", "h=0.07"}), 0);
  ASSERT_TRUE(fs::is_symlink(report));
  const std::string target = fs::read_symlink(report).string();
  EXPECT_EQ(target.rfind(".rep.r-", 0), 0u) << target;
  // The earlier report's directory, the lock file and the temporary link are gone.
  EXPECT_EQ(names_in(report.parent_path()), (std::vector<std::string>{target, "rep"}));
  EXPECT_NE(read_file(report / "report.md").find("| h | 0.07 |"), std::string::npos);
}

TEST(ReportTransaction, APlainReportDirectoryOfAnEarlierVersionBecomesTheSymlink) {
  if (!exe_set()) GTEST_SKIP() << "FRICTIONID_EXE not set";
  ScratchDir s("migrate");
  const fs::path report = s.path() / "rep";
  fs::create_directories(report / "seed");
  std::ofstream(report / "report.json") << "{}\n";
  std::ofstream(report / "fit_M_z.svg") << "<svg></svg>\n";
  std::ofstream(report / "seed" / "report.md") << "# old\n";
  ASSERT_EQ(run_fit(report, s.path() / "err"), 0) << read_file(s.path() / "err");
  ASSERT_TRUE(fs::is_symlink(report));
  EXPECT_FALSE(fs::exists(report / "fit_M_z.svg"));  // the old report went as a whole
  EXPECT_EQ(names_in(s.path()).size(), 3u);          // err, rep and its target
}

TEST(ReportTransaction, ADirectoryWithOtherFilesIsRefusedAndLeftUntouched) {
  if (!exe_set()) GTEST_SKIP() << "FRICTIONID_EXE not set";
  ScratchDir s("foreign");
  const fs::path report = s.path() / "rep";
  fs::create_directories(report);
  std::ofstream(report / "notes.txt") << "mine\n";
  EXPECT_EQ(run_fit(report, s.path() / "err"), 1);  // refused before the fit
  const std::string err = read_file(s.path() / "err");
  EXPECT_NE(err.find("notes.txt"), std::string::npos) << err;
  EXPECT_EQ(names_in(report), (std::vector<std::string>{"notes.txt"}));
  EXPECT_EQ(names_in(s.path()), (std::vector<std::string>{"err", "rep"}));
}

TEST(ReportTransaction, DotAndSlashAreNotReportDirectories) {
  if (!exe_set()) GTEST_SKIP() << "FRICTIONID_EXE not set";
  ScratchDir s("dot");
  for (const char* dir : {".", "..", "/"}) {
    EXPECT_EQ(run_fit(dir, s.path() / "err"), 2) << dir;
    EXPECT_NE(read_file(s.path() / "err").find("a directory of its own"), std::string::npos)
        << read_file(s.path() / "err");
  }
}

// Holds the lock of report directory `report` the way a running fit does.
class HeldLock {
 public:
  explicit HeldLock(const fs::path& report)
      : path_(report.parent_path() / ("." + report.filename().string() + ".lock")) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);  // not in the child
    ::flock(fd_, LOCK_EX);
  }
  void release() {
    if (fd_ < 0) return;
    ::unlink(path_.c_str());
    ::close(fd_);
    fd_ = -1;
  }
  ~HeldLock() { release(); }

 private:
  fs::path path_;
  int fd_ = -1;
};

TEST(ReportLock, NoWaitFailsAtOnceWhenAnotherRunHoldsTheDirectory) {
  if (!exe_set()) GTEST_SKIP() << "FRICTIONID_EXE not set";
  ScratchDir s("nowait");
  const fs::path report = s.path() / "rep";
  HeldLock lock(report);
  EXPECT_EQ(run_fit(report, s.path() / "err", {"--no-wait"}), 1);
  const std::string err = read_file(s.path() / "err");
  EXPECT_NE(err.find("another frictionid run is writing report directory"), std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(fs::symlink_status(report)));
}

TEST(ReportLock, ASecondRunSaysItWaitsAndWritesAfterTheFirst) {
  if (!exe_set()) GTEST_SKIP() << "FRICTIONID_EXE not set";
  ScratchDir s("wait");
  const fs::path report = s.path() / "rep";
  HeldLock lock(report);
  const Child c = start_fit(report, s.path() / "err");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  EXPECT_FALSE(fs::exists(fs::symlink_status(report)));  // still waiting
  EXPECT_NE(read_file(c.err).find("waiting for another run"), std::string::npos)
      << read_file(c.err);
  lock.release();
  EXPECT_EQ(wait_exit(c.pid), 0) << read_file(c.err);
  EXPECT_TRUE(fs::exists(report / "report.json"));
}

// Ctrl-C at any instant of a run, the report stage included: the run ends with 0 (it had already
// swapped the new report in) or 130, and then the earlier report is there as it was.
TEST(ReportSignals, CtrlCAtAnyInstantEndsWith130AndKeepsTheEarlierReportOrFinishes) {
  if (!exe_set()) GTEST_SKIP() << "FRICTIONID_EXE not set";
  ScratchDir s("ctrlc");
  const fs::path report = s.path() / "rep";
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(run_fit(report, s.path() / "err", {"--fix", "h=0.07"}), 0);
  // The signal lands anywhere in a run as long as the first one took, start-up included, so
  // the trials both interrupt and finish however fast this machine runs the fit.
  const auto run_us =
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - t0)
          .count();
  const std::string before = read_file(report / "report.md");
  std::mt19937 rng(17);
  int interrupted = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Child c = start_fit(report, s.path() / "err2", {"--fix", "h=0.08"});
    std::this_thread::sleep_for(std::chrono::microseconds(
        std::uniform_int_distribution<long long>(0, static_cast<long long>(run_us))(rng)));
    ::kill(c.pid, SIGINT);
    const int code = wait_exit(c.pid);
    ASSERT_TRUE(code == 0 || code == 130) << code << ": " << read_file(s.path() / "err2");
    if (code == 130) {
      ++interrupted;
      EXPECT_EQ(read_file(report / "report.md"), before);
    } else {
      EXPECT_NE(read_file(report / "report.md"), before);  // the new run, complete
      ASSERT_EQ(run_fit(report, s.path() / "err", {"--fix", "h=0.07"}), 0);  // back to before
    }
    // No staging directory stays behind: err, err2, rep and its target.
    EXPECT_EQ(names_in(s.path()).size(), 4u);
  }
  EXPECT_GT(interrupted, 0);
}

}  // namespace
}  // namespace report_transaction_test
