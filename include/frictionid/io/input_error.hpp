// The one error type for rejected user input: it carries where (file, line, column) and what.
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
        message_(what) {}
  explicit InputError(const std::string& what) : InputError("", 0, 0, what) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }
  // What is wrong, without the place that what() puts in front of it.
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& file, std::size_t line, std::size_t column,
                            const std::string& what) {
    std::string where = file;
    if (line > 0) where += (where.empty() ? "line " : ":") + std::to_string(line);
    if (column > 0) where += (line > 0 ? ":" : ":column ") + std::to_string(column);
    return where.empty() ? what : where + ": " + what;
  }
  std::string file_;
  std::size_t line_;
  std::size_t column_;
  std::string message_;
};

}  // namespace frictionid
