// A file's fingerprint is the SHA-256 of its bytes, read as a stream; what has no fixed bytes
// (a FIFO, a device, a directory) is refused at once, without waiting for a writer.
#include "io/file_fingerprint.hpp"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <frictionid/io/input_error.hpp>
#include "io/sha256.hpp"
#include "support/scratch_dir.hpp"

namespace frictionid::file_fingerprint_test {
namespace {

using test::ScratchDir;

std::string message_of(const std::string& path) {
  try {
    (void)fingerprint_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FileFingerprint, IsTheSizeAndSha256OfTheBytes) {
  const ScratchDir d("fingerprint");
  std::string bytes;
  for (int i = 0; i < 100000; ++i) bytes += std::to_string(i) + ",";
  std::ofstream(d / "a.csv", std::ios::binary) << bytes;
  const FileFingerprint f = fingerprint_file(d / "a.csv");
  EXPECT_EQ(f.size, bytes.size());
  EXPECT_EQ(f.sha256, sha256_hex(bytes));
  EXPECT_GT(f.mtime_ns, 0);
  EXPECT_TRUE(f.same_bytes(fingerprint_file(d / "a.csv")));
}

TEST(FileFingerprint, AFifoADeviceAndADirectoryAreNotRegularFiles) {
  const ScratchDir d("fingerprint_special");
  ASSERT_EQ(::mkfifo((d / "pipe.csv").c_str(), 0600), 0);
  EXPECT_NE(message_of(d / "pipe.csv").find("not a regular file (a FIFO)"), std::string::npos);
  EXPECT_NE(message_of("/dev/zero").find("not a regular file (a character device)"),
            std::string::npos);
  EXPECT_NE(message_of(d.path().string()).find("not a regular file (a directory)"),
            std::string::npos);
  EXPECT_NE(message_of(d / "missing.csv").find("No such file"), std::string::npos);
}

}  // namespace
}  // namespace frictionid::file_fingerprint_test
