#include "app/option_parsers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>

#include <frictionid/io/input_error.hpp>

namespace frictionid::option_parsers_test {
namespace {

// The InputError thrown by `f`, or a test failure when it returns normally.
InputError rejected(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("(no error thrown)");
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// --- parse_assignments ---

TEST(ParseAssignments, ReadsNameValuePairs) {
  const auto m = parse_assignments("--param", "f=0.8,kappa=1.2,h=-3e-2");
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m.at("f"), 0.8);
  EXPECT_EQ(m.at("kappa"), 1.2);
  EXPECT_EQ(m.at("h"), -3e-2);
}

TEST(ParseAssignments, AllowsSpacesAroundNamesAndValues) {
  const auto m = parse_assignments("--fix", " f = 0.5 , b_tilde=2 ");
  EXPECT_EQ(m.at("f"), 0.5);
  EXPECT_EQ(m.at("b_tilde"), 2.0);
}

TEST(ParseAssignments, ErrorNamesTheOptionInFileSlot) {
  const InputError e = rejected([] { parse_assignments("--fix", "f"); });
  EXPECT_EQ(e.file(), "--fix");
  EXPECT_TRUE(Contains(e.what(), "--fix: "));
}

TEST(ParseAssignments, RejectsDuplicateName) {
  const InputError e = rejected([] { parse_assignments("--param", "f=1,kappa=2,f=3"); });
  EXPECT_TRUE(Contains(e.what(), "'f'"));
  EXPECT_TRUE(Contains(e.what(), "more than once"));
}

TEST(ParseAssignments, RejectsEmptyName) {
  const InputError e = rejected([] { parse_assignments("--param", "f=1,=2"); });
  EXPECT_TRUE(Contains(e.what(), "missing name"));
  EXPECT_TRUE(Contains(e.what(), "'=2'"));
}

TEST(ParseAssignments, RejectsMissingEquals) {
  const InputError e = rejected([] { parse_assignments("--param", "f=1,kappa1.2"); });
  EXPECT_TRUE(Contains(e.what(), "missing '='"));
  EXPECT_TRUE(Contains(e.what(), "'kappa1.2'"));
}

TEST(ParseAssignments, RejectsNonNumericValue) {
  const InputError e = rejected([] { parse_assignments("--param", "f=abc"); });
  EXPECT_TRUE(Contains(e.what(), "'abc'"));
  EXPECT_TRUE(Contains(e.what(), "finite decimal number"));
}

TEST(ParseAssignments, RejectsEmptyValue) {
  const InputError e = rejected([] { parse_assignments("--param", "f="); });
  EXPECT_TRUE(Contains(e.what(), "'f'"));
  EXPECT_TRUE(Contains(e.what(), "empty"));
}

TEST(ParseAssignments, RejectsNaNAndInf) {
  for (const char* spec : {"f=nan", "f=NaN", "f=inf", "f=-Infinity"}) {
    SCOPED_TRACE(spec);
    const InputError e = rejected([&] { parse_assignments("--param", spec); });
    EXPECT_TRUE(Contains(e.what(), std::string(spec).substr(2)));
  }
}

TEST(ParseAssignments, RejectsEmptyEntry) {
  EXPECT_THROW(parse_assignments("--param", "f=1,,kappa=2"), InputError);
  EXPECT_THROW(parse_assignments("--param", "f=1,"), InputError);
}

TEST(ParseAssignments, RejectsEmptySpec) {
  EXPECT_THROW(parse_assignments("--param", ""), InputError);
  EXPECT_THROW(parse_assignments("--param", "  "), InputError);
}

TEST(ParseAssignments, RejectsNameWithOtherCharacters) {
  const InputError e = rejected([] { parse_assignments("--param", "f:1=2"); });
  EXPECT_TRUE(Contains(e.what(), "'f:1'"));
}

// --- parse_bounds ---

TEST(ParseBounds, ReadsRanges) {
  const auto m = parse_bounds("--bounds", "f=0.1:2,h=-0.5:0.5");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m.at("f"), std::make_pair(0.1, 2.0));
  EXPECT_EQ(m.at("h"), std::make_pair(-0.5, 0.5));
}

TEST(ParseBounds, RejectsLowerNotBelowUpper) {
  const InputError equal = rejected([] { parse_bounds("--bounds", "f=1:1"); });
  EXPECT_TRUE(Contains(equal.what(), "lo < hi"));
  EXPECT_TRUE(Contains(equal.what(), "'1:1'"));
  EXPECT_THROW(parse_bounds("--bounds", "f=2:1"), InputError);
}

TEST(ParseBounds, RejectsMissingOrExtraColon) {
  EXPECT_TRUE(Contains(rejected([] { parse_bounds("--bounds", "f=0.1"); }).what(), "':'"));
  EXPECT_TRUE(Contains(rejected([] { parse_bounds("--bounds", "f=0:1:2"); }).what(), "'0:1:2'"));
}

TEST(ParseBounds, RejectsMissingEquals) {
  EXPECT_TRUE(Contains(rejected([] { parse_bounds("--bounds", "f0:1"); }).what(), "missing '='"));
}

TEST(ParseBounds, RejectsEmptyOrNonFiniteEnds) {
  for (const char* spec : {"f=:1", "f=0:", "f=-inf:1", "f=0:inf", "f=nan:1", "f=0:x"}) {
    SCOPED_TRACE(spec);
    EXPECT_THROW(parse_bounds("--bounds", spec), InputError);
  }
}

TEST(ParseBounds, RejectsDuplicateName) {
  EXPECT_TRUE(
      Contains(rejected([] { parse_bounds("--bounds", "f=0:1,f=1:2"); }).what(), "more than once"));
}

// --- parse_name_list ---

TEST(ParseNameList, KeepsGivenOrder) {
  const auto v = parse_name_list("--channels", "M_z, T_x,M_roll");
  EXPECT_EQ(v, (std::vector<std::string>{"M_z", "T_x", "M_roll"}));
}

TEST(ParseNameList, RejectsDuplicateName) {
  const InputError e = rejected([] { parse_name_list("--channels", "T_x,M_z,T_x"); });
  EXPECT_TRUE(Contains(e.what(), "'T_x'"));
  EXPECT_TRUE(Contains(e.what(), "more than once"));
  EXPECT_EQ(e.file(), "--channels");
}

TEST(ParseNameList, RejectsEmptyName) {
  EXPECT_THROW(parse_name_list("--channels", "T_x,,M_z"), InputError);
  EXPECT_THROW(parse_name_list("--channels", ",T_x"), InputError);
  EXPECT_THROW(parse_name_list("--channels", ""), InputError);
}

TEST(ParseNameList, RejectsNameWithOtherCharacters) {
  EXPECT_TRUE(
      Contains(rejected([] { parse_name_list("--channels", "T_x;M_z"); }).what(), "'T_x;M_z'"));
}

// --- parse_number / parse_double_strict ---

TEST(ParseNumber, AcceptsDecimalForms) {
  EXPECT_EQ(parse_number("--vx", "1"), 1.0);
  EXPECT_EQ(parse_number("--vx", "-2.5"), -2.5);
  EXPECT_EQ(parse_number("--vx", "+3"), 3.0);
  EXPECT_EQ(parse_number("--vx", ".5"), 0.5);
  EXPECT_EQ(parse_number("--vx", "5."), 5.0);
  EXPECT_EQ(parse_number("--vx", "1E-300"), 1e-300);
  EXPECT_EQ(parse_number("--vx", " 7 "), 7.0);
  EXPECT_EQ(parse_number("--vx", "4.9406564584124654e-324"),
            std::numeric_limits<double>::denorm_min());
}

TEST(ParseNumber, SeventeenDigitTextRoundTripsBitIdentical) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-330, 300);
  char buf[64];
  for (int i = 0; i < 20000; ++i) {
    double x = mantissa(rng) * std::pow(10.0, exponent(rng));
    if (i % 7 == 0) x = std::ldexp(mantissa(rng), -1060);  // subnormal
    std::snprintf(buf, sizeof buf, "%.17g", x);
    ASSERT_EQ(bits(parse_number("x", buf)), bits(x)) << buf;
  }
}

