// ReportTransaction and ReportDirectoryLock in process: a transaction that is not committed
// leaves DIR as it was and nothing staged; a committed one swaps the whole directory; the lock is
// re-entrant within a process, so write_report under the CLI's lock does not wait for itself.
#include "io/report_transaction.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <frictionid/io/input_error.hpp>
#include "io/atomic_file.hpp"
#include "io/report_directory_lock.hpp"
#include "io/report_location.hpp"
#include "support/scratch_dir.hpp"

namespace report_transaction_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;
using namespace frictionid;

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

void write_report_of(const std::string& dir, const std::string& marker) {
  ReportTransaction t(dir);
  write_file_atomically((t.staging() / "report.json").string(), marker);
  write_file_atomically((t.staging() / "report.md").string(), marker);
  t.commit();
}

TEST(ReportTransaction, WithoutCommitTheEarlierReportStaysAndNothingStagedRemains) {
  ScratchDir s("abort");
  const std::string dir = (s.path() / "rep").string();
  write_report_of(dir, "old");
  try {
    ReportTransaction t(dir);
    write_file_atomically((t.staging() / "report.json").string(), "new");
    throw std::runtime_error("disk full");  // as a failed write would
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read_file(s.path() / "rep" / "report.json"), "old");
  EXPECT_EQ(entries(s.path()), 2u);  // rep and its target
}

TEST(ReportTransaction, CommitSwapsTheWholeDirectory) {
  ScratchDir s("commit");
  const std::string dir = (s.path() / "rep").string();
  write_report_of(dir, "one");
  {
    ReportTransaction t(dir);
    write_file_atomically((t.staging() / "report.json").string(), "two");
    t.commit();
  }
  EXPECT_EQ(read_file(s.path() / "rep" / "report.json"), "two");
  EXPECT_FALSE(fs::exists(s.path() / "rep" / "report.md"));  // nothing of the first report
  EXPECT_EQ(entries(s.path()), 2u);
}

TEST(ReportDirectoryLock, IsReentrantWithinAProcess) {
  ScratchDir s("reentrant");
  const std::string dir = (s.path() / "rep").string();
  ReportDirectoryLock outer(dir, /*wait=*/false);
  write_report_of(dir, "inside");  // takes the lock again: must not wait for itself
  EXPECT_EQ(read_file(s.path() / "rep" / "report.json"), "inside");
}

TEST(ReportDirectoryLock, TheLockFileGoesWithTheLock) {
  ScratchDir s("lockfile");
  const std::string dir = (s.path() / "rep").string();
  {
    ReportDirectoryLock lock(dir, /*wait=*/false);
    EXPECT_TRUE(fs::exists(s.path() / ".rep.lock"));
  }
  EXPECT_FALSE(fs::exists(s.path() / ".rep.lock"));
}

TEST(ReportTransaction,
     AStopCheckThatSaysStopEndsTheCommitWithInterruptedAndKeepsTheEarlierReport) {
  ScratchDir s("stop");
  const std::string dir = (s.path() / "rep").string();
  write_report_of(dir, "old");
  int asked = 0;
  {
    ReportTransaction t(dir, [&asked] { return ++asked > 0; });
    write_file_atomically((t.staging() / "report.json").string(), "new");
    EXPECT_THROW(t.commit(), Interrupted);
  }
  EXPECT_GT(asked, 0);
  EXPECT_EQ(read_file(s.path() / "rep" / "report.json"), "old");
  EXPECT_EQ(entries(s.path()), 2u);  // rep and its target: nothing staged remains
}

// Another process holds the lock: the waiting run polls its stop check and ends with Interrupted
// when it says so, instead of waiting on.
TEST(ReportDirectoryLock, AWaitEndsWithInterruptedWhenTheStopCheckSaysSo) {
  ScratchDir s("stopwait");
  const std::string dir = (s.path() / "rep").string();
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t holder = ::fork();
  ASSERT_GE(holder, 0);
  if (holder == 0) {  // the other run: takes the lock, says so, and holds it
    ::close(ready[0]);
    const ReportDirectoryLock lock(dir, /*wait=*/false);
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(1);
    ::sleep(30);
    ::_exit(0);
  }
  ::close(ready[1]);
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  ::close(ready[0]);
  int asked = 0;
  bool said = false;
  EXPECT_THROW(ReportDirectoryLock(
                   dir, /*wait=*/true, [&said](const std::string&) { said = true; },
                   [&asked] { return ++asked >= 3; }),
               Interrupted);
  EXPECT_TRUE(said);
  EXPECT_EQ(asked, 3);
  ::kill(holder, SIGKILL);
  int status = 0;
  ::waitpid(holder, &status, 0);
}

TEST(ReportLocation, DotDotDotAndRootAreRejected) {
  for (const char* dir : {"", ".", "..", "/", "a/.."})
    EXPECT_THROW(report_location(dir), InputError) << dir;
  EXPECT_EQ(report_location("out/").name, "out");
  EXPECT_EQ(report_location("a/b").parent, fs::path("a"));
}

}  // namespace
}  // namespace report_transaction_test
