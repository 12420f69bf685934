// Inputs without an end (issue case A2): a pressure table is read up to a size limit, so
// table:/dev/zero is an error naming the file and the limit, in bounded memory and time.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/memory_cap.hpp"
#include "support/run_command.hpp"

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

}  // namespace
