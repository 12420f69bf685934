#include "app/option_parsers.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <system_error>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/io/pressure_map_reader.hpp>
#include <frictionid/io/wheel_form.hpp>
#include "io/text.hpp"

namespace frictionid {

namespace {

using text::trim;

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// A value for a message: the fewest digits that read back as the same double (2, 0.1, 1e-07);
// nan and inf as such.
std::string number_text(double x) {
  return text::shortest_number(x);
}

// The whole text, quoted, with control characters escaped.
std::string in_quotes(std::string_view s) {
  return text::shown(s, std::string_view::npos);
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
                           in_quotes(spec) + "; expected " + expected);
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
                     "missing name before '=' in " + in_quotes(item) + " (in " + in_quotes(spec) +
                         "); expected " + expected);
  for (char c : name)
    if (!is_name_char(c))
      throw InputError(option, 0, 0,
                       "invalid name " + in_quotes(name) + " in " + in_quotes(spec) +
                           ": expected letters, digits and '_' only (format: " + expected + ")");
}

double number_in(const std::string& option, const std::string& spec, std::string_view name,
                 std::string_view text, const char* role) {
  double value = 0;
  if (const char* why = text::parse_double_strict(text, value))
    throw InputError(option, 0, 0,
                     std::string(role) + " for " + in_quotes(name) + " is " + in_quotes(text) +
                         ": " + why + "; expected a finite decimal number (in " + in_quotes(spec) +
                         ")");
  return value;
}

// "name=rest" -> (name, rest), with both trimmed.
std::pair<std::string_view, std::string_view> split_assignment(const std::string& option,
                                                               const std::string& spec,
                                                               std::string_view item,
                                                               const char* expected) {
  const std::size_t eq = item.find('=');
  if (eq == std::string_view::npos)
    throw InputError(option, 0, 0,
                     "missing '=' in " + in_quotes(item) + " (in " + in_quotes(spec) +
                         "); expected " + expected);
  const std::string_view name = trim(item.substr(0, eq));
  check_name(option, spec, name, item, expected);
  return {name, trim(item.substr(eq + 1))};
}

void check_unique(const std::string& option, const std::string& spec, std::set<std::string>& seen,
                  std::string_view name) {
  if (!seen.emplace(name).second)
    throw InputError(option, 0, 0,
                     "name " + in_quotes(name) + " is given more than once in " + in_quotes(spec));
}

}  // namespace

double parse_number(const std::string& what, const std::string& text) {
  double value = 0;
  const std::string_view t = trim(text);
  if (const char* why = text::parse_double_strict(t, value))
    throw InputError(what, 0, 0,
                     "got " + in_quotes(text) + " (" + why + "); expected a finite decimal number");
  return value;
}

std::uint64_t parse_whole_number(const std::string& option, const std::string& text,
                                 std::uint64_t lo, std::uint64_t hi) {
  const std::string range =
      "; expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  const std::string_view t = trim(text);
  const bool digits_only =
      !t.empty() && t.find_first_not_of("0123456789") == std::string_view::npos;
  if (!digits_only) {
    const bool negative = !t.empty() && t.front() == '-';
    throw InputError(
        option, 0, 0,
        "got " + in_quotes(text) + (negative ? " (negative)" : " (not a whole number)") + range);
  }
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range || value > hi)
    throw InputError(option, 0, 0, "got " + in_quotes(text) + " (too large)" + range);
  if (ec != std::errc() || end != t.data() + t.size())
    throw InputError(option, 0, 0, "got " + in_quotes(text) + " (not a whole number)" + range);
  if (value < lo) throw InputError(option, 0, 0, "got " + in_quotes(text) + " (too small)" + range);
  return value;
}

void check_thread_option(int threads) {
  if (threads < 0) throw InputError("--threads must be 0 (every hardware thread) or more");
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
                       "bounds for " + in_quotes(name) + " are " + in_quotes(range) +
                           "; expected exactly one ':' as in lo:hi (in " + in_quotes(spec) + ")");
    const double lo = number_in(option, spec, name, trim(range.substr(0, colon)), "lower bound");
    const double hi = number_in(option, spec, name, trim(range.substr(colon + 1)), "upper bound");
    if (!(lo < hi))
      throw InputError(option, 0, 0,
                       "bounds for " + in_quotes(name) + " are " + in_quotes(range) +
                           ": expected lo < hi (in " + in_quotes(spec) + ")");
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

