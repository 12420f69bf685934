// Writes a whole file or nothing: content goes to a temporary file in the same directory, is
// flushed, then renamed over the target, so a crash or an error never leaves a half-written file.
#pragma once

#include <string>

namespace frictionid {

// Throws std::runtime_error (with the path and the system's reason) on failure; the temporary
// file is removed in that case.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace frictionid
