// Splitting CSV lines into fields (io/csv_fields.hpp).
#include "io/csv_fields.hpp"

#include <libfccp/csv.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include <frictionid/io/input_error.hpp>
#include "io/encoding_sniffer.hpp"
#include "io/line_reader.hpp"
#include "io/text.hpp"

namespace frictionid::io_detail {

namespace {

using QuotePolicy = ::io::double_quote_escape<',', '"'>;
using TrimPolicy = ::io::trim_chars<' ', '\t'>;
using text::shown;

}  // namespace

void split_fields(char* line, std::size_t length, std::vector<std::string_view>& fields,
                  const std::string& file, std::size_t line_no) {
  fields.clear();
  char* const line_end = line + length;
  if (std::memchr(line, '"', length) == nullptr) {
    char* begin = line;
    while (true) {
      char* comma = static_cast<char*>(std::memchr(begin, ',', line_end - begin));
      char* b = begin;
      char* e = comma ? comma : line_end;
      while (b != e && (*b == ' ' || *b == '\t')) ++b;
      while (b != e && (e[-1] == ' ' || e[-1] == '\t')) --e;
      fields.emplace_back(b, static_cast<std::size_t>(e - b));
      if (!comma) return;
      begin = comma + 1;
    }
  }
  char* begin = line;
  while (true) {
    const char* end_c = nullptr;
    try {
      end_c = QuotePolicy::find_next_column_end(begin);
    } catch (const ::io::error::escaped_string_not_closed&) {
      throw InputError(file, line_no, fields.size() + 1,
                       "unterminated quoted field " + shown(begin) + "; expected a closing '\"'");
    }
    char* end = begin + (end_c - begin);
    const bool last = *end == '\0';
    char* next = end + 1;
    char* b = begin;
    char* e = end;
    TrimPolicy::trim(b, e);
    QuotePolicy::unescape(b, e);
    fields.emplace_back(b, static_cast<std::size_t>(e - b));
    if (last) return;
    begin = next;
  }
}

std::string delimiter_hint(const std::vector<std::string_view>& fields) {
  static constexpr std::pair<char, const char*> kOthers[] = {
      {';', "';'"}, {'\t', "tab"}, {'|', "'|'"}};
  for (const auto& [c, name] : kOthers)
    for (std::string_view f : fields)
      if (f.find(c) != std::string_view::npos)
        return std::string("; the line contains ") + name +
               " characters: the file seems to use another delimiter, expected ','";
  return "";
}

std::size_t reject_carriage_return(const char* line, const std::string& path, std::size_t line_no) {
  const char* const cr = ::strchrnul(line, '\r');
  if (*cr != '\r') return static_cast<std::size_t>(cr - line);
  const auto column = std::count(line, cr, ',') + 1;
  throw InputError(path, line_no, static_cast<std::size_t>(column),
                   line_no == 1
                       ? "the first line contains a carriage return (CR): the file seems to use "
                         "CR-only (classic Mac) line ends; expected LF or CRLF line ends"
                       : "the line contains a carriage return (CR) inside it: the rows seem to "
                         "use CR-only (classic Mac) line ends; expected LF or CRLF line ends");
}

CsvRows::CsvRows(const std::string& path) : path_(path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, 0, "is a directory; expected a CSV file");
  reader_ = std::make_unique<LineReader>(path);
  if (const std::string hint = unsupported_encoding_hint(reader_->head()); !hint.empty())
    throw InputError(path, 1, 0, hint);
  char* line = reader_->next_line();
  if (line == nullptr)
    throw InputError(path, 0, 0, "empty file; expected a header row with the column names");
  const std::size_t length = reject_carriage_return(line, path, 1);
  std::vector<std::string_view> fields;
  split_fields(line, length, fields, path, 1);
  if (fields.size() == 1 && fields[0].empty())
    throw InputError(path, 1, 0, "header row is empty; expected the column names");
  if (fields.size() == 1) {
    const std::string hint = delimiter_hint(fields);
    if (!hint.empty())
      throw InputError(path, 1, 1, "header is a single field " + shown(fields[0]) + hint);
  }
  header_.assign(fields.begin(), fields.end());
}

CsvRows::~CsvRows() = default;

bool CsvRows::next(std::vector<std::string_view>& fields) {
  while (char* line = reader_->next_line()) {
    line_ = reader_->line_number();
    const std::size_t length = reject_carriage_return(line, path_, line_);
    split_fields(line, length, fields, path_, line_);
    if (fields.size() == 1 && fields[0].empty()) continue;  // blank line
    if (rows_ == kMaxRows)
      throw InputError(path_, line_, 0,
                       "more than 20000000 rows; expected at most that many (split the data or "
                       "subsample it)");
    ++rows_;
    if (fields.size() != header_.size()) {
      const bool few = fields.size() < header_.size();
      throw InputError(path_, line_, (few ? fields.size() : header_.size()) + 1,
                       "row has " + std::to_string(fields.size()) + " fields, expected " +
                           std::to_string(header_.size()) + " as in the header" +
                           (few ? std::string(" (the row ends early)")
                                : "; first extra field " + shown(fields[header_.size()])) +
                           delimiter_hint(fields));
    }
    return true;
  }
  return false;
}

std::vector<std::string> csv_header(const std::string& path) {
  return CsvRows(path).header();
}

}  // namespace frictionid::io_detail