model::PressureLaw<double> parse_pressure_option(const std::string& spec) {
  try {
    return parse_pressure_law(spec);
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError("--pressure", 0, 0, e.what());
  }
}

model::ContactSpot parse_contact_option(const std::string& spec) {
  static const std::string option = "--contact";
  static const char* const kExpected =
      "expected circle, ellipse:Q, rect:Q (0 < Q <= 4) or map:FILE";
  if (spec == "circle") return model::ContactSpot::circle();
  for (const char* kind : {"ellipse:", "rect:"}) {
    const std::string prefix = kind;
    if (spec.rfind(prefix, 0) != 0) continue;
    const std::string_view q_text = trim(std::string_view(spec).substr(prefix.size()));
    double q = 0;
    if (const char* why = text::parse_double_strict(q_text, q))
      throw InputError(
          option, 0, 0,
          in_quotes(spec) + ": Q is " + in_quotes(q_text) + " (" + why + "); " + kExpected);
    if (!(q > 0.0 && q <= 4.0))
      throw InputError(option, 0, 0,
                       in_quotes(spec) + ": Q = " + number_text(q) +
                           " is out of range; expected 0 < Q <= 4 (the spot's extent along y over "
                           "its extent R along x)");
    return prefix == "rect:" ? model::ContactSpot::rect(q) : model::ContactSpot::ellipse(q);
  }
  if (spec.rfind("map:", 0) == 0) {
    if (spec.size() == 4) throw InputError(option, 0, 0, "'map:': map:FILE needs a file name");
    return model::ContactSpot::pressure_map(load_pressure_map(spec.substr(4)));
  }
  throw InputError(option, 0, 0, "unknown contact spot " + in_quotes(spec) + "; " + kExpected);
}

std::string contact_label(const std::string& spec) {
  if (spec.rfind("map:", 0) == 0) return spec;
  return contact_spot_label(parse_contact_option(spec));
}

std::vector<std::string> parse_contact_list(const std::string& option, const std::string& spec) {
  static const char* const kExpected = "SPOT[,SPOT...], e.g. circle,ellipse:0.7";
  std::vector<std::string> result;
  std::set<std::string> seen;
  for (const std::string_view item : split_items(option, spec, kExpected)) {
    const std::string spot(item);
    parse_contact_option(spot);
    check_unique(option, spec, seen, item);
    result.push_back(spot);
  }
  return result;
}

namespace {

// The checks of a column map, whichever front end wrote it; `spec` is its text for messages.
ColumnMap checked_column_map(const std::vector<std::pair<std::string, std::string>>& pairs,
                             const std::string& spec) {
  static const std::string option = "--columns";
  static const char* const kExpected =
      "canonical=header[,canonical=header...], e.g. v_x=speed,omega=spin";
  ColumnMap map;
  // The native form's names and the wheel form's (R is in both).
  std::vector<std::string> canonical_names = dataset_column_names();
  for (const auto& name : wheel_column_names())
    if (std::find(canonical_names.begin(), canonical_names.end(), name) == canonical_names.end())
      canonical_names.push_back(name);
  std::set<std::string> headers;
  for (const auto& [canonical, header] : pairs) {
    if (std::find(canonical_names.begin(), canonical_names.end(), canonical) ==
        canonical_names.end()) {
      std::string hint, list;
      std::size_t best = std::numeric_limits<std::size_t>::max();
      for (const auto& name : canonical_names) {
        list += (list.empty() ? "" : ", ") + name;
        if (const std::size_t d = text::misspelling_distance(canonical, name); d < best) {
          best = d;
          hint = "; did you mean '" + name + "'?";
        }
      }
      throw InputError(option, 0, 0,
                       "unknown canonical column " + in_quotes(canonical) + " in " +
                           in_quotes(spec) + hint + " (expected one of: " + list + ")");
    }
    if (header.empty())
      throw InputError(option, 0, 0,
                       "empty header name for '" + canonical + "' in " + in_quotes(spec) +
                           "; expected " + kExpected);
    if (map.canonical_to_header.count(canonical))
      throw InputError(option, 0, 0,
                       "'" + canonical + "' is mapped more than once in " + in_quotes(spec));
    if (!headers.insert(header).second)
      throw InputError(option, 0, 0,
                       "header name " + in_quotes(header) +
                           " is mapped to more than one column in " + in_quotes(spec));
    map.canonical_to_header.emplace(canonical, header);
  }
  // A header name may not stand for two canonical columns of one form (v_x=omega leaves omega
  // unmapped). A file is read in one form, so a native name may share a header with a wheel-form
  // name: T_x=Fx maps a native file's Fx column, and the wheel form's Fx is not read then.
  for (const std::vector<std::string>& names : {dataset_column_names(), wheel_column_names()}) {
    std::vector<std::string> effective;
    for (const auto& name : names) {
      const auto it = map.canonical_to_header.find(name);
      effective.push_back(it == map.canonical_to_header.end() ? name : it->second);
    }
    for (std::size_t a = 0; a < effective.size(); ++a)
      for (std::size_t b = a + 1; b < effective.size(); ++b)
        if (effective[a] == effective[b])
          throw InputError(option, 0, 0,
                           "header name '" + effective[a] + "' would supply both " + names[a] +
                               " and " + names[b] + "; map the other one to a different name");
  }
  return map;
}

}  // namespace

