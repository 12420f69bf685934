// Every SVG and HTML file frictionid writes is well-formed whatever the text it shows: control
// characters (a\x01b, x\x0cy), bytes that are not UTF-8 (café in Latin-1), markup and random
// bytes in titles, labels, notes, errors and covariates. Checked with the small checker of
// support/xml_well_formed.hpp, which the first test shows to reject what it should.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <frictionid/io/summary_html.hpp>
#include "io/html_page.hpp"
#include "io/svg_plot.hpp"
#include "support/xml_well_formed.hpp"

namespace frictionid::writers_well_formed_test {
namespace {

using test::html_problem;
using test::xml_problem;

// The values of the issue: a --color-by column with control characters and Latin-1 bytes.
const std::vector<std::string> kHostile = {
    "a\x01"
    "b",
    "x\x0c"
    "y",
    "caf\xe9",
    "\xef\xbf\xbe",
    "\xc2\x85",
    "<b>&amp;\"'",
    "\xed\xa0\x80",
    "\x7f"};

svg::Plot plot_with(const std::vector<std::string>& texts) {
  svg::Plot p;
  p.title = texts.at(0);
  p.notes = {texts.at(1 % texts.size())};
  p.x_label = texts.at(2 % texts.size());
  p.y_label = texts.at(3 % texts.size());
  p.x_markers = {{0.5, texts.at(4 % texts.size())}};
  for (std::size_t k = 0; k < texts.size(); ++k)
    p.series.push_back({texts[k], "#1f77b4", svg::Mark::Dots, {0.0, 1.0}, {1.0, 2.0}});
  return p;
}

std::string svg_file(const svg::Plot& p) {
  return svg::standalone_file(svg::render(p));
}

TEST(WellFormedCheck, RejectsWhatItShould) {
  EXPECT_EQ(xml_problem(
                "<?xml version=\"1.0\"?>\n<svg a=\"1\"><text>caf\xc3\xa9 &amp; &#9;</text></svg>"),
            "");
  EXPECT_NE(xml_problem("<svg><text>a\x01"
                        "b</text></svg>"),
            "");
  EXPECT_NE(xml_problem("<svg><text>caf\xe9</text></svg>"), "");
  EXPECT_NE(xml_problem("<svg><text>\xef\xbf\xbe</text></svg>"), "");
  EXPECT_NE(xml_problem("<svg><a></svg></a>"), "");
  EXPECT_NE(xml_problem("<svg a=\"1\" a=\"2\"/>"), "");
  EXPECT_NE(xml_problem("<svg>a & b</svg>"), "");
  EXPECT_NE(xml_problem("<svg></svg><svg></svg>"), "");
  EXPECT_EQ(html_problem("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><script>a<b&&c"
                         "</script></head><body><p>x<br></p></body></html>\n"),
            "");
  EXPECT_NE(html_problem("<!DOCTYPE html><html><p>\xc2\x85</p></html>"), "");
}

TEST(SvgWriter, ControlCharactersAndLatin1InLabelsGiveAWellFormedFile) {
  const std::string file = svg_file(plot_with(kHostile));
  EXPECT_EQ(xml_problem(file), "");
  EXPECT_NE(file.find(">a\\x01b<"), std::string::npos);
  EXPECT_NE(file.find(">caf\\xe9<"), std::string::npos);
}

TEST(SvgWriter, EscapeKeepsTextThatIsAlreadyFine) {
  const std::string fine = "\xce\xba = 0.7 \xc2\xb1 2 %, tab\tand\nlines, \xf0\x9f\x99\x82";
  EXPECT_EQ(svg::escape(fine), fine);
  EXPECT_EQ(svg::escape("<a href=\"x\">&</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;");
}

// Random text: bytes weighted towards the troublesome ones, and now and then a valid
// multi-byte character or a piece of markup.
std::string random_text(std::mt19937_64& rng) {
  static const std::vector<std::string> kPieces = {"<",
                                                   ">",
                                                   "&",
                                                   "\"",
                                                   "'",
                                                   "]]>",
                                                   "<!--",
                                                   "</svg>",
                                                   "&amp;",
                                                   "\xe2\x80\xae",
                                                   "\xc3\xa9",
                                                   "\xf0\x9f\x99\x82",
                                                   "\xef\xbf\xbf",
                                                   "\xc0\xaf",
                                                   "\xf4\x90\x80\x80",
                                                   "\r\n",
                                                   "\t"};
  std::uniform_int_distribution<int> length(0, 24), kind(0, 3), byte(0, 255), low(0, 31);
  std::uniform_int_distribution<std::size_t> piece(0, kPieces.size() - 1);
  std::string s;
  for (int n = length(rng); n > 0; --n) {
    switch (kind(rng)) {
      case 0:
        s += static_cast<char>(byte(rng));
        break;
      case 1:
        s += static_cast<char>(low(rng));
        break;
      case 2:
        s += kPieces[piece(rng)];
        break;
      default:
        s += static_cast<char>('a' + low(rng) % 26);
    }
  }
  return s;
}

TEST(SvgWriter, RandomBytesInEveryTextGiveAWellFormedFile) {
  std::mt19937_64 rng(20261124);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::string> texts;
    for (int k = 0; k < 6; ++k) texts.push_back(random_text(rng));
    const std::string file = svg_file(plot_with(texts));
    const std::string problem = xml_problem(file);
    ASSERT_EQ(problem, "") << "trial " << trial;
  }
}

TEST(SummaryHtml, RandomBytesInLabelsErrorsWarningsAndCovariatesGiveAWellFormedPage) {
  std::mt19937_64 rng(30);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<SummaryRow> rows;
    for (int r = 0; r < 4; ++r) {
      SummaryRow row;
      row.label = random_text(rng);
      row.ok = r != 3;
      row.rows = 100;
      if (row.ok) {
        SummaryParameter f;
        f.name = r == 0 ? random_text(rng) : "f";
        f.value = 0.3 + 0.01 * r;
        f.std_error = 0.01;
        row.parameters = {f};
        row.warnings = {random_text(rng)};
      } else {
        row.error = random_text(rng);
      }
      row.covariates = {{"mean_N", 1000.0 * (r + 1)},
                        {random_text(rng), random_text(rng)},
                        {"group", r % 2 ? random_text(rng) : std::string("same")}};
      rows.push_back(row);
    }
    SummaryHtmlOptions o;
    o.title = random_text(rng);
    o.note = random_text(rng);
    o.trend_x = trial % 2 ? "mean_N" : random_text(rng);
    o.run_reports = RunReports::Full;
    o.run_directories[rows[0].label] = random_text(rng);
    const std::string page = summary_html(rows, o);
    const std::string problem = html_problem(page);
    ASSERT_EQ(problem, "") << "trial " << trial;
  }
}

TEST(HtmlPage, RandomBytesInTheTitleGiveAWellFormedPage) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    const std::string page = html::page_start(svg::escape(random_text(rng))) + "<p>" +
                             html::isolated(random_text(rng)) + "</p>" + html::page_end();
    ASSERT_EQ(html_problem(page), "") << "trial " << trial;
  }
}

}  // namespace
}  // namespace frictionid::writers_well_formed_test
