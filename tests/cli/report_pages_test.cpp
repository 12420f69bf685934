// What every page and plot frictionid writes has in common, read from the files of real runs of
// the built executable: a fit report, a comparison, a batch with a joint fit (summary.html,
// shared.html and the runs' reports) and a shimmy sweep.
//   - every <svg> (inline or a standalone file) is an image to assistive technology: role="img",
//     a <title> as its first child and an aria-label that says what is plotted;
//   - every series is drawn in a colour of the palette (io/palette.hpp);
//   - no label writes the newton as "N", the symbol of the normal load (docs/design.md §4.3);
//   - report.html and report.md name the interval method of each parameter's row, on a fit
//     where some rows use the profile interval and others the model's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/palette.hpp"
#include "support/run_command.hpp"
#include "support/scratch_dir.hpp"

namespace report_pages_test {
namespace {

namespace fs = std::filesystem;
using frictionid::test::read_file;
using frictionid::test::run_frictionid;
using frictionid::test::ScratchDir;

class ReportPages : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir("report_pages");
    const ScratchDir& d = *dir_;
    const std::string data = d / "data.csv";
    // Two slip directions and three loads: several colour groups in every plot.
    const std::vector<std::string> commands = {
        "generate --model seed --slip-angles 0,45 --rows 300 --noise 0.01 --output " + data,
        "fit " + data + " --model seed --no-global --report " + (d / "fit"),
        "compare " + data + " --models seed,corrected --no-global --report " + (d / "compare"),
        "generate --model seed --rows 200 --noise 0.01 --loads 2000 --seed 2 --output " +
            (d / "a.csv"),
        "generate --model seed --rows 200 --noise 0.01 --loads 4000 --seed 3 --output " +
            (d / "b.csv"),
        "batch " + (d / "a.csv") + " " + (d / "b.csv") +
            " --no-global --shared kappa --per-run-reports full --report " + (d / "batch"),
        // epsilon only in 1.5 to 100: kappa, b and m nearly collinear (|r| > 0.99), so their
        // rows get the profile interval by default and the others the model's.
        "generate --model seed --param f=0.9,kappa=1.15,h=0.08 --rows 600 --noise 0.01 "
        "--eps-min 1.5 --output " +
            (d / "collinear.csv"),
        "fit " + (d / "collinear.csv") + " --model seed --report " + (d / "collinear")};
    for (const auto& c : commands) {
      const auto r = run_frictionid(c);
      setup_ok_ = setup_ok_ && r.code == 0;
      if (r.code != 0) setup_log_ += c + "\n" + r.out + "\n";
    }
    fs::create_directories(d.path() / "shimmy");
    const auto s = run_frictionid(
        "shimmy --model corrected --pressure uniform --param f=0.8 --N 1000 --R 0.05 --caster 0.1 "
        "--yaw-inertia 0.5 --yaw-stiffness 2000 --yaw-damping 1 --lateral-mass 20 "
        "--lateral-stiffness 2e5 --lateral-damping 50 --psi0 0.05 --duration 1 --speed-sweep "
        "5:30:3 --sweep-dir " +
        (d / "shimmy"));
    setup_ok_ = setup_ok_ && s.code == 0;
    if (s.code != 0) setup_log_ += "shimmy\n" + s.out;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  void SetUp() override { ASSERT_TRUE(setup_ok_) << setup_log_; }

  // Every file with one of the extensions under the scratch directory, by path. A report
  // directory is a symlink to a hidden one (docs/design.md §4.3): followed, the hidden names
  // skipped.
  static std::map<std::string, std::string> files(const std::set<std::string>& extensions) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(
             dir_->path(), fs::directory_options::follow_directory_symlink)) {
      const fs::path relative = e.path().lexically_relative(dir_->path());
      const bool hidden = std::any_of(relative.begin(), relative.end(), [](const fs::path& p) {
        return p.string().rfind('.', 0) == 0;
      });
      if (!hidden && e.is_regular_file() && extensions.count(e.path().extension().string()))
        out[relative.string()] = read_file(e.path());
    }
    return out;
  }

  static ScratchDir* dir_;
  static bool setup_ok_;
  static std::string setup_log_;
};

ScratchDir* ReportPages::dir_ = nullptr;
bool ReportPages::setup_ok_ = true;
std::string ReportPages::setup_log_;

