// --contact SPOT through the built executable (FRICTIONID_EXE): the circle as it always was, an
// ellipse of aspect 1 as the circle, datasets generated on a spot and fitted back, the aspect q
// fitted with --free q, circle and ellipse side by side in compare, reports that name the spot
// and fingerprint a map, and every rejection with exit 2, one line and nothing written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/file_fingerprint.hpp"
#include "support/matched_digits.hpp"
#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"
#include "support/signalled_run.hpp"
#include "support/without_traceability.hpp"

namespace contact_spot_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::CommandResult;
using frictionid::test::matched_digits;
using frictionid::test::read_file;
using frictionid::test::run_frictionid;
using frictionid::test::run_frictionid_split;
using frictionid::test::ScratchDir;
using frictionid::test::SplitResult;
using frictionid::test::without_traceability;
using json = nlohmann::json;

const std::string kFootprint = std::string(FRICTIONID_SOURCE_DIR) + "/data/footprint_map.csv";

// A scratch directory named after the running test.
std::string test_name() {
  return ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

// Every file under dir, relative to it, with its bytes.
std::map<std::string, std::string> files_in(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = read_file(e.path());
  return out;
}

std::size_t lines_of(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

// A rejection: exit 2, one line "frictionid: error: ..." holding `says`, nothing left in `dir`.
void expect_rejected(const std::string& args, const std::string& says, const ScratchDir& dir) {
  SCOPED_TRACE(args);
  const auto before = files_in(dir.path());
  const CommandResult r = run_frictionid(args);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_EQ(r.out.rfind("frictionid: error: ", 0), 0u) << r.out;
  EXPECT_EQ(lines_of(r.out), 1u) << r.out;
  EXPECT_NE(r.out.find(says), std::string::npos) << r.out;
  EXPECT_EQ(files_in(dir.path()), before) << "something was written";
}

// A small noise-free dataset of the exact model on the circle.
std::string circle_data(const ScratchDir& dir) {
  const std::string data = dir / "circle.csv";
  const CommandResult g = run_frictionid(
      "generate --model exact --param f=0.8,kappa=1.2,h=0.1 --rows 80 --noise 0.01 --output " +
      data);
  EXPECT_EQ(g.code, 0) << g.out;
  return data;
}

TEST(ContactSpotCli, ContactCircleGivesTheBytesOfNoOption) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  // eval, one point and a file.
  const std::string point = "eval --param f=0.9,kappa=1.2,h=0.1 --vx 0.3 --omega 2 --R 0.1";
  EXPECT_EQ(run_frictionid(point + " --contact circle").out, run_frictionid(point).out);
  ASSERT_EQ(run_frictionid("eval --input " + data + " --output " + (dir / "a.csv")).code, 0);
  ASSERT_EQ(
      run_frictionid("eval --contact circle --input " + data + " --output " + (dir / "b.csv")).code,
      0);
  EXPECT_EQ(read_file(dir / "a.csv"), read_file(dir / "b.csv"));
  EXPECT_EQ(read_file(dir / "a.csv").find("M_tilt"), std::string::npos);
  // generate, data and truth.
  const std::string gen = "generate --param f=0.9,h=0.05 --rows 40 --noise 0.01 --seed 3";
  ASSERT_EQ(
      run_frictionid(gen + " --output " + (dir / "g1.csv") + " --truth " + (dir / "t1.json")).code,
      0);
  ASSERT_EQ(run_frictionid(gen + " --contact circle --output " + (dir / "g2.csv") + " --truth " +
                           (dir / "t2.json"))
                .code,
            0);
  EXPECT_EQ(read_file(dir / "g1.csv"), read_file(dir / "g2.csv"));
  EXPECT_EQ(read_file(dir / "t1.json"), read_file(dir / "t2.json"));
  EXPECT_EQ(read_file(dir / "g1.csv").find("M_tilt"), std::string::npos);
  // fit: every report file, but for the command line the traceability repeats.
  const std::string fit = "fit " + data + " --model exact --threads 1 --report ";
  ASSERT_EQ(run_frictionid(fit + (dir / "r1")).code, 0);
  ASSERT_EQ(run_frictionid(fit + (dir / "r2") + " --contact circle").code, 0);
  const auto r1 = files_in(dir / "r1"), r2 = files_in(dir / "r2");
  ASSERT_EQ(r1.size(), r2.size());
  for (const auto& [name, bytes] : r1)
    EXPECT_EQ(without_traceability(r2.at(name)), without_traceability(bytes)) << name;
  EXPECT_FALSE(json::parse(r1.at("report.json")).contains("contact"));
  // compare: the same, models under their own names.
  const std::string cmp = "compare " + data + " --models seed,exact --threads 1 --report ";
  ASSERT_EQ(run_frictionid(cmp + (dir / "c1")).code, 0);
  ASSERT_EQ(run_frictionid(cmp + (dir / "c2") + " --contact circle").code, 0);
  const auto c1 = files_in(dir / "c1"), c2 = files_in(dir / "c2");
  ASSERT_EQ(c1.size(), c2.size());
  for (const auto& [name, bytes] : c1)
    EXPECT_EQ(without_traceability(c2.at(name)), without_traceability(bytes)) << name;
}

TEST(ContactSpotCli, EvalOnAnEllipseOfAspectOneEqualsTheCircle) {
  for (const char* kinematics : {"--vx 0.3 --omega 2", "--vx -0.02 --vy 0.05 --omega -3",
                                 "--vx 0.4 --omega 0", "--vx 0 --omega 1.5"}) {
    SCOPED_TRACE(kinematics);
    const std::string point =
        std::string("eval --param f=0.9,kappa=1.3,h=0.2 --R 0.05 --N 2000 ") + kinematics;
    const CommandResult circle = run_frictionid(point);
    const CommandResult ellipse = run_frictionid(point + " --contact ellipse:1");
    ASSERT_EQ(circle.code, 0) << circle.out;
    ASSERT_EQ(ellipse.code, 0) << ellipse.out;
    const json c = json::parse(circle.out), e = json::parse(ellipse.out);
    EXPECT_FALSE(c.contains("M_tilt"));
    EXPECT_NEAR(e["M_tilt"].get<double>(), 0.0, 1e-12 * 2000 * 0.05);
    for (const char* k : {"T_x", "T_y", "M_z", "M_roll", "N"}) {
      const double scale = (k[0] == 'M' ? 0.05 : 1.0) * 2000.0;  // f N, f N R
      EXPECT_NEAR(e[k].get<double>(), c[k].get<double>(), 1e-12 * scale) << k;
    }
  }
}

TEST(ContactSpotCli, EvalAppendsMTiltOnASpotOtherThanTheCircle) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  ASSERT_EQ(run_frictionid("eval --contact rect:0.5 --param h_y=0.1 --input " + data +
                           " --output " + (dir / "out.csv"))
                .code,
            0);
  const std::string out = read_file(dir / "out.csv");
  const std::string header = out.substr(0, out.find('\n'));
  // The input has no M_tilt column, so its prediction takes the plain name.
  const std::string tail = ",M_roll_model,M_tilt,N_model";
  ASSERT_GE(header.size(), tail.size());
  EXPECT_EQ(header.substr(header.size() - tail.size()), tail) << header;
}

