#include "io/dataset_csv.hpp"

#include <libfccp/csv.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>
#include <string_view>
#include <vector>

#include "io/input_error.hpp"
#include "io/option_parsers.hpp"

namespace frictionid {

namespace {

// The canonical columns, in the order used for slots below.
enum Slot : int {
  kVx,
  kVy,
  kOmega,
  kN,
  kR,
  kTx,
  kTy,
  kMz,
  kMroll,
  kSigmaTx,
  kSigmaTy,
  kSigmaMz,
  kSigmaMroll,
  kSlotCount
};
constexpr int kFirstChannel = kTx;
constexpr int kFirstSigma = kSigmaTx;

constexpr const char* kCanonical[kSlotCount] = {
    "v_x", "v_y",    "omega",     "N",         "R",         "T_x",         "T_y",
    "M_z", "M_roll", "sigma_T_x", "sigma_T_y", "sigma_M_z", "sigma_M_roll"};
constexpr const char* kMeaning[kSlotCount] = {"slip velocity along the rolling axis [m/s]",
                                              "lateral slip velocity [m/s]",
                                              "spin [rad/s]",
                                              "normal load [N], > 0",
                                              "contact radius [m], > 0",
                                              "measured T_x [N]",
                                              "measured T_y [N]",
                                              "measured M_z [N m]",
                                              "measured M_roll [N m]",
                                              "standard deviation of T_x [N], > 0",
                                              "standard deviation of T_y [N], > 0",
                                              "standard deviation of M_z [N m], > 0",
                                              "standard deviation of M_roll [N m], > 0"};
constexpr bool kRequiredColumn[kSlotCount] = {true,  false, true,  true,  true,  false, false,
                                              false, false, false, false, false, false};

using QuotePolicy = io::double_quote_escape<',', '"'>;
using TrimPolicy = io::trim_chars<' ', '\t'>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The text quoted for a message, cut at 60 bytes; control characters other than tab (e.g. a CR)
// are shown as \xNN so that the message stays one readable line.
std::string shown(std::string_view text) {
  constexpr std::size_t kMax = 60;
  std::string out = "'";
  for (const char c : text.substr(0, kMax)) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t') || u == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += {'\\', 'x', kHex[u >> 4], kHex[u & 15]};
    } else {
      out += c;
    }
  }
  return out + (text.size() > kMax ? "...'" : "'");
}

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

// Case-insensitive optimal string alignment distance (edits + adjacent transpositions).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[m];
}

// Distance when `candidate` looks like a misspelling of `target` (a case-only difference, one edit
// for short names, two for names of 6+ characters), else SIZE_MAX.
std::size_t misspelling_distance(std::string_view candidate, std::string_view target) {
  const std::size_t d = edit_distance(candidate, target);
  const std::size_t limit = target.size() >= 6 ? 2 : 1;
  return d <= limit ? d : std::numeric_limits<std::size_t>::max();
}

int canonical_slot(std::string_view name) {
  for (int s = 0; s < kSlotCount; ++s)
    if (name == kCanonical[s]) return s;
  return -1;
}

std::string canonical_list() {
  std::string out;
  for (int s = 0; s < kSlotCount; ++s) out += (s ? ", " : "") + std::string(kCanonical[s]);
  return out;
}

// Splits `line` in place into trimmed, unquoted fields (views into `line`) and returns the line's
// length. The vector is reused between rows, so a row costs no allocation. Lines without a quote
// take a memchr fast path; others go through fast-cpp-csv-parser's double-quote policy.
std::size_t split_fields(char* line, std::vector<std::string_view>& fields, const std::string& file,
                         std::size_t line_no) {
  fields.clear();
  const std::size_t length = std::strlen(line);
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
      if (!comma) return length;
      begin = comma + 1;
    }
  }
  char* begin = line;
  while (true) {
    const char* end_c = nullptr;
    try {
      end_c = QuotePolicy::find_next_column_end(begin);
    } catch (const io::error::escaped_string_not_closed&) {
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
    if (last) return length;
    begin = next;
  }
}

// A hint when a line looks separated by something other than ','.
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

// Rows a file of `file_bytes` probably holds, judged by its first data row; capped by the
// shortest possible row (one character per field plus separators) so a short first row cannot
// make the reservation absurd. Zero when the size is unknown.
std::size_t estimate_rows(std::uintmax_t file_bytes, std::size_t first_row_length,
                          std::size_t field_count) {
  if (file_bytes == static_cast<std::uintmax_t>(-1) || file_bytes == 0) return 0;
  const std::uintmax_t typical =
      file_bytes / (first_row_length + 1) + file_bytes / (first_row_length + 1) / 8 + 16;
  const std::uintmax_t most = file_bytes / (2 * field_count) + 1;
  return static_cast<std::size_t>(std::min(typical, most));
}

