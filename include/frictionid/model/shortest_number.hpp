// Numbers as labels spell them: the fewest significant digits that read back as the same double.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace frictionid::model {

// The fewest significant digits that read back as x: "0.6", not 0.59999999999999998; nan and
// inf as printf spells them. For messages and labels (io's text::shortest_number is this one).
inline std::string shortest_number(double x) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

}  // namespace frictionid::model
