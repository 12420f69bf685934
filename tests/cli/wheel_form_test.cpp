// Rig data through the built executable (FRICTIONID_EXE): the same rows written in the native
// form, in the wheel form (ISO axes, units in the header), in the wheel form (SAE axes) and as
// TYDEX give the same fitted parameters; the report says which form it read and why; every bad
// wheel-form input exits with code 2 naming file:line:column and writes nothing; a standing wheel
// needs h fixed; batch fits a directory of .tdx files and keeps columns with --keep.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

namespace wheel_form_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::ScratchDir;

constexpr double kPi = 3.141592653589793;

frictionid::test::CommandResult run(const std::string& args) {
  return frictionid::test::run_frictionid(args);
}

std::string g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// A native row of `frictionid generate` and the rig row that gives it (docs/physics.md §1.1):
// V_x = 20 m/s and r_e = 0.3 m; alpha from v_y, the slip ratio from v_x, the inclination from
// omega (psi_dot = 0).
struct RigRow {
  double V, alpha, slip, re, gamma, Omega;
  double Fz, Fx, Fy, Mz, My;
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',')
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

std::vector<RigRow> rig_rows(const std::string& native_csv) {
  std::istringstream in(native_csv);
  std::string line;
  std::getline(in, line);
  const auto header = split(line);
  std::map<std::string, std::size_t> col;
  for (std::size_t k = 0; k < header.size(); ++k) col[header[k]] = k;
  std::vector<RigRow> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = split(line);
    const auto at = [&](const char* name) { return std::stod(f.at(col.at(name))); };
    RigRow r;
    const double Vx = 20.0, vy = at("v_y");
    r.re = 0.3;
    r.V = std::hypot(Vx, vy);
    r.alpha = std::atan2(-vy, Vx);
    r.slip = -at("v_x") / Vx;
    r.Omega = Vx * (1.0 + r.slip) / r.re;
    r.gamma = std::asin(-at("omega") / r.Omega);
    r.Fz = at("N");
    r.Fx = -at("T_x");
    r.Fy = -at("T_y");
    r.Mz = -at("M_z");
    r.My = -at("M_roll");
    rows.push_back(r);
  }
  return rows;
}

// The wheel form with units in the header; SAE turns y and z over.
std::string wheel_csv(const std::vector<RigRow>& rows, bool sae) {
  const double s = sae ? -1.0 : 1.0;
  std::string out =
      "V[km/h],alpha[deg],slip_ratio,r_e[mm],gamma[deg],R[mm],Fz[kN],Fx[N],Fy[N],Mz[N*m],"
      "My[N*m],tire\n";
  for (const RigRow& r : rows)
    out += g17(r.V * 3.6) + "," + g17(r.alpha * 180.0 / kPi) + "," + g17(r.slip) + "," +
           g17(r.re * 1000.0) + "," + g17(s * r.gamma * 180.0 / kPi) + ",50," +
           g17(s * r.Fz / 1000.0) + "," + g17(r.Fx) + "," + g17(s * r.Fy) + "," + g17(s * r.Mz) +
           "," + g17(s * r.My) + ",T1\n";
  return out;
}

// A TYDEX file (published layout), angles in ISO 8855's signs, SI units but for the speed.
std::string tydex(const std::vector<RigRow>& rows) {
  const auto line = [](const char* name, const char* unit) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%-10s%-30s%-10s%-10s%-10s%s\n", name, "channel", unit, "1", "0",
                  "0");
    return std::string(buf);
  };
  std::string out = "**HEADER\nRELEASE   Release of TYDEX-Format                 1.3\n";
  out += "**MEASURCHANNELS\n" + line("TRAJVELW", "km/h") + line("SLIPANGL", "rad") +
         line("LONGSLIP", "-") + line("WHROTSPD", "rad/s") + line("INCLANGL", "rad") +
         line("FZW", "N") + line("FXW", "N") + line("FYW", "N") + line("MZW", "Nm") +
         line("MYW", "Nm") + "**MEASURDATA\n";
  for (const RigRow& r : rows)
    out += g17(r.V * 3.6) + " " + g17(-r.alpha) + " " + g17(r.slip) + " " + g17(r.Omega) + " " +
           g17(-r.gamma) + " " + g17(r.Fz) + " " + g17(r.Fx) + " " + g17(r.Fy) + " " + g17(r.Mz) +
           " " + g17(r.My) + "\n";
  return out + "**END\n";
}

nlohmann::json report(const std::string& dir) {
  return nlohmann::json::parse(read_file(fs::path(dir) / "report.json"));
}

