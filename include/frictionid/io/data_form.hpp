// How to read a data file, and how it was read. A dataset comes in one of two forms: the native
// form (the contact's sliding velocity, spin and resistances: v_x, v_y, omega, N, R, T_x, ...;
// docs/design.md §4.1) or the wheel form (what a tire or landing-gear rig records: travel speed,
// slip angle, slip ratio or wheel speed, inclination, the road's forces on the tire, in ISO or
// SAE axes; §4.1a), as CSV or as a TYDEX file (§4.1b). Every reader turns it into the native
// Dataset, and reports record which form was read and why, the axes and the units.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/io/dataset_csv.hpp>

namespace frictionid {

enum class InputForm { Auto, Native, Wheel };
// ISO 8855 / TYDEX W (x along the wheel heading, y left, z up) or SAE J670 (x forward, y right,
// z down); docs/physics.md §1.1 has every sign.
enum class Axes { Iso, Sae };

struct DatasetReadOptions {
  // Auto: a .tdx file or one that begins with **HEADER is TYDEX (the wheel form); a CSV file is
  // the wheel form when its header has V and alpha and no v_x, else the native form.
  InputForm form = InputForm::Auto;
  Axes axes = Axes::Iso;  // of a wheel-form CSV file
  // The contact radius R [m] of every row of a wheel-form file without an R column.
  std::optional<double> contact_radius;
  // Renames: a canonical name (native or wheel form) -> the header (or TYDEX channel) name.
  ColumnMap columns;
  bool require_channels = true;  // false: kinematics only (eval --input)
};

// A column read with a unit: its header as written and the unit ("V[km/h]", "km/h").
struct ColumnUnit {
  std::string column;
  std::string unit;
};

struct DataForm {
  std::string form;    // "native" or "wheel"; empty: not recorded (data from memory)
  std::string format;  // "csv" or "tydex"
  std::string axes;    // the wheel form's axes, "iso" or "sae"; empty for the native form
  std::string reason;  // why this form, e.g. "--input-form wheel" or "auto: the header has ..."
  // Every column read with a unit, in file order; a column not listed was read as SI.
  std::vector<ColumnUnit> units;
};

const char* input_form_name(InputForm f);  // "auto", "native", "wheel"
const char* axes_name(Axes a);             // "iso", "sae"

// {"form", "format", "axes" (null for native), "reason", "units": {column: unit, ...}}.
nlohmann::ordered_json data_form_json(const DataForm& f);

// One line for a page: "wheel form (CSV, SAE axes): auto: the header has V and alpha and no
// v_x; units V[km/h] km/h, alpha[deg] deg; other columns SI".
std::string data_form_text(const DataForm& f);

}  // namespace frictionid
