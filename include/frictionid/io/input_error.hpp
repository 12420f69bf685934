// The one error type for rejected user input: it carries where (file, line, column) and what.
// Its text (what(), message()) is safe to print: every byte of the file name and message that
// is not printable ASCII is escaped as \xNN, and a long message is cut (src/io/text.hpp), so a
// hostile file name or a 40 MB line reaches neither the terminal nor a Python exception raw.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace frictionid {

class InputError : public std::runtime_error {
 public:
  // line/column are 1-based; 0 means "not applicable" and is left out of the message.
  InputError(std::string file, std::size_t line, std::size_t column, const std::string& what)
      : std::runtime_error(format(file, line, column, what)),
        file_(std::move(file)),
        line_(line),
        column_(column),
        message_(bounded(what)) {}
  explicit InputError(const std::string& what) : InputError("", 0, 0, what) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }
  // What is wrong, without the place that what() puts in front of it; escaped and bounded as
  // what() is. file() is the name as given (for code that opens it), not escaped.
  const std::string& message() const { return message_; }

 private:
  // Defined in src/io/input_error.cpp, with the escaping of src/io/text.hpp.
  static std::string bounded(const std::string& what);
  static std::string format(const std::string& file, std::size_t line, std::size_t column,
                            const std::string& what);
  std::string file_;
  std::size_t line_;
  std::size_t column_;
  std::string message_;
};

}  // namespace frictionid
