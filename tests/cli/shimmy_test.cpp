// frictionid shimmy through the built executable (FRICTIONID_EXE, set by ctest): the JSON summary
// with its energy account, the trajectory CSV at k dt, the speed sweep's files, --from-report,
// and exit code 2 with one line and nothing written on bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_command.hpp"

namespace shimmy_test {
namespace {

namespace fs = std::filesystem;

using RunResult = frictionid::test::SplitResult;

RunResult run(const std::string& args) {
  return frictionid::test::run_frictionid_split(args);
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("frictionid_cli_shimmy_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

const std::string kWheel =
    "shimmy --model corrected --pressure uniform --param f=0.8 --N 1000 --R 0.05 --caster 0.1 "
    "--yaw-inertia 0.5 --yaw-stiffness 2000 --yaw-damping 1 --lateral-mass 20 "
    "--lateral-stiffness 2e5 --lateral-damping 50 --psi0 0.05";

TEST(CliShimmy, PrintsTheSummaryWithItsEnergyAccountAndWritesRowsAtMultiplesOfTheStep) {
  const fs::path d = fresh_dir("run");
  const fs::path csv = d / "traj.csv";
  const RunResult r =
      run(kWheel + " --speed 15 --duration 0.5 --output-step 0.002 --output " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"model", "parameters", "speed", "caster", "final", "outcome", "energy", "trajectory_rows"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"y", "y_dot", "psi", "psi_dot"}) EXPECT_TRUE(j["final"].contains(key));
  const auto& e = j["energy"];
  const double initial = e["initial"], final_ = e["final"], work = e["contact_work"],
               damping = e["damping_dissipated"], friction = e["friction_dissipated"];
  EXPECT_NEAR(final_ - initial, work - damping,
              1e-8 * std::max({initial, std::fabs(work), damping, friction}));
  EXPECT_GE(friction, 0.0);
  EXPECT_DOUBLE_EQ(initial, 0.5 * 2000 * 0.05 * 0.05);

  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t,y,y_dot,psi,psi_dot,u_y,T_y,M_z");
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line); ++rows) {
    const double t = std::stod(line.substr(0, line.find(',')));
    EXPECT_EQ(t, static_cast<double>(rows) * 0.002) << line;
  }
  EXPECT_EQ(rows, 251u);
  EXPECT_EQ(rows, j["trajectory_rows"].get<std::size_t>());
  fs::remove_all(d);
}

TEST(CliShimmy, TheIntegratorIsNamedAndItsImplicitStepsCounted) {
  // The creep of docs/physics.md §10.8 at low speed: the default switches to implicit steps,
  // --integrator explicit never does and takes far more steps to the same end.
  std::string creep = kWheel + " --speed 3 --duration 0.4";
  creep.replace(creep.find("--N 1000"), 8, "--N 2000");
  nlohmann::json j[2];
  int k = 0;
  for (const char* integrator : {"switching", "explicit"}) {
    const RunResult r = run(creep + " --integrator " + integrator);
    ASSERT_EQ(r.code, 0) << r.err;
    j[k] = nlohmann::json::parse(r.out);
    EXPECT_EQ(j[k]["integrator"], integrator);
    ++k;
  }
  // At 3 m/s the oscillation has died out by 0.4 s: not judged, and the summary says why.
  EXPECT_EQ(j[0]["outcome"]["kind"], "duration");
  EXPECT_TRUE(j[0]["outcome"].contains("detail"));
  EXPECT_GT(j[0]["implicit_steps"].get<long>(), 0);
  EXPECT_GT(j[0]["stiffness_switches"].get<long>(), 0);
  EXPECT_EQ(j[1]["implicit_steps"].get<long>(), 0);
  EXPECT_LT(5 * j[0]["steps"].get<long>(), j[1]["steps"].get<long>());
  // The closed-form model chatters at its friction limit (§10.8), so the two end within the
  // threshold's resolution of each other, not to the tolerance.
  const double y = j[1]["final"]["y"].get<double>();
  EXPECT_NEAR(j[0]["final"]["y"].get<double>(), y, 1e-3 * std::fabs(y));
}

TEST(CliShimmy, RigidStrutEndsAtRest) {
  const RunResult r = run(kWheel + " --lateral rigid --speed 10 --duration 1");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"]["kind"], "rest");
  EXPECT_EQ(j["final"]["phase"], "stick");
}

// A map's table takes seconds to minutes for a rough map (its build grows as the square of the
// cells): --progress counts its points on stderr and clears the line before the summary;
// without it (stderr is no terminal here) stderr stays empty. The summary is the same.
TEST(CliShimmy, AContactTableShowsItsPointsOnTheProgressLine) {
  const std::string map = std::string(FRICTIONID_SOURCE_DIR) + "/data/footprint_map.csv";
  const std::string args =
      "shimmy --model exact --param f=0.8 --N 1000 --R 0.05 --speed 20 --caster 0.1 "
      "--yaw-inertia 0.5 --yaw-stiffness 2000 --yaw-damping 2 --lateral-mass 20 "
      "--lateral-stiffness 2e5 --lateral-damping 100 --psi0 0.05 --duration 0.05 --contact map:" +
      map;
  const RunResult shown = run(args + " --progress");
  ASSERT_EQ(shown.code, 0) << shown.err;
  EXPECT_NE(shown.err.find("\rcontact table: 4096 points"), std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("\rcontact table: 8192 points"), std::string::npos) << shown.err;
  EXPECT_EQ(shown.err.size() - shown.err.rfind("\r\033[K"), 4u) << "the line is cleared last";
  EXPECT_EQ(shown.err.find('\n'), std::string::npos);
  const RunResult quiet = run(args);
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  auto j = nlohmann::json::parse(shown.out), k = nlohmann::json::parse(quiet.out);
  j.erase("wall_time_s");
  k.erase("wall_time_s");
  EXPECT_EQ(j, k);
}

TEST(CliShimmy, SpeedSweepWritesTheMapAndTheKeldyshBaselineRuns) {
  for (const char* law : {"friction", "nonholonomic"}) {
    const fs::path d = fresh_dir(law);
    const RunResult r = run(kWheel + " --duration 1 --contact-law " + law +
                            " --speed-sweep 5:30:3 --sweep-dir " + d.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["points"].size(), 3u);
    EXPECT_TRUE(j.contains("onsets"));
    // A run that is neither stable at rest nor shimmying says why it was not judged.
    for (const auto& p : j["points"]) {
      if (p["outcome"] != "duration") {
        EXPECT_FALSE(p.contains("detail")) << p;
        continue;
      }
      const std::string detail = p.at("detail");
      EXPECT_TRUE(detail == "holding" || detail == "decaying" || detail == "few_cycles" ||
                  detail == "irregular")
          << detail;
    }
    std::ifstream in(d / "shimmy.csv");
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "V,outcome,amplitude,frequency");
    std::size_t rows = 0;
    for (std::string line; std::getline(in, line);) ++rows;
    EXPECT_EQ(rows, 3u);
    std::ifstream html(d / "shimmy.html");
    const std::string page((std::istreambuf_iterator<char>(html)),
                           std::istreambuf_iterator<char>());
    EXPECT_NE(page.find("<svg"), std::string::npos);
    fs::remove_all(d);
  }
}

