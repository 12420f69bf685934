// Numbers with their uncertainty, as the pages show them (io/estimate_text.hpp).
#include "io/estimate_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

namespace frictionid {
namespace {

constexpr const char* kNbsp = "\u00a0";

// Fixed notation below 10^7 and up to 6 decimals, or up to 12 for numbers of 0.001 and more
// ("0.85000010"); beyond, the reader would count zeros ("0.0000000072", "123456789"), and the
// shared exponent reads better.
constexpr int kFinestFixedPlace = -6;
constexpr int kFinestFixedPlaceOfLargerNumbers = -12;
constexpr double kLargerNumber = 1e-3;
constexpr double kLargestFixed = 1e7;

// The decimal exponent x has in "%e" form once rounded to `digits` significant digits
// (0.0996 to 2 digits is 1.0e-01, exponent -1).
int exponent_at(double x, int digits) {
  const std::string s = fmt::format("{:.{}e}", std::abs(x), std::max(0, digits - 1));
  return std::atoi(s.c_str() + s.find('e') + 1);
}

// "× 10⁻⁸", with no-break spaces so that no line ends inside.
std::string power_of_ten(int e) {
  static const char* const kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string digits;
  for (char ch : std::to_string(std::abs(e))) digits += kDigits[ch - '0'];
  return std::string("×") + kNbsp + "10" + (e < 0 ? "⁻" : "") + digits;
}

// "-0.00" and "-0" say a sign the number does not have.
std::string without_negative_zero(std::string s) {
  if (!s.empty() && s[0] == '-' && s.find_first_of("123456789") == std::string::npos) s.erase(0, 1);
  return s;
}

// x times 10^-e, with one rounding only (10^|e| is exact for |e| <= 22).
double scaled(double x, int e) {
  return e >= 0 ? x / std::pow(10.0, e) : x * std::pow(10.0, -e);
}

// x rounded to the decimal place 10^place in fixed notation (place > 0 rounds to tens, ...).
std::string fixed_at(double x, int place) {
  if (place > 0)
    return without_negative_zero(
        fmt::format("{:.0f}", std::round(scaled(x, place)) * std::pow(10.0, place)));
  return without_negative_zero(fmt::format("{:.{}f}", x, -place));
}

// Whether numbers up to `magnitude`, rounded to 10^place, read well without an exponent.
bool fixed_reads_well(double magnitude, int place) {
  if (magnitude >= kLargestFixed) return false;
  return place >= kFinestFixedPlace ||
         (magnitude >= kLargerNumber && place >= kFinestFixedPlaceOfLargerNumbers);
}

// The exponent a group of numbers up to `magnitude`, rounded to 10^place, share.
int shared_exponent(double magnitude, int place) {
  const int e = exponent_at(magnitude, 1);
  return exponent_at(magnitude, std::max(1, e - place + 1));
}

}  // namespace

std::string plain_number(double x) {
  if (std::isnan(x)) return kNoNumber;
  if (std::isinf(x)) return x > 0 ? "+inf" : "-inf";
  const std::string g = fmt::format("{:.6g}", x);
  const auto e = g.find('e');
  if (e == std::string::npos) return g;
  return g.substr(0, e) + kNbsp + power_of_ten(std::atoi(g.c_str() + e + 1));
}

std::string relative_error_text(double value, double stderr_value) {
  if (!std::isfinite(value) || !std::isfinite(stderr_value) || value == 0 || stderr_value < 0)
    return {};
  const double percent = 100.0 * stderr_value / std::abs(value);
  if (!std::isfinite(percent)) return {};
  if (percent == 0) return "0 %";
  const int place = exponent_at(percent, 2) - 1;
  return fixed_at(percent, std::min(0, place)) + " %";
}

EstimateText estimate_text(double value, std::optional<double> stderr_value) {
  EstimateText t;
  if (!std::isfinite(value)) {
    t.value = kNoNumber;
    return t;
  }
  const bool usable = stderr_value && std::isfinite(*stderr_value) && *stderr_value >= 0;
  if (!usable) {
    t.value = plain_number(value);
    return t;
  }
  const double s = *stderr_value;
  t.relative = relative_error_text(value, s);
  if (s == 0) {
    t.value = plain_number(value);
    t.error = "0";
    return t;
  }
  const int place = exponent_at(s, 2) - 1;  // the place of the error's second digit
  const double magnitude = std::max(std::abs(value), s);
  if (fixed_reads_well(magnitude, place)) {
    t.value = fixed_at(value, place);
    t.error = fixed_at(s, place);
    return t;
  }
  const int e = shared_exponent(magnitude, place);
  t.value = fixed_at(scaled(value, e), std::min(0, place - e));
  t.error = fixed_at(scaled(s, e), std::min(0, place - e));
  t.exponent = power_of_ten(e);
  return t;
}

std::string EstimateText::joined() const {
  if (error.empty()) return value_alone();
  if (exponent.empty()) return value + " ± " + error;
  return "(" + value + " ± " + error + ")" + kNbsp + exponent;
}

std::string EstimateText::value_alone() const {
  return exponent.empty() ? value : value + kNbsp + exponent;
}

std::string EstimateText::error_alone() const {
  if (error.empty()) return kNoNumber;
  return exponent.empty() ? error : error + kNbsp + exponent;
}

std::string stderr_text(std::optional<double> stderr_value) {
  // Next to a value of 0 the error sets the magnitude alone.
  return estimate_text(0.0, stderr_value).error_alone();
}

std::pair<std::string, std::string> interval_text(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    return {plain_number(lo), plain_number(hi)};
  const int place = exponent_at(hi - lo, 2) - 1;  // 2 significant digits of the width
  const double magnitude = std::max(std::abs(lo), std::abs(hi));
  if (fixed_reads_well(magnitude, place)) return {fixed_at(lo, place), fixed_at(hi, place)};
  const int e = shared_exponent(magnitude, place);
  const std::string factor = std::string(kNbsp) + power_of_ten(e);
  return {fixed_at(scaled(lo, e), std::min(0, place - e)) + factor,
          fixed_at(scaled(hi, e), std::min(0, place - e)) + factor};
}

}  // namespace frictionid
