// What a batch does with inputs that are not plain files (issue cases: a FIFO, a device, a loop
// of symbolic links, an empty directory a glob matches), with a journal whose fit read other
// bytes than the file now holds, and with the temporary files a killed batch left behind.
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/memory_cap.hpp"
#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

namespace batch_inputs_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;

frictionid::test::CommandResult run(const std::string& args) {
  return frictionid::test::run_frictionid(args);
}

void make_run(const std::string& path, int seed) {
  fs::create_directories(fs::path(path).parent_path());
  const auto r =
      run("generate --model seed --param f=0.8,kappa=1.2,h=0.1 --rows 300 --noise 0.01 "
          "--seed " +
          std::to_string(seed) + " --output " + path);
  ASSERT_EQ(r.code, 0) << r.out;
}

TEST(BatchInputs, AFifoOrADeviceNamedAsAnInputIsNotARegularFile) {
  const ScratchDir d("batch_inputs_named");
  ASSERT_EQ(::mkfifo((d / "pipe.csv").c_str(), 0600), 0);
  const auto fifo = run("batch " + d / "pipe.csv" + " --report " + d / "out");
  EXPECT_EQ(fifo.code, 2) << fifo.out;
  EXPECT_NE(fifo.out.find("not a regular file (a FIFO)"), std::string::npos) << fifo.out;
  const auto zero = run("batch /dev/zero --report " + d / "out2");
  EXPECT_EQ(zero.code, 2) << zero.out;
  EXPECT_NE(zero.out.find("not a regular file (a character device)"), std::string::npos)
      << zero.out;
}

TEST(BatchInputs, AManifestNamingAFifoSaysWhereAndThatItIsNotARegularFile) {
  const ScratchDir d("batch_inputs_manifest");
  make_run(d / "good.csv", 1);
  ASSERT_EQ(::mkfifo((d / "pipe.csv").c_str(), 0600), 0);
  std::ofstream(d / "manifest.csv") << "path,label\ngood.csv,a\npipe.csv,b\n";
  const auto r = run("batch " + d / "manifest.csv" + " --report " + d / "out");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("manifest.csv:3:1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not a regular file (a FIFO)"), std::string::npos) << r.out;
}

