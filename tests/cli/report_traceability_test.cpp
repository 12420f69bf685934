// Every page and report.json name what made them (issue: traceability): the input files with
// size and SHA-256, the frictionid version and the command line; run on the built executable.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "io/file_fingerprint.hpp"
#include "support/run_command.hpp"

namespace report_traceability_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::CommandResult;
using frictionid::test::run_frictionid;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class ReportTraceability : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("frictionid_traceability_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    data_ = (dir_ / "data.csv").string();
    const CommandResult g = run_frictionid(
        "generate --model seed --param f=0.8,kappa=1.2,h=0.1 --rows 60 --output " + data_);
    ASSERT_EQ(g.code, 0) << g.out;
    const auto fp = frictionid::fingerprint_file(data_);
    sha256_ = fp.sha256;
    size_ = fp.size;
    const CommandResult v = run_frictionid("--version");
    ASSERT_EQ(v.code, 0) << v.out;
    version_ = v.out.substr(v.out.find(' ') + 1);
    version_ = version_.substr(0, version_.find_first_of("\r\n"));
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The traceability lines every page must hold.
  void expect_named(const std::string& page, const std::string& command,
                    const std::string& what) const {
    EXPECT_NE(page.find(sha256_), std::string::npos) << what;
    EXPECT_NE(page.find(std::to_string(size_) + " bytes"), std::string::npos) << what;
    EXPECT_NE(page.find(version_), std::string::npos) << what;
    EXPECT_NE(page.find(command), std::string::npos) << what << ": " << command;
  }

  fs::path dir_;
  std::string data_, sha256_, version_;
  std::uint64_t size_ = 0;
};

TEST_F(ReportTraceability, FitReportNamesInputVersionAndCommandLine) {
  const std::string rep = (dir_ / "rep").string();
  const std::string args = "fit " + data_ + " --model seed --no-global --report " + rep;
  const CommandResult f = run_frictionid(args);
  ASSERT_EQ(f.code, 0) << f.out;

  const auto j = nlohmann::json::parse(slurp(fs::path(rep) / "report.json"));
  const auto& p = j.at("provenance");
  EXPECT_EQ(p.at("version"), version_);
  // "frictionid", not the path of the executable that ran.
  EXPECT_EQ(p.at("command_line"), "frictionid " + args);
  EXPECT_TRUE(p.at("python_call").is_null());
  EXPECT_EQ(p.at("options").at("model"), "seed");
  EXPECT_EQ(p.at("options").at("no_global"), true);
  ASSERT_EQ(p.at("inputs").size(), 1u);
  EXPECT_EQ(p.at("inputs")[0].at("path"), data_);
  EXPECT_EQ(p.at("inputs")[0].at("size"), size_);
  EXPECT_EQ(p.at("inputs")[0].at("sha256"), sha256_);

  for (const char* page : {"report.md", "report.html"})
    expect_named(slurp(fs::path(rep) / page), "frictionid " + args, page);
}

TEST_F(ReportTraceability, SameCommandTwiceGivesByteIdenticalReports) {
  // No time, no modification time: touching the file changes nothing in the report.
  const std::string a = (dir_ / "a").string(), b = (dir_ / "b").string();
  ASSERT_EQ(run_frictionid("fit " + data_ + " --model seed --no-global --report " + a).code, 0);
  fs::last_write_time(data_, fs::last_write_time(data_) + std::chrono::hours(1));
  ASSERT_EQ(run_frictionid("fit " + data_ + " --model seed --no-global --report " + b).code, 0);
  for (const char* file : {"report.json", "report.md", "report.html"}) {
    std::string ta = slurp(fs::path(a) / file), tb = slurp(fs::path(b) / file);
    // The command lines differ only in the report directory's name.
    for (std::string* t : {&ta, &tb})
      for (auto at = t->find(dir_.string()); at != std::string::npos;
           at = t->find(dir_.string(), at + 1))
        t->replace(at + dir_.string().size() + 1, 1, "X");
    EXPECT_EQ(ta, tb) << file;
  }
}

TEST_F(ReportTraceability, CompareAndBatchPagesNameTheirInputsAndCommand) {
  const std::string cmp = (dir_ / "cmp").string();
  const std::string compare_args =
      "compare " + data_ + " --models seed,corrected --no-global --report " + cmp;
  ASSERT_EQ(run_frictionid(compare_args).code, 0);
  for (const char* page : {"compare.md", "compare.html", "seed/report.html"})
    expect_named(slurp(fs::path(cmp) / page), "frictionid " + compare_args, page);
  const auto cj = nlohmann::json::parse(slurp(fs::path(cmp) / "compare.json"));
  EXPECT_EQ(cj.at("provenance").at("inputs")[0].at("sha256"), sha256_);
  EXPECT_EQ(cj.at("provenance").at("options").at("models"),
            nlohmann::json::array({"seed", "corrected"}));

  const std::string out = (dir_ / "batch").string();
  const std::string batch_args =
      "batch " + data_ + " --no-global --per-run-reports full --report " + out;
  const CommandResult b = run_frictionid(batch_args);
  ASSERT_EQ(b.code, 0) << b.out;
  expect_named(slurp(fs::path(out) / "summary.html"), "frictionid " + batch_args, "summary.html");
  for (const auto& e : fs::recursive_directory_iterator(fs::path(out) / "runs"))
    if (e.path().filename() == "report.html")
      expect_named(slurp(e.path()), "frictionid " + batch_args, e.path().string());
}

}  // namespace
}  // namespace report_traceability_test
