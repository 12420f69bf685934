#include "io/text.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace frictionid::text::text_test {
namespace {

TEST(ParseDoubleStrict, ReturnsNullOnSuccessAndReasonOnFailure) {
  double v = 0;
  EXPECT_EQ(parse_double_strict("2.5", v), nullptr);
  EXPECT_EQ(v, 2.5);
  EXPECT_NE(parse_double_strict("2.5 ", v), nullptr);  // no trimming at this level
  EXPECT_STREQ(parse_double_strict("", v), "empty");
}

// Short decimals take a fast path of their own; they must read bit for bit as from_chars reads
// them, the sign of a zero and the rounding of the last digit included.
TEST(ParseDoubleStrict, ShortDecimalsReadBitIdenticalToFromChars) {
  const auto expect_as_from_chars = [](const std::string& text) {
    double expected = 0, got = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), expected);
    ASSERT_TRUE(ec == std::errc() && ptr == text.data() + text.size()) << text;
    ASSERT_EQ(parse_double_strict(text, got), nullptr) << text;
    std::uint64_t a, b;
    std::memcpy(&a, &expected, sizeof a);
    std::memcpy(&b, &got, sizeof b);
    ASSERT_EQ(a, b) << text;
  };
  for (const char* text : {"0",
                           "-0",
                           "0.0",
                           "-0.000",
                           "7",
                           "2000",
                           "-2",
                           "00012",
                           "0.05",
                           "-1.25",
                           "5.",
                           ".5",
                           "-.5",
                           "0.1",
                           "0.3",
                           "1.7976931348623157",
                           "9007199254740992",
                           "9007199254740993",
                           "900719925474099.3",
                           "0.9007199254740993",
                           "123456789012345678",
                           "1234567890123456789",
                           "12345678901234567890",
                           "0.000000000000000001",
                           "0.0000000000000000001"})
    expect_as_from_chars(text);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 200000; ++i) {
    std::string text = std::to_string(rng() >> (rng() % 64));
    const std::size_t after_point = rng() % 20;
    if (after_point > 0 && after_point <= text.size())
      text.insert(text.size() - after_point, 1, '.');
    if (rng() % 2) text.insert(0, 1, '-');
    expect_as_from_chars(text);
  }
  double v = 0;
  EXPECT_STREQ(parse_double_strict("1.2.3", v), "unexpected characters after the number");
  EXPECT_STREQ(parse_double_strict("12a", v), "unexpected characters after the number");
  EXPECT_STREQ(parse_double_strict(".", v), "not a number");
  EXPECT_STREQ(parse_double_strict("-", v), "not a number");
  EXPECT_EQ(parse_double_strict("+7", v), nullptr);
  EXPECT_EQ(v, 7.0);
}

TEST(Trim, RemovesSpacesAndTabsAtBothEndsOnly) {
  EXPECT_EQ(trim(" \t a b\t "), "a b");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim(" \t"), "");
}

TEST(Shown, QuotesCutsAndEscapesControlCharacters) {
  EXPECT_EQ(shown("v_x"), "'v_x'");
  EXPECT_EQ(shown("a\rb"), "'a\\x0db'");
  EXPECT_EQ(shown(std::string(70, 'x')), "'" + std::string(60, 'x') + "...'");
  EXPECT_EQ(shown(std::string(70, 'x'), std::string::npos), "'" + std::string(70, 'x') + "'");
}

TEST(EditDistance, CountsEditsAndAdjacentTranspositionsIgnoringCase) {
  EXPECT_EQ(edit_distance("omega", "omega"), 0u);
  EXPECT_EQ(edit_distance("OMEGA", "omega"), 0u);
  EXPECT_EQ(edit_distance("omgea", "omega"), 1u);  // one transposition
  EXPECT_EQ(edit_distance("v_x", "vx"), 1u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(MisspellingDistance, AllowsOneEditForShortNamesAndTwoFromSixCharacters) {
  EXPECT_EQ(misspelling_distance("vx", "v_x"), 1u);
  EXPECT_EQ(misspelling_distance("wx", "v_y"), std::numeric_limits<std::size_t>::max());
  EXPECT_EQ(misspelling_distance("M_rol", "M_roll"), 1u);
  EXPECT_EQ(misspelling_distance("Mroll_", "M_roll"), 2u);
}

}  // namespace
}  // namespace frictionid::text::text_test

namespace frictionid::text::text_test {
namespace {

TEST(ShownText, EveryByteThatIsNotPrintableAsciiIsEscaped) {
  EXPECT_EQ(shown("omega\xFF\xFE\x8B"), "'omega\\xff\\xfe\\x8b'");
  EXPECT_EQ(shown("\xE2\x80\x8Bv_x"), "'\\xe2\\x80\\x8bv_x'");
  EXPECT_EQ(shown("a\rb\x7F"), "'a\\x0db\\x7f'");
}

TEST(InvisibleCharacters, CountAsOneEditForDidYouMean) {
  EXPECT_EQ(misspelling_distance("\xE2\x80\x8Bv_x", "v_x"), 1u);
  EXPECT_EQ(misspelling_distance("\xEF\xBB\xBFomega", "omega"), 1u);
  EXPECT_EQ(without_invisible("\xC2\xA0N\xE2\x80\x8D"), "N");
}

TEST(CommandLine, QuotesOnlyWordsAShellWouldSplitAndEscapesControlBytes) {
  EXPECT_EQ(command_line({"frictionid", "fit", "data/run 1.csv", "--fix", "kappa=1.2", ""}),
            "frictionid fit 'data/run 1.csv' --fix kappa=1.2 ''");
  EXPECT_EQ(command_line({"it's", "a$b", "x*"}), "'it'\\''s' 'a$b' 'x*'");
  // A control character or a non-ASCII byte cannot reach a page or a terminal as such.
  EXPECT_EQ(command_line({"a\x1b[2Jb", "é"}), "'a\\x1b[2Jb' '\\xc3\\xa9'");
}

}  // namespace
}  // namespace frictionid::text::text_test
