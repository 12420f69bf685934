// frictionid batch through the built executable (FRICTIONID_EXE): every summary row equals a
// single `frictionid fit` of the same rows bit for bit, failed runs are rows with exit code 4,
// the summary does not depend on --jobs, a killed batch resumes from its journal, and bad
// inputs exit with code 2 and say what is wrong.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include "support/matched_digits.hpp"
#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"
#include "support/without_traceability.hpp"

namespace batch_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;

using RunResult = frictionid::test::CommandResult;

RunResult run(const std::string& args) {
  return frictionid::test::run_frictionid(args);
}

// summary.csv as label -> column -> cell (cells may be double-quoted).
using Table = std::map<std::string, std::map<std::string, std::string>>;

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      out.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

Table read_summary(const fs::path& csv) {
  std::istringstream in(read_file(csv));
  std::string line;
  std::getline(in, line);
  const auto header = csv_cells(line);
  Table t;
  while (std::getline(in, line)) {
    const auto cells = csv_cells(line);
    EXPECT_EQ(cells.size(), header.size()) << line;
    for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k)
      t[cells[0]][header[k]] = cells[k];
  }
  return t;
}

double number(const std::string& cell) {
  EXPECT_FALSE(cell.empty());
  return std::strtod(cell.c_str(), nullptr);
}

// Every value the summary row holds equals the single fit's report.json bit for bit.
void expect_row_equals_single_fit(const std::map<std::string, std::string>& row,
                                  const std::string& csv, const ScratchDir& d,
                                  const std::string& extra_args = "") {
  const std::string report = d / ("single_" + fs::path(csv).stem().string());
  const RunResult f = run("fit " + csv + " --report " + report + " " + extra_args);
  ASSERT_EQ(f.code, 0) << f.out;
  const auto j = nlohmann::json::parse(read_file(fs::path(report) / "report.json"));
  EXPECT_EQ(row.at("status"), "ok");
  EXPECT_EQ(std::stoul(row.at("rows")), j["rows"].get<std::size_t>());
  for (const auto& [name, p] : j["parameters"].items()) {
    EXPECT_EQ(number(row.at(name)), p["value"].get<double>()) << name;
    if (!p["stderr"].is_null())
      EXPECT_EQ(number(row.at(name + "_stderr")), p["stderr"].get<double>()) << name;
    else
      EXPECT_EQ(row.at(name + "_stderr"), "") << name;
    if (!p["ci95"].is_null()) {
      EXPECT_EQ(number(row.at(name + "_ci95_lo")), p["ci95"][0].get<double>()) << name;
      EXPECT_EQ(number(row.at(name + "_ci95_hi")), p["ci95"][1].get<double>()) << name;
    }
  }
  EXPECT_EQ(number(row.at("cost")), j["statistics"]["cost"].get<double>());
  EXPECT_EQ(number(row.at("reduced_chi2")), j["statistics"]["reduced_chi2"].get<double>());
  EXPECT_EQ(std::stoul(row.at("warnings")), j["warnings"].size());
}

// Three small synthetic runs at different noise seeds: in/run1.csv ... in/run3.csv.
void make_runs(const ScratchDir& d, int count = 3, int rows = 200) {
  fs::create_directories(d / "in");
  for (int i = 1; i <= count; ++i) {
    const RunResult g =
        run("generate --model seed --rows " + std::to_string(rows) + " --noise 0.01 --seed " +
            std::to_string(i) + " --output " + d / ("in/run" + std::to_string(i) + ".csv"));
    ASSERT_EQ(g.code, 0) << g.out;
  }
}

