#include "io/csv_cell.hpp"

#include "io/text.hpp"

namespace frictionid {

namespace {

bool starts_a_formula(std::string_view s) {
  if (s.empty()) return false;
  switch (s.front()) {
    case '=':
    case '+':
    case '-':
    case '@':
    case '\t':
    case '\r':
      break;
    default:
      return false;
  }
  double number = 0.0;
  return text::parse_double_strict(s, number) != nullptr;
}

}  // namespace

std::string csv_cell(std::string_view s) {
  std::string cell = starts_a_formula(s) ? "'" + std::string(s) : std::string(s);
  const bool quote = cell.find_first_of(",\"\r\n") != std::string::npos ||
                     (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t' ||
                                        cell.back() == ' ' || cell.back() == '\t'));
  if (!quote) return cell;
  std::string out = "\"";
  for (const char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace frictionid