TEST(WheelFormCli, TheSameRowsInFourFormsGiveTheSameFit) {
  ScratchDir d("wheel_cli_four_forms");
  const auto gen =
      run("generate --model seed --param f=0.8,kappa=1.2,h=0.06 --rows 160 --noise "
          "0.01 --seed 5 --slip-angles 0,20,-35 --forward-only --output " +
          d / "native.csv");
  ASSERT_EQ(gen.code, 0) << gen.out;
  const auto rows = rig_rows(read_file(d / "native.csv"));
  ASSERT_EQ(rows.size(), 160u);
  std::ofstream(d / "iso.csv") << wheel_csv(rows, false);
  std::ofstream(d / "sae.csv") << wheel_csv(rows, true);
  std::ofstream(d / "rig.tdx") << tydex(rows);
  const std::string fit = " --model seed --seed 3 --starts 2 --global-evaluations 400 --report ";
  ASSERT_EQ(run("fit " + d / "native.csv" + fit + d / "r_native").code, 0);
  ASSERT_EQ(run("fit " + d / "iso.csv" + fit + d / "r_iso").code, 0);
  ASSERT_EQ(run("fit " + d / "sae.csv --axes sae" + fit + d / "r_sae").code, 0);
  ASSERT_EQ(run("fit " + d / "rig.tdx --contact-radius 0.05" + fit + d / "r_tdx").code, 0);
  const auto native = report(d / "r_native");
  for (const char* form : {"r_iso", "r_sae", "r_tdx"}) {
    const auto other = report(d / form);
    for (const auto& [name, p] : native.at("parameters").items()) {
      const double a = p.at("value").get<double>();
      const double b = other.at("parameters").at(name).at("value").get<double>();
      EXPECT_LE(std::abs(a - b), 1e-9 * std::abs(a))
          << form << " " << name << ": " << g17(a) << " vs " << g17(b);
    }
  }
  // The ISO and SAE files read to bit-identical rows: the same report, but for its provenance.
  auto iso = report(d / "r_iso"), sae = report(d / "r_sae");
  iso.erase("provenance");
  sae.erase("provenance");
  EXPECT_EQ(iso.dump(), sae.dump());
}