TEST(ContactSpotCli, AGeneratedEllipseDatasetWithMTiltRefitsToEightDigits) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = dir / "ellipse.csv", truth = dir / "truth.json";
  const CommandResult g = run_frictionid(
      "generate --model exact --contact ellipse:0.7 --param f=0.9,kappa=1.15,h=0.08,h_y=0.05 "
      "--rows 150 --slip-angles 0,40 --output " +
      data + " --truth " + truth);
  ASSERT_EQ(g.code, 0) << g.out;
  const std::string csv = read_file(data);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "v_x,v_y,omega,N,R,T_x,T_y,M_z,M_roll,M_tilt");
  EXPECT_EQ(json::parse(read_file(truth))["contact"], "ellipse:0.7");
  const CommandResult f = run_frictionid("fit " + data +
                                         " --model exact --contact ellipse:0.7 --threads 2 "
                                         "--report " +
                                         (dir / "report"));
  ASSERT_EQ(f.code, 0) << f.out;
  const json r = json::parse(read_file(dir.path() / "report" / "report.json"));
  EXPECT_EQ(r["contact"], "ellipse:0.7");
  EXPECT_EQ(r["channels"], json::array({"T_x", "T_y", "M_z", "M_roll", "M_tilt"}));
  const std::map<std::string, double> want = {
      {"f", 0.9}, {"kappa", 1.15}, {"h", 0.08}, {"h_y", 0.05}};
  for (const auto& [name, value] : want)
    EXPECT_GE(matched_digits(r["parameters"][name]["value"].get<double>(), value), 8.0) << name;
  EXPECT_TRUE(r["parameters"]["q"]["fixed"].get<bool>());
  EXPECT_EQ(r["parameters"]["q"]["value"].get<double>(), 0.7);
}

