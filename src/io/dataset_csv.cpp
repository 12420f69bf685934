#include <frictionid/io/dataset_csv.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <set>
#include <string_view>
#include <vector>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/units.hpp>
#include "identify/row_chunks.hpp"
#include "io/csv_fields.hpp"
#include "io/encoding_sniffer.hpp"
#include "io/huge_pages.hpp"
#include "io/line_reader.hpp"
#include "io/text.hpp"

namespace frictionid {

namespace {

using io_detail::delimiter_hint;
using io_detail::reject_carriage_return;
using io_detail::split_fields;
using text::misspelling_distance;
using text::shown;

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
  kMtilt,
  kSigmaTx,
  kSigmaTy,
  kSigmaMz,
  kSigmaMroll,
  kSigmaMtilt,
  kSlotCount
};
constexpr int kFirstChannel = kTx;
constexpr int kFirstSigma = kSigmaTx;

constexpr const char* kCanonical[kSlotCount] = {
    "v_x",    "v_y",    "omega",     "N",         "R",         "T_x",          "T_y",         "M_z",
    "M_roll", "M_tilt", "sigma_T_x", "sigma_T_y", "sigma_M_z", "sigma_M_roll", "sigma_M_tilt"};
constexpr const char* kMeaning[kSlotCount] = {"slip velocity along the rolling axis [m/s]",
                                              "lateral slip velocity [m/s]",
                                              "spin [rad/s]",
                                              "normal load [N], > 0",
                                              "contact radius [m], > 0",
                                              "measured T_x [N]",
                                              "measured T_y [N]",
                                              "measured M_z [N m]",
                                              "measured M_roll [N m]",
                                              "measured M_tilt [N m]",
                                              "standard deviation of T_x [N], > 0",
                                              "standard deviation of T_y [N], > 0",
                                              "standard deviation of M_z [N m], > 0",
                                              "standard deviation of M_roll [N m], > 0",
                                              "standard deviation of M_tilt [N m], > 0"};
// What a unit in a column's header must measure (io/units.hpp).
constexpr Quantity kQuantity[kSlotCount] = {
    Quantity::Speed, Quantity::Speed, Quantity::AngularRate, Quantity::Force,  Quantity::Length,
    Quantity::Force, Quantity::Force, Quantity::Moment,      Quantity::Moment, Quantity::Moment,
    Quantity::Force, Quantity::Force, Quantity::Moment,      Quantity::Moment, Quantity::Moment};
constexpr bool kRequiredColumn[kSlotCount] = {true,  false, true,  true,  true,
                                              false, false, false, false, false,
                                              false, false, false, false, false};

using text::kNaN;

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

// Reserves room for `rows` rows in `column`; a large column gets huge pages, since every row of
// it is about to be written.
template <class T>
void reserve_column(std::vector<T>& column, std::size_t rows) {
  column.reserve(rows);
  io_detail::advise_huge_pages(column.data(), column.capacity() * sizeof(T));
}

void reserve_rows(Dataset& d, std::size_t rows, const bool (&has_sigma)[kChannelCount]) {
  reserve_column(d.line, rows);
  for (auto* v : {&d.v_x, &d.v_y, &d.omega, &d.N, &d.R}) reserve_column(*v, rows);
  for (int c = 0; c < kChannelCount; ++c) {
    reserve_column(d.value[c], rows);
    reserve_column(d.present[c], rows);
    if (has_sigma[c]) reserve_column(d.sigma[c], rows);
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

// The header name each slot is looked up under: canonical, or renamed by the column map.
std::array<Column, kSlotCount> lookup_names(const ColumnMap& columns) {
  std::array<Column, kSlotCount> col;
  for (int s = 0; s < kSlotCount; ++s) col[s].header = kCanonical[s];
  for (const auto& [canonical, header] : columns.canonical_to_header) {
    const int s = canonical_slot(canonical);
    if (s < 0)
      throw InputError(
          "column map", 0, 0,
          "unknown canonical column '" + canonical + "'; expected one of: " + canonical_list());
    col[s].header = header;
  }
  for (int s = 0; s < kSlotCount; ++s)
    for (int t = s + 1; t < kSlotCount; ++t)
      if (col[s].header == col[t].header)
        throw InputError("column map", 0, 0,
                         "header name '" + col[s].header + "' would supply both " + kCanonical[s] +
                             " and " + kCanonical[t] + "; map the other one to a different name");
  return col;
}

// What the header says: where each slot's column is, which fields are used, and in what order
// a row is read.
struct Header {
  std::string path;
  std::array<Column, kSlotCount> col;
  std::vector<std::string> names;         // the header's fields
  std::vector<std::string> bare;          // the fields without a unit in brackets
  double factor[kSlotCount] = {};         // each slot's unit in SI (1: no unit)
  std::vector<bool> used;                 // per field: a slot reads it
  std::vector<std::size_t> extra_fields;  // fields kept as text (Dataset::extra_names)
  std::vector<int> order;                 // the used slots in field order
  bool has_sigma[kChannelCount] = {};
  int first_channel_field = std::numeric_limits<int>::max();
  std::size_t field_count() const { return names.size(); }

  // The header's names for a message; a header of thousands of fields is cut after a few
  // hundred bytes, saying how many names are left out.
  std::string header_list() const {
    std::string out;
    for (std::size_t k = 0; k < names.size(); ++k) {
      std::string name = shown(names[k]);
      if (k > 0 && out.size() + name.size() > 2 * text::kMaxQuotedBytes)
        return out + ", ... (" + std::to_string(names.size() - k) + " more)";
      out += (k ? ", " : "") + name;
    }
    return out;
  }

  // The best "did you mean" among the header names not yet used, for the slots [first, last)
  // that the caller wants matched; sets `column` to the misspelt header column.
  std::string suggestion(int first, int last, std::size_t& column) const {
    std::size_t best = std::numeric_limits<std::size_t>::max();
    int best_slot = -1, best_field = -1;
    for (int s = first; s < last; ++s) {
      if (col[s].field >= 0 || (s < kFirstChannel && !kRequiredColumn[s])) continue;
      for (std::size_t k = 0; k < names.size(); ++k) {
        if (used[k]) continue;
        if (const std::size_t d = misspelling_distance(bare[k], col[s].header); d < best)
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
           col[best_slot].header + "' given by the column map for " + kCanonical[best_slot] +
           ": check the spelling";
  }
};

// Finds every slot's column in the header fields; duplicates are errors.
void match_columns(Header& h, const std::vector<std::string_view>& fields) {
  if (h.field_count() == 1 && h.names[0].empty())
    throw InputError(h.path, 1, 0,
                     "header row is empty; expected column names such as v_x,omega,N,R,T_x");
  if (h.field_count() == 1) {
    const std::string hint = delimiter_hint(fields);
    if (!hint.empty())
      throw InputError(h.path, 1, 1, "header is a single field " + shown(h.names[0]) + hint);
  }
  h.used.assign(h.field_count(), false);
  for (int s = 0; s < kSlotCount; ++s) {
    h.factor[s] = 1.0;
    for (std::size_t k = 0; k < h.field_count(); ++k) {
      if (h.names[k] != h.col[s].header && h.bare[k] != h.col[s].header) continue;
      if (h.col[s].field >= 0)
        throw InputError(h.path, 1, k + 1,
                         "duplicate column " + describe(h.col[s], s) + " (also column " +
                             std::to_string(h.col[s].field + 1) + "); expected each column once");
      h.col[s].field = static_cast<int>(k);
      h.used[k] = true;
      // A unit in brackets is converted on reading; none is SI.
      h.factor[s] = column_unit_factor(kQuantity[s], h.names[k], split_header_name(h.names[k]),
                                       h.path, 1, k + 1);
    }
  }
}

// Required columns (all missing ones listed, a likely misspelling pointed at), at least one
// channel, and no sigma column without its channel.
void check_columns(const Header& h, const std::vector<std::string_view>& fields,
                   bool require_channels) {
  const auto& col = h.col;
  std::string missing, hint;
  std::size_t column = 0;
  for (int s = 0; s < kSlotCount; ++s)
    if (kRequiredColumn[s] && col[s].field < 0)
      missing += (missing.empty() ? "" : ", ") + describe(col[s], s);
  if (!missing.empty()) {
    hint = h.suggestion(0, kFirstChannel, column);
    if (hint.empty())
      hint =
          "; map other header names to the canonical ones with a column map canonical=header "
          "(e.g. omega=spin)";
    throw InputError(h.path, 1, column,
                     "missing required column(s) " + missing + "; the header has " +
                         h.header_list() + hint + delimiter_hint(fields));
  }
  bool any_channel = false;
  for (int s = kFirstChannel; s < kFirstSigma; ++s) any_channel |= col[s].field >= 0;
  if (!any_channel && require_channels) {
    hint = h.suggestion(kFirstChannel, kFirstSigma, column);
    std::string expected;
    for (int s = kFirstChannel; s < kFirstSigma; ++s)
      expected += (s > kFirstChannel ? ", " : "") + describe(col[s], s);
    throw InputError(h.path, 1, column,
                     "no measured channel column; expected at least one of " + expected +
                         "; the header has " + h.header_list() + hint);
  }
  for (int s = kFirstSigma; s < kSlotCount; ++s) {
    const int c = s - kFirstSigma + kFirstChannel;
    if (col[s].field >= 0 && col[c].field < 0) {
      hint = h.suggestion(c, c + 1, column);
      throw InputError(h.path, 1, static_cast<std::size_t>(col[s].field) + 1,
                       "column " + describe(col[s], s) + " is given but there is no column " +
                           describe(col[c], c) + " it belongs to; the header has " +
                           h.header_list() + hint);
    }
  }
}

// An extra column whose name is a likely misspelling of a column the file lacks (`vy` for v_y,
// `Tx` for T_x, `m_z` for M_z) is an error: read as an extra column, a lateral slip would be
// taken as 0 and a channel left out of the fit, and the fit would say nothing.
void reject_misspelt_extras(const Header& h) {
  for (std::size_t k = 0; k < h.field_count(); ++k) {
    if (h.used[k] || h.names[k].empty()) continue;
    std::size_t best = std::numeric_limits<std::size_t>::max();
    int slot = -1;
    for (int s = 0; s < kSlotCount; ++s) {
      if (h.col[s].field >= 0) continue;
      if (const std::size_t d = misspelling_distance(h.bare[k], h.col[s].header); d < best)
        best = d, slot = s;
    }
    if (slot < 0) continue;
    throw InputError(h.path, 1, k + 1,
                     "column " + shown(h.names[k]) + " looks like a misspelling of " +
                         describe(h.col[slot], slot) +
                         ", which the file does not have; did you mean '" + h.col[slot].header +
                         "'? Rename the column, or map it with a column map " + kCanonical[slot] +
                         "=" + h.names[k] + " (an unrelated column needs another name)");
  }
}

// Reads and checks the header line; fills the extra column names of `data`.
Header read_header(char* line, const std::string& path, const ColumnMap& columns,
                   bool require_channels, std::vector<std::string_view>& fields, Dataset& data) {
  if (line == nullptr)
    throw InputError(path, 0, 0,
                     "empty file; expected a header row such as v_x,v_y,omega,N,R,T_x,T_y,M_z");
  const std::size_t length = reject_carriage_return(line, path, 1);
  Header h;
  h.path = path;
  h.col = lookup_names(columns);
  split_fields(line, length, fields, path, 1);
  h.names.assign(fields.begin(), fields.end());
  for (const auto& name : h.names) h.bare.push_back(split_header_name(name).name);
  match_columns(h, fields);
  check_columns(h, fields, require_channels);
  reject_misspelt_extras(h);
  for (std::size_t k = 0; k < h.field_count(); ++k)
    if (!h.used[k] && !h.names[k].empty()) {
      h.extra_fields.push_back(k);
      data.extra_names.push_back(h.names[k]);
    }
  data.extra_values.resize(h.extra_fields.size());
  for (int s = 0; s < kSlotCount; ++s)
    if (h.col[s].field >= 0) h.order.push_back(s);
  std::sort(h.order.begin(), h.order.end(),
            [&](int a, int b) { return h.col[a].field < h.col[b].field; });
  for (int c = 0; c < kChannelCount; ++c) h.has_sigma[c] = h.col[kFirstSigma + c].field >= 0;
  for (int s = kFirstChannel; s < kFirstSigma; ++s)
    if (h.col[s].field >= 0)
      h.first_channel_field = std::min(h.first_channel_field, h.col[s].field);
  return h;
}

// Parses the used fields of one row into value[] and given[] (empty field: not given).
void parse_row(const Header& h, const std::vector<std::string_view>& fields, std::size_t line_no,
               double (&value)[kSlotCount], bool (&given)[kSlotCount]) {
  for (const int s : h.order) {
    const std::string_view text = fields[static_cast<std::size_t>(h.col[s].field)];
    const std::size_t column = static_cast<std::size_t>(h.col[s].field) + 1;
    given[s] = !text.empty();
    value[s] = kNaN;
    if (text.empty()) {
      if (s < kFirstChannel)
        throw InputError(
            h.path, line_no, column,
            "empty field in column " + describe(h.col[s], s) + "; expected " + kMeaning[s]);
      continue;
    }
    if (const char* why = text::parse_double_strict(text, value[s]))
      throw InputError(h.path, line_no, column,
                       "column " + describe(h.col[s], s) + " has " + shown(text) + " (" + why +
                           "); expected a finite decimal number: " + kMeaning[s]);
    if (h.factor[s] != 1.0) {
      value[s] *= h.factor[s];
      if (!std::isfinite(value[s]))
        throw InputError(h.path, line_no, column,
                         "column " + describe(h.col[s], s) + " has " + shown(text) +
                             ", which is out of range in SI units; expected " + kMeaning[s]);
    }
    if ((s == kN || s == kR) && !(value[s] > 0))
      throw InputError(
          h.path, line_no, column,
          "column " + describe(h.col[s], s) + " has " + shown(text) + "; expected " + kMeaning[s]);
  }
}

// Every measured channel with a sigma column has a sigma > 0, and the row measures something.
void check_row_channels(const Header& h, const std::vector<std::string_view>& fields,
                        std::size_t line_no, const double (&value)[kSlotCount],
                        const bool (&given)[kSlotCount], bool require_channels) {
  bool any = false;
  for (int c = 0; c < kChannelCount; ++c) {
    const int s = kFirstChannel + c;
    const bool present = h.col[s].field >= 0 && given[s];
    any |= present;
    if (!present || !h.has_sigma[c]) continue;
    const int q = kFirstSigma + c;
    const std::size_t column = static_cast<std::size_t>(h.col[q].field) + 1;
    if (!given[q])
      throw InputError(h.path, line_no, column,
                       "empty field in column " + describe(h.col[q], q) + " while " +
                           describe(h.col[s], s) + " is given; expected " + kMeaning[q]);
    if (!(value[q] > 0))
      throw InputError(h.path, line_no, column,
                       "column " + describe(h.col[q], q) + " has " +
                           shown(fields[static_cast<std::size_t>(h.col[q].field)]) + "; expected " +
                           kMeaning[q]);
  }
  if (!any && require_channels)
    throw InputError(h.path, line_no, static_cast<std::size_t>(h.first_channel_field) + 1,
                     "no measured channel in this row; expected a value in at least one of "
                     "the channel columns");
}

void append_row(const Header& h, const std::vector<std::string_view>& fields, std::size_t line_no,
                const double (&value)[kSlotCount], const bool (&given)[kSlotCount], Dataset& data) {
  data.line.push_back(line_no);
  data.v_x.push_back(value[kVx]);
  data.v_y.push_back(h.col[kVy].field >= 0 ? value[kVy] : 0.0);
  data.omega.push_back(value[kOmega]);
  data.N.push_back(value[kN]);
  data.R.push_back(value[kR]);
  for (int c = 0; c < kChannelCount; ++c) {
    const int s = kFirstChannel + c;
    const bool present = h.col[s].field >= 0 && given[s];
    data.value[c].push_back(present ? value[s] : kNaN);
    data.present[c].push_back(present ? 1 : 0);
    if (h.has_sigma[c]) data.sigma[c].push_back(present ? value[kFirstSigma + c] : kNaN);
  }
  for (std::size_t k = 0; k < h.extra_fields.size(); ++k)
    data.extra_values[k].emplace_back(fields[h.extra_fields[k]]);
}

}  // namespace

const std::vector<std::string>& dataset_column_names() {
  static const std::vector<std::string> names(std::begin(kCanonical), std::end(kCanonical));
  return names;
}

namespace {

// A bound on memory for an input without end (a pipe, `yes`): about 2 GB of rows.
constexpr std::size_t kMaxRows = 20'000'000;

void throw_too_many_rows(const std::string& path, std::size_t line_no) {
  throw InputError(path, line_no, 0,
                   "more than 20000000 rows; expected at most that many (split the data or "
                   "subsample it)");
}

// Reads the data rows that `reader` has left into `data` (line numbers as the reader counts
// them). `file_bytes`: the size the first row's length is scaled by to reserve the columns.
void read_rows(io_detail::LineReader& reader, const Header& h, std::uintmax_t file_bytes,
               bool require_channels, Dataset& data) {
  const std::string& path = h.path;
  std::vector<std::string_view> fields;
  fields.reserve(32);
  double value[kSlotCount] = {};
  bool given[kSlotCount] = {};
  while (char* line = reader.next_line()) {
    const std::size_t line_no = reader.line_number();
    const std::size_t length = reject_carriage_return(line, path, line_no);
    split_fields(line, length, fields, path, line_no);
    if (fields.size() == 1 && fields[0].empty()) continue;  // blank line
    if (data.rows() == kMaxRows) throw_too_many_rows(path, line_no);
    if (data.rows() == 0)
      reserve_rows(data, estimate_rows(file_bytes, length, h.field_count()), h.has_sigma);
    if (fields.size() != h.field_count()) {
      const bool few = fields.size() < h.field_count();
      throw InputError(path, line_no, (few ? fields.size() : h.field_count()) + 1,
                       "row has " + std::to_string(fields.size()) + " fields, expected " +
                           std::to_string(h.field_count()) + " as in the header" +
                           (few ? std::string(" (the row ends early)")
                                : "; first extra field " + shown(fields[h.field_count()])) +
                           delimiter_hint(fields));
    }
    parse_row(h, fields, line_no, value, given);
    check_row_channels(h, fields, line_no, value, given, require_channels);
    append_row(h, fields, line_no, value, given, data);
  }
}

// A regular file this large is read in parts side by side, one per hardware thread.
constexpr std::uintmax_t kPartBytes = std::uintmax_t{1} << 20;

// Where the parts after the first begin: the line starts nearest after equal shares of the
// file; none for a small file, a pipe or one core.
std::vector<std::uint64_t> part_starts(const std::string& path, std::uintmax_t file_bytes) {
  std::vector<std::uint64_t> starts;
  std::error_code ec;
  if (file_bytes == static_cast<std::uintmax_t>(-1) || !std::filesystem::is_regular_file(path, ec))
    return starts;
  const auto cores = static_cast<std::uintmax_t>(resolve_thread_count(0));
  const std::uintmax_t parts = std::min<std::uintmax_t>({cores, 8, file_bytes / kPartBytes});
  if (parts < 2) return starts;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return starts;  // read in one part; the reader reports what is wrong
  char block[4096];
  for (std::uintmax_t k = 1; k < parts; ++k) {
    std::uint64_t at = file_bytes / parts * k;
    if (!starts.empty()) at = std::max(at, starts.back());
    std::uint64_t start = 0;
    for (;;) {
      const ssize_t n = ::pread(fd, block, sizeof block, static_cast<off_t>(at));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      if (const void* lf = std::memchr(block, '\n', static_cast<std::size_t>(n))) {
        start = at + static_cast<std::uint64_t>(static_cast<const char*>(lf) - block) + 1;
        break;
      }
      at += static_cast<std::uint64_t>(n);
    }
    if (start == 0 || start >= file_bytes) break;
    if (starts.empty() || start > starts.back()) starts.push_back(start);
  }
  ::close(fd);
  return starts;
}

// One part of a file read on its own thread: its rows, numbered from its first line, and what
// stopped it.
struct Part {
  Dataset data;
  std::size_t lines = 0;  // lines it read, blank ones included
  std::exception_ptr error;
};

// Appends part `p`, whose first line is line `base` + 1 of the file, to `data`.
void append_part(Part& p, std::size_t base, Dataset& data) {
  auto append = [](auto& to, auto& from) { to.insert(to.end(), from.begin(), from.end()); };
  for (std::size_t& l : p.data.line) l += base;
  append(data.line, p.data.line);
  for (auto [to, from] : {std::pair{&data.v_x, &p.data.v_x}, std::pair{&data.v_y, &p.data.v_y},
                          std::pair{&data.omega, &p.data.omega}, std::pair{&data.N, &p.data.N},
                          std::pair{&data.R, &p.data.R}})
    append(*to, *from);
  for (int c = 0; c < kChannelCount; ++c) {
    append(data.value[c], p.data.value[c]);
    append(data.present[c], p.data.present[c]);
    append(data.sigma[c], p.data.sigma[c]);
  }
  for (std::size_t k = 0; k < data.extra_values.size(); ++k)
    for (auto& v : p.data.extra_values[k]) data.extra_values[k].push_back(std::move(v));
}

}  // namespace

Dataset load_dataset_csv(const std::string& path, const ColumnMap& columns, bool require_channels) {
  lookup_names(columns);  // a bad column map is an error before the file is touched
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, 0, "is a directory; expected a CSV file");

  io_detail::LineReader reader(path);
  // The head as the reader read it: opening the path again would lose it from a pipe.
  if (const std::string hint = unsupported_encoding_hint(reader.head()); !hint.empty())
    throw InputError(path, 1, 0, hint);

  Dataset data;
  data.source = path;
  std::vector<std::string_view> fields;
  fields.reserve(32);
  const Header h = read_header(reader.next_line(), path, columns, require_channels, fields, data);

  std::error_code size_error;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, size_error);
  // The parts after the first are read side by side with it; the first one then holds the
  // whole file's rows, so it reserves for them.
  std::vector<std::uint64_t> starts = part_starts(path, file_bytes);
  if (!starts.empty() && !reader.stop_at(starts.front())) starts.clear();
  std::vector<Part> parts(starts.size());
  for (Part& p : parts) {
    p.data.extra_names = data.extra_names;
    p.data.extra_values.resize(data.extra_values.size());
  }
  // Task 0 reads on from the header into `data` (its error, the first in file order, is thrown
  // once every part has finished); task k opens the file at starts[k - 1] and keeps its error.
  for_each_task(parts.size() + 1, static_cast<int>(parts.size()) + 1, [&](std::size_t k) {
    if (k == 0) return read_rows(reader, h, file_bytes, require_channels, data);
    Part& p = parts[k - 1];
    try {
      io_detail::LineReader r(path, starts[k - 1]);
      if (k < starts.size()) r.stop_at(starts[k]);
      read_rows(r, h, file_bytes / (starts.size() + 1), require_channels, p.data);
      p.lines = r.line_number();
    } catch (...) {
      p.error = std::current_exception();
    }
  });

  // The rows and the first error in file order, as one reader going through would meet them.
  std::size_t base = reader.line_number();
  for (Part& p : parts) {
    if (data.rows() + p.data.rows() > kMaxRows)
      throw_too_many_rows(path, base + p.data.line[kMaxRows - data.rows()]);
    if (p.error) {
      try {
        std::rethrow_exception(p.error);
      } catch (const InputError& e) {
        if (e.line() == 0) throw;
        throw InputError(e.file(), base + e.line(), e.column(), e.message());
      }
    }
    append_part(p, base, data);
    base += p.lines;
  }
  if (data.rows() == 0)
    throw InputError(path, 1, 0,
                     "the header is not followed by any data row; expected at least one "
                     "measurement row");
  return data;
}

}  // namespace frictionid