TEST(ParseNumber, ErrorNamesWhatAndQuotesText) {
  const InputError e = rejected([] { parse_number("--omega", "12x"); });
  EXPECT_EQ(e.file(), "--omega");
  EXPECT_TRUE(Contains(e.what(), "'12x'"));
  EXPECT_TRUE(Contains(e.what(), "finite decimal number"));
}

TEST(ParseNumber, RejectsTrailingGarbage) {
  for (const char* t : {"1.5x", "1,5", "1 2", "1e", "1e+", "--1", "+-1", "++1", "0.5.1"}) {
    SCOPED_TRACE(t);
    EXPECT_THROW(parse_number("x", t), InputError);
  }
}

TEST(ParseNumber, RejectsEmpty) {
  EXPECT_THROW(parse_number("x", ""), InputError);
  EXPECT_THROW(parse_number("x", "   "), InputError);
  EXPECT_THROW(parse_number("x", "+"), InputError);
  EXPECT_THROW(parse_number("x", "-"), InputError);
}

TEST(ParseNumber, RejectsNaNAndInf) {
  for (const char* t : {"nan", "NAN", "-nan", "nan(0x1)", "inf", "-INF", "infinity", "+inf"}) {
    SCOPED_TRACE(t);
    EXPECT_THROW(parse_number("x", t), InputError);
  }
}