TEST(Batch, DirectoryRowsEqualSingleFitsBitForBit) {
  const ScratchDir d("dir");
  make_runs(d);
  const RunResult b = run("batch " + d / "in" + " --report " + d / "out");
  ASSERT_EQ(b.code, 0) << b.out;
  const Table t = read_summary(d / "out/summary.csv");
  ASSERT_EQ(t.size(), 3u);
  for (int i = 1; i <= 3; ++i) {
    const std::string label = "run" + std::to_string(i);
    ASSERT_TRUE(t.count(label)) << label;
    expect_row_equals_single_fit(t.at(label), d / ("in/" + label + ".csv"), d);
    EXPECT_TRUE(fs::exists(d / ("out/runs/" + label + "/report.json")));
  }
  const auto j = nlohmann::json::parse(read_file(d / "out/summary.json"));
  EXPECT_EQ(j["runs"].size(), 3u);
  EXPECT_EQ(j["runs"][0]["label"], "run1");  // ordered by label
}

TEST(Batch, ManifestRowsEqualSingleFitsAndKeepTheirColumns) {
  const ScratchDir d("manifest");
  make_runs(d);
  std::ofstream(d / "in/campaign.csv") << "path,label,load_case,fix\n"
                                       << "run1.csv,first,low,\n"
                                       << "run2.csv,second,\"high, wet\",h=1\n";
  const RunResult b = run("batch " + d / "in/campaign.csv" + " --report " + d / "out");
  ASSERT_EQ(b.code, 0) << b.out;
  const Table t = read_summary(d / "out/summary.csv");
  ASSERT_EQ(t.size(), 2u);
  expect_row_equals_single_fit(t.at("first"), d / "in/run1.csv", d);
  expect_row_equals_single_fit(t.at("second"), d / "in/run2.csv", d, "--fix h=1");
  EXPECT_EQ(t.at("second").at("load_case"), "high, wet");
  EXPECT_EQ(t.at("second").at("fix"), "h=1");
  EXPECT_FALSE(t.at("first").at("mean_N").empty());
}

TEST(Batch, GroupByRowsEqualSingleFitsOfTheSameRows) {
  const ScratchDir d("groups");
  make_runs(d);
  // One file holding the three runs, told apart by a run_id column.
  std::ofstream all(d / "all.csv");
  for (int i = 1; i <= 3; ++i) {
    std::istringstream in(read_file(d / ("in/run" + std::to_string(i) + ".csv")));
    std::string line;
    std::getline(in, line);
    if (i == 1) all << line << ",run_id\n";
    while (std::getline(in, line)) all << line << ",r" << i << "\n";
  }
  all.close();
  const RunResult b =
      run("batch " + d / "all.csv" + " --group-by run_id --jobs 2 --report " + d / "out");
  ASSERT_EQ(b.code, 0) << b.out;
  const Table t = read_summary(d / "out/summary.csv");
  ASSERT_EQ(t.size(), 3u);
  for (int i = 1; i <= 3; ++i) {
    const std::string label = "r" + std::to_string(i);
    expect_row_equals_single_fit(t.at(label), d / ("in/run" + std::to_string(i) + ".csv"), d);
    EXPECT_EQ(t.at(label).at("run_id"), label);
  }
}

TEST(Batch, GroupByANumericColumnLabelsRunsByItsValue) {
  const ScratchDir d("numeric_groups");
  const RunResult g =
      run("generate --model seed --rows 300 --loads 2000,4000 --output " + d / "rig.csv");
  ASSERT_EQ(g.code, 0) << g.out;
  const RunResult b = run("batch " + d / "rig.csv" + " --group-by N --report " + d / "out");
  ASSERT_EQ(b.code, 0) << b.out;
  const Table t = read_summary(d / "out/summary.csv");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t.at("2000").at("rows"), "150");
  EXPECT_EQ(t.at("4000").at("N"), "4000");
  EXPECT_EQ(number(t.at("4000").at("mean_N")), 4000.0);
  EXPECT_TRUE(fs::exists(d / "out/runs/2000/report.json"));
}