void reserve_rows(Dataset& d, std::size_t rows, const bool (&has_sigma)[kChannelCount]) {
  d.line.reserve(rows);
  for (auto* v : {&d.v_x, &d.v_y, &d.omega, &d.N, &d.R}) v->reserve(rows);
  for (int c = 0; c < kChannelCount; ++c) {
    d.value[c].reserve(rows);
    d.present[c].reserve(rows);
    if (has_sigma[c]) d.sigma[c].reserve(rows);
  }
}

struct Column {
  int field = -1;      // 0-based field index in the row, -1 when the file lacks the column
  std::string header;  // the header name looked up for this slot
};

std::string describe(const Column& col, int slot) {
  if (col.header == kCanonical[slot]) return "'" + col.header + "'";
  return "'" + col.header + "' (" + kCanonical[slot] + ")";
}

}  // namespace

ColumnMap parse_column_map(const std::string& spec) {
  ColumnMap map;
  std::string_view all(spec);
  auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
  };
  if (trim(all).empty()) return map;
  const std::string option = "--columns";
  const std::string expected = "canonical=header[,canonical=header...], e.g. v_x=speed,omega=spin";
  std::set<std::string> headers;
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = all.find(',', pos);
    const std::string_view item = trim(
        all.substr(pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos));
    if (item.empty())
      throw InputError(option, 0, 0, "empty entry in " + shown(spec) + "; expected " + expected);
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos)
      throw InputError(
          option, 0, 0,
          "missing '=' in " + shown(item) + " (in " + shown(spec) + "); expected " + expected);
    const std::string canonical(trim(item.substr(0, eq)));
    const std::string header(trim(item.substr(eq + 1)));
    if (canonical_slot(canonical) < 0) {
      std::string hint;
      std::size_t best = std::numeric_limits<std::size_t>::max();
      for (int s = 0; s < kSlotCount; ++s)
        if (const std::size_t d = misspelling_distance(canonical, kCanonical[s]); d < best) {
          best = d;
          hint = "; did you mean '" + std::string(kCanonical[s]) + "'?";
        }
      throw InputError(option, 0, 0,
                       "unknown canonical column " + shown(canonical) + " in " + shown(spec) +
                           hint + " (expected one of: " + canonical_list() + ")");
    }
    if (header.empty())
      throw InputError(
          option, 0, 0,
          "empty header name for '" + canonical + "' in " + shown(spec) + "; expected " + expected);
    if (map.canonical_to_header.count(canonical))
      throw InputError(option, 0, 0,
                       "'" + canonical + "' is mapped more than once in " + shown(spec));
    if (!headers.insert(header).second)
      throw InputError(
          option, 0, 0,
          "header name " + shown(header) + " is mapped to more than one column in " + shown(spec));
    map.canonical_to_header.emplace(canonical, header);
    if (comma == std::string_view::npos) break;
    pos = comma + 1;
  }
  return map;
}

