// The wheel form's columns and the conversion of one wheel-form row into a native row
// (docs/physics.md §1.1), shared by the CSV reader (wheel_form.cpp) and the TYDEX reader
// (tydex_reader.cpp): the same checks, the same arithmetic, the same messages.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include <frictionid/dataset.hpp>
#include <frictionid/io/data_form.hpp>
#include <frictionid/io/units.hpp>

namespace frictionid::io_detail {

enum WheelSlot : int {
  kWheelV,
  kWheelAlpha,
  kWheelSlipRatio,
  kWheelOmegaW,
  kWheelRe,
  kWheelGamma,
  kWheelPsiDot,
  kWheelR,
  kWheelFz,
  kWheelFx,
  kWheelFy,
  kWheelMz,
  kWheelMy,
  kWheelMx,
  kWheelSlotCount
};
inline constexpr int kFirstWheelChannel = kWheelFx;

struct WheelSlotInfo {
  const char* name;     // canonical column name
  Quantity quantity;    // what a unit of the column must measure
  const char* meaning;  // for messages
};
const WheelSlotInfo& wheel_slot(int slot);
// The slot of a canonical name, or -1.
int wheel_slot_index(std::string_view name);

// Where each slot's values come from: whether the file has it, the column's header as written
// (for messages) and its 1-based field number (0 for a value that is not a field of the row,
// such as a TYDEX constant).
struct WheelColumns {
  std::array<bool, kWheelSlotCount> present{};
  std::array<std::string, kWheelSlotCount> header;
  std::array<std::size_t, kWheelSlotCount> field{};
  bool has(int slot) const { return present[slot]; }
  // "'Fz[kN]'" or "'load' (Fz)" for a renamed column.
  std::string describe(int slot) const;
};

// One row in SI units and in the file's axes; given[s] false for an empty cell.
struct WheelRow {
  std::array<double, kWheelSlotCount> value{};
  std::array<bool, kWheelSlotCount> given{};
};

class WheelConverter {
 public:
  // Checks the columns: V, alpha, gamma and Fz, one of slip_ratio and omega_w, r_e unless
  // both, R unless contact_radius (and not both), and a channel when require_channels. Throws
  // InputError(path, header_line, field, ...) naming what is missing.
  WheelConverter(std::string path, std::size_t header_line, WheelColumns columns, Axes axes,
                 std::optional<double> contact_radius, bool require_channels);

  // Checks the row and appends its native values, its line and sgn(Omega) to `out` (v_x, v_y,
  // omega, N, R, tilt_sign, value/present of every channel); throws InputError(path, line,
  // field, ...) for a row the wheel form does not allow. Extra columns are the caller's.
  void append(const WheelRow& row, std::size_t line, Dataset& out) const;

  const WheelColumns& columns() const { return columns_; }

 private:
  [[noreturn]] void reject(std::size_t line, int slot, const std::string& what) const;

  std::string path_;
  WheelColumns columns_;
  Axes axes_;
  std::optional<double> contact_radius_;
  bool require_channels_;
};

}  // namespace frictionid::io_detail
