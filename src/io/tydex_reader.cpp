// TYDEX files read as the wheel form (include/frictionid/io/tydex_reader.hpp).
#include <frictionid/io/tydex_reader.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/units.hpp>
#include "io/encoding_sniffer.hpp"
#include "io/line_reader.hpp"
#include "io/text.hpp"
#include "io/wheel_rows.hpp"

namespace frictionid {

namespace {

using io_detail::kWheelSlotCount;
using io_detail::wheel_slot;
using text::shown;

// The published layout of a CONSTANTS or MEASURCHANNELS line: name, description, unit, then
// numbers (1-based columns 1-10, 11-40, 41-50, 51-).
constexpr std::size_t kNameEnd = 10, kDescriptionEnd = 40, kUnitEnd = 50;

// TYDEX's names of the wheel-form columns, by slot, in the order they are looked for.
const std::vector<std::string>& tydex_names(int slot) {
  static const std::vector<std::string> names[kWheelSlotCount] = {
      {"TRAJVELW", "LONGVEL"},  // V
      {"SLIPANGL"},             // alpha
      {"LONGSLIP"},             // slip_ratio
      {"WHROTSPD"},             // omega_w
      {},                       // r_e
      {"INCLANGL"},             // gamma
      {},                       // psi_dot
      {},                       // R
      {"FZW"},
      {"FXW", "FX"},
      {"FYW"},
      {"MZW"},
      {"MYW"},
      {"MXW"},
  };
  return names[slot];
}

// TYDEX angles are ISO 8855's (positive about +z and +x); the wheel form's slip angle and
// inclination are positive the other way (docs/physics.md §1.1).
double tydex_sign(int slot) {
  return slot == io_detail::kWheelAlpha || slot == io_detail::kWheelGamma ? -1.0 : 1.0;
}

struct Entry {
  std::string name, unit;
  std::size_t line = 0;
  double number = 1.0;     // a constant's value, or a channel's factor
  std::string value_text;  // a constant's value as written
};

std::vector<std::string_view> blank_split(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && text::is_space(s[i])) ++i;
    const std::size_t b = i;
    while (i < s.size() && !text::is_space(s[i])) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

class TydexReader {
 public:
  TydexReader(const std::string& path, const DatasetReadOptions& options)
      : path_(path), options_(options) {}

  Dataset read(DataForm* form);

 private:
  enum class Section { None, Header, Comments, Constants, Channels, Data, Other };

  Entry parse_entry(std::string_view line, std::size_t line_no, bool channel) const;
  void resolve(std::size_t line_no);
  void append_row(std::string_view line, std::size_t line_no);