TEST(ContactSpotCli, FreeQRecoversTheAspect) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = dir / "rect.csv";
  ASSERT_EQ(run_frictionid("generate --model exact --contact rect:0.7 "
                           "--param f=0.9,kappa=1.15,h=0.08,h_y=0.05 --rows 100 --output " +
                           data)
                .code,
            0);
  // From the spot's Q = 0.6, the local fit alone (the global stage integrates afresh for every
  // q it tries).
  const CommandResult f = run_frictionid("fit " + data +
                                         " --model exact --contact rect:0.6 --free q --no-global "
                                         "--threads 2 --report " +
                                         (dir / "report"));
  ASSERT_EQ(f.code, 0) << f.out;
  const json r = json::parse(read_file(dir.path() / "report" / "report.json"));
  EXPECT_FALSE(r["parameters"]["q"]["fixed"].get<bool>());
  EXPECT_GE(matched_digits(r["parameters"]["q"]["value"].get<double>(), 0.7), 8.0);
  EXPECT_GE(matched_digits(r["parameters"]["h_y"]["value"].get<double>(), 0.05), 8.0);
}

TEST(ContactSpotCli, CompareFitsCircleAndEllipseSideBySide) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = dir / "ellipse.csv";
  ASSERT_EQ(run_frictionid("generate --model exact --contact ellipse:0.7 "
                           "--param f=0.9,kappa=1.15,h=0.08 --rows 120 --noise 0.005 --output " +
                           data)
                .code,
            0);
  const CommandResult c = run_frictionid("compare " + data +
                                         " --models exact --contact circle,ellipse:0.7 "
                                         "--threads 2 --report " +
                                         (dir / "cmp"));
  ASSERT_EQ(c.code, 0) << c.out;
  EXPECT_NE(c.out.find("preferred by AIC: exact@ellipse:0.7"), std::string::npos) << c.out;
  const json j = json::parse(read_file(dir.path() / "cmp" / "compare.json"));
  ASSERT_EQ(j["models"].size(), 2u);
  EXPECT_EQ(j["models"][0]["model"], "exact");
  EXPECT_FALSE(j["models"][0].contains("contact"));
  EXPECT_EQ(j["models"][1]["contact"], "ellipse:0.7");
  EXPECT_GT(j["models"][1]["delta_aic"].get<double>(), -1.0);
  EXPECT_EQ(j["preferred_by_aic"], "exact@ellipse:0.7");
  EXPECT_EQ(j["preferred_by_bic"], "exact@ellipse:0.7");
  EXPECT_GT(j["models"][0]["delta_aic"].get<double>(), 10.0);
  EXPECT_EQ(j["provenance"]["options"]["contacts"], json::array({"circle", "ellipse:0.7"}));
  EXPECT_TRUE(fs::exists(dir.path() / "cmp" / "exact" / "report.json"));
  const json own = json::parse(read_file(dir.path() / "cmp" / "exact@ellipse_0.7" / "report.json"));
  EXPECT_EQ(own["contact"], "ellipse:0.7");
  EXPECT_NE(read_file(dir.path() / "cmp" / "compare.md").find("| exact@ellipse:0.7 |"),
            std::string::npos);
}

// `rows` rows of the exact model on the footprint map (f = 0.8, h = 0.05, h_y = 0.03) written to
// `data`: the exit code.
int generate_on_footprint(const std::string& data, int rows) {
  return run_frictionid("generate --model exact --contact map:" + kFootprint +
                        " --param f=0.8,h=0.05,h_y=0.03 --rows " + std::to_string(rows) +
                        " --output " + data)
      .code;
}

TEST(ContactSpotCli, AFitOnAMapNamesItAndFingerprintsItsFile) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = dir / "map.csv";
  ASSERT_EQ(generate_on_footprint(data, 100), 0);
  const CommandResult f =
      run_frictionid("fit " + data + " --model exact --contact map:" + kFootprint +
                     " --threads 2 --report " + (dir / "report"));
  ASSERT_EQ(f.code, 0) << f.out;
  const json r = json::parse(read_file(dir.path() / "report" / "report.json"));
  EXPECT_EQ(r["pressure"], "map");
  EXPECT_EQ(r["contact"], "map:" + kFootprint);
  EXPECT_GE(matched_digits(r["parameters"]["h_y"]["value"].get<double>(), 0.03), 8.0);
  const auto& inputs = r["provenance"]["inputs"];
  ASSERT_EQ(inputs.size(), 2u);
  EXPECT_EQ(inputs[1]["path"], kFootprint);
  EXPECT_EQ(inputs[1]["sha256"], frictionid::fingerprint_file(kFootprint).sha256);
  EXPECT_NE(read_file(dir.path() / "report" / "report.md")
                .find("# frictionid fit: model exact, pressure map, contact map:"),
            std::string::npos);
}