TEST(WheelFormCli, TheReportSaysWhichFormItReadAndWhy) {
  ScratchDir d("wheel_cli_report");
  std::ofstream(d / "w.csv") << "V[km/h],alpha[deg],slip_ratio,r_e,gamma,R,Fz[kN],Fx,Fy\n"
                                "36,2,0.01,0.3,0,0.05,-4,-100,-200\n"
                                "36,-2,-0.02,0.3,0.02,0.05,-4,120,210\n"
                                "36,1,0.05,0.3,-0.02,0.05,-6,-300,-5\n";
  const auto r = run("fit " + d / "w.csv" + " --axes sae --model seed --no-global --fix " +
                     "kappa=1,a=2,b=9,m=3 --report " + d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto form = report(d / "out").at("provenance").at("data_form");
  EXPECT_EQ(form.at("form"), "wheel");
  EXPECT_EQ(form.at("axes"), "sae");
  EXPECT_EQ(form.at("reason"), "auto: the header has V and alpha and no v_x");
  EXPECT_EQ(form.at("units").at("Fz[kN]"), "kN");
  EXPECT_NE(read_file(fs::path(d / "out") / "report.md").find("SAE J670 axes"), std::string::npos);
}

// Each bad wheel-form input: exit code 2, one line naming file:line:column and why, no report.
TEST(WheelFormCli, BadWheelFormInputExitsTwoAtItsPlaceAndWritesNothing) {
  ScratchDir d("wheel_cli_bad");
  const std::string header = "V,alpha[deg],slip_ratio,r_e,gamma,R,Fz,Fy\n";
  struct Case {
    std::string name, csv, options, where, why;
  };
  const std::vector<Case> cases = {
      {"v0", header + "10,1,0,0.3,0,0.05,4000,1\n0,1,0.1,0.3,0,0.05,4000,1\n", "",
       ":3:3:", "V = 0"},
      {"re", header + "10,1,0,-0.3,0,0.05,4000,1\n", "", ":2:4:", "effective rolling radius"},
      {"alpha", header + "10,90,0,0.3,0,0.05,4000,1\n", "", ":2:2:", "between -90 and 90"},
      {"fz_iso", header + "10,1,0,0.3,0,0.05,-4000,1\n", "", ":2:7:", "Fz > 0 in ISO"},
      {"fz_sae", header + "10,1,0,0.3,0,0.05,4000,1\n", " --axes sae", ":2:7:", "Fz < 0 in SAE"},
      {"unit", "V,alpha[kN],slip_ratio,r_e,gamma,R,Fz,Fy\n10,1,0,0.3,0,0.05,4000,1\n", "",
       ":1:2:", "expected one of rad, deg"},
      {"unknown", "V[knots],alpha,slip_ratio,r_e,gamma,R,Fz,Fy\n10,1,0,0.3,0,0.05,4000,1\n", "",
       ":1:1:", "m/s, km/h, mph"},
  };
  for (const Case& c : cases) {
    const std::string path = d / (c.name + ".csv");
    std::ofstream(path) << c.csv;
    const std::string out = d / ("out_" + c.name);
    const auto r = run("fit " + path + c.options + " --model seed --report " + out);
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.out;
    EXPECT_NE(r.out.find(path + c.where), std::string::npos) << c.name << ": " << r.out;
    EXPECT_NE(r.out.find(c.why), std::string::npos) << c.name << ": " << r.out;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
}

TEST(WheelFormCli, AStandingWheelNeedsTheTiltFixedAtZero) {
  ScratchDir d("wheel_cli_standing");
  std::ofstream(d / "w.csv") << "V,alpha,omega_w,r_e,gamma,R,Fz,Fx\n"
                                "1,0,2,0.3,0,0.05,4000,-300\n"
                                "0,0,0,0.3,0,0.05,4000,0\n"
                                "1,0,4,0.3,0,0.05,4000,-3000\n"
                                "1,0,1,0.3,0,0.05,4000,2000\n";
  const auto refused = run("fit " + d / "w.csv" + " --model seed --report " + d / "a");
  EXPECT_EQ(refused.code, 2) << refused.out;
  EXPECT_NE(refused.out.find("w.csv:3:"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(d / "a"));
  const auto fitted =
      run("fit " + d / "w.csv" +
          " --model seed --fix h=0,kappa=1,a=2,b=9,m=3 --no-global --report " + d / "b");
  EXPECT_EQ(fitted.code, 0) << fitted.out;
}

TEST(WheelFormCli, BatchFitsADirectoryOfTydexFilesAndKeepsColumns) {
  ScratchDir d("wheel_cli_batch");
  fs::create_directories(d / "runs");
  const std::string source = std::string(FRICTIONID_TEST_DATA_DIR) + "/wheel/rig_iso.tdx";
  fs::copy_file(source, d / "runs/left.tdx");
  fs::copy_file(source, d / "runs/right.TDX");
  const auto r = run("batch " + d / "runs" +
                     " --contact-radius 0.05 --model seed --no-global --fix "
                     "kappa=1,h=0,a=2,b=9,m=3 --keep NOMPRES,INFLPRES --jobs 1 --report " +
                     d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string summary = read_file(fs::path(d / "out") / "summary.csv");
  std::istringstream in(summary);
  std::string header, left, right;
  std::getline(in, header);
  std::getline(in, left);
  std::getline(in, right);
  EXPECT_NE(header.find(",NOMPRES,INFLPRES"), std::string::npos) << header;
  EXPECT_EQ(left.rfind("left,ok,4,", 0), 0u) << left;
  EXPECT_EQ(right.rfind("right,ok,4,", 0), 0u) << right;
  EXPECT_NE(left.find(",240,240|241|242|243"), std::string::npos) << left;
  const auto run_report =
      nlohmann::json::parse(read_file(fs::path(d / "out") / "runs/left/report.json"));
  EXPECT_EQ(run_report.at("provenance").at("data_form").at("format"), "tydex");
}

TEST(WheelFormCli, BatchGroupsWheelFormRowsByAColumn) {
  ScratchDir d("wheel_cli_group");
  std::ofstream(d / "rig.csv") << "V,alpha[deg],slip_ratio,r_e,gamma,R,Fz[kN],Fx,tire\n"
                                  "10,1,0.01,0.3,0,0.05,4,-100,A\n"
                                  "10,1,0.02,0.3,0,0.05,4,-190,A\n"
                                  "10,1,-0.01,0.3,0,0.05,4,110,B\n"
                                  "10,1,-0.02,0.3,0,0.05,4,180,B\n";
  const auto r = run("batch " + d / "rig.csv" +
                     " --group-by tire --model seed --no-global --fix kappa=1,h=0,a=2,b=9,m=3 "
                     "--jobs 1 --report " +
                     d / "out");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string summary = read_file(fs::path(d / "out") / "summary.csv");
  EXPECT_NE(summary.find("\nA,ok,2,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\nB,ok,2,"), std::string::npos) << summary;
}

}  // namespace
}  // namespace wheel_form_test
