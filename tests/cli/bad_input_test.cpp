// Malformed, unusual and huge inputs through the built executable (FRICTIONID_EXE): every file of
// the corpus tests/data/bad against its line in tests/data/bad/expected.tsv, malformed option
// values, inputs generated on the fly (very long lines, 10^7 rows), faults (unwritable outputs,
// Ctrl-C) and reproducibility. A failure must exit with the documented code, say on one line
// where (file:line:column) and what was expected, and leave nothing behind; a success must be
// complete and free of NaN.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <frictionid/io/dataset_csv.hpp>
#include "support/scratch_dir.hpp"
#include "support/signalled_run.hpp"
#include "support/without_traceability.hpp"

namespace bad_input_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;

const fs::path kBadDir = fs::path(FRICTIONID_TEST_DATA_DIR) / "bad";
const fs::path kManifest = kBadDir / "expected.tsv";

// ---- running the executable ----------------------------------------------------------------

struct RunResult {
  int code;         // exit status; -1 when the process did not exit normally (e.g. a signal)
  std::string out;  // stdout
  std::string err;  // stderr
};

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs FRICTIONID_EXE with `args` in the working directory `cwd`.
RunResult run(const std::vector<std::string>& args, const fs::path& cwd) {
  static std::atomic<int> counter{0};
  const char* exe = std::getenv("FRICTIONID_EXE");
  if (!exe) return {-1, "", "FRICTIONID_EXE not set"};
  const fs::path err_file =
      fs::temp_directory_path() /
      ("frictionid_bad_stderr_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::string cmd = "cd " + shell_quote(cwd.string()) + " && exec " + shell_quote(exe);
  for (const auto& a : args) cmd += " " + shell_quote(a);
  cmd += " 2>" + shell_quote(err_file.string());
  RunResult r{-1, "", ""};
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, "", "popen failed"};
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_file(err_file);
  fs::remove(err_file);
  return r;
}

// A fresh empty directory, removed with everything in it at the end of the scope.
// Every file and directory under `dir`, relative to it.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    names.push_back(fs::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s.empty() ? "(nothing)" : s;
}

// Temporary files of the atomic writer (".NAME.tmp.XXXXXX") anywhere under `dir`.
std::vector<std::string> temporary_files(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& name : listing(dir))
    if (name.find(".tmp.") != std::string::npos) found.push_back(name);
  return found;
}

std::size_t count_lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

// True when `text` holds a printed non-finite number ("nan", "-nan", "inf", "-inf", "infinity",
// in any case) as a token of its own.
bool has_non_finite_token(const std::string& text) {
  static const std::set<std::string> kBad = {"nan",  "-nan", "+nan",     "inf",
                                             "-inf", "+inf", "infinity", "-infinity"};
  std::string token;
  auto flush = [&] {
    const bool bad = kBad.count(token) > 0;
    token.clear();
    return bad;
  };
  for (char c : text) {
    const char l = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if ((l >= 'a' && l <= 'z') || (l >= '0' && l <= '9') || l == '_' || l == '-' || l == '+' ||
        l == '.') {
      token += l;
    } else if (flush()) {
      return true;
    }
  }
  return flush();
}

// Every number in `j` is finite and no value is null (nlohmann writes NaN and Inf as null).
bool all_finite(const nlohmann::json& j, std::string& where, const std::string& path = "") {
  if (j.is_null()) return where = path, false;
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return where = path, false;
  if (j.is_object())
    for (const auto& [k, v] : j.items())
      if (!all_finite(v, where, path + "/" + k)) return false;
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i)
      if (!all_finite(j[i], where, path + "/" + std::to_string(i))) return false;
  return true;
}

// ---- the manifest --------------------------------------------------------------------------

struct Case {
  std::string file, kind, exit, where, expect, note;
  std::size_t manifest_line = 0;

  std::string name() const {
    std::string n = kind + "_" + file;
    for (char& c : n)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
  }
  bool accepts_exit(int code) const {
    std::stringstream s(exit);
    std::string alt;
    while (std::getline(s, alt, '|'))
      if (alt == std::to_string(code)) return true;
    return false;
  }
};

// For GoogleTest's messages and the ctest listing (instead of a byte dump).
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.kind << " " << c.file;
}

