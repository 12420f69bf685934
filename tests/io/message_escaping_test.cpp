// Messages that reach a terminal or a Python exception: every byte of a path, label or value
// that is not printable ASCII is escaped, and a message quotes a bounded part of what it
// complains about, however large the input (src/io/text.hpp, InputError).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include "io/text.hpp"
#include "support/scratch_dir.hpp"

namespace frictionid::message_escaping_test {
namespace {

bool printable_ascii(const std::string& s) {
  for (const char c : s)
    if (!((c >= 0x20 && c < 0x7f) || c == '\t')) return false;
  return true;
}

// A file name that retitles and clears a terminal, and a label with a right-to-left override.
const std::string kTerminalEscape = "x\x1b]0;PWNED\a\x1b[2J.csv";
const std::string kRightToLeft =
    "r\xe2\x80\xae"
    "abc";

TEST(TerminalText, EscapesEveryByteThatIsNotPrintableAscii) {
  EXPECT_EQ(text::escaped(kTerminalEscape), "x\\x1b]0;PWNED\\x07\\x1b[2J.csv");
  EXPECT_EQ(text::escaped(kRightToLeft), "r\\xe2\\x80\\xaeabc");
  EXPECT_EQ(text::escaped("caf\xe9"), "caf\\xe9");  // Latin-1, not UTF-8
  EXPECT_EQ(text::escaped("a\nb\rc\x7f"), "a\\x0ab\\x0dc\\x7f");
  EXPECT_EQ(text::escaped("plain text, tab\there"), "plain text, tab\there");
}

TEST(TerminalText, EscapingTwiceChangesNothing) {
  for (const std::string& s : {kTerminalEscape, kRightToLeft, std::string("a\\x1b")})
    EXPECT_EQ(text::escaped(text::escaped(s)), text::escaped(s));
}

TEST(TerminalText, ALongMessageKeepsItsStartAndEndAndSaysHowMuchIsLeftOut) {
  const std::string message = "start " + std::string(40'000'000, '\x1b') + " end";
  const std::string shown = text::for_terminal(message);
  EXPECT_LE(shown.size(), text::kMaxMessageBytes + 64);
  EXPECT_TRUE(printable_ascii(shown));
  EXPECT_EQ(shown.rfind("start \\x1b", 0), 0u);
  EXPECT_EQ(shown.substr(shown.size() - 8), "\\x1b end");
  EXPECT_NE(shown.find(" bytes left out] ... "), std::string::npos);
  // Escapes are never cut in half.
  EXPECT_EQ(shown.find("\\x1 "), std::string::npos);
  EXPECT_EQ(text::for_terminal("short"), "short");
}

TEST(InputError, WhatEscapesTheFileNameAndTheMessage) {
  const InputError e(kTerminalEscape, 3, 2, "label " + kRightToLeft + " is odd");
  EXPECT_STREQ(e.what(), "x\\x1b]0;PWNED\\x07\\x1b[2J.csv:3:2: label r\\xe2\\x80\\xaeabc is odd");
  EXPECT_EQ(e.message(), "label r\\xe2\\x80\\xaeabc is odd");
  EXPECT_EQ(e.file(), kTerminalEscape);  // as given, for code that opens it
  // A message that quotes with shown() is unchanged.
  EXPECT_STREQ(InputError("f.csv", 1, 0, "found " + text::shown("a\rb")).what(),
               "f.csv:1: found 'a\\x0db'");
}

TEST(InputError, AMessageIsBoundedWhateverItQuotes) {
  const InputError e(std::string(100'000, 'p'), 7, 0, "found " + std::string(40'000'000, 'x'));
  EXPECT_LT(std::string(e.what()).size(), 2 * text::kMaxMessageBytes);
  EXPECT_LT(e.message().size(), text::kMaxMessageBytes + 64);
}

TEST(ShownText, QuotesAtMost200BytesEvenWhenAskedForAll) {
  const std::string huge(40'000'000, 'x');
  EXPECT_EQ(text::shown(huge, std::string::npos),
            "'" + std::string(text::kMaxQuotedBytes, 'x') + "...'");
  EXPECT_EQ(text::kMaxQuotedBytes, 200u);
}

TEST(DatasetCsvMessages, AHeaderOf200000FieldsGivesAMessageOfAFewHundredBytes) {
  test::ScratchDir dir("bounded_header_message");
  const std::string path = dir / "wide.csv";
  {
    std::ofstream out(path);
    for (int k = 0; k < 200'000; ++k) out << (k ? "," : "") << "column" << k;
    out << "\n";
  }
  try {
    load_dataset_csv(path);
    FAIL() << "a header without the required columns was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_LT(what.size(), 1500u) << what.substr(0, 2000);
    EXPECT_NE(what.find("'column0', 'column1'"), std::string::npos) << what;
    EXPECT_NE(what.find("more)"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace frictionid::message_escaping_test
