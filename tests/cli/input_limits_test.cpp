// Inputs without an end (issue case A2): a pressure table is read up to a size limit, so
// table:/dev/zero is an error naming the file and the limit, in bounded memory and time.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/memory_cap.hpp"
#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

namespace input_limits_test {
namespace {

TEST(InputLimits, APressureTableWithoutEndIsRejectedAtTheSizeLimit) {
  const char* exe = std::getenv("FRICTIONID_EXE");
  if (!exe) GTEST_SKIP() << "FRICTIONID_EXE not set";
  // 400 MB: far below what reading without a limit would take.
  const std::string cmd = frictionid::test::memory_cap_prefix(400) + "exec '" + std::string(exe) +
                          "' coefficients --pressure table:/dev/zero 2>&1 >/dev/null";
  const auto t0 = std::chrono::steady_clock::now();
  const auto [code, err] = frictionid::test::run_command(cmd);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("/dev/zero: is larger than 16 MiB"), std::string::npos) << err;
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20));
}

// Whether process pid has installed a handler for sig (Linux: the SigCgt mask of
// /proc/PID/status). Before that, a signal takes its default action: a start-up that the
// sanitizers slow down must not be mistaken for a slow reaction.
bool catches(pid_t pid, int sig) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1u;
  return false;
}

// The longest a signal may take to act. Under the sanitizers the build asks its stop check no less
// often, but a node of its table takes 2-5 times as long, more when the linker keeps the -O0 copy
// of the table's lookups (the sanitizer build compiles the code that reads and orchestrates at
// -O0, and which copy of a shared template it keeps changes with how sources are batched).
#ifdef FRICTIONID_SANITIZE
constexpr double kSignalLatency = 3.0;
#else
constexpr double kSignalLatency = 1.0;
#endif

// A signal during a long model build (an exact fit with a 20,000-sample pressure table, whose
// ring integrals cost seconds per build) acts within a second: exit 130, no report. The delays
// count from when the fit catches the signal.
TEST(InputLimits, ASignalDuringAFitWithALargePressureTableActsWithinASecond) {
  const char* exe = std::getenv("FRICTIONID_EXE");
  if (!exe) GTEST_SKIP() << "FRICTIONID_EXE not set";
  const frictionid::test::ScratchDir d("table_signal");
  {
    std::ofstream table(d / "table.csv");
    table << "r,sigma0\n";
    table.precision(17);
    for (int i = 0; i < 20000; ++i) {
      const double r = i / 19999.0;
      table << r << "," << 1.5 * std::sqrt(1.0 - r * r) + 0.01 << "\n";
    }
  }
  const auto made = frictionid::test::run_frictionid(
      "generate --model exact --pressure hertz --param f=0.85,kappa=1.3,h=0.12 --rows 300 "
      "--noise 0.01 --output " +
      d / "data.csv");
  ASSERT_EQ(made.code, 0) << made.out;
  const std::string table = "table:" + d / "table.csv", data = d / "data.csv";
  for (const auto& [sig, delay_ms] : std::vector<std::pair<int, int>>{
           {SIGINT, 300}, {SIGINT, 1500}, {SIGTERM, 800}, {SIGINT, 3000}}) {
    const std::string report = d / ("report" + std::to_string(delay_ms));
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      std::freopen("/dev/null", "w", stderr);
      std::freopen("/dev/null", "w", stdout);
      ::execl(exe, exe, "fit", data.c_str(), "--model", "exact", "--pressure", table.c_str(),
              "--report", report.c_str(), static_cast<char*>(nullptr));
      std::_Exit(127);
    }
    const auto started = std::chrono::steady_clock::now();
    while (!catches(pid, sig) &&
           std::chrono::steady_clock::now() - started < std::chrono::seconds(30))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(catches(pid, sig)) << "the fit never installed its handler for signal " << sig;
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    const auto sent = std::chrono::steady_clock::now();
    ::kill(pid, sig);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    const double latency =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 130) << "signal " << sig << " after " << delay_ms << " ms";
    EXPECT_LT(latency, kSignalLatency) << "signal " << sig << " after " << delay_ms << " ms";
    EXPECT_FALSE(std::ifstream(report + "/report.json").good());
  }
}

}  // namespace
}  // namespace input_limits_test