std::vector<Case> manifest() {
  std::vector<Case> cases;
  std::ifstream in(kManifest);
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream s(line);
    std::string field;
    while (std::getline(s, field, '\t')) f.push_back(field);
    f.resize(6);
    cases.push_back({f[0], f[1], f[2], f[3], f[4], f[5], line_no});
  }
  return cases;
}

// ---- the corpus, one test per manifest line ------------------------------------------------

class Corpus : public ::testing::TestWithParam<Case> {};

TEST_P(Corpus, BehavesAsTheManifestSays) {
  const Case& c = GetParam();
  SCOPED_TRACE("expected.tsv:" + std::to_string(c.manifest_line) + ": " + c.kind + " " + c.file +
               (c.note.empty() ? "" : " (" + c.note + ")"));
  const std::string input = (kBadDir / c.file).string();
  ScratchDir dir(c.name());
  const fs::path report = dir / "report";
  const fs::path output = dir / "out.csv";

  std::vector<std::string> args;
  if (c.kind == "fit")
    args = {"fit", input, "--model", "seed", "--report", report.string()};
  else if (c.kind == "eval")
    args = {"eval",    "--model", "exact",    "--param",      "f=0.8,kappa=1.2,h=0.1",
            "--input", input,     "--output", output.string()};
  else if (c.kind == "coefficients")
    args = {"coefficients", "--pressure", "table:" + input};
  else if (c.kind == "map")
    args = {"coefficients", "--contact", "map:" + input};
  else
    FAIL() << "unknown kind '" << c.kind << "'";

  const RunResult r = run(args, dir.path());
  const std::string all = r.out + r.err;
  ASSERT_TRUE(c.accepts_exit(r.code))
      << "exit " << r.code << ", expected " << c.exit << "\nstdout:\n"
      << r.out << "stderr:\n"
      << r.err;
  if (c.expect != "-") {
    EXPECT_NE(all.find(c.expect), std::string::npos) << all;
  }

  if (r.code != 0) {
    // One line on stderr that says where and what; nothing written anywhere.
    if (r.code == 2) {
      EXPECT_EQ(r.out, "");
      EXPECT_EQ(r.err.rfind("frictionid: error: ", 0), 0u) << r.err;
    }
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    if (c.where != "-") {
      EXPECT_NE(r.err.find(c.where + ": "), std::string::npos) << r.err;
    }
    EXPECT_TRUE(listing(dir.path()).empty())
        << "left behind after a failure: " << joined(listing(dir.path()));
  } else {
    // Complete output; NaN or Inf anywhere in it is a failure (a skip for a known bug).
    std::string non_finite;
    if (c.kind == "fit") {
      ASSERT_TRUE(fs::exists(report / "report.json")) << all;
      EXPECT_TRUE(fs::exists(report / "report.md"));
      EXPECT_TRUE(temporary_files(dir.path()).empty()) << joined(temporary_files(dir.path()));
      const auto j = nlohmann::json::parse(read_file(report / "report.json"));
      EXPECT_GE(j.at("rows").get<int>(), 1);
      for (const auto& [name, p] : j.at("parameters").items())
        if (!p.at("value").is_number() || !std::isfinite(p.at("value").get<double>()))
          non_finite += " report.json parameter " + name + ";";
      const auto& cost = j.at("statistics").at("cost");
      if (!cost.is_number() || !std::isfinite(cost.get<double>()))
        non_finite += " report.json cost;";
      if (has_non_finite_token(r.out)) non_finite += " stdout;";
      if (has_non_finite_token(read_file(report / "report.md"))) non_finite += " report.md;";
    } else if (c.kind == "eval") {
      ASSERT_TRUE(fs::exists(output)) << all;
      EXPECT_TRUE(temporary_files(dir.path()).empty()) << joined(temporary_files(dir.path()));
      const std::string csv = read_file(output);
      if (has_non_finite_token(csv)) non_finite += " out.csv;";
      const std::size_t wrote = r.err.find("wrote ");
      ASSERT_NE(wrote, std::string::npos) << r.err;
      EXPECT_EQ(count_lines(csv), std::stoul(r.err.substr(wrote + 6)) + 1) << csv;
    } else {
      std::string where;
      if (!all_finite(nlohmann::json::parse(r.out), where)) non_finite += " stdout at " + where;
    }
    if (!non_finite.empty()) {
      if (c.note.rfind("known bug", 0) == 0) GTEST_SKIP() << c.note << ":" << non_finite;
      ADD_FAILURE() << "NaN or Inf in:" << non_finite << "\n" << all;
    }
  }
  EXPECT_TRUE(temporary_files(kBadDir).empty()) << joined(temporary_files(kBadDir));
}