  std::string path_;
  const DatasetReadOptions& options_;
  std::vector<Entry> constants_, channels_;
  Dataset data_;
  DataForm form_;
  // After resolve(): where each slot comes from (a channel index, or a constant), the factor
  // to SI of the slot's unit, and the converter.
  std::array<int, kWheelSlotCount> channel_of_{};
  std::array<std::optional<double>, kWheelSlotCount> constant_of_{};
  std::array<double, kWheelSlotCount> to_si_{};
  std::vector<int> extra_channels_;           // channel index per extra column from a channel
  std::vector<std::string> extra_constants_;  // the values of extra columns from constants
  std::unique_ptr<io_detail::WheelConverter> converter_;
  std::size_t rows_ = 0;
};

Entry TydexReader::parse_entry(std::string_view line, std::size_t line_no, bool channel) const {
  const char* what = channel ? "MEASURCHANNELS" : "CONSTANTS";
  const std::string layout =
      std::string("; expected the published layout of a ") + what +
      " line: the name in columns 1-10, a description in 11-40, the unit in 41-50, then " +
      (channel ? "the conversion factor (and two offsets)" : "the value");
  if (line.size() <= kUnitEnd)
    throw InputError(
        path_, line_no, line.size() + 1,
        std::string(what) + " line " + shown(line) + " ends before column 51" + layout);
  Entry e;
  e.line = line_no;
  e.name = std::string(text::trim(line.substr(0, kNameEnd)));
  e.unit = std::string(text::trim(line.substr(kDescriptionEnd, kUnitEnd - kDescriptionEnd)));
  if (e.name.empty() || e.name.find_first_of(" \t") != std::string::npos)
    throw InputError(
        path_, line_no, 1,
        std::string(what) + " line " + shown(line) + " has no name in columns 1-10" + layout);
  const auto numbers = blank_split(line.substr(kUnitEnd));
  if (numbers.empty() || numbers.size() > (channel ? 3u : 1u))
    throw InputError(path_, line_no, kUnitEnd + 1,
                     std::string(what) + " line for " + shown(e.name) + " has " +
                         std::to_string(numbers.size()) + " numbers after column 50" + layout);
  double x[3] = {1.0, 0.0, 0.0};
  for (std::size_t k = 0; k < numbers.size(); ++k)
    if (const char* why = text::parse_double_strict(numbers[k], x[k]))
      throw InputError(path_, line_no, kUnitEnd + 1,
                       std::string(what) + " line for " + shown(e.name) + " has " +
                           shown(numbers[k]) + " (" + why + ")" + layout);
  if (channel && (x[1] != 0.0 || x[2] != 0.0))
    throw InputError(path_, line_no, kUnitEnd + 1,
                     "channel " + shown(e.name) +
                         " has non-zero offsets; frictionid reads channels with a conversion "
                         "factor only (physical value = factor * measured value): apply the "
                         "offsets to the data and set them to 0");
  if (channel && !(x[0] != 0.0)) {
    throw InputError(path_, line_no, kUnitEnd + 1,
                     "channel " + shown(e.name) + " has the conversion factor " +
                         shown(numbers[0]) + "; expected a non-zero factor");
  }
  e.number = x[0];
  if (!channel) e.value_text = std::string(numbers[0]);
  return e;
}

void TydexReader::resolve(std::size_t line_no) {
  if (channels_.empty())
    throw InputError(path_, line_no, 0,
                     "**MEASURDATA comes before any **MEASURCHANNELS line; expected the "
                     "channels (name, unit, factor) first");
  for (std::size_t a = 0; a < channels_.size(); ++a)
    for (std::size_t b = a + 1; b < channels_.size(); ++b)
      if (channels_[a].name == channels_[b].name)
        throw InputError(path_, channels_[b].line, 1,
                         "duplicate channel " + shown(channels_[b].name) + " (also line " +
                             std::to_string(channels_[a].line) + ")");
  // The names each slot is looked up under: TYDEX's, or the column map's.
  std::array<std::vector<std::string>, kWheelSlotCount> names;
  for (int s = 0; s < kWheelSlotCount; ++s) names[s] = tydex_names(s);
  for (const auto& [canonical, header] : options_.columns.canonical_to_header)
    if (const int s = io_detail::wheel_slot_index(canonical); s >= 0) names[s] = {header};

  io_detail::WheelColumns columns;
  std::vector<bool> channel_used(channels_.size(), false), constant_used(constants_.size(), false);
  for (int s = 0; s < kWheelSlotCount; ++s) {
    channel_of_[s] = -1;
    const Entry* source = nullptr;
    for (const auto& name : names[s]) {
      for (std::size_t k = 0; k < channels_.size() && !source; ++k)
        if (channels_[k].name == name) {
          source = &channels_[k];
          channel_of_[s] = static_cast<int>(k);
          channel_used[k] = true;
          columns.field[s] = k + 1;
        }
      if (source) break;
    }
    if (!source)
      for (const auto& name : names[s]) {
        for (std::size_t k = 0; k < constants_.size() && !source; ++k)
          if (constants_[k].name == name) {
            source = &constants_[k];
            constant_used[k] = true;
          }
        if (source) break;
      }
    if (!source) continue;
    columns.present[s] = true;
    columns.header[s] =
        source->name +
        (channel_of_[s] < 0 ? " (constant, line " + std::to_string(source->line) + ")" : "");
    // A TYDEX unit is the unit of the physical value; no unit is SI.
    const HeaderName split{source->name, source->unit, !source->unit.empty()};
    to_si_[s] = column_unit_factor(wheel_slot(s).quantity, source->name + " [" + source->unit + "]",
                                   split, path_, source->line, kDescriptionEnd + 1);
    if (!source->unit.empty()) form_.units.push_back({source->name, source->unit});
    if (channel_of_[s] < 0) {
      const double x = source->number * to_si_[s] * tydex_sign(s);
      if (!std::isfinite(x))
        throw InputError(path_, source->line, kUnitEnd + 1,
                         "constant " + shown(source->name) + " is out of range in SI units");
      constant_of_[s] = x;
    }
  }
  converter_ = std::make_unique<io_detail::WheelConverter>(
      path_, line_no, columns, Axes::Iso, options_.contact_radius, options_.require_channels);
  // Every channel and constant is kept as an extra text column under its name, the ones read
  // as wheel-form columns included.
  for (std::size_t k = 0; k < channels_.size(); ++k) {
    extra_channels_.push_back(static_cast<int>(k));
    data_.extra_names.push_back(channels_[k].name);
  }
  for (const auto& c : constants_) {
    if (std::find(data_.extra_names.begin(), data_.extra_names.end(), c.name) !=
        data_.extra_names.end())
      continue;  // a channel of that name has the row's values
    extra_constants_.push_back(c.value_text);
    data_.extra_names.push_back(c.name);
  }
  data_.extra_values.resize(data_.extra_names.size());
}

void TydexReader::append_row(std::string_view line, std::size_t line_no) {
  if (rows_ == 20'000'000)
    throw InputError(path_, line_no, 0, "more than 20000000 rows; expected at most that many");
  ++rows_;
  const auto tokens = blank_split(line);
  if (tokens.size() != channels_.size())
    throw InputError(path_, line_no, std::min(tokens.size(), channels_.size()) + 1,
                     "data row has " + std::to_string(tokens.size()) + " values, expected " +
                         std::to_string(channels_.size()) +
                         " (one per MEASURCHANNELS line, separated by blanks)");
  std::vector<double> raw(tokens.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    if (tokens[k] == "NOTAVAIL") continue;
    double x = 0.0;
    if (const char* why = text::parse_double_strict(tokens[k], x))
      throw InputError(path_, line_no, k + 1,
                       "channel " + shown(channels_[k].name) + " has " + shown(tokens[k]) + " (" +
                           why + "); expected a finite decimal number or NOTAVAIL");
    raw[k] = x * channels_[k].number;
  }
  io_detail::WheelRow row;
  for (int s = 0; s < kWheelSlotCount; ++s) {
    row.given[s] = false;
    if (constant_of_[s]) {
      row.value[s] = *constant_of_[s];
      row.given[s] = true;
    } else if (channel_of_[s] >= 0 && !std::isnan(raw[channel_of_[s]])) {
      row.value[s] = raw[channel_of_[s]] * to_si_[s] * tydex_sign(s);
      if (!std::isfinite(row.value[s]))
        throw InputError(path_, line_no, channel_of_[s] + 1,
                         "channel " + shown(channels_[channel_of_[s]].name) + " has " +
                             shown(tokens[channel_of_[s]]) + ", out of range in SI units");
      row.given[s] = true;
    }
  }
  converter_->append(row, line_no, data_);
  std::size_t e = 0;
  for (int k : extra_channels_) {
    const bool as_written = channels_[k].number == 1.0 || tokens[k] == "NOTAVAIL";
    data_.extra_values[e++].emplace_back(as_written ? std::string(tokens[k])
                                                    : text::shortest_number(raw[k]));
  }
  for (const auto& value : extra_constants_) data_.extra_values[e++].push_back(value);
}

Dataset TydexReader::read(DataForm* form) {
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec))
    throw InputError(path_, 0, 0, "is a directory; expected a TYDEX file");
  io_detail::LineReader reader(path_);
  if (const std::string hint = unsupported_encoding_hint(reader.head()); !hint.empty())
    throw InputError(path_, 1, 0, hint);
  data_.source = path_;
  form_.form = "wheel";
  form_.format = "tydex";
  form_.axes = axes_name(Axes::Iso);
  Section section = Section::None;
  bool data_seen = false;
  while (char* raw = reader.next_line()) {
    const std::size_t line_no = reader.line_number();
    const std::string_view line(raw, reader.line_length());
    if (line.find('\r') != std::string_view::npos)
      throw InputError(path_, line_no, 0,
                       "the line contains a carriage return (CR): CR-only line ends; expected LF "
                       "or CRLF line ends");
    const std::string_view trimmed = text::trim(line);
    if (trimmed.empty()) continue;
    if (trimmed.rfind("**", 0) == 0) {
      const auto words = blank_split(trimmed.substr(2));
      const std::string keyword = words.empty() ? std::string() : upper(words[0]);
      if (section == Section::None && keyword != "HEADER")
        throw InputError(
            path_, line_no, 1,
            "the first keyword is " + shown(trimmed) + "; a TYDEX file begins with **HEADER");
      section = keyword == "HEADER"           ? Section::Header
                : keyword == "COMMENTS"       ? Section::Comments
                : keyword == "CONSTANTS"      ? Section::Constants
                : keyword == "MEASURCHANNELS" ? Section::Channels
                : keyword == "MEASURDATA"     ? Section::Data
                                              : Section::Other;
      if (section == Section::Data) {
        if (data_seen) throw InputError(path_, line_no, 1, "a second **MEASURDATA; expected one");
        data_seen = true;
        resolve(line_no);
      } else if (data_seen && (section == Section::Constants || section == Section::Channels)) {
        throw InputError(path_, line_no, 1,
                         shown(trimmed) +
                             " after **MEASURDATA; expected the constants and "
                             "channels before the data");
      }
      if (keyword == "END") break;
      continue;
    }
    if (section == Section::None)
      throw InputError(
          path_, line_no, 1,
          "the file begins with " + shown(trimmed) + "; a TYDEX file begins with **HEADER");
    if (trimmed.front() == '!') continue;  // a comment
    switch (section) {
      case Section::Constants:
        constants_.push_back(parse_entry(line, line_no, false));
        break;
      case Section::Channels:
        channels_.push_back(parse_entry(line, line_no, true));
        break;
      case Section::Data:
        append_row(trimmed, line_no);
        break;
      default:
        break;  // HEADER, COMMENTS and model sections are not read
    }
  }
  if (section == Section::None)
    throw InputError(path_, 0, 0, "empty file; expected a TYDEX file that begins with **HEADER");
  if (!data_seen)
    throw InputError(path_, reader.line_number(), 0,
                     "no **MEASURDATA section; expected the measured rows after "
                     "**MEASURCHANNELS");
  if (data_.rows() == 0)
    throw InputError(path_, reader.line_number(), 0,
                     "**MEASURDATA has no data row; expected at least one measurement row");
  if (form) *form = std::move(form_);
  return std::move(data_);
}

}  // namespace

bool has_tydex_extension(const std::string& path) {
  const std::string ext = upper(std::filesystem::path(path).extension().string());
  return ext == ".TDX";
}

Dataset load_tydex(const std::string& path, const DatasetReadOptions& options, DataForm* form) {
  if (options.axes == Axes::Sae)
    throw InputError(path, 0, 0,
                     "--axes sae does not apply to a TYDEX file, whose channels are in the W "
                     "axes of ISO 8855 (TYDEX release 1.3)");
  return TydexReader(path, options).read(form);
}

}  // namespace frictionid
