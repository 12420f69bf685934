// Units in column headers: `NAME[UNIT]` (`V[km/h]`, `alpha[deg]`, `Fz[kN]`). A reader knows the
// quantity of each of its columns (a speed, an angle, a force, ...) and converts a value given in
// a unit to SI on reading; a column without a unit is SI. A unit that is unknown, or that is not
// one of its column's quantity (`alpha[kN]`), is an InputError naming the column and listing the
// units known for that quantity (docs/design.md §4.1a).
//
// The factors are the definitions (SI per unit): km/h = 1000/3600 m/s, mph = 0.44704 m/s,
// deg = pi/180 rad, rpm = 2 pi/60 rad/s, in = 0.0254 m, lbf = 4.4482216152605 N,
// lbf*ft = 4.4482216152605 * 0.3048 N m. A value is converted with one multiplication by the
// factor rounded to double, so a value in SI (factor 1) reads back bit for bit.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frictionid {

enum class Quantity { Speed, Angle, AngularRate, Length, Force, Moment, Dimensionless };

// "speed", "angle", "angular rate", "length", "force", "moment", "dimensionless".
const char* quantity_name(Quantity q);

// The SI unit a value of q is read as when its column has no unit: "m/s", "rad", "rad/s", "m",
// "N", "N*m", "1".
const char* si_unit(Quantity q);

// A header split into its name and its unit: "V[km/h]" is {"V", "km/h", true}, "V [km/h]" too
// (spaces around either part are dropped); "V" and a header whose brackets do not close it at its
// end ("V[km/h", "a[b]c") are the name alone, with has_unit false.
struct HeaderName {
  std::string name;
  std::string unit;
  bool has_unit = false;
};
HeaderName split_header_name(std::string_view header);

// The units known for q, in the order the messages list them.
const std::vector<std::string>& known_units(Quantity q);

// SI per `unit` for a value of quantity q; nullopt when the unit is not one of q's.
std::optional<double> unit_factor(Quantity q, std::string_view unit);

// The quantity whose units include `unit`, if any (for a message that says "kN is a force
// unit").
std::optional<Quantity> quantity_of_unit(std::string_view unit);

// The factor a column named `header` (already split) of quantity q is read with: 1 without a
// unit. Throws InputError(file, line, column, ...) for an empty, unknown or misplaced unit,
// naming the column and listing q's units.
double column_unit_factor(Quantity q, const std::string& header, const HeaderName& split,
                          const std::string& file, std::size_t line, std::size_t column);

}  // namespace frictionid