TEST(CliShimmy, TwoDimensionalSweepHasTheParameterColumn) {
  const fs::path d = fresh_dir("map");
  const RunResult r = run(kWheel +
                          " --duration 0.5 --speed-sweep 5:30:2 --sweep-param "
                          "yaw-damping:0:5:2 --sweep-dir " +
                          d.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(d / "shimmy.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "V,yaw-damping,outcome,amplitude,frequency");
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 4u);
  fs::remove_all(d);
}

std::string version() {
  const RunResult v = run("--version");
  return v.out.substr(v.out.find(' ') + 1, v.out.find('\n') - v.out.find(' ') - 1);
}

void write_report(const fs::path& path, const std::string& version) {
  std::ofstream(path) << R"({"model": "corrected", "pressure": "uniform", "parameters": {"f": )"
                      << R"({"value": 0.8}, "kappa": {"value": 1.0}, "h": {"value": 0.0}}, )"
                      << R"("provenance": {"version": ")" << version << R"("}})";
}

TEST(CliShimmy, FromReportTakesTheFittedModel) {
  const fs::path d = fresh_dir("report");
  write_report(d / "report.json", version());
  const RunResult r =
      run("shimmy --from-report " + (d / "report.json").string() + " --psi0 0.05 --duration 0.1");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "corrected");
  EXPECT_DOUBLE_EQ(j["parameters"]["f"].get<double>(), 0.8);
  fs::remove_all(d);
}

TEST(CliShimmy, BadInputExitsWithCodeTwoOneLineAndWritesNothing) {
  const fs::path d = fresh_dir("bad");
  write_report(d / "other.json", "0.0.0-elsewhere");
  write_report(d / "report.json", version());
  const std::string out = " --output " + (d / "traj.csv").string();
  const std::string sweep_dir = " --sweep-dir " + d.string();
  for (const std::string& args :
       {kWheel + " --N 0",
        kWheel + " --R -1",
        kWheel + " --speed 0",
        kWheel + " --duration 0",
        kWheel + " --yaw-inertia 0",
        kWheel + " --lateral-mass -2",
        kWheel + " --yaw-stiffness -1",
        kWheel + " --yaw-damping -1",
        kWheel + " --lateral-stiffness -1",
        kWheel + " --lateral-damping -0.5",
        kWheel + " --speed nan",
        kWheel + " --speed-sweep 30:5:3" + sweep_dir,
        kWheel + " --speed-sweep 5:30:1" + sweep_dir,
        kWheel + " --speed-sweep 5:5:3" + sweep_dir,
        kWheel + " --speed-sweep 5:30:3 --sweep-param yaw-damping:2:1:3" + sweep_dir,
        kWheel + " --speed-sweep 5:30:3 --sweep-param mass:1:2:3" + sweep_dir,
        "shimmy --from-report " + (d / "other.json").string(),
        "shimmy --from-report " + (d / "report.json").string() + " --param f=0.5",
        "shimmy --from-report " + (d / "missing.json").string(),
        kWheel + " --integrator implicit"}) {
    const RunResult r = run(args + out);
    EXPECT_EQ(r.code, 2) << args << ": " << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args << ": " << r.out;
    EXPECT_FALSE(fs::exists(d / "traj.csv")) << args;
    EXPECT_FALSE(fs::exists(d / "shimmy.csv")) << args;
  }
  fs::remove_all(d);
}

}  // namespace
}  // namespace shimmy_test
