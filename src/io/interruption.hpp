// The process-wide "stop now" flag: SIGINT, SIGTERM and SIGHUP set it (the handler lives in
// src/cli), and long steps of the report stage (waiting for the lock, the
// final swap) check it so that an interrupted run ends with the earlier report intact.
#pragma once

#include <atomic>
#include <stdexcept>

namespace frictionid {

// Set from a signal handler; lock-free so that is allowed.
std::atomic<bool>& interrupt_flag();

// Thrown when a report step sees the flag; the CLI maps it to exit code 130.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws Interrupted("interrupted " + what) when the flag is set.
void throw_if_interrupted(const char* what);

}  // namespace frictionid