INSTANTIATE_TEST_SUITE_P(BadInput, Corpus, ::testing::ValuesIn(manifest()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.name();
                         });

TEST(BadInputManifest, HasAValidLineForEveryFileAndAtLeastFortyFiles) {
  const auto cases = manifest();
  std::set<std::string> files, names;
  for (const auto& c : cases) {
    SCOPED_TRACE("expected.tsv:" + std::to_string(c.manifest_line));
    EXPECT_TRUE(c.kind == "fit" || c.kind == "eval" || c.kind == "coefficients" || c.kind == "map")
        << c.kind;
    EXPECT_FALSE(c.exit.empty());
    EXPECT_FALSE(c.where.empty());
    EXPECT_FALSE(c.expect.empty());
    EXPECT_TRUE(names.insert(c.name()).second) << "duplicate case " << c.name();
    files.insert(c.file);
    const bool exists = fs::exists(kBadDir / c.file);
    EXPECT_TRUE(exists || c.expect == "cannot open file") << c.file << " is missing";
  }
  std::size_t on_disk = 0;
  for (const auto& e : fs::directory_iterator(kBadDir)) {
    const std::string name = e.path().filename().string();
    if (name == "expected.tsv") continue;
    ++on_disk;
    EXPECT_TRUE(files.count(name)) << name << " has no line in expected.tsv";
  }
  EXPECT_GE(on_disk, 40u);
}

// ---- option values -------------------------------------------------------------------------

