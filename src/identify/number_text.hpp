// Numbers in messages and warnings: %g with a given number of significant digits.
#pragma once

#include <cstdio>
#include <string>

namespace frictionid {

inline std::string number_text(double v, int digits = 4) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace frictionid