// The <svg> elements of a page or file: each from "<svg" to its "</svg>".
std::vector<std::string> svg_elements(const std::string& text) {
  std::vector<std::string> out;
  for (auto at = text.find("<svg"); at != std::string::npos; at = text.find("<svg", at + 1)) {
    const auto end = text.find("</svg>", at);
    out.push_back(text.substr(at, end == std::string::npos ? std::string::npos : end + 6 - at));
  }
  return out;
}

// The attributes of an element's start tag (at the start of `element`); values as written.
std::map<std::string, std::string> attributes(const std::string& element) {
  const std::string tag = element.substr(0, element.find('>'));
  static const std::regex attribute("([A-Za-z_:][-A-Za-z0-9_:.]*)=\"([^\"]*)\"");
  std::map<std::string, std::string> out;
  for (std::sregex_iterator m(tag.begin(), tag.end(), attribute), end; m != end; ++m)
    out[(*m)[1]] = (*m)[2];
  return out;
}

TEST_F(ReportPages, EverySvgIsAnImageWithATitleAndALabel) {
  std::map<std::string, std::size_t> svgs_per_kind;
  for (const auto& [path, text] : files({".svg", ".html"})) {
    for (const std::string& svg : svg_elements(text)) {
      const auto a = attributes(svg);
      EXPECT_EQ(a.count("role") ? a.at("role") : "", "img") << path;
      const std::string label = a.count("aria-label") ? a.at("aria-label") : "";
      // It says what is plotted against what, not just a name.
      EXPECT_NE(label.find(" against "), std::string::npos) << path << ": " << label;
      std::size_t first = svg.find('>') + 1;
      while (first < svg.size() && std::isspace(static_cast<unsigned char>(svg[first]))) ++first;
      ASSERT_EQ(svg.compare(first, 7, "<title>"), 0) << path << ": " << svg.substr(0, 300);
      const auto title_end = svg.find("</title>", first);
      ASSERT_NE(title_end, std::string::npos) << path;
      EXPECT_GT(title_end, first + 7) << path << ": an empty title";
      ++svgs_per_kind[fs::path(path).filename().string()];
    }
  }
  // Every kind of page was read, with its plots.
  for (const char* page :
       {"report.html", "compare.html", "summary.html", "shared.html", "shimmy.html"})
    EXPECT_GT(svgs_per_kind[page], 0u) << page;
  EXPECT_GE(svgs_per_kind["collapse_T_x.svg"], 1u);
  EXPECT_GE(svgs_per_kind["compare_T_x.svg"], 1u);
}

// Every colour in a plot is one of the palette's, its reference black or backdrop grey, or one
// of the frame's neutral greys and white (background, grid, ticks, notes).
TEST_F(ReportPages, EverySeriesIsDrawnInAPaletteColour) {
  std::set<std::string> allowed(frictionid::palette::kSeries.begin(),
                                frictionid::palette::kSeries.end());
  allowed.insert({frictionid::palette::kReference, frictionid::palette::kBackdrop});
  const std::set<std::string> frame = {"#ffffff", "#e3e3e3", "#333333",
                                       "#888888", "#777777", "#555555"};
  static const std::regex colour("(stroke|fill)=\"(#[0-9a-fA-F]{6})\"");
  std::set<std::string> series_colours;
  for (const auto& [path, text] : files({".svg", ".html"}))
    for (const std::string& svg : svg_elements(text))
      for (std::sregex_iterator m(svg.begin(), svg.end(), colour), end; m != end; ++m) {
        const std::string c = (*m)[2];
        if (frame.count(c)) continue;
        EXPECT_TRUE(allowed.count(c)) << path << ": " << c;
        series_colours.insert(c);
      }
  // Several series colours were seen: groups, models, runs.
  EXPECT_GE(series_colours.size(), 4u);
}