TEST(BadInput, MalformedOptionValuesExitWithCodeTwoAndOneLineNamingTheOption) {
  ScratchDir dir("options");
  const std::string data = (kBadDir / "crlf_line_ends.csv").string();
  const std::string report = (dir / "report");
  const std::vector<std::pair<std::string, std::string>> fit_cases = {
      {"--param", "f=abc"},
      {"--param", "f"},
      {"--param", "=1"},
      {"--param", "f=1,f=2"},
      {"--param", "f=1,,h=2"},
      {"--param", "f=nan"},
      {"--param", "f=inf"},
      {"--param", "f=0x1p-1"},
      {"--param", "f=1e999"},
      {"--param", "f=0.8 kappa=1"},
      {"--param", "zz=1"},
      {"--bounds", "f=1:0"},
      {"--bounds", "f=1"},
      {"--bounds", "f=0:1:2"},
      {"--bounds", "f=a:1"},
      {"--bounds", "f=:1"},
      {"--bounds", "f=0:inf"},
      {"--bounds", "kappa=-1:2"},
      {"--bounds", ","},
      {"--fix", "f="},
      {"--fix", "f=0.8;kappa=1"},
      {"--fix", "kappa=0"},
      {"--fix", "f-x=1"},
      {"--fix", "n=1"},
      {"--columns", "v_x"},
      {"--columns", "vx=speed"},
      {"--columns", "v_x="},
      {"--columns", "v_x=a,v_x=b"},
      {"--columns", "v_x=a,omega=a"},
      {"--columns", "v_x=omega"},
      {"--columns", "v_x=speed,"},
      {"--channels", "T_x,,M_z"},
      {"--channels", "T_z"},
      {"--channels", "T_x,T_x"},
      {"--loss", "huber:-1"},
      {"--loss", "huber:abc"},
      {"--loss", "l2"},
      {"--pressure", "power:"},
      {"--pressure", "power:-1"},
      {"--pressure", "power:1e999"},
      {"--pressure", "power:1e308"},
      {"--pressure", "table:"},
      {"--pressure", "table:/nonexistent/table.csv"},
      {"--starts", "0"},
      {"--starts", "abc"},
  };
  for (const auto& [option, value] : fit_cases) {
    const RunResult r =
        run({"fit", data, "--model", "seed", option, value, "--report", report}, dir.path());
    const std::string what = option + " " + value;
    EXPECT_EQ(r.code, 2) << what << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << what << ": " << r.err;
    const std::string named = option == "--pressure" && value.rfind("table:/", 0) == 0
                                  ? "/nonexistent/table.csv"
                                  : option;
    EXPECT_NE(r.err.find(named), std::string::npos) << what << ": " << r.err;
    EXPECT_EQ(r.out, "") << what;
  }
  // {option the message must name, eval arguments}
  const std::vector<std::pair<std::string, std::vector<std::string>>> eval_cases = {
      {"--param", {"--param", "f=0.8,kappa=abc,h=0.1", "--vx", "0.1", "--omega", "1"}},
      {"--param", {"--param", "f=0.8,,h=0.1", "--vx", "0.1", "--omega", "1"}},
      {"--vx", {"--param", "f=0.8", "--vx", "nan", "--omega", "1"}},
      {"--N", {"--param", "f=0.8", "--vx", "0.1", "--omega", "1", "--N", "0"}},
      {"--R", {"--param", "f=0.8", "--vx", "0.1", "--omega", "1", "--R", "-1"}},
      {"--columns",
       {"--param", "f=0.8", "--input", data, "--output", "o.csv", "--columns", "v_x=,omega=spin"}},
  };
  for (const auto& [named, extra] : eval_cases) {
    std::vector<std::string> args = {"eval", "--model", "seed"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run(args, dir.path());
    const std::string what = joined(extra);
    EXPECT_EQ(r.code, 2) << what << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << what << ": " << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << what << ": " << r.err;
  }
  EXPECT_TRUE(listing(dir.path()).empty()) << joined(listing(dir.path()));
}

// ---- inputs made on the fly ----------------------------------------------------------------

TEST(BadInput, ALineLongerThanTheReaderLimitIsRejectedWithItsLineNumber) {
  ScratchDir dir("long_line");
  {
    std::ofstream f(dir / "long.csv", std::ios::binary);
    f << "v_x,omega,N,R,T_x\n0.1,2,2000,0.05,1299\n0.1,2,2000,0.05,";
    f << std::string((1u << 24) + 10, '1') << "\n0.2,2,2000,0.05,1300\n";
  }
  const RunResult r =
      run({"fit", "long.csv", "--model", "seed", "--report", (dir / "report")}, dir.path());
  EXPECT_EQ(r.code, 2) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find("long.csv:3: line is longer than"), std::string::npos)
      << r.err.substr(0, 500);
  EXPECT_EQ(count_lines(r.err), 1u);
  EXPECT_LT(r.err.size(), 300u);
  EXPECT_FALSE(fs::exists(dir / "report"));
}

TEST(BadInput, AHugeFieldIsCutShortInTheMessage) {
  ScratchDir dir("huge_field");
  {
    std::ofstream f(dir / "d.csv", std::ios::binary);
    f << "v_x,omega,N,R,T_x\n0.1,2,2000,0.05," << std::string(1u << 20, '7') << "\n";
    std::ofstream t(dir / "t.csv", std::ios::binary);
    t << "rho,sigma0\n0,1\n0.5," << std::string(1u << 20, 'x') << "\n1,0\n";
  }
  RunResult r = run({"fit", "d.csv", "--model", "seed", "--report", "report"}, dir.path());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("d.csv:2:5: column 'T_x' has '7777"), std::string::npos)
      << r.err.substr(0, 500);
  EXPECT_NE(r.err.find("out of the double range"), std::string::npos) << r.err.substr(0, 500);
  EXPECT_LT(r.err.size(), 400u);
  r = run({"coefficients", "--pressure", "table:t.csv"}, dir.path());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("t.csv:3:2: sigma0: expected a finite number"), std::string::npos)
      << r.err.substr(0, 500);
  EXPECT_LT(r.err.size(), 400u);
  EXPECT_EQ(count_lines(r.err), 1u);
}

