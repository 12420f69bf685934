// write_file_atomically and outputs that are not regular files: a FIFO or a device is written
// in place and stays what it is; a symlink stays a symlink and its target gets the content.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "io/atomic_file.hpp"
#include "support/scratch_dir.hpp"

namespace atomic_file_test {
namespace {

namespace fs = std::filesystem;
using frictionid::write_file_atomically;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;

TEST(AtomicFile, AFifoIsWrittenInPlaceAndStaysAFifo) {
  ScratchDir s("fifo");
  const fs::path fifo = s.path() / "out.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  std::string received;
  std::thread reader([&] { received = read_file(fifo); });
  write_file_atomically(fifo.string(), "a,b\n1,2\n");
  reader.join();
  EXPECT_EQ(received, "a,b\n1,2\n");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(std::distance(fs::directory_iterator(s.path()), fs::directory_iterator()), 1);
}

TEST(AtomicFile, AFileUnderDevShmIsCreatedLikeAnyOther) {
  if (!fs::is_directory("/dev/shm")) GTEST_SKIP() << "no /dev/shm";
  const fs::path dir = fs::path("/dev/shm") / ("frictionid-atomic-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_file_atomically((dir / "summary.csv").string(), "a\n");
  write_file_atomically((dir / "summary.csv").string(), "b\n");
  EXPECT_EQ(read_file(dir / "summary.csv"), "b\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(AtomicFile, AWriteFlushedLaterReplacesTheFileWholeAndLeavesNoTemporary) {
  ScratchDir s("later");
  write_file_atomically(s / "report.json", "old\n");
  write_file_atomically(s / "report.json", "new\n", frictionid::Flush::Later);
  EXPECT_EQ(read_file(s.path() / "report.json"), "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(s.path()), fs::directory_iterator()), 1);
}

TEST(AtomicFile, ASymlinkStaysASymlinkAndItsTargetGetsTheContent) {
  ScratchDir s("symlink");
  std::ofstream(s.path() / "target.csv") << "old\n";
  fs::create_symlink("target.csv", s.path() / "link.csv");
  write_file_atomically((s.path() / "link.csv").string(), "new\n");
  EXPECT_TRUE(fs::is_symlink(s.path() / "link.csv"));
  EXPECT_EQ(read_file(s.path() / "target.csv"), "new\n");
}

TEST(AtomicFile, ADanglingSymlinkCreatesItsTarget) {
  ScratchDir s("dangling");
  fs::create_symlink("made.csv", s.path() / "link.csv");
  write_file_atomically((s.path() / "link.csv").string(), "x\n");
  EXPECT_TRUE(fs::is_symlink(s.path() / "link.csv"));
  EXPECT_EQ(read_file(s.path() / "made.csv"), "x\n");
}

TEST(AtomicFile, ALinkToADeviceWritesToTheDeviceAndReplacesNothing) {
  ScratchDir s("device");
  fs::create_symlink("/dev/null", s.path() / "sink");
  write_file_atomically((s.path() / "sink").string(), "discarded\n");
  EXPECT_TRUE(fs::is_symlink(s.path() / "sink"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_EQ(std::distance(fs::directory_iterator(s.path()), fs::directory_iterator()), 1);
}

TEST(AtomicFile, AnUnwritableDeviceGivesAClearError) {
  try {
    write_file_atomically("/proc/version", "x");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write /proc/version"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace atomic_file_test
