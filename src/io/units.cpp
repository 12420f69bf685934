// Units of column headers (include/frictionid/io/units.hpp).
#include <frictionid/io/units.hpp>

#include <array>
#include <utility>

#include <frictionid/io/input_error.hpp>
#include "io/text.hpp"

namespace frictionid {

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;
// The international foot and pound-force, as defined (NIST SP 811, appendix B).
constexpr double kFoot = 0.3048;
constexpr double kPoundForce = 4.4482216152605;

struct Unit {
  const char* name;
  double factor;  // SI per unit
};

struct QuantityUnits {
  Quantity quantity;
  const char* name;
  const char* si;
  std::vector<Unit> units;  // the first is the SI unit
};

const std::array<QuantityUnits, 7>& table() {
  static const std::array<QuantityUnits, 7> t = {{
      {Quantity::Speed,
       "speed",
       "m/s",
       {{"m/s", 1.0}, {"km/h", 1000.0 / 3600.0}, {"mph", 0.44704}}},
      {Quantity::Angle, "angle", "rad", {{"rad", 1.0}, {"deg", kPi / 180.0}}},
      {Quantity::AngularRate,
       "angular rate",
       "rad/s",
       {{"rad/s", 1.0},
        {"deg/s", kPi / 180.0},
        {"rpm", 2.0 * kPi / 60.0},
        {"1/min", 2.0 * kPi / 60.0}}},
      {Quantity::Length, "length", "m", {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}}},
      {Quantity::Force, "force", "N", {{"N", 1.0}, {"kN", 1000.0}, {"lbf", kPoundForce}}},
      {Quantity::Moment,
       "moment",
       "N*m",
       {{"N*m", 1.0},
        {"Nm", 1.0},
        {"N\xC2\xB7m", 1.0},  // N·m
        {"kN*m", 1000.0},
        {"kNm", 1000.0},
        {"kN\xC2\xB7m", 1000.0},
        {"lbf*ft", kPoundForce * kFoot},
        {"lbf\xC2\xB7"
         "ft",
         kPoundForce * kFoot}}},
      {Quantity::Dimensionless, "dimensionless", "1", {{"1", 1.0}, {"-", 1.0}, {"%", 0.01}}},
  }};
  return t;
}

const QuantityUnits& entry(Quantity q) {
  for (const auto& e : table())
    if (e.quantity == q) return e;
  return table()[0];  // unreachable: every quantity has an entry
}

// "a speed", "an angle", ..., "a dimensionless number": for a message.
std::string described(Quantity q) {
  if (q == Quantity::Dimensionless) return "a dimensionless number";
  const char* name = quantity_name(q);
  return std::string(name[0] == 'a' ? "an " : "a ") + name;
}

std::string unit_list(Quantity q) {
  std::string out;
  for (const auto& u : known_units(q)) out += (out.empty() ? "" : ", ") + u;
  return out;
}

}  // namespace

const char* quantity_name(Quantity q) {
  return entry(q).name;
}

const char* si_unit(Quantity q) {
  return entry(q).si;
}

HeaderName split_header_name(std::string_view header) {
  HeaderName h;
  const std::string_view trimmed = text::trim(header);
  const std::size_t open = trimmed.find('[');
  if (open == std::string_view::npos || trimmed.empty() || trimmed.back() != ']' ||
      trimmed.find('[', open + 1) != std::string_view::npos ||
      trimmed.find(']') != trimmed.size() - 1) {
    h.name = std::string(trimmed);
    return h;
  }
  h.name = std::string(text::trim(trimmed.substr(0, open)));
  h.unit = std::string(text::trim(trimmed.substr(open + 1, trimmed.size() - open - 2)));
  h.has_unit = true;
  return h;
}

const std::vector<std::string>& known_units(Quantity q) {
  static const auto lists = [] {
    std::array<std::vector<std::string>, 7> out;
    for (std::size_t k = 0; k < table().size(); ++k)
      for (const auto& u : table()[k].units) out[k].push_back(u.name);
    return out;
  }();
  for (std::size_t k = 0; k < table().size(); ++k)
    if (table()[k].quantity == q) return lists[k];
  return lists[0];
}

std::optional<double> unit_factor(Quantity q, std::string_view unit) {
  for (const auto& u : entry(q).units)
    if (unit == u.name) return u.factor;
  return std::nullopt;
}

std::optional<Quantity> quantity_of_unit(std::string_view unit) {
  for (const auto& e : table())
    for (const auto& u : e.units)
      if (unit == u.name) return e.quantity;
  return std::nullopt;
}

double column_unit_factor(Quantity q, const std::string& header, const HeaderName& split,
                          const std::string& file, std::size_t line, std::size_t column) {
  if (!split.has_unit) return 1.0;
  const std::string expected = "; " + split.name + " is " + described(q) + ": expected one of " +
                               unit_list(q) + " (no unit: " + si_unit(q) + ")";
  if (split.unit.empty())
    throw InputError(file, line, column,
                     "column " + text::shown(header) + " has an empty unit" + expected);
  if (const auto factor = unit_factor(q, split.unit)) return *factor;
  const auto other = quantity_of_unit(split.unit);
  throw InputError(file, line, column,
                   "column " + text::shown(header) + " has the unit " + text::shown(split.unit) +
                       (other ? ", the unit of " + described(*other)
                              : std::string(", which frictionid does not know")) +
                       expected);
}

}  // namespace frictionid