// Before the search a fit on a map computes its rows' integrals (~7 us a row on the footprint,
// ~40 us on a rough 30 x 30 grid): --progress shows the rows done on its line, then the search;
// the report is the one written without it.
TEST(ContactSpotCli, AFitOnAMapShowsItsRowsIntegralsOnTheProgressLine) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = dir / "map.csv";
  ASSERT_EQ(generate_on_footprint(data, 3000), 0);
  const std::string fit = "fit " + data + " --model exact --contact map:" + kFootprint +
                          " --threads 1 --global-evaluations 300 --report ";
  const SplitResult shown = run_frictionid_split(fit + (dir / "shown") + " --progress");
  ASSERT_EQ(shown.code, 0) << shown.err;
  const std::size_t rows = shown.err.find("\rfrictionid: contact integrals 1024/3000 rows");
  ASSERT_NE(rows, std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("\rfrictionid: contact integrals 2048/3000 rows"), std::string::npos);
  const std::size_t search = shown.err.find("\rfrictionid: global search");
  ASSERT_NE(search, std::string::npos) << shown.err;
  EXPECT_LT(rows, search);
  ASSERT_EQ(run_frictionid(fit + (dir / "quiet")).code, 0);
  EXPECT_EQ(without_traceability(read_file(dir.path() / "shown" / "report.json")),
            without_traceability(read_file(dir.path() / "quiet" / "report.json")));
}

TEST(ContactSpotCli, EvalAndGenerateOnAMapWriteTheSameBytesOnOneAndTwoThreads) {
  const ScratchDir dir("contact_" + test_name());
  const std::string model =
      " --model exact --contact map:" + kFootprint + " --param f=0.8,kappa=1.1,h=0.05,h_y=0.03 ";
  for (const char* threads : {"1", "2"}) {
    const std::string t = threads;
    const std::string design = "--rows 200 --noise 0.01 --slip-angles 0,7,-4 --threads " + t;
    ASSERT_EQ(
        run_frictionid("generate" + model + design + " --output " + (dir / ("g" + t + ".csv")))
            .code,
        0);
    ASSERT_EQ(run_frictionid("eval" + model + "--threads " + t + " --input " + (dir / "g1.csv") +
                             " --output " + (dir / ("e" + t + ".csv")))
                  .code,
              0);
  }
  EXPECT_EQ(read_file(dir / "g1.csv"), read_file(dir / "g2.csv"));
  const std::string one = read_file(dir / "e1.csv");
  EXPECT_EQ(one, read_file(dir / "e2.csv"));
  EXPECT_EQ(lines_of(one), 201u);
}

TEST(ContactSpotCli, EvalShowsTheModelsRowsOnTheProgressLine) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = dir / "map.csv";
  ASSERT_EQ(generate_on_footprint(data, 3000), 0);
  const std::string eval = "eval --model exact --contact map:" + kFootprint +
                           " --param f=0.8,h_y=0.03 --threads 1 --input " + data + " --output ";
  const SplitResult shown = run_frictionid_split(eval + (dir / "shown.csv") + " --progress");
  ASSERT_EQ(shown.code, 0) << shown.err;
  const std::size_t first = shown.err.find("\rfrictionid: model 1024/3000 rows");
  ASSERT_NE(first, std::string::npos) << shown.err;
  EXPECT_GT(shown.err.find("\rfrictionid: model 2048/3000 rows"), first) << shown.err;
  ASSERT_EQ(run_frictionid(eval + (dir / "quiet.csv")).code, 0);
  EXPECT_EQ(read_file(dir / "shown.csv"), read_file(dir / "quiet.csv"));
}