// N is the normal load; a label that means newtons writes "newton". The old labels, "T_x [N]",
// "fitted M_z [N m]", "Measured T_x in N against eps", all match the pattern.
TEST_F(ReportPages, NoLabelWritesTheNewtonAsN) {
  static const std::regex newton_as_n(
      "[\\[(]\\s*k?N(\\s*(·|\\.|\\*)?\\s*m)?\\s*[\\])]|\\bin k?N( m)?\\b(?! R)");
  for (const char* old : {"T_x [N]", "fitted M_z [N m]", "Measured T_x in N against eps",
                          "load N (N)", "RMSE T_y [kN]"})
    EXPECT_TRUE(std::regex_search(std::string(old), newton_as_n)) << old;
  for (const auto& [path, text] : files({".svg", ".html", ".md"})) {
    std::smatch m;
    if (std::regex_search(text, m, newton_as_n))
      ADD_FAILURE() << path << ": \"" << m.str() << "\" in "
                    << text.substr(static_cast<std::size_t>(std::max<long>(0, m.position() - 60)),
                                   160);
  }
  // The unit is there, written out.
  const auto pages = files({".svg", ".html", ".md"});
  EXPECT_NE(pages.at("fit/fit_T_x.svg").find("T_x [newton]"), std::string::npos);
  EXPECT_NE(pages.at("fit/fit_M_z.svg").find("M_z [newton metre]"), std::string::npos);
  EXPECT_NE(pages.at("fit/report.html").find("<td>newton metre</td>"), std::string::npos);
  EXPECT_NE(pages.at("fit/report.md").find("| M_z | newton metre |"), std::string::npos);
  EXPECT_NE(pages.at("compare/compare.html").find("RMSE T_x [newton]"), std::string::npos);
  EXPECT_NE(pages.at("batch/summary.html").find("mean_N [newton]"), std::string::npos);
}

// The cells of the row <tr data-param="name"> of report.html: each cell's data-value (empty
// without one) and text.
std::vector<std::pair<std::string, std::string>> html_row(const std::string& page,
                                                          const std::string& name) {
  std::vector<std::pair<std::string, std::string>> cells;
  const auto row = page.find("<tr data-param=\"" + name + "\">");
  if (row == std::string::npos) return cells;
  const std::string tr = page.substr(row, page.find("</tr>", row) - row);
  for (auto at = tr.find("<td"); at != std::string::npos; at = tr.find("<td", at + 1)) {
    const auto a = attributes(tr.substr(at));
    const auto begin = tr.find('>', at) + 1;
    cells.emplace_back(a.count("data-value") ? a.at("data-value") : "",
                       tr.substr(begin, tr.find("</td>", begin) - begin));
  }
  return cells;
}

TEST_F(ReportPages, EachParameterRowNamesItsIntervalMethod) {
  const auto report = nlohmann::json::parse(read_file(dir_->path() / "collinear/report.json"));
  const std::string html = read_file(dir_->path() / "collinear/report.html");
  const std::string md = read_file(dir_->path() / "collinear/report.md");
  ASSERT_EQ(report.at("interval_method"), "model");
  std::set<std::string> methods;
  for (const auto& [name, p] : report.at("parameters").items()) {
    const bool profiled = p.contains("ci95_profile");
    std::string method = "—";
    nlohmann::json interval = nullptr;
    if (profiled) {
      const auto closed = p.at("profile_closed");
      method = closed[0] && closed[1] ? "profile"
               : closed[0]            ? "profile, open above (ends at the bound)"
               : closed[1]            ? "profile, open below (ends at the bound)"
                                      : "profile, open on both sides (ends at the bound)";
      interval = p.at("ci95_profile");
    } else if (!p.at("ci95").is_null()) {
      method = "model (t·stderr)";
      interval = p.at("ci95");
    }
    methods.insert(method.rfind("profile", 0) == 0 ? "profile"
                                                   : method.substr(0, method.find(' ')));
    // report.html: name, value, stderr, low, high, interval method, ...
    const auto cells = html_row(html, name);
    ASSERT_GT(cells.size(), 5u) << name;
    EXPECT_EQ(cells[5].second, method) << name;
    if (!interval.is_null()) {
      EXPECT_EQ(std::stod(cells[3].first), interval[0].get<double>()) << name;
      EXPECT_EQ(std::stod(cells[4].first), interval[1].get<double>()) << name;
    }
    // report.md: the row's last cell.
    const auto at = md.find("| " + name + " |");
    ASSERT_NE(at, std::string::npos) << name;
    const std::string line = md.substr(at, md.find('\n', at) - at);
    EXPECT_EQ(line.substr(line.rfind("| ", line.size() - 3)), "| " + method + " |") << line;
  }
  // The fit is the one asked for: some rows profiled, some not.
  EXPECT_TRUE(methods.count("profile")) << html;
  EXPECT_TRUE(methods.count("model")) << html;
}

}  // namespace
}  // namespace report_pages_test