TEST(BatchInputs, SpecialFilesAndLinkLoopsInADirectoryAreSkippedByNameAndTheRestFitted) {
  const ScratchDir d("batch_inputs_dir");
  make_run(d / "in/good1.csv", 1);
  make_run(d / "in/good2.csv", 2);
  ASSERT_EQ(::mkfifo((d / "in/pipe.csv").c_str(), 0600), 0);
  fs::create_symlink("loop_b.csv", d / "in/loop_a.csv");
  fs::create_symlink("loop_a.csv", d / "in/loop_b.csv");
  const auto r = run("batch " + d / "in" + " --report " + d / "out");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("skipped " + d / "in/pipe.csv" + ": not a regular file (a FIFO)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("skipped " + d / "in/loop_a.csv" + ": a loop of symbolic links"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("2 runs: 2 fitted"), std::string::npos) << r.out;
}

TEST(BatchInputs, AGlobOverLinkLoopsAndAnEmptyDirectoryFitsTheGoodFiles) {
  const ScratchDir d("batch_inputs_glob");
  make_run(d / "in/run1.csv", 1);
  fs::create_directories(d / "in/run_empty");
  fs::create_symlink("run_loop2", d / "in/run_loop1");
  fs::create_symlink("run_loop1", d / "in/run_loop2");
  const auto r = run("batch '" + d / "in/run*" + "' --report " + d / "out");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("skipped " + d / "in/run_empty" + ": no *.csv file"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("skipped " + d / "in/run_loop1" + ": a loop of symbolic links"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 runs: 1 fitted"), std::string::npos) << r.out;
}

TEST(BatchInputs, AnUnreadableDirectoryIsExitTwoNamingItAndPermissionDenied) {
  // Root reads every directory: as root, the batch runs as nobody (setpriv, util-linux).
  std::string as_user;
  if (::geteuid() == 0) {
    if (std::system("command -v setpriv >/dev/null 2>&1") != 0)
      GTEST_SKIP() << "running as root without setpriv";
    as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  }
  const ScratchDir d("batch_inputs_unreadable");
  make_run(d / "in/run1.csv", 1);
  fs::create_directories(d / "out");
  fs::permissions(d.path(), fs::perms::all);
  fs::permissions(d / "out", fs::perms::all);
  fs::permissions(d / "in", fs::perms::none);
  const auto r = frictionid::test::run_command(as_user + std::getenv("FRICTIONID_EXE") + " batch " +
                                               d / "in" + " --report " + d / "out" + " 2>&1");
  fs::permissions(d / "in", fs::perms::owner_all);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find(d / "in"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("permission denied"), std::string::npos) << r.out;
}

// The journal's line says which bytes its fit read: a file replaced while the batch ran (after
// planning, before its fit) and restored afterwards is fitted again, and the batch says why.
TEST(BatchInputs, AJournalLineOfOtherBytesThanTheFileHoldsIsFittedAgainAndSaidSo) {
  const ScratchDir d("batch_inputs_resume");
  make_run(d / "in/run1.csv", 1);
  make_run(d / "in/run2.csv", 2);
  ASSERT_EQ(run("batch " + d / "in" + " --report " + d / "out").code, 0);
  // The line of run1 as a fit of replaced bytes would have left it.
  std::stringstream journal;
  std::ifstream in(d / "out/journal.jsonl");
  for (std::string line; std::getline(in, line);) {
    auto j = nlohmann::json::parse(line);
    ASSERT_TRUE(j.contains("input")) << line;
    EXPECT_EQ(j["input"]["sha256"].get<std::string>().size(), 64u);
    if (j["label"] == "run1") j["input"]["sha256"] = std::string(64, '0');
    journal << j.dump() << "\n";
  }
  in.close();
  std::ofstream(d / "out/journal.jsonl") << journal.str();
  const auto again = run("batch " + d / "in" + " --report " + d / "out");
  EXPECT_EQ(again.code, 0) << again.out;
  EXPECT_NE(again.out.find("run 'run1': its journal line is of other bytes"), std::string::npos)
      << again.out;
  EXPECT_NE(again.out.find("2 runs: 1 fitted, 1 from the journal"), std::string::npos) << again.out;
}

TEST(BatchInputs, ARerunRemovesTheTemporaryFilesAKilledBatchLeft) {
  const ScratchDir d("batch_inputs_leftovers");
  make_run(d / "in/run1.csv", 1);
  ASSERT_EQ(run("batch " + d / "in" + " --report " + d / "out").code, 0);
  std::ofstream(d / "out/runs/run1/.report.json.tmp.Ab12Cd") << "{\"half";
  std::ofstream(d / "out/.summary.csv.tmp.Zz9yX8") << "label";
  std::ofstream(d / "out/runs/run1/keep.tmp.txt") << "a user's file";
  ASSERT_EQ(run("batch " + d / "in" + " --report " + d / "out").code, 0);
  EXPECT_FALSE(fs::exists(d / "out/runs/run1/.report.json.tmp.Ab12Cd"));
  EXPECT_FALSE(fs::exists(d / "out/.summary.csv.tmp.Zz9yX8"));
  EXPECT_TRUE(fs::exists(d / "out/runs/run1/keep.tmp.txt"));
}

// A sparse file of over a gigabyte among a batch's inputs: planning hashes it as a stream and its
// run fails with the single fit's message, under a memory cap the file would not fit in (the
// previous build read each input whole to hash it and ended in std::bad_alloc).
TEST(BadInputLarge, ASparseGigabyteInputFailsItsRunWithTheReadersMessageInBoundedMemory) {
  const ScratchDir d("batch_inputs_sparse");
  make_run(d / "in/good.csv", 1);
  { std::ofstream(d / "in/sparse.csv") << "v_x,omega,N,R,T_x\n"; }
  fs::resize_file(d / "in/sparse.csv", std::uintmax_t{1200} << 20);  // a hole: no disk used
  const auto r = frictionid::test::run_command(frictionid::test::memory_cap_prefix(1000) +
                                               std::getenv("FRICTIONID_EXE") + " batch " +
                                               d / "in" + " --report " + d / "out" + " 2>&1");
  EXPECT_EQ(r.code, 4) << r.out;
  EXPECT_NE(r.out.find("line is longer than 2^24-1 characters"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 runs: 2 fitted"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace batch_inputs_test
