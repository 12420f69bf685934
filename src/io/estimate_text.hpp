// How the human-facing pages (report.md, report.html, compare.*, summary.html) show a number
// with its uncertainty, by the convention of the PDG, lmfit and statsmodels: the standard error
// to 2 significant digits, the value rounded to the same decimal place, an interval to a digit
// that separates its ends, and the relative error. A "%.6g" value says six digits are known when
// the error may already be in the third; "0.06 to 0.06" says nothing at all. The JSON reports
// keep every digit; these texts are for reading only.
//
// No text here holds an "e-05": a browser may break a line inside it (at the '-'), and a reader
// takes "7.19256e-05" for a different kind of number than the value beside it. A value needing
// an exponent is shown as "7.2 × 10⁻⁵" with no-break spaces, and a value with its error shares
// one exponent: "(1.234 ± 0.056) × 10⁻⁸".
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace frictionid {

// "—": what every page shows for a number that is absent, NaN or infinite.
inline constexpr const char* kNoNumber = "—";

// x to 6 significant digits (as %.6g) with an exponent written "× 10ⁿ" instead of "e+n";
// kNoNumber for NaN; "+inf" or "-inf" for an infinity (a bound that is no bound).
std::string plain_number(double x);

// One estimate as shown: value and error share a decimal place (and an exponent, when one is
// needed). With no usable error (absent, NaN, infinite, negative) only `value` is filled
// (plain_number); with an error of 0 the value is plain_number and the error "0".
struct EstimateText {
  std::string value;     // "0.850039"; the mantissa when `exponent` is set
  std::string error;     // "0.000072"; empty without a usable error
  std::string exponent;  // "" or the shared factor, e.g. "× 10⁻⁸" (no-break spaces inside)
  std::string relative;  // "0.0085 %": error/|value| to 2 significant digits; empty when undefined

  // "0.850039 ± 0.000072", "(1.234 ± 0.056) × 10⁻⁸", or the value alone without an error.
  std::string joined() const;
  // The value alone, with the exponent when there is one: "1.234 × 10⁻⁸".
  std::string value_alone() const;
  // The error alone, with the exponent when there is one; kNoNumber without an error.
  std::string error_alone() const;
};

EstimateText estimate_text(double value, std::optional<double> stderr_value);

// A standard error alone (a sandwich or bootstrap stderr) to 2 significant digits; kNoNumber when
// absent or not a usable error.
std::string stderr_text(std::optional<double> stderr_value);

// error/|value| as a percentage to 2 significant digits, "0.0085 %"; empty when value is 0 or
// either is not finite.
std::string relative_error_text(double value, double stderr_value);

// The ends of an interval, each to the decimal place of 2 significant digits of its width, which
// always tells them apart ("0.0598" and "0.0602", never "0.06" and "0.06"); a point interval
// (lo == hi) shows plain_number twice; a non-finite end is kNoNumber or ±inf as plain_number.
std::pair<std::string, std::string> interval_text(double lo, double hi);

}  // namespace frictionid
