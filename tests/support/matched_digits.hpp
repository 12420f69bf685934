// Parameter recovery counted in matched digits.
#pragma once

#include <cmath>

namespace frictionid::test {

// Matched digits as Ceres' examples/nist.cc scores them: -log10 of the relative error, 17 for
// an exact match.
inline double matched_digits(double estimate, double truth) {
  const double rel = std::fabs(estimate - truth) / std::fabs(truth);
  return rel == 0.0 ? 17.0 : -std::log10(rel);
}

}  // namespace frictionid::test