TEST(ParseNumber, RejectsHexFloat) {
  for (const char* t : {"0x1p3", "0X10", "-0x1.8p1", "+0x2"}) {
    SCOPED_TRACE(t);
    EXPECT_TRUE(Contains(rejected([&] { parse_number("x", t); }).what(), "hexadecimal"));
  }
}

TEST(ParseNumber, RejectsOverflow) {
  for (const char* t : {"1e309", "-1e309", "1.7976931348623159e308"}) {
    SCOPED_TRACE(t);
    EXPECT_TRUE(
        Contains(rejected([&] { parse_number("x", t); }).what(), "out of the double range"));
  }
  EXPECT_EQ(parse_number("x", "1.7976931348623157e308"), std::numeric_limits<double>::max());
}

TEST(ParseNumber, RejectsUnderflowToZero) {
  EXPECT_TRUE(Contains(rejected([] { parse_number("x", "1e-400"); }).what(), "out of the"));
  EXPECT_EQ(parse_number("x", "0e-400"), 0.0);
}

TEST(ParseColumnMap, ReadsCanonicalToHeaderPairs) {
  const ColumnMap m = parse_column_map("v_x=speed, omega = spin rate");
  EXPECT_EQ(m.canonical_to_header,
            (std::map<std::string, std::string>{{"v_x", "speed"}, {"omega", "spin rate"}}));
  EXPECT_TRUE(parse_column_map("").canonical_to_header.empty());
}

TEST(ParseColumnMap, UnknownCanonicalNameRejectedWithSuggestion) {
  try {
    parse_column_map("v_x=speed,omgea=spin");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--columns");
    EXPECT_TRUE(Contains(e.what(), "'omgea'"));
    EXPECT_TRUE(Contains(e.what(), "did you mean 'omega'?"));
  }
}

TEST(ParseColumnMap, MalformedEntriesRejected) {
  EXPECT_THROW(parse_column_map("v_x"), InputError);             // missing '='
  EXPECT_THROW(parse_column_map("v_x="), InputError);            // empty header name
  EXPECT_THROW(parse_column_map("v_x=a,,omega=b"), InputError);  // empty entry
  EXPECT_THROW(parse_column_map("v_x=a,v_x=b"), InputError);     // canonical twice
  EXPECT_THROW(parse_column_map("v_x=a,v_y=a"), InputError);     // header twice
}

}  // namespace
}  // namespace frictionid::option_parsers_test

namespace frictionid::option_parsers_test {
namespace {

TEST(WholeNumbers, NegativesAreRejectedNotWrapped) {
  const InputError e = rejected([] { parse_whole_number("--seed", "-1", 0, UINT64_MAX); });
  EXPECT_EQ(e.file(), "--seed");
  EXPECT_NE(std::string(e.what()).find("negative"), std::string::npos) << e.what();
}

TEST(WholeNumbers, ValuesPastTheTypeOrTheLimitAreRejectedNotClamped) {
  for (const char* text : {"18446744073709551616", "99999999999999999999999"})
    EXPECT_NE(
        std::string(rejected([&] { parse_whole_number("--seed", text, 0, UINT64_MAX); }).what())
            .find("too large"),
        std::string::npos);
  EXPECT_NE(std::string(
                rejected([] { parse_whole_number("--seed", "4294967297", 0, 4294967295u); }).what())
                .find("from 0 to 4294967295"),
            std::string::npos);
}

TEST(WholeNumbers, FractionsExponentsAndSignsAreNotWholeNumbers) {
  for (const char* text : {"1e3", "2.0", "+5", "0x10", "", " ", "5 5"})
    rejected([&] { parse_whole_number("--rows", text, 1, 10); });
}

TEST(WholeNumbers, TheRangeEndsAreIncluded) {
  EXPECT_EQ(parse_whole_number("--rows", "1", 1, 10), 1u);
  EXPECT_EQ(parse_whole_number("--rows", " 10 ", 1, 10), 10u);
  EXPECT_EQ(parse_whole_number("--seed", "18446744073709551615", 0, UINT64_MAX), UINT64_MAX);
  rejected([] { parse_whole_number("--rows", "0", 1, 10); });
}

}  // namespace
}  // namespace frictionid::option_parsers_test

