// Names that attack what shows them, through the built executable (FRICTIONID_EXE): file names
// and values with terminal controls (ESC, BEL), a right-to-left override, spreadsheet formulas,
// control characters and Latin-1 bytes. Messages escape them, CSV files neutralise formulas,
// SVG and HTML reports stay well-formed, and an error message stays small whatever it quotes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"
#include "support/xml_well_formed.hpp"

namespace hostile_names_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;

// Retitles the terminal and clears it when printed raw.
const std::string kTerminalControls = "x\x1b]0;PWNED\a\x1b[2J";
// U+202E RIGHT-TO-LEFT OVERRIDE: reverses the text after it.
const std::string kRightToLeft =
    "r\xe2\x80\xae"
    "abc";

// One shell word.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

frictionid::test::CommandResult run(const std::string& args) {
  return frictionid::test::run_frictionid(args);
}

// Empty when every byte is printable ASCII or a line end, else the first other byte's offset.
std::string raw_bytes(const std::string& out) {
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto u = static_cast<unsigned char>(out[i]);
    if (!((u >= 0x20 && u < 0x7f) || u == '\n'))
      return "byte " + std::to_string(u) + " at " + std::to_string(i) + " in: " + out;
  }
  return "";
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A small dataset to fit, made once per test by `generate`.
std::string make_data(const ScratchDir& dir, const std::string& name = "good.csv") {
  const std::string path = dir / name;
  const auto g = run("generate --rows 200 --seed 1 --output " + quoted(path));
  EXPECT_EQ(g.code, 0) << g.out;
  return path;
}

const char* const kBadRows = "v_x,omega,N,R,T_x\n0.1,2,1000,0.05,abc\n";

TEST(TerminalEscapes, FitPrintsAFileNameWithTerminalControlsEscaped) {
  ScratchDir dir("escape_fit");
  const std::string bad = dir / (kTerminalControls + ".csv");
  write(bad, kBadRows);
  for (const std::string& data : {bad, dir / (kTerminalControls + "_missing.csv")}) {
    const auto r = run("fit " + quoted(data) + " --report " + quoted(dir / "r"));
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_EQ(raw_bytes(r.out), "");
    EXPECT_NE(r.out.find("x\\x1b]0;PWNED\\x07\\x1b[2J"), std::string::npos) << r.out;
  }
}

TEST(TerminalEscapes, BatchFailureLinesPrintLabelsAndBidiOverridesEscaped) {
  ScratchDir dir("escape_batch");
  const std::string in = dir / "in";
  fs::create_directories(in);
  make_data(dir, "in/" + kRightToLeft + ".csv");
  write(in + "/" + kTerminalControls + ".csv", kBadRows);
  write(in + "/" + kRightToLeft + "_bad.csv", kBadRows);
  const auto r = run("batch " + quoted(in) + " --report " + quoted(dir / "out"));
  EXPECT_EQ(r.code, 4) << r.out;
  EXPECT_EQ(raw_bytes(r.out), "");
  EXPECT_NE(r.out.find("run 'x\\x1b]0;PWNED\\x07\\x1b[2J' failed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("run 'r\\xe2\\x80\\xaeabc_bad' failed"), std::string::npos) << r.out;
}

TEST(TerminalEscapes, EverySubcommandPrintsHostilePathsAndValuesEscaped) {
  ScratchDir dir("escape_every_command");
  const std::string good = make_data(dir);
  const std::string missing = quoted(dir / (kTerminalControls + ".csv"));
  const std::string nowhere = quoted(dir / (kTerminalControls + "/sub/out.csv"));
  const std::string hostile_report = quoted(dir / (kTerminalControls + "_report"));
  const std::string table = quoted("table:" + dir / (kTerminalControls + ".table"));
  const std::vector<std::string> commands = {
      "fit " + missing + " --report " + quoted(dir / "r1"),
      "fit " + quoted(good) + " --report " + hostile_report,  // report: <path> on stdout
      "fit " + quoted(good) + " --report " + quoted(dir / "r2") + " --starts " +
          quoted(kTerminalControls),               // a parse error quoting the value
      "fit " + quoted(kTerminalControls) + " ''",  // "empty argument after ..."
      "compare " + missing + " --report " + quoted(dir / "r3"),
      "batch " + missing + " --report " + quoted(dir / "r4"),
      "eval --input " + missing + " --output " + quoted(dir / "e.csv"),
      "eval --input " + quoted(good) + " --output " + nowhere,
      "generate --rows 10 --output " + nowhere,
      "generate --rows 10 --output " + quoted(dir / (kTerminalControls + ".csv")),
      "coefficients --pressure " + table,
      "simulate --pressure " + table + " --inertia-ratio 0.5 --param f=0.3,kappa=1,h=0.1",
  };
  for (const auto& command : commands) {
    const auto r = run(command);
    EXPECT_EQ(raw_bytes(r.out), "") << command;
    EXPECT_NE(r.out.find("\\x1b"), std::string::npos) << command << "\n" << r.out;
  }
}

// summary.csv as lines.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t from = 0;
  for (auto eol = text.find('\n'); eol != std::string::npos; eol = text.find('\n', from)) {
    out.push_back(text.substr(from, eol - from));
    from = eol + 1;
  }
  return out;
}

TEST(FormulaCells, SummaryCsvNeutralisesLabelsFromFileNamesAndKeepsNumbers) {
  ScratchDir dir("formula_summary");
  const std::string in = dir / "in";
  fs::create_directories(in);
  const std::vector<std::string> labels = {"=1+2", "@SUM(A1)", "+cmd", "-2+3"};
  for (const auto& label : labels) make_data(dir, "in/" + label + ".csv");
  const auto r = run("batch " + quoted(in) + " --report " + quoted(dir / "out"));
  ASSERT_EQ(r.code, 0) << r.out;
  const auto lines = lines_of(read_file(dir.path() / "out" / "summary.csv"));
  ASSERT_EQ(lines.size(), labels.size() + 1);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    EXPECT_EQ(lines[k].front(), '\'') << lines[k];
    // The numbers that follow stay plain numbers.
    EXPECT_NE(lines[k].find(",ok,200,"), std::string::npos) << lines[k];
  }
  // summary.json keeps the labels as they are.
  const std::string json = read_file(dir.path() / "out" / "summary.json");
  EXPECT_NE(json.find("\"label\": \"=1+2\""), std::string::npos);
}

