// Splitting one CSV line into fields, with the rules of the dataset reader (docs/design.md
// §4.1): comma separated, double-quoted fields ("" inside quotes is a quote), spaces and tabs
// around a field trimmed; and the two line checks every CSV reader of frictionid makes (CR-only
// line ends, another delimiter). Shared by the native reader (dataset_csv.cpp) and the wheel-form
// reader (wheel_form.cpp).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace frictionid::io_detail {

// Splits `line` (of `length` characters up to its NUL) in place into trimmed, unquoted fields
// (views into `line`). The vector is reused between rows, so a row costs no allocation. Lines
// without a quote take a memchr fast path; others go through fast-cpp-csv-parser's double-quote
// policy. Throws InputError(file, line_no, field) for an unterminated quoted field.
void split_fields(char* line, std::size_t length, std::vector<std::string_view>& fields,
                  const std::string& file, std::size_t line_no);

// A hint when a line looks separated by something other than ',' ("" otherwise).
std::string delimiter_hint(const std::vector<std::string_view>& fields);

// The line's length up to its first NUL; throws InputError when it holds a carriage return (the
// file then uses CR-only line ends).
std::size_t reject_carriage_return(const char* line, const std::string& path, std::size_t line_no);

class LineReader;

// A CSV file read row by row with the rules above, for readers that are not the native one:
// opening it checks that it is not a directory, that its first bytes are not of a compressed or
// UTF-16/32 file, and reads the header; rows then come one by one, blank lines skipped, each
// with as many fields as the header (else an InputError naming the line). At most max_rows rows.
class CsvRows {
 public:
  static constexpr std::size_t kMaxRows = 20'000'000;

  explicit CsvRows(const std::string& path);
  ~CsvRows();
  CsvRows(const CsvRows&) = delete;
  CsvRows& operator=(const CsvRows&) = delete;

  const std::string& path() const { return path_; }
  const std::vector<std::string>& header() const { return header_; }

  // The next row's fields (views valid until the next call); false at the end of the file.
  bool next(std::vector<std::string_view>& fields);
  // The 1-based line of the row next() returned last.
  std::size_t line() const { return line_; }

 private:
  std::string path_;
  std::unique_ptr<LineReader> reader_;
  std::vector<std::string> header_;
  std::size_t line_ = 1;
  std::size_t rows_ = 0;
};

// The header fields of a CSV file, read as CsvRows reads them (only the first line is read).
std::vector<std::string> csv_header(const std::string& path);

}  // namespace frictionid::io_detail
