// The whole of a small input file (a pressure table or map), read with a bound: such a file is a
// few thousand samples, and a path like /dev/zero must not be read forever.
#pragma once

#include <string>

namespace frictionid::io {

// At most 16 MiB of `path`. Throws InputError naming the path: a directory ("is a directory;
// expected <expected_file>"), a file that cannot be opened ("cannot open the <what>"), or a
// larger one ("is larger than 16 MiB; expected <expected_content>").
std::string read_small_file(const std::string& path, const std::string& expected_file,
                            const std::string& what, const std::string& expected_content);

}  // namespace frictionid::io
