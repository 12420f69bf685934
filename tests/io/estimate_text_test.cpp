#include "io/estimate_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace frictionid::estimate_text_test {
namespace {

const std::string kNbsp = "\u00a0";
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(EstimateText, StderrToTwoDigitsAndValueToTheSamePlace) {
  // The "0.850039 ± 7.19256e-05".
  const EstimateText t = estimate_text(0.850039, 7.19256e-05);
  EXPECT_EQ(t.value, "0.850039");
  EXPECT_EQ(t.error, "0.000072");
  EXPECT_EQ(t.exponent, "");
  EXPECT_EQ(t.joined(), "0.850039 ± 0.000072");
  EXPECT_EQ(t.relative, "0.0085 %");

  EXPECT_EQ(estimate_text(1.23456789, 0.0123).joined(), "1.235 ± 0.012");
  EXPECT_EQ(estimate_text(12.3456, 1.5).joined(), "12.3 ± 1.5");
  EXPECT_EQ(estimate_text(1234.5, 56.0).joined(), "1234 ± 56");
}

TEST(EstimateText, ValueDropsDigitsItsErrorDoesNotSupport) {
  // Six digits of a value whose error is in the second: the value is rounded to it.
  EXPECT_EQ(estimate_text(0.0612345, 0.0123).joined(), "0.061 ± 0.012");
  // An error of 123 makes the units digit of the value noise: rounded to tens.
  EXPECT_EQ(estimate_text(45678.9, 123.0).joined(), "45680 ± 120");
}

TEST(EstimateText, RoundingTheErrorUpCarriesIntoTheNextDigit) {
  // 0.0996 to two digits is 0.10, so the value is rounded to hundredths, not thousandths.
  EXPECT_EQ(estimate_text(1.23456, 0.0996).joined(), "1.23 ± 0.10");
  EXPECT_EQ(estimate_text(5.0, 0.996).joined(), "5.0 ± 1.0");
}

TEST(EstimateText, NegativeValuesKeepTheirSignAndNegativeZeroLosesIt) {
  EXPECT_EQ(estimate_text(-0.850039, 7.19256e-05).joined(), "-0.850039 ± 0.000072");
  EXPECT_EQ(estimate_text(-0.850039, 7.19256e-05).relative, "0.0085 %");
  EXPECT_EQ(estimate_text(-0.001, 0.5).joined(), "0.00 ± 0.50");
}

TEST(EstimateText, HugeAndTinyMagnitudesShareOneExponentWithoutAnEString) {
  const EstimateText tiny = estimate_text(1.23456e-9, 5.6e-11);
  EXPECT_EQ(tiny.joined(), "(1.235 ± 0.056)" + kNbsp + "×" + kNbsp + "10⁻⁹");
  EXPECT_EQ(tiny.value_alone(), "1.235" + kNbsp + "×" + kNbsp + "10⁻⁹");
  EXPECT_EQ(tiny.error_alone(), "0.056" + kNbsp + "×" + kNbsp + "10⁻⁹");
  EXPECT_EQ(tiny.relative, "4.5 %");

  const EstimateText huge = estimate_text(3.14159e12, 2.7e10);
  EXPECT_EQ(huge.joined(), "(3.142 ± 0.027)" + kNbsp + "×" + kNbsp + "10¹²");
  for (const std::string& s : {tiny.joined(), huge.joined()}) {
    EXPECT_EQ(s.find('e'), std::string::npos) << s;
    EXPECT_EQ(s.find(' ', s.find(')')), std::string::npos) << "a breakable space in " << s;
  }
  // Rounding the value may carry it into the next power of ten.
  EXPECT_EQ(estimate_text(9.99996e-9, 1.2e-11).joined(),
            "(1.0000 ± 0.0012)" + kNbsp + "×" + kNbsp + "10⁻⁸");
}

TEST(EstimateText, ValueWithoutStderrIsPlainSixDigits) {
  const EstimateText t = estimate_text(0.850039123, std::nullopt);
  EXPECT_EQ(t.joined(), "0.850039");
  EXPECT_EQ(t.error, "");
  EXPECT_EQ(t.error_alone(), "—");
  EXPECT_EQ(t.relative, "");
  // An error that is no error (NaN, infinite, negative) is shown as none.
  EXPECT_EQ(estimate_text(0.85, kNaN).joined(), "0.85");
  EXPECT_EQ(estimate_text(0.85, kInf).joined(), "0.85");
  EXPECT_EQ(estimate_text(0.85, -1.0).joined(), "0.85");
  EXPECT_EQ(estimate_text(7.19256e-05, std::nullopt).joined(),
            "7.19256" + kNbsp + "×" + kNbsp + "10⁻⁵");
}

TEST(EstimateText, StderrZeroShowsTheValueAndAZeroError) {
  const EstimateText t = estimate_text(0.85, 0.0);
  EXPECT_EQ(t.joined(), "0.85 ± 0");
  EXPECT_EQ(t.relative, "0 %");
  // Relative error of a zero value is undefined, not infinite.
  EXPECT_EQ(estimate_text(0.0, 0.01).relative, "");
  EXPECT_EQ(estimate_text(0.0, 0.01).joined(), "0.000 ± 0.010");
}

TEST(EstimateText, NaNAndInfiniteValuesShowAsADash) {
  EXPECT_EQ(estimate_text(kNaN, 0.1).joined(), "—");
  EXPECT_EQ(estimate_text(kInf, 0.1).joined(), "—");
  EXPECT_EQ(estimate_text(-kInf, std::nullopt).joined(), "—");
  EXPECT_EQ(estimate_text(kNaN, 0.1).relative, "");
}

TEST(IntervalText, EndsAreAlwaysToldApart) {
  // The "h = 0.06, 95 % interval 0.06 to 0.06".
  EXPECT_EQ(interval_text(0.059812, 0.060231),
            std::make_pair(std::string("0.05981"), std::string("0.06023")));
  EXPECT_EQ(interval_text(1.125, 1.375), std::make_pair(std::string("1.12"), std::string("1.38")));
  EXPECT_EQ(interval_text(-2.5, 40.0), std::make_pair(std::string("-2"), std::string("40")));
  // Ends that differ only in the seventh digit get the digits that tell them apart.
  const auto [lo, hi] = interval_text(0.8500001, 0.8500009);
  EXPECT_NE(lo, hi);
  EXPECT_EQ(lo, "0.85000010");
  EXPECT_EQ(hi, "0.85000090");
}

TEST(IntervalText, HugeAndTinyEndsShareOneExponent) {
  EXPECT_EQ(interval_text(1.1e-9, 1.3e-9), std::make_pair("1.10" + kNbsp + "×" + kNbsp + "10⁻⁹",
                                                          "1.30" + kNbsp + "×" + kNbsp + "10⁻⁹"));
}

TEST(IntervalText, PointAndNonFiniteEnds) {
  EXPECT_EQ(interval_text(0.5, 0.5), std::make_pair(std::string("0.5"), std::string("0.5")));
  EXPECT_EQ(interval_text(kNaN, 1.0), std::make_pair(std::string("—"), std::string("1")));
  EXPECT_EQ(interval_text(0.0, kInf), std::make_pair(std::string("0"), std::string("+inf")));
}

TEST(PlainNumber, SixDigitsWithAnUnbreakableExponent) {
  EXPECT_EQ(plain_number(0.850039123), "0.850039");
  EXPECT_EQ(plain_number(1e-300), "1" + kNbsp + "×" + kNbsp + "10⁻³⁰⁰");
  EXPECT_EQ(plain_number(-2.5e20), "-2.5" + kNbsp + "×" + kNbsp + "10²⁰");
  EXPECT_EQ(plain_number(kNaN), "—");
  EXPECT_EQ(plain_number(-kInf), "-inf");
}

}  // namespace
}  // namespace frictionid::estimate_text_test
