// A batch run records the fingerprint of the bytes its fit read, not of the bytes planned: a file
// replaced between planning and the fit is fitted, and journalled, as what was read.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "app/batch_fit_run.hpp"
#include "app/batch_runs.hpp"
#include "io/sha256.hpp"
#include "support/scratch_dir.hpp"

namespace frictionid::app::batch_fingerprint_test {
namespace {

std::string rows_text(double scale) {
  std::ostringstream s;
  s << "v_x,omega,N,R,T_x,M_z\n";
  s.precision(17);
  for (int i = 1; i <= 60; ++i) {
    const double v = 0.01 * i;
    s << v << ",2," << 1000 * (1 + i % 3) << ",0.05," << scale * 0.8 * v / (v + 0.1) * 1000 << ","
      << scale * 0.3 / (1 + v) << "\n";
  }
  return s.str();
}

TEST(BatchFingerprint, AFitRecordsTheBytesItReadNotTheBytesPlanned) {
  const test::ScratchDir d("batch_fingerprint");
  const std::string path = d / "run1.csv";
  std::ofstream(path) << rows_text(1.0);
  FitRequest request;
  request.model = "seed";
  const auto runs = plan_batch_runs({path}, request, {}, "");
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].input.sha256, sha256_hex(rows_text(1.0)));

  FileFingerprint read;
  (void)fit_batch_run(runs[0], 1, nullptr, {}, nullptr, &read);
  EXPECT_EQ(read.sha256, runs[0].input.sha256);  // unchanged: the planned bytes

  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a later modification time
  std::ofstream(path) << rows_text(1.5);
  (void)fit_batch_run(runs[0], 1, nullptr, {}, nullptr, &read);
  EXPECT_EQ(read.sha256, sha256_hex(rows_text(1.5)));
  EXPECT_NE(read.sha256, runs[0].input.sha256);
}

}  // namespace
}  // namespace frictionid::app::batch_fingerprint_test