TEST(Batch, WritesSummaryHtmlWithEveryRunLinksToReportsAndTrendPlots) {
  const ScratchDir d("html");
  make_runs(d, 2);
  std::ofstream(d / "in/broken.csv") << "v_x,omega,N,R,T_x\n0.1,2,1000,0.05,abc\n";
  const RunResult b = run("batch " + d / "in" + " --per-run-reports full --report " + d / "out");
  EXPECT_EQ(b.code, 4) << b.out;
  const std::string page = read_file(d / "out/summary.html");
  for (const char* label : {"run1", "run2", "broken"})
    EXPECT_NE(page.find("data-label=\"" + std::string(label) + "\""), std::string::npos) << label;
  EXPECT_NE(page.find("<a href=\"runs/run1/report.html\">run1</a>"), std::string::npos);
  EXPECT_TRUE(fs::exists(d / "out/runs/run1/report.html"));
  EXPECT_EQ(page.find("href=\"runs/broken/"), std::string::npos);
  EXPECT_NE(page.find("data-label=\"broken\" class=\"failed\""), std::string::npos);
  EXPECT_NE(page.find("f against mean_N"), std::string::npos);
  EXPECT_EQ(page.find("nan"), std::string::npos);
  // The page holds summary.csv's numbers: every run's f, exactly.
  const Table t = read_summary(d / "out/summary.csv");
  const std::string f_cell = "data-param=\"f\" data-value=\"";
  for (const char* label : {"run1", "run2"}) {
    const auto row = page.find("data-label=\"" + std::string(label) + "\"");
    const auto cell = page.find(f_cell, row);
    ASSERT_NE(cell, std::string::npos) << label;
    EXPECT_EQ(std::strtod(page.c_str() + cell + f_cell.size(), nullptr),
              number(t.at(label).at("f")))
        << label;
  }
}

TEST(Batch, TrendXTakesAGroupByColumn) {
  const ScratchDir d("trend_x");
  ASSERT_EQ(
      run("generate --model seed --rows 300 --loads 1000,2000,3000 --output " + d / "rig.csv").code,
      0);
  const RunResult b =
      run("batch " + d / "rig.csv" + " --group-by N --trend-x N --report " + d / "out");
  ASSERT_EQ(b.code, 0) << b.out;
  const std::string page = read_file(d / "out/summary.html");
  EXPECT_NE(page.find("kappa against N"), std::string::npos);
  EXPECT_EQ(page.find("Left out"), std::string::npos);
}

TEST(Batch, AFailedRunIsARowAndExitCodeFourWhileTheOthersSucceed) {
  const ScratchDir d("failed");
  make_runs(d, 2);
  std::ofstream(d / "in/broken.csv") << "v_x,omega,N,R,T_x\n0.1,2,1000,0.05,abc\n";
  const RunResult b = run("batch " + d / "in" + " --report " + d / "out");
  EXPECT_EQ(b.code, 4) << b.out;
  EXPECT_NE(b.out.find("broken"), std::string::npos) << b.out;
  const Table t = read_summary(d / "out/summary.csv");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t.at("broken").at("status"), "failed");
  EXPECT_NE(t.at("broken").at("error").find("broken.csv:2"), std::string::npos)
      << t.at("broken").at("error");
  EXPECT_EQ(t.at("broken").at("f"), "");
  EXPECT_EQ(t.at("run1").at("status"), "ok");
  EXPECT_EQ(t.at("run2").at("status"), "ok");
  EXPECT_EQ(read_file(d / "out/summary.csv").find("nan"), std::string::npos);
}

TEST(Batch, SummariesDoNotDependOnTheNumberOfJobs) {
  const ScratchDir d("jobs");
  make_runs(d, 4);
  std::ofstream(d / "in/broken.csv") << "v_x,omega\n";
  for (const char* jobs : {"1", "2"}) {
    const RunResult b = run("batch " + d / "in" + " --jobs " + jobs + " --report " +
                            d / ("out" + std::string(jobs)));
    EXPECT_EQ(b.code, 4) << b.out;
  }
  // summary.html names its command (with its --jobs) in the Traceability section; the rest is
  // the same bytes.
  for (const char* file : {"summary.csv", "summary.json", "summary.html"})
    EXPECT_EQ(frictionid::test::without_traceability(read_file(d / ("out1/" + std::string(file)))),
              frictionid::test::without_traceability(read_file(d / ("out2/" + std::string(file)))))
        << file;
  EXPECT_NE(read_file(d / "out2/summary.html").find("--jobs 2"), std::string::npos);
}