Dataset load_dataset_csv(const std::string& path, const ColumnMap& columns, bool require_channels) {
  // Which header name each slot is looked up under.
  Column col[kSlotCount];
  for (int s = 0; s < kSlotCount; ++s) col[s].header = kCanonical[s];
  for (const auto& [canonical, header] : columns.canonical_to_header) {
    const int s = canonical_slot(canonical);
    if (s < 0)
      throw InputError(
          "--columns", 0, 0,
          "unknown canonical column '" + canonical + "'; expected one of: " + canonical_list());
    col[s].header = header;
  }
  for (int s = 0; s < kSlotCount; ++s)
    for (int t = s + 1; t < kSlotCount; ++t)
      if (col[s].header == col[t].header)
        throw InputError("--columns", 0, 0,
                         "header name '" + col[s].header + "' would supply both " + kCanonical[s] +
                             " and " + kCanonical[t] + "; map the other one to a different name");

  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, 0, "is a directory; expected a CSV file");

  Dataset data;
  data.source = path;
  try {
    io::LineReader reader(path);

    // ---- header ----
    char* line = reader.next_line();
    if (line == nullptr)
      throw InputError(path, 0, 0,
                       "empty file; expected a header row such as v_x,v_y,omega,N,R,T_x,T_y,M_z");
    // A CR left inside the first line means CR-only line ends (CRLF's CR is already stripped).
    if (const char* cr = std::strchr(line, '\r')) {
      const auto column = std::count(static_cast<const char*>(line), cr, ',') + 1;
      throw InputError(path, 1, static_cast<std::size_t>(column),
                       "the first line contains a carriage return (CR): the file seems to use "
                       "CR-only (classic Mac) line ends; expected LF or CRLF line ends");
    }
    std::vector<std::string_view> fields;
    fields.reserve(32);
    split_fields(line, fields, path, 1);
    const std::vector<std::string> names(fields.begin(), fields.end());
    const std::size_t field_count = names.size();
    if (field_count == 1 && names[0].empty())
      throw InputError(path, 1, 0,
                       "header row is empty; expected column names such as v_x,omega,N,R,T_x");
    if (field_count == 1) {
      const std::string hint = delimiter_hint(fields);
      if (!hint.empty())
        throw InputError(path, 1, 1, "header is a single field " + shown(names[0]) + hint);
    }

    std::vector<bool> used(field_count, false);
    for (int s = 0; s < kSlotCount; ++s) {
      for (std::size_t k = 0; k < field_count; ++k) {
        if (names[k] != col[s].header) continue;
        if (col[s].field >= 0)
          throw InputError(path, 1, k + 1,
                           "duplicate column " + describe(col[s], s) + " (also column " +
                               std::to_string(col[s].field + 1) + "); expected each column once");
        col[s].field = static_cast<int>(k);
        used[k] = true;
      }
    }

    auto header_list = [&] {
      std::string out;
      for (std::size_t k = 0; k < field_count; ++k) out += (k ? ", " : "") + shown(names[k]);
      return out;
    };
    // The best "did you mean" among the header names not yet used, for the slots [first, last)
    // that the caller wants matched; sets `column` to the misspelt header column.
    auto suggestion = [&](int first, int last, std::size_t& column) {
      std::size_t best = std::numeric_limits<std::size_t>::max();
      int best_slot = -1, best_field = -1;
      for (int s = first; s < last; ++s) {
        if (col[s].field >= 0 || (s < kFirstChannel && !kRequiredColumn[s])) continue;
        for (std::size_t k = 0; k < field_count; ++k) {
          if (used[k]) continue;
          if (const std::size_t d = misspelling_distance(names[k], col[s].header); d < best)
            best = d, best_slot = s, best_field = static_cast<int>(k);
        }
      }
      if (best_slot < 0) return std::string();
      column = static_cast<std::size_t>(best_field) + 1;
      const std::string& name = names[static_cast<std::size_t>(best_field)];
      if (col[best_slot].header == kCanonical[best_slot])
        return "; did you mean '" + col[best_slot].header + "'? (column " + std::to_string(column) +
               " is " + shown(name) + ")";
      return "; column " + std::to_string(column) + " " + shown(name) + " is close to '" +
             col[best_slot].header + "' given by --columns for " + kCanonical[best_slot] +
             ": check the spelling";
    };

    // Required columns: report all that are missing, point at a likely misspelling.
    {
      std::string missing, hint;
      std::size_t column = 0;
      for (int s = 0; s < kSlotCount; ++s) {
        if (!kRequiredColumn[s] || col[s].field >= 0) continue;
        missing += (missing.empty() ? "" : ", ") + describe(col[s], s);
      }
      if (!missing.empty()) hint = suggestion(0, kFirstChannel, column);
      if (hint.empty())
        hint = "; map other header names with --columns canonical=header (e.g. omega=spin)";
      if (!missing.empty())
        throw InputError(path, 1, column,
                         "missing required column(s) " + missing + "; the header has " +
                             header_list() + hint + delimiter_hint(fields));
    }
    {
      bool any_channel = false;
      for (int s = kFirstChannel; s < kFirstSigma; ++s) any_channel |= col[s].field >= 0;
      if (!any_channel && require_channels) {
        std::string hint;
        std::size_t column = 0;
        hint = suggestion(kFirstChannel, kFirstSigma, column);
        std::string expected;
        for (int s = kFirstChannel; s < kFirstSigma; ++s)
          expected += (s > kFirstChannel ? ", " : "") + describe(col[s], s);
        throw InputError(path, 1, column,
                         "no measured channel column; expected at least one of " + expected +
                             "; the header has " + header_list() + hint);
      }
    }
    for (int s = kFirstSigma; s < kSlotCount; ++s) {
      const int c = s - kFirstSigma + kFirstChannel;
      if (col[s].field >= 0 && col[c].field < 0) {
        std::size_t column = 0;
        const std::string hint = suggestion(c, c + 1, column);
        throw InputError(path, 1, static_cast<std::size_t>(col[s].field) + 1,
                         "column " + describe(col[s], s) + " is given but there is no column " +
                             describe(col[c], c) + " it belongs to; the header has " +
                             header_list() + hint);
      }
    }

    // The used slots in field order, so a row is scanned left to right.
    std::vector<int> order;
    for (int s = 0; s < kSlotCount; ++s)
      if (col[s].field >= 0) order.push_back(s);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return col[a].field < col[b].field; });
    const bool has_sigma[kChannelCount] = {col[kSigmaTx].field >= 0, col[kSigmaTy].field >= 0,
                                           col[kSigmaMz].field >= 0, col[kSigmaMroll].field >= 0};
    int first_channel_field = std::numeric_limits<int>::max();
    for (int s = kFirstChannel; s < kFirstSigma; ++s)
      if (col[s].field >= 0) first_channel_field = std::min(first_channel_field, col[s].field);

    // ---- rows ----
    std::error_code size_error;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path, size_error);
    double value[kSlotCount] = {};
    bool given[kSlotCount] = {};
    while ((line = reader.next_line()) != nullptr) {
      const std::size_t line_no = reader.get_file_line();
      const std::size_t length = split_fields(line, fields, path, line_no);
      if (fields.size() == 1 && fields[0].empty()) continue;  // blank line
      if (data.rows() == 0)
        reserve_rows(data, estimate_rows(file_bytes, length, field_count), has_sigma);
      if (fields.size() != field_count) {
        const bool few = fields.size() < field_count;
        throw InputError(path, line_no, (few ? fields.size() : field_count) + 1,
                         "row has " + std::to_string(fields.size()) + " fields, expected " +
                             std::to_string(field_count) + " as in the header" +
                             (few ? std::string(" (the row ends early)")
                                  : "; first extra field " + shown(fields[field_count])) +
                             delimiter_hint(fields));
      }
      for (const int s : order) {
        const std::string_view text = fields[static_cast<std::size_t>(col[s].field)];
        const std::size_t column = static_cast<std::size_t>(col[s].field) + 1;
        given[s] = !text.empty();
        value[s] = kNaN;
        if (text.empty()) {
          if (s < kFirstChannel)
            throw InputError(
                path, line_no, column,
                "empty field in column " + describe(col[s], s) + "; expected " + kMeaning[s]);
          continue;
        }
        if (const char* why = parse_double_strict(text, value[s]))
          throw InputError(path, line_no, column,
                           "column " + describe(col[s], s) + " has " + shown(text) + " (" + why +
                               "); expected a finite decimal number: " + kMeaning[s]);
        if ((s == kN || s == kR) && !(value[s] > 0))
          throw InputError(path, line_no, column,
                           "column " + describe(col[s], s) + " has " + shown(text) + "; expected " +
                               kMeaning[s]);
      }

      bool any = false;
      for (int c = 0; c < kChannelCount; ++c) {
        const int s = kFirstChannel + c;
        const bool present = col[s].field >= 0 && given[s];
        any |= present;
        if (!present || !has_sigma[c]) continue;
        const int q = kFirstSigma + c;
        const std::size_t column = static_cast<std::size_t>(col[q].field) + 1;
        if (!given[q])
          throw InputError(path, line_no, column,
                           "empty field in column " + describe(col[q], q) + " while " +
                               describe(col[s], s) + " is given; expected " + kMeaning[q]);
        if (!(value[q] > 0))
          throw InputError(path, line_no, column,
                           "column " + describe(col[q], q) + " has " +
                               shown(fields[static_cast<std::size_t>(col[q].field)]) +
                               "; expected " + kMeaning[q]);
      }
      if (!any && require_channels)
        throw InputError(path, line_no, static_cast<std::size_t>(first_channel_field) + 1,
                         "no measured channel in this row; expected a value in at least one of "
                         "the channel columns");

      data.line.push_back(line_no);
      data.v_x.push_back(value[kVx]);
      data.v_y.push_back(col[kVy].field >= 0 ? value[kVy] : 0.0);
      data.omega.push_back(value[kOmega]);
      data.N.push_back(value[kN]);
      data.R.push_back(value[kR]);
      for (int c = 0; c < kChannelCount; ++c) {
        const int s = kFirstChannel + c;
        const bool present = col[s].field >= 0 && given[s];
        data.value[c].push_back(present ? value[s] : kNaN);
        data.present[c].push_back(present ? 1 : 0);
        if (has_sigma[c]) data.sigma[c].push_back(present ? value[kFirstSigma + c] : kNaN);
      }
    }
    if (data.rows() == 0)
      throw InputError(path, 1, 0,
                       "the header is not followed by any data row; expected at least one "
                       "measurement row");
  } catch (const io::error::can_not_open_file& e) {
    throw InputError(path, 0, 0,
                     std::string("cannot open file") +
                         (e.errno_value ? std::string(": ") + std::strerror(e.errno_value) : ""));
  } catch (const io::error::line_length_limit_exceeded& e) {
    throw InputError(path, static_cast<std::size_t>(e.file_line), 0,
                     "line is longer than 2^24-1 characters; expected a CSV row");
  }
  return data;
}

}  // namespace frictionid
