// The error of a fit that cannot produce a usable result, in a header of its own: the pieces of
// the fit (statistics, intervals, reweighting) throw it without depending on the runner above
// them.
#pragma once

#include <stdexcept>

namespace frictionid {

// A fit that cannot produce a usable result (every start failed, interrupted, model not finite).
class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace frictionid