// Ctrl-C while generate runs the model over the rows of a 24 x 24 map (integrated one by one: a
// table would need more points than the rows; 1.3 s of work on two cores, 0.03 s to the first
// progress line): exit 130, a line that says the file was not written, and nothing written.
TEST(ContactSpotCli, GenerateStopsOnCtrlCWithNothingWritten) {
  const ScratchDir dir("contact_" + test_name());
  const std::string map = dir / "map24.csv", out = dir / "out.csv", err = dir / "stderr.txt";
  {
    std::ofstream m(map);
    m << "x,y,sigma0\n";
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i) {
        const double x = -1.0 + i / 11.5, y = -0.8 + j * 1.6 / 23.0;
        m << x << ',' << y << ',' << std::max(0.0, (1.0 - x * x) * (1.0 - y * y / 0.64)) << '\n';
      }
  }
  const pid_t pid =
      frictionid::test::start_frictionid({"generate", "--model", "exact", "--contact", "map:" + map,
                                          "--rows", "50000", "--progress", "--output", out},
                                         err);
  ASSERT_GT(pid, 0);
  // The progress line shows the model's rows once they run, after the handler is installed.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  ASSERT_TRUE(frictionid::test::wait_for(
      [&] { return read_file(err).find("frictionid: model ") != std::string::npos; }, deadline))
      << read_file(err);
  const std::optional<int> status = frictionid::test::signal_and_wait(pid, SIGINT, deadline);
  ASSERT_TRUE(status) << "generate did not stop after SIGINT";
  ASSERT_TRUE(WIFEXITED(*status)) << "killed by signal " << WTERMSIG(*status);
  EXPECT_EQ(WEXITSTATUS(*status), 130);
  EXPECT_NE(read_file(err).find("frictionid: interrupted; " + out + " not written"),
            std::string::npos)
      << read_file(err);
  EXPECT_EQ(files_in(dir.path()).size(), 2u);  // the map and stderr.txt
}

TEST(ContactSpotCli, CoefficientsOfASpotAreItsSlopeMatchedOnes) {
  const CommandResult j = run_frictionid("coefficients --contact ellipse:0.6 --kappa 1.2");
  ASSERT_EQ(j.code, 0) << j.out;
  const json c = json::parse(j.out);
  EXPECT_EQ(c["contact"], "ellipse:0.6");
  for (const char* k : {"a", "b", "m", "p0", "b_tilde"}) {
    ASSERT_TRUE(c.contains(k)) << k;
    EXPECT_GT(c[k].get<double>(), 0.0) << k;
  }
  EXPECT_NEAR(c["b_tilde"].get<double>(),
              c["p0"].get<double>() * c["p0"].get<double>() * c["b"].get<double>(), 1e-12);
  const CommandResult table =
      run_frictionid("coefficients --contact map:" + kFootprint + " --format table");
  ASSERT_EQ(table.code, 0) << table.out;
  EXPECT_NE(table.out.find("contact spot   map:"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("b_tilde"), std::string::npos) << table.out;
}

TEST(ContactSpotCli, SimulateOnAnEllipseOfAspectOneStopsAsOnTheCircle) {
  const std::string body =
      "simulate --param f=0.3 --inertia-ratio 0.5 --v0 1 --omega0 10 --R 0.1 --tol 1e-9";
  const CommandResult circle = run_frictionid(body);
  const CommandResult ellipse = run_frictionid(body + " --contact ellipse:1");
  ASSERT_EQ(circle.code, 0) << circle.out;
  ASSERT_EQ(ellipse.code, 0) << ellipse.out;
  const json c = json::parse(circle.out), e = json::parse(ellipse.out);
  EXPECT_EQ(e["contact"], "ellipse:1");
  EXPECT_NEAR(e["eps_final"].get<double>(), c["eps_final"].get<double>(), 1e-6);
  EXPECT_NEAR(e["t_stop_slide"].get<double>(), c["t_stop_slide"].get<double>(), 1e-6);
}

TEST(ContactSpotCli, BatchRunsTakeTheirSpotFromTheCommandLineOrTheManifest) {
  const ScratchDir dir("contact_" + test_name());
  ASSERT_EQ(run_frictionid("generate --model exact --contact ellipse:0.7 "
                           "--param f=0.9,h=0.05 --rows 60 --output " +
                           (dir / "a.csv"))
                .code,
            0);
  ASSERT_EQ(run_frictionid("generate --model exact --param f=0.9,h=0.05 --rows 60 --output " +
                           (dir / "b.csv"))
                .code,
            0);
  std::ofstream(dir / "runs.csv") << "path,contact\na.csv,ellipse:0.7\nb.csv,\n";
  const CommandResult b =
      run_frictionid("batch " + (dir / "runs.csv") +
                     " --model exact --jobs 1 --threads 1 --report " + (dir / "out"));
  ASSERT_EQ(b.code, 0) << b.out;
  const json a = json::parse(read_file(dir.path() / "out" / "runs" / "a" / "report.json"));
  const json c = json::parse(read_file(dir.path() / "out" / "runs" / "b" / "report.json"));
  EXPECT_EQ(a["contact"], "ellipse:0.7");
  EXPECT_GE(matched_digits(a["parameters"]["h"]["value"].get<double>(), 0.05), 8.0);
  EXPECT_FALSE(c.contains("contact"));
  const std::string summary = read_file(dir.path() / "out" / "summary.csv");
  EXPECT_NE(summary.find(",contact"), std::string::npos) << summary;  // a covariate
}

TEST(ContactSpotCli, AnAspectOutOfRangeOrNotANumberIsRejected) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  for (const char* spot : {"ellipse:0", "ellipse:-1", "rect:4.5"})
    expect_rejected("fit " + data + " --model exact --contact " + spot + " --report " + (dir / "r"),
                    "expected 0 < Q <= 4", dir);
  for (const char* spot : {"ellipse:abc", "rect:", "ellipse:nan", "square:1"})
    expect_rejected("eval --vx 1 --omega 1 --contact " + std::string(spot),
                    "expected circle, ellipse:Q, rect:Q (0 < Q <= 4) or map:FILE", dir);
}

