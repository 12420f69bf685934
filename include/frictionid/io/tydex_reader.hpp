// Reading a TYDEX file (.tdx, "TYDEX-Format, Description and Reference Manual", release 1.3,
// Unrau & Zamow 1997) as the wheel form of a dataset (docs/design.md §4.1b).
//
// Layout: keyword lines **HEADER (first), **COMMENTS, **CONSTANTS, **MEASURCHANNELS,
// **MEASURDATA, then model sections and **END, which are not read. A CONSTANTS or
// MEASURCHANNELS line has the published fixed columns: name in columns 1-10, description 11-40,
// unit 41-50, then (blank separated) the value of a constant, or a channel's conversion factor
// and its two offsets. MEASURDATA holds one row per line, one blank-separated number per channel
// (NOTAVAIL: not measured). Lines that begin with '!' are comments.
//
// Channels and constants named as below are read as the wheel-form columns (in the W axes of
// ISO 8855); a constant gives its column's value in every row, a channel of the same name wins:
//
//   TRAJVELW (or LONGVEL)  V       road speed of the contact centre
//   SLIPANGL               alpha   = -SLIPANGL (TYDEX's slip angle is ISO 8855's: positive for
//                                   a velocity towards +y, the wheel form's is not)
//   LONGSLIP               slip_ratio
//   WHROTSPD               omega_w
//   INCLANGL               gamma   = -INCLANGL (likewise)
//   FZW, FXW (or FX), FYW, MZW, MYW, MXW   Fz, Fx, Fy, Mz, My, Mx
//
// r_e, R and psi_dot have no TYDEX name here: give them with a column map (r_e=NAME for a channel
// or constant NAME), R also with contact_radius; r_e is not needed when both LONGSLIP and
// WHROTSPD are given. Every other channel and constant is kept as an extra text column under its
// TYDEX name (INFLPRES, RUNTIME, ...), so a batch can group or keep by it.
#pragma once

#include <string>

#include <frictionid/dataset.hpp>
#include <frictionid/io/data_form.hpp>

namespace frictionid {

// True when the path ends in .tdx (any case).
bool has_tydex_extension(const std::string& path);

// Reads the file; throws InputError (file, line, column) for anything it cannot read.
Dataset load_tydex(const std::string& path, const DatasetReadOptions& options,
                   DataForm* form = nullptr);

}  // namespace frictionid
