#include "io/option_parsers.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <system_error>

#include "io/input_error.hpp"

namespace frictionid {

namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

std::string quoted(std::string_view s) {
  return "'" + std::string(s) + "'";
}

// Splits `spec` at commas into trimmed items; rejects an empty spec and empty items.
std::vector<std::string_view> split_items(const std::string& option, const std::string& spec,
                                          const char* expected) {
  std::vector<std::string_view> items;
  const std::string_view all(spec);
  if (trim(all).empty())
    throw InputError(option, 0, 0, "empty value; expected " + std::string(expected));
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = all.find(',', pos);
    const std::string_view item = trim(
        all.substr(pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos));
    if (item.empty())
      throw InputError(option, 0, 0,
                       "empty entry (entry " + std::to_string(items.size() + 1) + ") in " +
                           quoted(spec) + "; expected " + expected);
    items.push_back(item);
    if (comma == std::string_view::npos) break;
    pos = comma + 1;
  }
  return items;
}

void check_name(const std::string& option, const std::string& spec, std::string_view name,
                std::string_view item, const char* expected) {
  if (name.empty())
    throw InputError(option, 0, 0,
                     "missing name before '=' in " + quoted(item) + " (in " + quoted(spec) +
                         "); expected " + expected);
  for (char c : name)
    if (!is_name_char(c))
      throw InputError(option, 0, 0,
                       "invalid name " + quoted(name) + " in " + quoted(spec) +
                           ": expected letters, digits and '_' only (format: " + expected + ")");
}

double number_in(const std::string& option, const std::string& spec, std::string_view name,
                 std::string_view text, const char* role) {
  double value = 0;
  if (const char* why = parse_double_strict(text, value))
    throw InputError(option, 0, 0,
                     std::string(role) + " for " + quoted(name) + " is " + quoted(text) + ": " +
                         why + "; expected a finite decimal number (in " + quoted(spec) + ")");
  return value;
}

// "name=rest" -> (name, rest), with both trimmed.
std::pair<std::string_view, std::string_view> split_assignment(const std::string& option,
                                                               const std::string& spec,
                                                               std::string_view item,
                                                               const char* expected) {
  const std::size_t eq = item.find('=');
  if (eq == std::string_view::npos)
    throw InputError(
        option, 0, 0,
        "missing '=' in " + quoted(item) + " (in " + quoted(spec) + "); expected " + expected);
  const std::string_view name = trim(item.substr(0, eq));
  check_name(option, spec, name, item, expected);
  return {name, trim(item.substr(eq + 1))};
}

void check_unique(const std::string& option, const std::string& spec, std::set<std::string>& seen,
                  std::string_view name) {
  if (!seen.emplace(name).second)
    throw InputError(option, 0, 0,
                     "name " + quoted(name) + " is given more than once in " + quoted(spec));
}

}  // namespace

const char* parse_double_strict(std::string_view text, double& out) {
  if (text.empty()) return "empty";
  const char* first = text.data();
  const char* const last = first + text.size();
  // from_chars accepts '-' but not '+'; allow one '+' that is followed by a digit or '.'.
  if (*first == '+') {
    if (last - first < 2 || !((first[1] >= '0' && first[1] <= '9') || first[1] == '.'))
      return "not a number";
    ++first;
  }
  const char* digits = first + (*first == '-' ? 1 : 0);
  if (last - digits >= 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X'))
    return "hexadecimal floats are not accepted";
  const auto [ptr, ec] = std::from_chars(first, last, out);
  if (ec == std::errc::result_out_of_range) return "out of the double range";
  if (ec != std::errc()) return "not a number";
  if (std::isnan(out)) return "NaN is not allowed";
  if (std::isinf(out)) return "Inf is not allowed";
  if (ptr != last) return "unexpected characters after the number";
  return nullptr;
}

double parse_number(const std::string& what, const std::string& text) {
  double value = 0;
  const std::string_view t = trim(text);
  if (const char* why = parse_double_strict(t, value))
    throw InputError(what, 0, 0,
                     "got " + quoted(text) + " (" + why + "); expected a finite decimal number");
  return value;
}

std::map<std::string, double> parse_assignments(const std::string& option,
                                                const std::string& spec) {
  static const char* const kExpected = "name=value[,name=value...], e.g. f=0.8,kappa=1.2";
  std::map<std::string, double> result;
  std::set<std::string> seen;
  for (const std::string_view item : split_items(option, spec, kExpected)) {
    const auto [name, text] = split_assignment(option, spec, item, kExpected);
    check_unique(option, spec, seen, name);
    result.emplace(std::string(name), number_in(option, spec, name, text, "value"));
  }
  return result;
}

std::map<std::string, std::pair<double, double>> parse_bounds(const std::string& option,
                                                              const std::string& spec) {
  static const char* const kExpected = "name=lo:hi[,name=lo:hi...], e.g. f=0.1:2,h=-0.5:0.5";
  std::map<std::string, std::pair<double, double>> result;
  std::set<std::string> seen;
  for (const std::string_view item : split_items(option, spec, kExpected)) {
    const auto [name, range] = split_assignment(option, spec, item, kExpected);
    check_unique(option, spec, seen, name);
    const std::size_t colon = range.find(':');
    if (colon == std::string_view::npos || range.find(':', colon + 1) != std::string_view::npos)
      throw InputError(option, 0, 0,
                       "bounds for " + quoted(name) + " are " + quoted(range) +
                           "; expected exactly one ':' as in lo:hi (in " + quoted(spec) + ")");
    const double lo = number_in(option, spec, name, trim(range.substr(0, colon)), "lower bound");
    const double hi = number_in(option, spec, name, trim(range.substr(colon + 1)), "upper bound");
    if (!(lo < hi))
      throw InputError(option, 0, 0,
                       "bounds for " + quoted(name) + " are " + quoted(range) +
                           ": expected lo < hi (in " + quoted(spec) + ")");
    result.emplace(std::string(name), std::make_pair(lo, hi));
  }
  return result;
}

std::vector<std::string> parse_name_list(const std::string& option, const std::string& spec) {
  static const char* const kExpected = "name[,name...], e.g. T_x,M_z";
  std::vector<std::string> result;
  std::set<std::string> seen;
  for (const std::string_view item : split_items(option, spec, kExpected)) {
    check_name(option, spec, item, item, kExpected);
    check_unique(option, spec, seen, item);
    result.emplace_back(item);
  }
  return result;
}

}  // namespace frictionid