TEST(BadInput, RowsOfAHundredThousandColumnsAndMegabyteNumbersAreRead) {
  ScratchDir dir("wide");
  const std::string base = read_file(kBadDir / "crlf_line_ends.csv");
  std::istringstream lines(base);
  std::string line;
  std::ofstream f(dir / "wide.csv", std::ios::binary);
  bool header = true;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    f << line;
    for (int k = 0; k < 100000; ++k) f << (header ? ",extra" + std::to_string(k) : ",1");
    // A valid number padded to a megabyte with leading zeros in an ignored column.
    f << (header ? ",padded" : "," + std::string(1u << 20, '0') + "1.5") << "\n";
    header = false;
  }
  f.close();
  const RunResult r = run({"fit", "wide.csv", "--model", "seed", "--report", "report"}, dir.path());
  EXPECT_EQ(r.code, 0) << r.err.substr(0, 500);
  EXPECT_NE(r.out.find("12 rows"), std::string::npos) << r.out;
}

TEST(BadInput, ADirectoryGivenAsDataOrPressureTableIsRejected) {
  ScratchDir dir("directory");
  fs::create_directories(dir / "sub.csv");
  RunResult r = run({"fit", "sub.csv", "--model", "seed", "--report", "report"}, dir.path());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("sub.csv: is a directory"), std::string::npos) << r.err;
  r = run({"coefficients", "--pressure", "table:sub.csv"}, dir.path());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("sub.csv: is a directory"), std::string::npos) << r.err;
  r = run({"eval", "--model", "seed", "--param", "f=1", "--input", "sub.csv", "--output", "o.csv"},
          dir.path());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(listing(dir.path()), std::vector<std::string>{"sub.csv"});
}

// 10^7 rows (~250 MB, made here and deleted at the end): read completely in-process, and through
// the executable with a bad last row, which must be reported with its line number.
TEST(BadInputLarge, TenMillionRowsLoadAndABadLastRowIsFound) {
  ScratchDir dir("ten_million");
  const fs::path file = dir / "big.csv";
  constexpr std::size_t kRows = 10'000'000;
  {
    std::vector<std::string> pattern;
    for (int i = 0; i < 1000; ++i) {
      char row[96];
      std::snprintf(row, sizeof row, "%.3f,%d,%d,0.05,%d\n", (i - 500) * 0.002, i % 2 ? 2 : -2,
                    2000 + (i % 3) * 2000, 100 + i);
      pattern.emplace_back(row);
    }
    std::string chunk;
    for (const auto& row : pattern) chunk += row;
    std::FILE* f = std::fopen(file.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("v_x,omega,N,R,T_x\n", f);
    for (std::size_t i = 0; i < kRows / pattern.size(); ++i)
      ASSERT_EQ(std::fwrite(chunk.data(), 1, chunk.size(), f), chunk.size());
    ASSERT_EQ(std::fclose(f), 0);
  }
  {
    const frictionid::Dataset d = frictionid::load_dataset_csv(file.string());
    ASSERT_EQ(d.rows(), kRows);
    EXPECT_EQ(d.line.back(), kRows + 1);
    EXPECT_DOUBLE_EQ(d.v_x.back(), 499 * 0.002);
    EXPECT_EQ(d.N.back(), 2000 + (999 % 3) * 2000);
    EXPECT_EQ(d.value[0].back(), 1099);
  }
  {
    std::ofstream f(file, std::ios::binary | std::ios::app);
    f << "0.1,2,0,0.05,1\n";
  }
  const RunResult r =
      run({"fit", file.string(), "--model", "seed", "--report", (dir / "report")}, dir.path());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("big.csv:10000002:3: column 'N' has '0'"), std::string::npos) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u);
  EXPECT_FALSE(fs::exists(dir / "report"));
}

// ---- faults --------------------------------------------------------------------------------

TEST(BadInput, UnwritableReportOrOutputFailsWithExitOneAndLeavesNoTemporaryFile) {
  ScratchDir dir("unwritable");
  const std::string data = (kBadDir / "crlf_line_ends.csv").string();
  std::ofstream(dir / "a_file") << "x";
  RunResult r = run({"fit", data, "--model", "seed", "--report", "a_file"}, dir.path());
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("a_file"), std::string::npos) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  r = run({"fit", data, "--model", "seed", "--report", "a_file/report"}, dir.path());
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  fs::create_directories(dir / "out_dir");
  r = run({"eval", "--model", "seed", "--param", "f=0.8", "--input", data, "--output", "out_dir"},
          dir.path());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("out_dir"), std::string::npos) << r.err;
  r = run({"eval", "--model", "seed", "--param", "f=0.8", "--input", data, "--output",
           "missing_dir/out.csv"},
          dir.path());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"a_file", "out_dir"}));
}

