#include <frictionid/io/report_writer.hpp>

#include <gtest/gtest.h>

#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace frictionid::report_writer_test {
namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A fresh directory under the system temp dir, removed at scope exit.
class ScratchDir {
 public:
  ScratchDir() {
    std::string tmpl = (fs::temp_directory_path() / "report_writer_test-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = tmpl;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Sets an environment variable for the scope of the object, then restores it.
class ScopedEnv {
 public:
  ScopedEnv(std::string name, const std::string& value) : name_(std::move(name)) {
    const char* old = std::getenv(name_.c_str());
    had_ = old != nullptr;
    if (had_) old_ = old;
    ::setenv(name_.c_str(), value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (had_)
      ::setenv(name_.c_str(), old_.c_str(), 1);
    else
      ::unsetenv(name_.c_str());
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  bool had_ = false;
  std::string old_;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// "nan" as a word, any case (std::regex would do, but trips GCC 12's -Wmaybe-uninitialized at -O2).
bool mentions_nan(const std::string& text) {
  auto letter = [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) != 0; };
  for (std::size_t i = 0; i + 3 <= text.size(); ++i) {
    std::string w = text.substr(i, 3);
    for (char& ch : w) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (w != "nan") continue;
    if ((i == 0 || !letter(text[i - 1])) && (i + 3 == text.size() || !letter(text[i + 3])))
      return true;
  }
  return false;
}

// T_x of the seed's approximant, used only to give the fake fit plausible predictions.
double toy_t_x(double v, double u, double n) {
  return 0.3 * n * v / std::sqrt(v * v + 0.5 * u * u);
}

// Rows: a slip sweep at fixed spin, plus one pure-spin row (eps = 0) and one pure-slip row
// (eps = inf). M_z is measured on every other row only.
Dataset make_dataset(std::size_t rows = 12) {
  Dataset d;
  d.source = "toy.csv";
  for (std::size_t i = 0; i < rows; ++i) {
    const double v = i == 0 ? 0.0 : 0.001 * std::pow(1.7, static_cast<double>(i % 40));
    const double omega = i == 1 ? 0.0 : 2.0;
    d.line.push_back(i + 2);
    d.v_x.push_back(v);
    d.v_y.push_back(0.0);
    d.omega.push_back(omega);
    d.N.push_back(100.0);
    d.R.push_back(0.01);
    const double t = toy_t_x(v, omega * 0.01, 100.0);
    const double wiggle = 1.0 + 0.01 * std::sin(static_cast<double>(i));
    d.value[0].push_back(t * wiggle);
    d.present[0].push_back(1);
    d.value[2].push_back(i % 2 == 0 ? 0.02 * wiggle : 0.0);
    d.present[2].push_back(i % 2 == 0 ? 1 : 0);
  }
  for (int c : {1, 3}) {
    d.value[c].assign(rows, 0.0);
    d.present[c].assign(rows, 0);
  }
  return d;
}

FitResult make_result(const Dataset& d) {
  FitResult r;
  r.model = "corrected";
  r.pressure = "hertz";
  r.rows = d.rows();
  r.channels = {Channel::T_x, Channel::M_z};

  ParameterEstimate kappa;
  kappa.name = "kappa";  // deliberately not alphabetical: the report must keep this order
  kappa.value = 1.25;
  kappa.initial = 1.0;
  kappa.lower = 0.1;
  kappa.upper = 10.0;
  kappa.std_error = 0.0625;
  kappa.ci95 = std::array<double, 2>{1.125, 1.375};
  ParameterEstimate f;
  f.name = "f";
  f.value = 0.3125;
  f.initial = 0.5;
  f.lower = 0.0;
  f.upper = kInf;  // unbounded above
  f.std_error = 0.00390625;
  f.ci95 = std::array<double, 2>{0.3046875, 0.3203125};
  ParameterEstimate h;
  h.name = "h";
  h.value = 0.0;
  h.initial = 0.0;
  h.lower = -1.0;
  h.upper = 1.0;
  h.fixed = true;
  ParameterEstimate a;
  a.name = "a";
  a.value = 4.0;
  a.initial = 2.5;
  a.lower = 0.0;
  a.upper = 4.0;
  a.at_bound = true;
  ParameterEstimate m;
  m.name = "m";
  m.value = 7.5;
  m.initial = 6.0;
  m.lower = 1.0;
  m.upper = 100.0;  // free, inside its bounds, no stderr: "not determined"
  r.parameters = {kappa, f, h, a, m};

  r.correlation_names = {"kappa", "f"};
  r.correlation = {{1.0, -0.375}, {-0.375, 1.0}};
  r.cost = 5.5;
  r.chi2 = 11.0;
  r.residuals = 18;
  r.dof = 15;
  r.reduced_chi2 = 11.0 / 15.0;
  r.aic = -12.5;
  r.bic = -9.75;
  r.covariance_scaled_by_reduced_chi2 = true;
  r.loss = "huber:2";

  ChannelSummary tx;
  tx.channel = Channel::T_x;
  tx.rows = 12;
  tx.scale = 0.25;
  tx.scale_source = "1% of median |T_x|";
  tx.rmse = 0.125;
  tx.r2 = 0.96875;
  ChannelSummary mz;
  mz.channel = Channel::M_z;
  mz.rows = 6;
  mz.scale = 0.001;
  mz.scale_source = "fixed";
  r.channel_summaries = {tx, mz};  // M_z: rmse and r2 absent

  r.global.algorithm = "GN_MLSL_LDS";
  r.global.starts = 8;
  r.global.reached_best = 6;
  r.global.evaluations = 4096;
  r.global.subsample_rows = 12;
  r.global.seed = 18446744073709551615ull;  // full 64-bit range must survive
  r.solver.iterations = 17;
  r.solver.termination = "CONVERGENCE";
  r.solver.converged = true;
  r.solver.time_s = 1.234;  // must not reach the report
  r.warnings = {"a is at its upper bound 4", "M_z has only 6 rows"};

  const std::size_t n = d.rows();
  for (std::size_t i = 0; i < n; ++i) {
    const double u = std::abs(d.omega[i]) * d.R[i];
    r.eps.push_back(u > 0 ? std::hypot(d.v_x[i], d.v_y[i]) / u : kInf);
    r.fitted[0].push_back(toy_t_x(d.v_x[i], u, d.N[i]));
    r.fitted[2].push_back(0.02);
  }
  return r;
}

TEST(ReportJson, HasEveryDesignKeyInOrder) {
  const Dataset d = make_dataset();
  const ojson j = report_json(make_result(d));

  std::vector<std::string> top;
  for (auto it = j.begin(); it != j.end(); ++it) top.push_back(it.key());
  EXPECT_EQ(top, (std::vector<std::string>{"model", "pressure", "rows", "channels", "parameters",
                                           "correlation", "statistics", "global_search", "solver",
                                           "warnings", "interval_method", "bootstrap_replicates"}));
  for (const char* k :
       {"value", "stderr", "ci95", "fixed", "at_bound", "initial", "lower", "upper"})
    EXPECT_TRUE(j["parameters"]["f"].contains(k)) << k;
  for (const char* k : {"names", "matrix"}) EXPECT_TRUE(j["correlation"].contains(k)) << k;
  for (const char* k : {"cost", "chi2", "reduced_chi2", "aic", "bic", "dof", "residuals", "rmse",
                        "r2", "scales", "covariance_scaled_by_reduced_chi2", "loss"})
    EXPECT_TRUE(j["statistics"].contains(k)) << k;
  for (const char* k :
       {"algorithm", "starts", "reached_best", "evaluations", "subsample_rows", "seed"})
    EXPECT_TRUE(j["global_search"].contains(k)) << k;
  for (const char* k : {"iterations", "termination", "time_s", "converged"})
    EXPECT_TRUE(j["solver"].contains(k)) << k;
  // The wall time must not reach the report (it would differ from run to run).
  EXPECT_TRUE(j["solver"]["time_s"].is_null());
  EXPECT_EQ(j.dump().find("1.234"), std::string::npos);
}

TEST(ReportJson, ReproducesTheFitResult) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  const ojson j = report_json(r);

  EXPECT_EQ(j["model"], "corrected");
  EXPECT_EQ(j["pressure"], "hertz");
  EXPECT_EQ(j["rows"], 12);
  EXPECT_EQ(j["channels"], ojson::array({"T_x", "M_z"}));

  std::vector<std::string> order;
  for (auto it = j["parameters"].begin(); it != j["parameters"].end(); ++it)
    order.push_back(it.key());
  EXPECT_EQ(order, (std::vector<std::string>{"kappa", "f", "h", "a", "m"}));
  const ojson& kappa = j["parameters"]["kappa"];
  EXPECT_EQ(kappa["value"].get<double>(), 1.25);
  EXPECT_EQ(kappa["stderr"].get<double>(), 0.0625);
  EXPECT_EQ(kappa["ci95"], ojson::array({1.125, 1.375}));
  EXPECT_EQ(kappa["initial"].get<double>(), 1.0);
  EXPECT_EQ(kappa["lower"].get<double>(), 0.1);
  EXPECT_EQ(kappa["upper"].get<double>(), 10.0);
  EXPECT_EQ(kappa["fixed"], false);
  EXPECT_EQ(j["parameters"]["h"]["fixed"], true);
  EXPECT_EQ(j["parameters"]["a"]["at_bound"], true);

  EXPECT_EQ(j["correlation"]["names"], ojson::array({"kappa", "f"}));
  EXPECT_EQ(j["correlation"]["matrix"][0][1].get<double>(), -0.375);

  const ojson& st = j["statistics"];
  EXPECT_EQ(st["cost"].get<double>(), 5.5);
  EXPECT_EQ(st["chi2"].get<double>(), 11.0);
  EXPECT_EQ(st["reduced_chi2"].get<double>(), 11.0 / 15.0);  // round trip is exact
  EXPECT_EQ(st["aic"].get<double>(), -12.5);
  EXPECT_EQ(st["bic"].get<double>(), -9.75);
  EXPECT_EQ(st["dof"], 15);
  EXPECT_EQ(st["residuals"], 18);
  EXPECT_EQ(st["rmse"]["T_x"].get<double>(), 0.125);
  EXPECT_EQ(st["r2"]["T_x"].get<double>(), 0.96875);
  EXPECT_EQ(st["scales"]["T_x"]["sigma"].get<double>(), 0.25);
  EXPECT_EQ(st["scales"]["T_x"]["source"], "1% of median |T_x|");
  EXPECT_EQ(st["covariance_scaled_by_reduced_chi2"], true);
  EXPECT_EQ(st["loss"], "huber:2");

  EXPECT_EQ(j["global_search"]["algorithm"], "GN_MLSL_LDS");
  EXPECT_EQ(j["global_search"]["starts"], 8);
  EXPECT_EQ(j["global_search"]["reached_best"], 6);
  EXPECT_EQ(j["global_search"]["evaluations"], 4096);
  EXPECT_EQ(j["global_search"]["subsample_rows"], 12);
  EXPECT_EQ(j["global_search"]["seed"].get<unsigned long long>(), 18446744073709551615ull);
  EXPECT_EQ(j["solver"]["iterations"], 17);
  EXPECT_EQ(j["solver"]["termination"], "CONVERGENCE");
  EXPECT_EQ(j["solver"]["converged"], true);
  EXPECT_EQ(j["warnings"], ojson::array({"a is at its upper bound 4", "M_z has only 6 rows"}));
}

TEST(ReportJson, AbsentOptionalsAreNull) {
  const Dataset d = make_dataset();
  const ojson j = report_json(make_result(d));
  EXPECT_TRUE(j["parameters"]["h"]["stderr"].is_null());
  EXPECT_TRUE(j["parameters"]["h"]["ci95"].is_null());
  EXPECT_TRUE(j["parameters"]["m"]["stderr"].is_null());
  EXPECT_TRUE(j["statistics"]["rmse"]["M_z"].is_null());
  EXPECT_TRUE(j["statistics"]["r2"]["M_z"].is_null());
  EXPECT_TRUE(j["parameters"]["f"]["upper"].is_null());  // infinite bound: unbounded
}

TEST(ReportJson, NonFiniteNumbersBecomeNullAndNoNanTextAnywhere) {
  const Dataset d = make_dataset();
  FitResult r = make_result(d);
  r.parameters[0].value = kNaN;
  r.parameters[1].std_error = kNaN;
  r.parameters[1].ci95 = std::array<double, 2>{kNaN, -kInf};
  r.correlation[0][1] = kNaN;
  r.aic = kInf;
  r.reduced_chi2 = kNaN;
  r.channel_summaries[0].rmse = kNaN;

  const ojson j = report_json(r);
  EXPECT_TRUE(j["parameters"]["kappa"]["value"].is_null());
  EXPECT_TRUE(j["parameters"]["f"]["stderr"].is_null());
  EXPECT_TRUE(j["parameters"]["f"]["ci95"][0].is_null());
  EXPECT_TRUE(j["parameters"]["f"]["ci95"][1].is_null());
  EXPECT_TRUE(j["correlation"]["matrix"][0][1].is_null());
  EXPECT_TRUE(j["statistics"]["aic"].is_null());
  EXPECT_TRUE(j["statistics"]["reduced_chi2"].is_null());
  EXPECT_TRUE(j["statistics"]["rmse"]["T_x"].is_null());

  const std::string text = j.dump(2);
  EXPECT_FALSE(mentions_nan(text)) << text;
  EXPECT_EQ(text.find("inf"), std::string::npos) << text;
  EXPECT_EQ(text.find("Infinity"), std::string::npos) << text;
  const std::string md = report_markdown(r);
  EXPECT_FALSE(mentions_nan(md)) << md;

  ScratchDir dir;
  write_report(dir.path().string(), r, d);
  EXPECT_FALSE(mentions_nan(slurp(dir.path() / "report.json")));
  EXPECT_FALSE(mentions_nan(slurp(dir.path() / "report.md")));
}

TEST(ReportMarkdown, ResultLineComesFirstWithEveryParameter) {
  const Dataset d = make_dataset();
  const std::string md = report_markdown(make_result(d));
  const auto result = md.find(
      "**Result:** kappa = 1.250 ± 0.062 (5.0 %); f = 0.3125 ± 0.0039 (1.2 %); h = 0 (fixed); "
      "a = 4 (at a bound); m = 7.5 (not determined).\n");
  ASSERT_NE(result, std::string::npos) << md;
  EXPECT_LT(result, md.find("## Parameters"));
}

TEST(ReportMarkdown, HasTitleTableNotesWarningsCorrelationAndLinks) {
  const Dataset d = make_dataset();
  FitResult r = make_result(d);
  const std::string md = report_markdown(r);

  EXPECT_NE(md.find("# frictionid fit: model corrected, pressure hertz"), std::string::npos);
  // The stderr to 2 digits, the value to the same place, the interval to 2 digits of its width.
  EXPECT_NE(md.find("| kappa | 1.250 ± 0.062 | [1.12, 1.38] | — | 1 | [0.1, 10] |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| f | 0.3125 ± 0.0039 | [0.305, 0.320] |"), std::string::npos) << md;
  EXPECT_NE(md.find("[0, +inf]"), std::string::npos) << md;
  EXPECT_NE(md.find("| fixed |"), std::string::npos);
  EXPECT_NE(md.find("| at bound (stderr not meaningful) |"), std::string::npos);
  EXPECT_NE(md.find("| m | 7.5 | — | — | 6 | [1, 100] | not determined |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("- a is at its upper bound 4\n- M_z has only 6 rows\n"), std::string::npos);
  // The interval method chosen decides the CI column; a bootstrap adds its own columns.
  r.intervals = IntervalMethod::Sandwich;
  r.interval_method = "sandwich";
  r.parameters[0].ci95_sandwich = std::array<double, 2>{1.0, 1.5};
  r.parameters[0].std_error_sandwich = 0.125;
  r.bootstrap_replicates = 50;
  r.parameters[0].ci95_bootstrap = std::array<double, 2>{1.1, 1.4};
  r.parameters[0].std_error_bootstrap = 0.07;
  const std::string md2 = report_markdown(r);
  EXPECT_NE(md2.find("| kappa | 1.250 ± 0.062 | [1.00, 1.50] | 0.12 | 0.070 | [1.10, 1.40] | 1 |"),
            std::string::npos)
      << md2;
  EXPECT_NE(md2.find("HC3 sandwich"), std::string::npos);
  EXPECT_NE(md2.find("50 wild (Rademacher) refits"), std::string::npos);
  EXPECT_NE(md.find("| kappa | 1.00 | -0.38 |"), std::string::npos) << md;
  EXPECT_NE(md.find("1% of median \\|T_x\\|"), std::string::npos) << md;  // escaped in a cell
  EXPECT_NE(md.find("![fit_T_x](fit_T_x.svg)"), std::string::npos);
  EXPECT_NE(md.find("![residuals_M_z](residuals_M_z.svg)"), std::string::npos);
  EXPECT_EQ(md.find("1.234"), std::string::npos);  // wall time stays out

  r.warnings.clear();
  EXPECT_NE(report_markdown(r).find("## Warnings\n\n- none\n"), std::string::npos);
  EXPECT_NE(report_markdown(r, {}).find("No plots were produced"), std::string::npos);
}

TEST(ReportOutput, SameResultGivesByteIdenticalFiles) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  EXPECT_EQ(report_json(r).dump(2), report_json(make_result(d)).dump(2));
  EXPECT_EQ(report_markdown(r), report_markdown(make_result(d)));

  ScratchDir a, b;
  const auto files_a = write_report(a.path().string(), r, d);
  const auto files_b = write_report(b.path().string(), r, d);
  ASSERT_EQ(names_in(a.path()), names_in(b.path()));
  for (const auto& name : names_in(a.path()))
    EXPECT_EQ(slurp(a.path() / name), slurp(b.path() / name)) << name;
  EXPECT_EQ(files_a.size(), files_b.size());
}

TEST(WriteReport, WritesOnlyReportFilesIntoAFreshNestedDir) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  ScratchDir scratch;
  const fs::path dir = scratch.path() / "nested" / "out";  // does not exist yet

  const std::vector<std::string> files = write_report(dir.string(), r, d);
  std::vector<std::string> returned;
  for (const auto& f : files) {
    EXPECT_EQ(fs::path(f).parent_path(), dir);
    returned.push_back(fs::path(f).filename().string());
  }
  std::sort(returned.begin(), returned.end());
  EXPECT_EQ(returned, names_in(dir));  // nothing written that is not reported, no temp files

  // Both report files are there, and report.json parses back to what report_json gives.
  const std::string json = slurp(dir / "report.json");
  // (write_report adds the provenance of its options: here the defaults.)
  EXPECT_EQ(ojson::parse(json), report_json(r, Provenance{}));
  EXPECT_EQ(json.back(), '\n');
  EXPECT_EQ(slurp(dir / "report.md").find("# frictionid fit"), 0u);

  std::vector<std::string> expected = {"report.json", "report.md", "report.html"};
  for (const char* c : {"T_x", "M_z"})
    for (const char* kind : {"collapse_", "fit_", "residuals_", "residuals_fitted_", "qq_"})
      expected.push_back(kind + std::string(c) + ".svg");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names_in(dir), expected);

  for (const auto& name : names_in(dir)) {
    if (fs::path(name).extension() != ".svg") continue;
    const std::string svg = slurp(dir / name);
    EXPECT_TRUE(svg.rfind("<?xml", 0) == 0 || svg.rfind("<svg", 0) == 0) << name;
    const std::string md = slurp(dir / "report.md");
    EXPECT_NE(md.find("(" + name + ")"), std::string::npos) << name << " not linked";
  }
}

TEST(WriteReport, RemovesItsPlotStagingDir) {
  const Dataset d = make_dataset();
  ScratchDir out, tmp;
  {
    ScopedEnv private_tmp("TMPDIR", tmp.path().string());  // where the plot staging dir goes
    write_report(out.path().string(), make_result(d), d);
  }
  EXPECT_TRUE(names_in(tmp.path()).empty());
}

TEST(WriteReport, EdgeRowsAreNamedInThePlotTitle) {
  const Dataset d = make_dataset();
  ScratchDir dir;
  write_report(dir.path().string(), make_result(d), d);
  // Row 0 has v = 0 (eps = 0), row 1 has omega = 0 (eps = inf); both are measured for T_x.
  const std::string svg = slurp(dir.path() / "fit_T_x.svg");
  EXPECT_NE(svg.find("eps = 0 rows at the left edge, eps = inf rows at the right edge"),
            std::string::npos);
}

TEST(WriteReport, ChannelWithoutPredictionsIsSkippedNotFatal) {
  const Dataset d = make_dataset();
  FitResult r = make_result(d);
  r.fitted[2].clear();  // M_z predictions missing: nothing to plot for it
  ScratchDir dir;
  write_report(dir.path().string(), r, d);
  EXPECT_FALSE(fs::exists(dir.path() / "fit_M_z.svg"));
  EXPECT_TRUE(fs::exists(dir.path() / "fit_T_x.svg"));
  EXPECT_EQ(slurp(dir.path() / "report.md").find("fit_M_z.svg"), std::string::npos);
}

TEST(WriteReport, PlotsNeedNoExternalProgram) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  ScratchDir dir, empty_bin;
  {
    ScopedEnv no_programs("PATH", empty_bin.path().string());
    write_report(dir.path().string(), r, d);
  }
  EXPECT_TRUE(fs::exists(dir.path() / "collapse_T_x.svg"));
  EXPECT_TRUE(fs::exists(dir.path() / "fit_M_z.svg"));
}

TEST(WriteReport, LargeDatasetIsSubsampledAndSaysSo) {
  const Dataset d = make_dataset(4001);
  FitResult r = make_result(d);
  r.channels = {Channel::T_x};
  ScratchDir dir;
  write_report(dir.path().string(), r, d);
  const std::string svg = slurp(dir.path() / "fit_T_x.svg");
  EXPECT_NE(svg.find("about 1 in 2 of 4001 rows plotted"), std::string::npos);
  EXPECT_NE(slurp(dir.path() / "residuals_T_x.svg").find("about 1 in 2 of 4001 rows plotted"),
            std::string::npos);
}

TEST(WriteReport, UnwritableDirectoryThrows) {
  ScratchDir scratch;
  const fs::path file = scratch.path() / "plain_file";
  std::ofstream(file) << "x";
  const Dataset d = make_dataset();
  EXPECT_THROW(write_report((file / "sub").string(), make_result(d), d), std::runtime_error);
}

}  // namespace
}  // namespace frictionid::report_writer_test

