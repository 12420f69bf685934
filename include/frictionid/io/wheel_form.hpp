// Reading a dataset in the wheel form (docs/design.md §4.1a, docs/physics.md §1.1): what a tire
// or landing-gear rig records, per row
//
//   V          speed of the contact centre, >= 0               [m/s]   required
//   alpha      slip angle, |alpha| < 90 deg                    [rad]   required
//   slip_ratio slip ratio, Omega r_e = V_x (1 + slip_ratio)    [1]     slip_ratio or omega_w
//   omega_w    the wheel's spin about its axle, + rolling fwd  [rad/s]
//   r_e        effective rolling radius, > 0                   [m]     unless both of the above
//   gamma      inclination                                     [rad]   required
//   psi_dot    yaw rate (0 when the column is absent)          [rad/s] optional
//   R          contact radius, > 0 (or DatasetReadOptions::contact_radius) [m]
//   Fz         the load on the tire                            [N]     required
//   Fx, Fy, Mz, My, Mx  what the road exerts on the tire       [N], [N m]  at least one
//
// each optionally with a unit in brackets (V[km/h], alpha[deg]; io/units.hpp), in ISO or SAE
// axes. The reader converts every row to the native Dataset (sliding velocity, spin, load and
// resistances, physics.md (1.9)), keeps the file's line numbers, records sgn(Omega) in
// Dataset::tilt_sign (the pressure tilt follows the rolling direction), and keeps every column,
// the wheel-form ones included, as extra text columns (for --plot-x, --group-by, --keep). Every
// rejection is an InputError naming file, line and column.
#pragma once

#include <string>
#include <vector>

#include <frictionid/dataset.hpp>

namespace frictionid {

struct DatasetReadOptions;  // io/data_form.hpp
struct DataForm;

// The wheel form's canonical column names, in the order of the table above.
const std::vector<std::string>& wheel_column_names();

// Reads a wheel-form CSV file (header, then rows; the CSV rules of the native reader). `form`,
// when given, receives how the file was read (form "wheel", format "csv", the axes, the units).
Dataset load_wheel_csv(const std::string& path, const DatasetReadOptions& options,
                       DataForm* form = nullptr);

}  // namespace frictionid