// Ctrl-C (SIGINT) and SIGTERM during a long fit: exit 130, no report, no temporary file.
TEST(BadInput, InterruptedFitExits130WithoutAReport) {
  for (const int sig : {SIGINT, SIGTERM}) {
    ScratchDir dir("interrupt_" + std::to_string(sig));
    const std::string data = (fs::path(FRICTIONID_SOURCE_DIR) / "data/example_hertz.csv").string();
    const std::string report = (dir / "report");
    const std::string err = (dir / "stderr.txt");
    const pid_t pid = frictionid::test::start_frictionid(
        {"fit", data, "--model", "exact", "--global-evaluations", "1000000", "--starts", "20",
         "--progress", "--report", report},
        err);
    ASSERT_GT(pid, 0);
    // --progress writes to stderr once the fit runs, i.e. after the handler is installed.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    const bool started = frictionid::test::wait_for(
        [&] {
          std::error_code ec;
          const auto size = fs::file_size(err, ec);
          return !ec && size > 0;
        },
        deadline);
    ASSERT_TRUE(started) << "no progress output from the fit";
    const std::optional<int> status = frictionid::test::signal_and_wait(pid, sig, deadline);
    ASSERT_TRUE(status) << "the fit did not stop after signal " << sig;
    ASSERT_TRUE(WIFEXITED(*status)) << "killed by signal " << WTERMSIG(*status);
    EXPECT_EQ(WEXITSTATUS(*status), 130);
    EXPECT_NE(read_file(err).find("no report written"), std::string::npos);
    EXPECT_EQ(listing(dir.path()), std::vector<std::string>{"stderr.txt"});
  }
}

// ---- reproducibility -----------------------------------------------------------------------

// The same numbers spelt differently (line ends, BOM, quotes, spaces, blank lines, column order,
// extra columns, renamed columns, +signs and exponents) give byte-identical reports, and so does
// a second run on the same file.
TEST(BadInput, EquivalentSpellingsOfOneDatasetGiveByteIdenticalReports) {
  ScratchDir dir("reproducible");
  const std::vector<std::vector<std::string>> inputs = {
      {"quoted_fields.csv"},
      {"quoted_fields.csv"},
      {"crlf_line_ends.csv"},
      {"utf8_bom.csv"},
      {"utf8_bom_crlf.csv"},
      {"no_trailing_newline.csv"},
      {"blank_lines_between_rows.csv"},
      {"spaces_around_fields.csv"},
      {"extra_columns.csv"},
      {"permuted_columns.csv"},
      {"trailing_comma.csv"},
      {"latin1_header.csv"},
      {"plus_signs_and_exponents.csv"},
      {"renamed_columns.csv", "--columns", "v_x=speed,omega=spin"},
  };
  std::vector<std::string> reference_files;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string out = "r" + std::to_string(i);
    std::vector<std::string> args = {
        "fit", (kBadDir / inputs[i][0]).string(), "--model", "seed", "--report", out};
    args.insert(args.end(), inputs[i].begin() + 1, inputs[i].end());
    const RunResult r = run(args, dir.path());
    ASSERT_EQ(r.code, 0) << inputs[i][0] << ": " << r.err;
    const auto files = listing(dir / out);
    if (i == 0) {
      reference_files = files;
      ASSERT_FALSE(files.empty());
      continue;
    }
    EXPECT_EQ(files, reference_files) << inputs[i][0];
    // Each report names its own file and options (Traceability); everything else is the same.
    for (const auto& f : reference_files)
      EXPECT_TRUE(frictionid::test::without_traceability(read_file(dir.path() / out / f)) ==
                  frictionid::test::without_traceability(read_file(dir.path() / "r0" / f)))
          << inputs[i][0] << ": " << f << " differs";
  }
}

}  // namespace
}  // namespace bad_input_test
