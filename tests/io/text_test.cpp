#include "io/text.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>

namespace frictionid::text {
namespace {

TEST(ParseDoubleStrict, ReturnsNullOnSuccessAndReasonOnFailure) {
  double v = 0;
  EXPECT_EQ(parse_double_strict("2.5", v), nullptr);
  EXPECT_EQ(v, 2.5);
  EXPECT_NE(parse_double_strict("2.5 ", v), nullptr);  // no trimming at this level
  EXPECT_STREQ(parse_double_strict("", v), "empty");
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
}  // namespace frictionid::text

namespace frictionid::text {
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

}  // namespace
}  // namespace frictionid::text
