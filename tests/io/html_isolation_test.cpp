// summary.html with hostile labels: a label with a bidirectional control (U+202E) is isolated in
// <bdi> so that it cannot reverse the text around it, and a malformed #sort= fragment does not
// throw in the page's script. (tests/cli/hostile_names_in_browser.py checks both in Chromium.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <frictionid/io/summary_html.hpp>
#include "io/html_page.hpp"

namespace frictionid::html_isolation_test {
namespace {

const std::string kRightToLeft =
    "r\xe2\x80\xae"
    "abc";

SummaryRow ok_run(const std::string& label) {
  SummaryRow r;
  r.label = label;
  r.ok = true;
  r.rows = 10;
  SummaryParameter f;
  f.name = "f";
  f.value = 0.3;
  r.parameters = {f};
  r.warnings = {"a warning"};
  r.covariates = {{"mean_N", 1000.0}};
  return r;
}

TEST(HtmlIsolation, TextThatCanChangeDirectionIsWrappedInBdiOtherTextIsNot) {
  EXPECT_EQ(html::isolated(kRightToLeft), "<bdi>" + kRightToLeft + "</bdi>");
  for (const std::string control :
       {"\xd8\x9c", "\xe2\x80\x8e", "\xe2\x80\x8f", "\xe2\x80\xaa", "\xe2\x81\xa6", "\xe2\x81\xa9"})
    EXPECT_EQ(html::isolated("a" + control), "<bdi>a" + control + "</bdi>");
  const std::string hebrew = "\xd7\xa9\xd7\x9c\xd7\x95\xd7\x9d",
                    arabic = "\xd8\xb3\xd9\x84\xd8\xa7\xd9\x85";
  EXPECT_EQ(html::isolated(hebrew), "<bdi>" + hebrew + "</bdi>");
  EXPECT_EQ(html::isolated(arabic + ".csv"), "<bdi>" + arabic + ".csv</bdi>");
  EXPECT_EQ(html::isolated("run <1>"), "run &lt;1&gt;");
  EXPECT_EQ(html::isolated("caf\xc3\xa9 \xc2\xa7"
                           "3 \xce\xba"),
            "caf\xc3\xa9 \xc2\xa7"
            "3 \xce\xba");
}

TEST(SummaryHtml, LabelsWithABidiOverrideAreIsolatedInBdi) {
  const std::vector<SummaryRow> rows = {
      ok_run(kRightToLeft), ok_run("plain"),
      failed_summary_row(kRightToLeft + "2", 0, kRightToLeft + "2.csv: no such file", {})};
  const std::string page = summary_html(rows, {});
  EXPECT_NE(page.find("<td><bdi>" + kRightToLeft + "</bdi></td>"), std::string::npos);
  EXPECT_NE(page.find("<li><bdi>" + kRightToLeft + "2</bdi>: <bdi>" + kRightToLeft +
                      "2.csv: no such file</bdi></li>"),
            std::string::npos);
  EXPECT_NE(page.find("<td>plain</td>"), std::string::npos);  // ASCII labels as before
  // Every occurrence of the raw override is inside <bdi> or an attribute value.
  for (auto at = page.find("\xe2\x80\xae"); at != std::string::npos;
       at = page.find("\xe2\x80\xae", at + 1)) {
    const auto open = page.rfind("<bdi>", at), close = page.rfind("</bdi>", at);
    const bool in_bdi = open != std::string::npos && (close == std::string::npos || close < open);
    const bool in_attribute = page.rfind("data-label=\"", at) > page.rfind('>', at) ||
                              page.rfind('>', at) == std::string::npos;
    EXPECT_TRUE(in_bdi || in_attribute) << page.substr(at - 40, 80);
  }
}

TEST(SummaryHtml, AMalformedSortFragmentIsCaughtInThePageScript) {
  const std::string page = summary_html({ok_run("a")}, {});
  const auto decode = page.find("decodeURIComponent(");
  ASSERT_NE(decode, std::string::npos);
  EXPECT_EQ(page.find("decodeURIComponent(", decode + 1), std::string::npos);
  const auto try_at = page.rfind("try {", decode);
  ASSERT_NE(try_at, std::string::npos);
  EXPECT_EQ(page.find('}', try_at), page.find("} catch (e)", try_at));
  EXPECT_GT(page.find("} catch (e)", try_at), decode);
}

}  // namespace
}  // namespace frictionid::html_isolation_test