namespace frictionid::option_parsers_test {
namespace {

// --- parse_contact_option (--contact SPOT) ---

TEST(ParseContactOption, ReadsEachKindOfSpotWithItsAspect) {
  EXPECT_EQ(parse_contact_option("circle").kind, model::SpotKind::Circle);
  const auto ellipse = parse_contact_option("ellipse:0.6");
  EXPECT_EQ(ellipse.kind, model::SpotKind::Ellipse);
  EXPECT_EQ(ellipse.q, 0.6);
  const auto rect = parse_contact_option("rect:4");
  EXPECT_EQ(rect.kind, model::SpotKind::Rect);
  EXPECT_EQ(rect.q, 4.0);
}

TEST(ParseContactOption, AnAspectOutsideZeroToFourOrNotANumberIsRejectedNamingTheOption) {
  for (const char* spec : {"ellipse:0", "ellipse:-0.5", "rect:4.0000001", "rect:1e9"}) {
    const InputError e = rejected([spec] { parse_contact_option(spec); });
    EXPECT_EQ(e.file(), "--contact");
    EXPECT_TRUE(Contains(e.what(), "expected 0 < Q <= 4")) << spec;
  }
  for (const char* spec : {"ellipse:", "ellipse:nan", "rect:inf", "rect:0.5x", "ellipse:one"}) {
    const InputError e = rejected([spec] { parse_contact_option(spec); });
    EXPECT_EQ(e.file(), "--contact");
    EXPECT_TRUE(Contains(e.what(), "expected circle, ellipse:Q, rect:Q (0 < Q <= 4) or map:FILE"))
        << spec;
  }
}

TEST(ParseContactOption, AnUnknownSpotListsTheKinds) {
  const InputError e = rejected([] { parse_contact_option("square:1"); });
  EXPECT_TRUE(Contains(e.what(), "--contact: unknown contact spot 'square:1'"));
  EXPECT_TRUE(Contains(e.what(), "map:FILE"));
  EXPECT_TRUE(Contains(rejected([] { parse_contact_option("map:"); }).what(), "needs a file name"));
}

TEST(ParseContactOption, AMapFilesErrorsKeepNamingTheFileLineAndColumn) {
  const std::string path = ::testing::TempDir() + "contact_option_bad_map.csv";
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("x,y,sigma0\n0,0,1\n1,0,1\n0,1,-2\n1,1,1\n", f);
  std::fclose(f);
  const InputError e = rejected([&] { parse_contact_option("map:" + path); });
  std::remove(path.c_str());
  EXPECT_EQ(e.file(), path);
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.column(), 3u);
}

TEST(ParseContactList, ReadsCompareSpotsInOrderAndRejectsRepeats) {
  EXPECT_EQ(parse_contact_list("--contact", "circle, ellipse:0.7"),
            (std::vector<std::string>{"circle", "ellipse:0.7"}));
  EXPECT_TRUE(Contains(rejected([] { parse_contact_list("--contact", "circle,circle"); }).what(),
                       "more than once"));
  EXPECT_TRUE(Contains(rejected([] { parse_contact_list("--contact", "circle,rect:5"); }).what(),
                       "expected 0 < Q <= 4"));
}

}  // namespace
}  // namespace frictionid::option_parsers_test

namespace frictionid::option_parsers_test {
namespace {

// A file is read in one form: a native column may be mapped to a header that is also a
// wheel-form name (a native file whose T_x column is called Fx), while two columns of one form
// still cannot share a header.
TEST(ParseColumnMap, ANativeColumnMayTakeAHeaderThatIsAWheelFormName) {
  const ColumnMap m = parse_column_map("v_x=speed,omega=spin,T_x=Fx");
  EXPECT_EQ(m.canonical_to_header.at("T_x"), "Fx");
  EXPECT_THROW(parse_column_map("v_x=omega"), InputError);
  EXPECT_THROW(parse_column_map("V=alpha"), InputError);
}

}  // namespace
}  // namespace frictionid::option_parsers_test
