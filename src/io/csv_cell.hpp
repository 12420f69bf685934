// One text cell of a CSV file that frictionid writes (summary.csv, shared.csv, eval's output).
#pragma once

#include <string>
#include <string_view>

namespace frictionid {

// The cell as written. A cell that a spreadsheet would evaluate as a formula (OWASP "CSV
// injection": it begins with '=', '+', '-', '@', a tab or a carriage return) gets a leading
// apostrophe, so that Excel and LibreOffice show it as text, unless the whole cell is a number
// (-2.5, +1e3), which stays a number. Then RFC 4180 quoting where the cell needs it: a comma,
// quote, CR or LF inside, or a space or tab at either end (which some readers trim).
std::string csv_cell(std::string_view s);

}  // namespace frictionid
