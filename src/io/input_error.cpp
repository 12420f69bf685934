#include <frictionid/io/input_error.hpp>

#include "io/text.hpp"

namespace frictionid {

std::string InputError::bounded(const std::string& what) {
  return text::for_terminal(what);
}

std::string InputError::format(const std::string& file, std::size_t line, std::size_t column,
                               const std::string& what) {
  // A path is at most a few KiB; a name that Python code passes as the source may be anything.
  std::string where = text::for_terminal(file, text::kMaxQuotedBytes);
  if (line > 0) where += (where.empty() ? "line " : ":") + std::to_string(line);
  if (column > 0) where += (line > 0 ? ":" : ":column ") + std::to_string(column);
  return where.empty() ? bounded(what) : where + ": " + bounded(what);
}

}  // namespace frictionid