namespace frictionid::report_writer_test {
namespace {

// A fit on another spot than the circle says so in report.json (after the pressure) and in the
// titles of report.md and report.html.
TEST(ReportContact, ASpotOtherThanTheCircleIsStatedInEveryFile) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  ScratchDir dir;
  ReportOptions o;
  o.contact = "ellipse:0.6";
  write_report((dir.path() / "r").string(), r, d, o);
  const ojson j = ojson::parse(slurp(dir.path() / "r" / "report.json"));
  std::vector<std::string> top;
  for (auto it = j.begin(); it != j.end(); ++it) top.push_back(it.key());
  ASSERT_GE(top.size(), 3u);
  EXPECT_EQ(top[1], "pressure");
  EXPECT_EQ(top[2], "contact");
  EXPECT_EQ(j["contact"], "ellipse:0.6");
  const std::string title = "model corrected, pressure hertz, contact ellipse:0.6";
  EXPECT_NE(slurp(dir.path() / "r" / "report.md").find("# frictionid fit: " + title),
            std::string::npos);
  EXPECT_NE(slurp(dir.path() / "r" / "report.html").find("<h1>frictionid fit: " + title + "</h1>"),
            std::string::npos);
}

// The circle is the default and is not named: its reports are the bytes they always were.
TEST(ReportContact, TheCircleIsNotStatedSoItsReportsStayAsTheyWere) {
  const Dataset d = make_dataset();
  const FitResult r = make_result(d);
  ScratchDir dir;
  ReportOptions circle;
  circle.contact = "circle";
  write_report((dir.path() / "default").string(), r, d);
  write_report((dir.path() / "circle").string(), r, d, circle);
  for (const char* name : {"report.json", "report.md", "report.html"}) {
    EXPECT_EQ(slurp(dir.path() / "circle" / name), slurp(dir.path() / "default" / name)) << name;
    EXPECT_EQ(slurp(dir.path() / "circle" / name).find("contact"), std::string::npos) << name;
  }
  EXPECT_FALSE(report_json(r, "circle").contains("contact"));
}

}  // namespace
}  // namespace frictionid::report_writer_test
