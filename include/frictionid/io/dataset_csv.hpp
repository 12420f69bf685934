// Reading a Dataset from a CSV file (docs/design.md "Dataset CSV").
//
// Format: a header row, then one row per steady-state measurement, comma separated. Fields may be
// double-quoted ("" inside quotes is a literal quote); spaces and tabs around a field are ignored.
// A UTF-8 BOM, CRLF line ends and blank lines (anywhere after the header) are accepted. Columns
// are matched by header name (canonical names below, or renamed with a ColumnMap); columns with
// other names are kept as text in Dataset::extra_names/extra_values (unvalidated: slip angle,
// camber, run ids), in file order.
//
//   v_x, omega, N, R                       required, every row, finite; N > 0, R > 0
//   v_y                                    optional column (0 when absent); if present, required
//   T_x, T_y, M_z, M_roll, M_tilt          at least one of these columns; a row may leave some
//                                          empty but must measure at least one channel
//   sigma_T_x, sigma_T_y, sigma_M_z,       optional; finite and > 0 in every row whose channel
//   sigma_M_roll, sigma_M_tilt             is present (ignored in rows where it is absent)
//
// Numbers are read with a correctly rounded conversion (values written with %.17g read back
// bit-identical); NaN/Inf spellings, hexadecimal floats, out-of-range values and trailing
// characters are rejected. Every rejection is an InputError naming file, line and column (1-based
// field number in the row) with the offending text and what was expected.
//
// In the result, every value[c] and present[c] has rows() entries (present[c][i] == 0 and
// value[c][i] == NaN where row i does not measure c, including files without that column);
// sigma[c] is empty when the file has no sigma column for c, else has rows() entries (NaN where
// the channel is absent).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>

namespace frictionid {

// Renames from --columns: canonical name -> header name in the file.
struct ColumnMap {
  std::map<std::string, std::string> canonical_to_header;
};

// The canonical column names, in the order of the table above.
const std::vector<std::string>& dataset_column_names();

// Reads and validates the file; throws InputError on any rejected input (including a file that
// cannot be opened). A canonical name that is remapped is looked up only under its new header
// name; a column literally named after it is then ignored.
// require_channels = false reads kinematics only (eval --input): no channel column is needed.
Dataset load_dataset_csv(const std::string& path, const ColumnMap& columns = {},
                         bool require_channels = true);

}  // namespace frictionid
