// The pages' style sheets, read as CSS: in print no heading is left at the foot of a page
// without what follows it, tables and figures are kept whole, and nothing that scrolls on screen
// (a wide table's box, a plot's box) or sticks scrolls or sticks on paper.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <vector>

#include <frictionid/io/compare_report.hpp>
#include <frictionid/io/summary_html.hpp>

#include "io/report_parts.hpp"

namespace frictionid::page_style_test {
namespace {

// One CSS rule: the @media condition around it ("" for none), one selector of its list, its
// declarations (property -> value, both trimmed).
struct Rule {
  std::string media;
  std::string selector;
  std::map<std::string, std::string> declarations;
};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

// The text of every <style> element of a page.
std::string style_text(const std::string& page) {
  std::string css;
  for (auto at = page.find("<style>"); at != std::string::npos; at = page.find("<style>", at)) {
    const auto end = page.find("</style>", at);
    css += page.substr(at + 7, end - at - 7) + "\n";
    at = end;
  }
  return css;
}

// The rules of a style sheet without comments, at most one level of @media deep.
void parse_rules(const std::string& css, const std::string& media, std::vector<Rule>& out) {
  std::size_t pos = 0;
  while (true) {
    const auto open = css.find('{', pos);
    if (open == std::string::npos) return;
    const std::string head = trim(css.substr(pos, open - pos));
    // The block's end: the brace that closes this one.
    std::size_t close = open + 1;
    for (int depth = 1; depth > 0; ++close)
      depth += css[close] == '{' ? 1 : css[close] == '}' ? -1 : 0;
    const std::string body = css.substr(open + 1, close - open - 2);
    if (head.rfind("@media", 0) == 0) {
      parse_rules(body, trim(head.substr(6)), out);
    } else {
      std::map<std::string, std::string> declarations;
      std::size_t at = 0;
      while (at < body.size()) {
        auto semicolon = body.find(';', at);
        if (semicolon == std::string::npos) semicolon = body.size();
        const std::string d = body.substr(at, semicolon - at);
        const auto colon = d.find(':');
        if (colon != std::string::npos)
          declarations[trim(d.substr(0, colon))] = trim(d.substr(colon + 1));
        at = semicolon + 1;
      }
      std::size_t from = 0;
      while (from <= head.size()) {
        auto comma = head.find(',', from);
        if (comma == std::string::npos) comma = head.size();
        out.push_back({media, trim(head.substr(from, comma - from)), declarations});
        from = comma + 1;
      }
    }
    pos = close;
  }
}

std::vector<Rule> rules_of(const std::string& page) {
  std::string css = style_text(page);
  for (auto c = css.find("/*"); c != std::string::npos; c = css.find("/*"))
    css.erase(c, css.find("*/", c) + 2 - c);
  std::vector<Rule> rules;
  parse_rules(css, "", rules);
  return rules;
}

// The value print gives `property` for `selector` by a rule of its own: empty when none does.
std::string in_print(const std::vector<Rule>& rules, const std::string& selector,
                     const std::string& property) {
  std::string value;
  for (const auto& r : rules)
    if (r.media == "print" && r.selector == selector) {
      const auto it = r.declarations.find(property);
      if (it != r.declarations.end()) value = it->second;
    }
  return value;
}

bool scrolls(const std::string& value) {
  return value == "auto" || value == "scroll";
}

// The pages: report.html, compare.html and summary.html (shared.html is summary.html's page).
std::vector<std::pair<std::string, std::string>> pages() {
  FitResult r;
  r.model = "seed";
  r.pressure = "hertz";
  return {{"report.html", report_html_page(r, {})},
          {"compare.html", compare_html_page(ModelComparison{}, {})},
          {"summary.html", summary_html({}, SummaryHtmlOptions{})}};
}

TEST(PrintStyle, HeadingsStayWithWhatFollowsThem) {
  for (const auto& [name, page] : pages()) {
    const auto rules = rules_of(page);
    for (const char* heading : {"h1", "h2", "h3"})
      EXPECT_EQ(in_print(rules, heading, "break-after"), "avoid") << name << " " << heading;
  }
}

TEST(PrintStyle, TablesAndFiguresAreKeptWhole) {
  for (const auto& [name, page] : pages()) {
    const auto rules = rules_of(page);
    for (const char* block : {"table", "figure", "figure.plot", "tr"})
      EXPECT_EQ(in_print(rules, block, "break-inside"), "avoid") << name << " " << block;
  }
}

// Every box that scrolls or sticks on screen is plain on paper: a printed page cannot scroll,
// and a scroll box would cut its table or plot off at the edge.
TEST(PrintStyle, NothingScrollsOrSticksOnPaper) {
  for (const auto& [name, page] : pages()) {
    const auto rules = rules_of(page);
    std::size_t scroll_boxes = 0;
    for (const auto& r : rules) {
      if (r.media == "print") {
        for (const auto& [property, value] : r.declarations) {
          if (property.rfind("overflow", 0) == 0) {
            EXPECT_FALSE(scrolls(value)) << name;
          }
          if (property == "position") {
            EXPECT_NE(value, "sticky") << name << " " << r.selector;
          }
        }
        continue;
      }
      for (const auto& [property, value] : r.declarations) {
        if (property.rfind("overflow", 0) == 0 && scrolls(value)) {
          ++scroll_boxes;
          // "overflow" in print covers overflow-x and overflow-y.
          const std::string print = in_print(rules, r.selector, "overflow");
          EXPECT_EQ(print.empty() ? in_print(rules, r.selector, property) : print, "visible")
              << name << ": " << r.selector << " { " << property << ": " << value << " }";
        }
        if (property == "position" && (value == "sticky" || value == "fixed")) {
          EXPECT_EQ(in_print(rules, r.selector, "position"), "static")
              << name << ": " << r.selector;
        }
      }
    }
    EXPECT_GT(scroll_boxes, 0u) << name << ": the pages' scroll boxes were not found";
  }
}

// The parser reads what it should: a rule list, @media blocks and comments.
TEST(PrintStyle, TheCssReaderReadsRulesAndMedia) {
  const auto rules = rules_of(
      "<style>/* a } */ a, b { overflow-x: auto; }\n@media print { a { overflow: "
      "visible } }</style>");
  ASSERT_EQ(rules.size(), 3u);
  EXPECT_EQ(rules[1].selector, "b");
  EXPECT_EQ(rules[1].declarations.at("overflow-x"), "auto");
  EXPECT_EQ(in_print(rules, "a", "overflow"), "visible");
  EXPECT_EQ(in_print(rules, "b", "overflow"), "");
}

}  // namespace
}  // namespace frictionid::page_style_test