ColumnMap parse_column_map(const std::string& spec) {
  static const std::string option = "--columns";
  static const char* const kExpected =
      "canonical=header[,canonical=header...], e.g. v_x=speed,omega=spin";
  if (trim(spec).empty()) return {};
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const std::string_view item : split_items(option, spec, kExpected)) {
    const auto [canonical, header] = split_assignment(option, spec, item, kExpected);
    pairs.emplace_back(canonical, header);
  }
  return checked_column_map(pairs, spec);
}

ColumnMap column_map(const std::map<std::string, std::string>& canonical_to_header) {
  std::vector<std::pair<std::string, std::string>> pairs(canonical_to_header.begin(),
                                                         canonical_to_header.end());
  std::string spec;
  for (const auto& [canonical, header] : pairs)
    spec += (spec.empty() ? "" : ",") + canonical + "=" + header;
  return checked_column_map(pairs, spec);
}

void check_values(const std::string& option, const std::map<std::string, double>& values) {
  for (const auto& [name, value] : values)
    if (!std::isfinite(value))
      throw InputError(option, 0, 0,
                       "value for " + in_quotes(name) + " is " + number_text(value) +
                           "; expected a finite number");
}

void check_bounds(const std::string& option,
                  const std::map<std::string, std::pair<double, double>>& bounds) {
  std::string spec;  // the bounds as --bounds text, for messages worded as parse_bounds words them
  for (const auto& [name, lohi] : bounds)
    spec += (spec.empty() ? "" : ",") + name + "=" + number_text(lohi.first) + ":" +
            number_text(lohi.second);
  for (const auto& [name, lohi] : bounds) {
    const auto [lo, hi] = lohi;
    const std::string range = number_text(lo) + ":" + number_text(hi);
    if (!std::isfinite(lo) || !std::isfinite(hi))
      throw InputError(option, 0, 0,
                       "bounds for " + in_quotes(name) + " are " + in_quotes(range) +
                           ": expected finite numbers (in " + in_quotes(spec) + ")");
    if (!(lo < hi))
      throw InputError(option, 0, 0,
                       "bounds for " + in_quotes(name) + " are " + in_quotes(range) +
                           ": expected lo < hi (in " + in_quotes(spec) + ")");
  }
}

void check_names(const std::string& option, const std::vector<std::string>& names) {
  std::set<std::string> seen;
  for (const auto& name : names) {
    if (name.empty()) throw InputError(option, 0, 0, "empty name in the list");
    if (!seen.insert(name).second)
      throw InputError(option, 0, 0, "name " + in_quotes(name) + " is given more than once");
  }
}

std::vector<double> parse_number_list(const std::string& option, const std::string& spec) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = spec.find(',', start);
    const std::string item =
        spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out.push_back(parse_number(option, item));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace frictionid
