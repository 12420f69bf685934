// --threads bounds every thread a batch runs: its runs at once and whatever each run's reading
// (a large CSV is read in parts side by side), fitting and report take.
#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

namespace thread_budget_test {
namespace {

using frictionid::test::ScratchDir;

// The threads of process `pid` now (its /proc/PID/task entries), 0 once it is gone.
int threads_of(pid_t pid) {
  const std::string dir = "/proc/" + std::to_string(pid) + "/task";
  DIR* d = ::opendir(dir.c_str());
  if (!d) return 0;
  int n = 0;
  while (const dirent* e = ::readdir(d))
    if (e->d_name[0] != '.') ++n;
  ::closedir(d);
  return n;
}

TEST(ThreadBudget, ABatchWithJobsTwoAndThreadsTwoNeverRunsMoreThanTwoThreads) {
  const ScratchDir d("thread_budget_batch");
  // Files of over 2 MiB, which the reader splits into parts read side by side.
  std::filesystem::create_directories(d.path() / "in");
  for (int k = 1; k <= 4; ++k) {
    const auto r = frictionid::test::run_frictionid(
        "generate --model seed --param f=0.85,kappa=1.3,h=0.1 --rows 30000 --noise 0.01 --seed " +
        std::to_string(k) + " --slip-angles 0,30 --output " + d / ("in/run" + std::to_string(k)) +
        ".csv");
    ASSERT_EQ(r.code, 0) << r.out;
  }
  const std::string exe = std::getenv("FRICTIONID_EXE");
  const std::string in = d / "in", out = d / "out";
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::execl(exe.c_str(), exe.c_str(), "batch", in.c_str(), "--jobs", "2", "--threads", "2",
            "--per-run-reports", "full", "--report", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ASSERT_GT(pid, 0);
  int most = 0, samples = 0;
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    most = std::max(most, threads_of(pid));
    ++samples;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_GT(samples, 20) << "too few samples to see the batch's threads";
  EXPECT_GE(most, 2) << "two runs at once should have been seen";
  EXPECT_LE(most, 2) << "a batch with --threads 2 ran " << most << " threads at once";
}

}  // namespace
}  // namespace thread_budget_test
