// Process exit codes, documented in README.md.
#pragma once

namespace frictionid::cli {
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;         // I/O or internal failure
inline constexpr int kExitBadInput = 2;        // invalid command line, file or value
inline constexpr int kExitFitFailed = 3;       // the solver did not produce a usable fit
inline constexpr int kExitSomeRunsFailed = 4;  // batch: the other runs succeeded
inline constexpr int kExitInterrupted = 130;
}  // namespace frictionid::cli