TEST(FormulaCells, EvalOutputNeutralisesTextColumnsAndKeepsNumbers) {
  ScratchDir dir("formula_eval");
  write(dir / "in.csv",
        "v_x,omega,N,R,note,=cmd\n"
        "0.1,2,1000,0.05,=1+2,-2.5\n"
        "0.2,2,1000,0.05,@SUM(A1),+3\n"
        "0.3,2,1000,0.05,-2+3,plain\n");
  const auto r = run("eval --param f=0.3,kappa=1,h=0.1 --input " + quoted(dir / "in.csv") +
                     " --output " + quoted(dir / "out.csv"));
  ASSERT_EQ(r.code, 0) << r.out;
  const auto lines = lines_of(read_file(dir.path() / "out.csv"));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_NE(lines[0].find(",note,'=cmd,"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find(",'=1+2,-2.5,"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find(",'@SUM(A1),+3,"), std::string::npos) << lines[2];
  EXPECT_NE(lines[3].find(",'-2+3,plain,"), std::string::npos) << lines[3];
}

TEST(WellFormedReports, ColorByValuesWithControlBytesAndLatin1GiveWellFormedSvgAndHtml) {
  ScratchDir dir("well_formed_reports");
  const std::string good = read_file(make_data(dir));
  const std::vector<std::string> values = {
      "a\x01"
      "b",
      "x\x0c"
      "y",
      "caf\xe9"};
  std::string text;
  std::size_t row = 0, from = 0;
  for (auto eol = good.find('\n'); eol != std::string::npos; eol = good.find('\n', from)) {
    text += good.substr(from, eol - from) + "," +
            (row == 0 ? std::string("surface") : values[row % values.size()]) + "\n";
    ++row;
    from = eol + 1;
  }
  write(dir / "colored.csv", text);
  const auto r = run("fit " + quoted(dir / "colored.csv") + " --color-by surface --report " +
                     quoted(dir / "rep"));
  ASSERT_EQ(r.code, 0) << r.out;
  std::size_t svgs = 0;
  for (const auto& e : fs::directory_iterator(dir.path() / "rep")) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() == ".svg") {
      ++svgs;
      EXPECT_EQ(frictionid::test::xml_problem(read_file(e.path())), "") << name;
    } else if (e.path().extension() == ".html") {
      EXPECT_EQ(frictionid::test::html_problem(read_file(e.path())), "") << name;
    }
  }
  EXPECT_GE(svgs, 2u);
  EXPECT_NE(read_file(dir.path() / "rep" / "collapse_T_x.svg").find("caf\\xe9"), std::string::npos);
}

TEST(BoundedMessages, AHeaderOfAMillionNamesGivesAMessageOfAFewHundredBytes) {
  ScratchDir dir("bounded_message");
  std::string header;
  for (int k = 0; k < 1'000'000; ++k) header += (k ? ",c" : "c") + std::to_string(k);
  write(dir / "wide.csv", header + "\n0\n");
  const auto r = run("fit " + quoted(dir / "wide.csv") + " --report " + quoted(dir / "r"));
  EXPECT_EQ(r.code, 2);
  EXPECT_LT(r.out.size(), 2000u) << r.out.substr(0, 3000);
  EXPECT_NE(r.out.find("wide.csv:1:"), std::string::npos) << r.out;  // where
  EXPECT_NE(r.out.find("more)"), std::string::npos) << r.out;        // how much is left out
}

}  // namespace
}  // namespace hostile_names_test