std::size_t journal_lines(const fs::path& p) {
  const std::string s = read_file(p);
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

// `frictionid batch in --jobs 1 --report out` in the background, its output discarded.
pid_t start_batch(const std::string& in, const std::string& out) {
  const std::string exe = std::getenv("FRICTIONID_EXE");
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::execl(exe.c_str(), exe.c_str(), "batch", in.c_str(), "--jobs", "1", "--report", out.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

void wait_for_lines(const fs::path& journal, std::size_t lines) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (journal_lines(journal) < lines && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

// Many copies of one 3000-row run: a batch that takes long enough to be stopped midway.
void make_copies(const ScratchDir& d, int runs) {
  make_runs(d, 1, 3000);
  for (int i = 2; i <= runs; ++i)
    fs::copy_file(d / "in/run1.csv", d / ("in/run" + std::to_string(i) + ".csv"));
}

TEST(Batch, AKilledBatchResumesWithoutRefittingFinishedRunsAndForceRefitsAll) {
  const ScratchDir d("resume");
  constexpr int kRuns = 16;
  make_copies(d, kRuns);
  const RunResult reference = run("batch " + d / "in" + " --jobs 1 --report " + d / "reference");
  ASSERT_EQ(reference.code, 0) << reference.out;

  const pid_t pid = start_batch(d / "in", d / "out");
  ASSERT_GT(pid, 0);
  const fs::path journal = d / "out/journal.jsonl";
  wait_for_lines(journal, 2);
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  const std::size_t finished = journal_lines(journal);
  ASSERT_GE(finished, 2u);
  ASSERT_LT(finished, static_cast<std::size_t>(kRuns)) << "the batch ended before the kill";
  EXPECT_FALSE(fs::exists(d / "out/summary.csv"));
  std::ofstream(journal, std::ios::app) << "{\"label\":\"run9\",\"ke";  // a torn last line

  const RunResult resumed = run("batch " + d / "in" + " --jobs 2 --report " + d / "out");
  ASSERT_EQ(resumed.code, 0) << resumed.out;
  EXPECT_NE(resumed.out.find(std::to_string(kRuns - finished) + " fitted, " +
                             std::to_string(finished) + " from the journal"),
            std::string::npos)
      << resumed.out;
  EXPECT_EQ(read_file(d / "out/summary.csv"), read_file(d / "reference/summary.csv"));
  EXPECT_EQ(read_file(d / "out/summary.json"), read_file(d / "reference/summary.json"));

  const RunResult again = run("batch " + d / "in" + " --report " + d / "out");
  EXPECT_NE(again.out.find("0 fitted, " + std::to_string(kRuns) + " from the journal"),
            std::string::npos)
      << again.out;
  const RunResult forced = run("batch " + d / "in" + " --force --report " + d / "out");
  EXPECT_NE(forced.out.find(std::to_string(kRuns) + " fitted, 0 from the journal"),
            std::string::npos)
      << forced.out;
  EXPECT_EQ(read_file(d / "out/summary.csv"), read_file(d / "reference/summary.csv"));
}

TEST(Batch, CtrlCStopsWithCode130AndKeepsFinishedRunsForTheRerun) {
  const ScratchDir d("interrupt");
  constexpr int kRuns = 16;
  make_copies(d, kRuns);
  const pid_t pid = start_batch(d / "in", d / "out");
  ASSERT_GT(pid, 0);
  const fs::path journal = d / "out/journal.jsonl";
  wait_for_lines(journal, 1);
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_FALSE(fs::exists(d / "out/summary.csv"));
  const std::size_t finished = journal_lines(journal);
  ASSERT_LT(finished, static_cast<std::size_t>(kRuns)) << "the batch ended before Ctrl-C";
  const RunResult resumed = run("batch " + d / "in" + " --report " + d / "out");
  ASSERT_EQ(resumed.code, 0) << resumed.out;
  EXPECT_NE(resumed.out.find(std::to_string(finished) + " from the journal"), std::string::npos)
      << resumed.out;
}

TEST(Batch, ChangedOptionsRefitRunsTheJournalHolds) {
  const ScratchDir d("options");
  make_runs(d, 2);
  ASSERT_EQ(run("batch " + d / "in" + " --report " + d / "out").code, 0);
  const RunResult b = run("batch " + d / "in" + " --seed 7 --report " + d / "out");
  EXPECT_NE(b.out.find("2 fitted, 0 from the journal"), std::string::npos) << b.out;
}

std::string global_algorithm(const fs::path& report_json) {
  return nlohmann::json::parse(read_file(report_json))["global_search"]["algorithm"];
}

TEST(Batch, WarmStartRowsAgreeWithFullSearchesAndSayWhereTheyStarted) {
  const ScratchDir d("warm");
  make_runs(d, 4, 300);
  ASSERT_EQ(run("batch " + d / "in" + " --report " + d / "cold").code, 0);
  const RunResult b = run("batch " + d / "in" + " --warm-start --report " + d / "warm");
  ASSERT_EQ(b.code, 0) << b.out;
  const Table cold = read_summary(d / "cold/summary.csv");
  const Table warm = read_summary(d / "warm/summary.csv");
  // The first run is fitted in full: the single fit's row, bit for bit.
  expect_row_equals_single_fit(warm.at("run1"), d / "in/run1.csv", d);
  EXPECT_EQ(global_algorithm(d / "warm/runs/run1/report.json"), "NLopt GN_CRS2_LM");
  for (const char* label : {"run2", "run3", "run4"}) {
    EXPECT_NE(global_algorithm(d / ("warm/runs/" + std::string(label) + "/report.json"))
                  .find("warm start from run 'run1'"),
              std::string::npos)
        << label;
    // The same optimum: far inside a standard error, to about 8 digits. (A parameter the data
    // do not determine, here h and b, has no standard error and may sit anywhere on its ridge.)
    int compared = 0;
    for (const char* p : {"f", "kappa", "h", "a", "b", "m"}) {
      if (cold.at(label).at(std::string(p) + "_stderr").empty()) continue;
      const double c = number(cold.at(label).at(p)), w = number(warm.at(label).at(p));
      const double se = number(cold.at(label).at(std::string(p) + "_stderr"));
      EXPECT_LE(std::fabs(w - c), 1e-3 * se) << label << " " << p;
      EXPECT_LE(std::fabs(w - c), 1e-7 * std::fabs(c)) << label << " " << p;
      ++compared;
    }
    EXPECT_GE(compared, 3) << label;
  }
}

TEST(Batch, AWarmFitThatFitsWorseThanTheFirstRunFallsBackToTheFullSearch) {
  const ScratchDir d("warm_fallback");
  fs::create_directories(d / "in");
  // The first run (by name) without noise fits to rounding; the second's warm fit, with 1 %
  // noise, cannot come near that and must get the full search.
  ASSERT_EQ(run("generate --model seed --rows 300 --noise 0 --output " + d / "in/a_clean.csv").code,
            0);
  ASSERT_EQ(
      run("generate --model seed --rows 300 --noise 0.01 --seed 4 --output " + d / "in/b_noisy.csv")
          .code,
      0);
  const RunResult b = run("batch " + d / "in" + " --warm-start --report " + d / "out");
  ASSERT_EQ(b.code, 0) << b.out;
  EXPECT_EQ(global_algorithm(d / "out/runs/b_noisy/report.json"), "NLopt GN_CRS2_LM");
  expect_row_equals_single_fit(read_summary(d / "out/summary.csv").at("b_noisy"),
                               d / "in/b_noisy.csv", d);
}

TEST(Batch, WarmStartSummariesDoNotDependOnTheNumberOfJobsAndResumeFromTheJournal) {
  const ScratchDir d("warm_jobs");
  make_runs(d, 4);
  for (const char* jobs : {"1", "2"})
    ASSERT_EQ(run("batch " + d / "in" + " --warm-start --jobs " + jobs + " --report " +
                  d / ("out" + std::string(jobs)))
                  .code,
              0);
  for (const char* file : {"summary.csv", "summary.json"})
    EXPECT_EQ(read_file(d / ("out1/" + std::string(file))),
              read_file(d / ("out2/" + std::string(file))))
        << file;
  const RunResult again = run("batch " + d / "in" + " --warm-start --report " + d / "out1");
  EXPECT_NE(again.out.find("0 fitted, 4 from the journal"), std::string::npos) << again.out;
  // A cold batch's journal holds only the first run's warm-start outcome: the rest depend on it.
  ASSERT_EQ(run("batch " + d / "in" + " --report " + d / "cold").code, 0);
  const RunResult warm = run("batch " + d / "in" + " --warm-start --report " + d / "cold");
  EXPECT_NE(warm.out.find("3 fitted, 1 from the journal"), std::string::npos) << warm.out;
}

TEST(Batch, ARunWhoseReportFileIsGoneIsFittedAgainOnTheRerun) {
  const ScratchDir d("lost_report");
  make_runs(d, 3);
  ASSERT_EQ(run("batch " + d / "in" + " --report " + d / "out").code, 0);
  const std::string before = read_file(d / "out/summary.csv");
  fs::remove(d / "out/runs/run2/report.json");
  const RunResult b = run("batch " + d / "in" + " --report " + d / "out");
  EXPECT_NE(b.out.find("1 fitted, 2 from the journal"), std::string::npos) << b.out;
  EXPECT_GT(fs::file_size(d / "out/runs/run2/report.json"), 0u);
  EXPECT_EQ(read_file(d / "out/summary.csv"), before);
}

TEST(Batch, PerRunReportsNoneAndFull) {
  const ScratchDir d("reports");
  make_runs(d, 1);
  ASSERT_EQ(run("batch " + d / "in" + " --per-run-reports none --report " + d / "none").code, 0);
  EXPECT_FALSE(fs::exists(d / "none/runs/run1"));
  ASSERT_EQ(run("batch " + d / "in" + " --per-run-reports full --report " + d / "full").code, 0);
  for (const char* file : {"report.json", "report.md", "report.html"})
    EXPECT_TRUE(fs::exists(d / ("full/runs/run1/" + std::string(file)))) << file;
}

// Runs at three loads made with one kappa and h and a friction f per load, without noise.
void make_load_runs(const ScratchDir& d) {
  fs::create_directories(d / "in");
  const char* f[] = {"0.7", "0.85", "1"};
  const char* load[] = {"2000", "4000", "6000"};
  for (int i = 0; i < 3; ++i) {
    const RunResult g = run(std::string("generate --model seed --rows 200 --noise 0 --param f=") +
                            f[i] + ",kappa=1.3,h=0.12 --loads " + load[i] + " --output " +
                            d / ("in/load" + std::string(load[i]) + ".csv"));
    ASSERT_EQ(g.code, 0) << g.out;
  }
}

using frictionid::test::matched_digits;

TEST(Batch, SharedKappaAndHAreOneValueForEveryRunWhileEachRunKeepsItsOwnF) {
  const ScratchDir d("shared");
  make_load_runs(d);
  const RunResult plain = run("batch " + d / "in" + " --report " + d / "plain");
  ASSERT_EQ(plain.code, 0) << plain.out;
  const RunResult r = run("batch " + d / "in" + " --shared kappa,h --report " + d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  // The runs' own fits are the same with or without --shared.
  EXPECT_EQ(read_file(fs::path(d / "out") / "summary.csv"),
            read_file(fs::path(d / "plain") / "summary.csv"));
  const Table t = read_summary(fs::path(d / "out") / "shared.csv");
  ASSERT_EQ(t.size(), 3u);
  const std::map<std::string, double> f = {
      {"load2000", 0.7}, {"load4000", 0.85}, {"load6000", 1.0}};
  for (const auto& [label, row] : t) {
    EXPECT_EQ(row.at("kappa"), t.begin()->second.at("kappa")) << label;
    EXPECT_EQ(row.at("h"), t.begin()->second.at("h")) << label;
    EXPECT_GE(matched_digits(number(row.at("kappa")), 1.3), 10.0) << row.at("kappa");
    EXPECT_GE(matched_digits(number(row.at("h")), 0.12), 10.0) << row.at("h");
    EXPECT_GE(matched_digits(number(row.at("f")), f.at(label)), 10.0)
        << label << " " << row.at("f");
  }
  const auto j = nlohmann::json::parse(read_file(fs::path(d / "out") / "shared.json"));
  EXPECT_EQ(j["shared"]["kappa"]["value"].get<double>(), number(t.begin()->second.at("kappa")));
  EXPECT_EQ(j["runs_fitted"].get<int>(), 3);
  EXPECT_EQ(j["solver"]["linear_solver"], "DENSE_SCHUR");
  const std::string page = read_file(fs::path(d / "out") / "shared.html");
  EXPECT_NE(page.find("<h1>frictionid batch: joint fit</h1>"), std::string::npos);
  EXPECT_NE(page.find("in which kappa = "), std::string::npos) << "the shared value in the note";
  EXPECT_EQ(page.find("nan"), std::string::npos);
}

TEST(Batch, ABadSharedParameterExitsWithCodeTwoNamingItBeforeAnyRunIsFitted) {
  const ScratchDir d("shared_bad");
  make_runs(d, 2, 100);
  const RunResult unknown = run("batch " + d / "in" + " --shared kapa --report " + d / "a");
  EXPECT_EQ(unknown.code, 2) << unknown.out;
  EXPECT_NE(unknown.out.find("--shared: unknown parameter 'kapa'"), std::string::npos)
      << unknown.out;
  EXPECT_FALSE(fs::exists(d / "a/summary.csv"));
  const RunResult fixed = run("batch " + d / "in" + " --shared h --fix h=0.1 --report " + d / "b");
  EXPECT_EQ(fixed.code, 2) << fixed.out;
  EXPECT_NE(fixed.out.find("shared parameter h is fixed"), std::string::npos) << fixed.out;
  EXPECT_FALSE(fs::exists(d / "b/summary.csv"));
}

TEST(Batch, BadInputsExitWithCodeTwoAndSayWhatIsWrong) {
  const ScratchDir d("bad");
  make_runs(d, 1);
  fs::create_directories(d / "empty");
  std::ofstream(d / "manifest.csv") << "path,label\nin/run1.csv,a\nin/missing.csv,b\n";
  std::ofstream(d / "clash.csv") << "path,cost\nin/run1.csv,12\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"batch " + d / "empty", "no *.csv file"},
      {"batch '" + d / "in/*.txt" + "'", "matches no CSV file"},
      {"batch " + d / "nowhere.csv", "no such file or directory"},
      {"batch " + d / "manifest.csv", "manifest.csv:3:1: no such file 'in/missing.csv'"},
      {"batch " + d / "in/run1.csv" + " --group-by load_case", "--group-by: no column 'load_case'"},
      {"batch " + d / "in" + " --per-run-reports some", "per-run-reports"},
      {"batch " + d / "clash.csv", "column 'cost' would clash"},
      {"batch " + d / "in" + " --trend-x load",
       "--trend-x: no covariate 'load'; the covariates "
       "are: mean_N, mean_speed, mean_omega_R"},
  };
  for (const auto& [args, message] : cases) {
    const RunResult r = run(args + " --report " + d / "out");
    EXPECT_EQ(r.code, 2) << args << ": " << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << args << ": " << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << args << ": " << r.out;
  }
}

}  // namespace
}  // namespace batch_test