TEST(ContactSpotCli, FreeQOnTheCircleOrAMapIsRejected) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  expect_rejected("fit " + data + " --model exact --free q --report " + (dir / "r"),
                  "--free q: q is the aspect of --contact ellipse:Q or rect:Q", dir);
  expect_rejected("fit " + data + " --model exact --contact map:" + kFootprint +
                      " --free q --report " + (dir / "r"),
                  "a pressure map has none to fit", dir);
}

TEST(ContactSpotCli, ATiltThatMakesThePressureNegativeIsRejectedNamingThePoint) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  expect_rejected("eval --vx 1 --omega 1 --contact ellipse:0.7 --param h=0.9,h_y=1",
                  "h = 0.9, h_y = 1 make the pressure 1 + h x + h_y y negative at (x, y) = (", dir);
  expect_rejected("generate --contact rect:0.5 --param h=0.6,h_y=1 --output " + (dir / "g.csv"),
                  "negative at (x, y) = (-1, -0.5) of the contact spot rect:0.5", dir);
  expect_rejected("fit " + data + " --model exact --contact ellipse:0.7 --fix h=0.9,h_y=0.9 " +
                      "--report " + (dir / "r"),
                  "--fix: h = 0.9, h_y = 0.9", dir);
}

TEST(ContactSpotCli, AnApproximantOnASpotOtherThanTheCircleIsRejected) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  expect_rejected("fit " + data + " --model seed --contact ellipse:0.7 --report " + (dir / "r"),
                  "a non-circular contact needs --model exact", dir);
  expect_rejected("eval --model corrected --vx 1 --omega 1 --contact rect:1",
                  "a non-circular contact needs --model exact", dir);
  expect_rejected("compare " + data + " --contact circle,ellipse:0.7 --report " + (dir / "r"),
                  "compare spots with --models exact", dir);
}

TEST(ContactSpotCli, PressureWithAMapIsRejected) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  expect_rejected("fit " + data + " --model exact --pressure hertz --contact map:" + kFootprint +
                      " --report " + (dir / "r"),
                  "--pressure: a pressure map (--contact map:", dir);
  expect_rejected("eval --vx 1 --omega 1 --pressure uniform --contact map:" + kFootprint,
                  "leave --pressure out with map:FILE", dir);
}

TEST(ContactSpotCli, ABadMapFileIsNamedAtItsLineAndColumnAndNothingIsWritten) {
  const ScratchDir dir("contact_" + test_name());
  const std::string data = circle_data(dir);
  const std::string map = dir / "ragged.csv";
  std::ofstream(map) << "x,y,sigma0\n0,0,1\n1,0,1\n0,1,1\n";
  expect_rejected(
      "fit " + data + " --model exact --contact map:" + map + " --report " + (dir / "r"),
      map + ":4:1: the grid has no point (x, y) = (1, 1)", dir);
}

}  // namespace
}  // namespace contact_spot_test
