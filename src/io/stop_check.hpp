// How a long step of the report stage (waiting for the lock, the final swap) learns that its
// caller wants it to stop: a check it asks, and the exception it throws then, leaving the
// earlier report intact. io keeps no flag of its own: the command line's check reads the flag
// that its signal handler sets (src/cli/signals.hpp) and maps Interrupted to exit code 130;
// Python passes none.
#pragma once

#include <functional>
#include <stdexcept>

namespace frictionid {

// True when the caller asks to stop; an empty check never does. Called from the waiting thread.
using StopCheck = std::function<bool()>;

// Thrown when a report step sees its stop check return true.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace frictionid
