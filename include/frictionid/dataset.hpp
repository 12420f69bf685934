// A set of steady-state measurements, one row per operating point (docs/design.md "Dataset CSV").
// Stored column-wise: fits touch every row of one column at a time.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace frictionid {

// M_tilt = ∫sigma y dS, beside M_roll = ∫sigma x dS: the pressure's tilt across the rolling
// direction (docs/physics.md §9.2).
enum class Channel : int { T_x = 0, T_y = 1, M_z = 2, M_roll = 3, M_tilt = 4 };
inline constexpr int kChannelCount = 5;
inline constexpr std::array<Channel, kChannelCount> kAllChannels = {
    Channel::T_x, Channel::T_y, Channel::M_z, Channel::M_roll, Channel::M_tilt};

inline const char* channel_name(Channel c) {
  static constexpr const char* names[kChannelCount] = {"T_x", "T_y", "M_z", "M_roll", "M_tilt"};
  return names[static_cast<int>(c)];
}

struct Dataset {
  std::string source;             // file name the rows came from (for messages and reports)
  std::vector<std::size_t> line;  // 1-based line in the source file of each row

  // Kinematics and load, SI units.
  std::vector<double> v_x, v_y, omega, N, R;
  // The sign the pressure tilt (h, h_y) takes on each row: the wheel form's tilt follows the
  // rolling direction, sgn of the wheel's spin (docs/physics.md §9.2). Empty: +1 on every row,
  // the native form's fixed +x.
  std::vector<double> tilt_sign;

  // Measured channels. present[c][i] != 0 when row i measures channel c; value is then finite.
  std::array<std::vector<double>, kChannelCount> value;
  std::array<std::vector<std::uint8_t>, kChannelCount> present;
  // Per-row standard deviations; empty vector when the file has no sigma column for c.
  std::array<std::vector<double>, kChannelCount> sigma;

  // The file's other columns (e.g. slip angle, camber, run id), as text in file order: reports
  // plot and colour by them, eval carries them into its predictions. extra_values[k] has rows()
  // entries.
  std::vector<std::string> extra_names;
  std::vector<std::vector<std::string>> extra_values;

  std::size_t rows() const { return v_x.size(); }
  double tilt_sign_at(std::size_t i) const { return tilt_sign.empty() ? 1.0 : tilt_sign[i]; }
  bool has_channel(Channel c) const {
    for (auto p : present[static_cast<int>(c)])
      if (p) return true;
    return false;
  }
  bool has_sigma(Channel c) const { return !sigma[static_cast<int>(c)].empty(); }

  // Every k-th row, from the first, with k the smallest stride that leaves at most max_rows
  // rows (max_rows >= 1): a deterministic subsample that spans the whole file.
  Dataset subsample(std::size_t max_rows) const;
};

}  // namespace frictionid
