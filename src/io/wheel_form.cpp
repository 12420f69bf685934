// The wheel form of a dataset as CSV (include/frictionid/io/wheel_form.hpp).
#include <frictionid/io/wheel_form.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <string_view>

#include <frictionid/io/data_form.hpp>
#include <frictionid/io/input_error.hpp>
#include "io/csv_fields.hpp"
#include "io/text.hpp"
#include "io/wheel_rows.hpp"

namespace frictionid {

namespace {

using io_detail::kWheelSlotCount;
using io_detail::wheel_slot;
using text::shown;

// The header name each wheel slot is looked up under: canonical, or renamed by the column map
// (whose names of the native form are not the wheel form's business).
std::array<std::string, kWheelSlotCount> wheel_lookup_names(const ColumnMap& columns) {
  std::array<std::string, kWheelSlotCount> names;
  for (int s = 0; s < kWheelSlotCount; ++s) names[s] = wheel_slot(s).name;
  for (const auto& [canonical, header] : columns.canonical_to_header)
    if (const int s = io_detail::wheel_slot_index(canonical); s >= 0) names[s] = header;
  return names;
}

// The slot whose lookup name is the header (as written, or its name without the unit), or -1.
int slot_of(const std::string& header, const HeaderName& split,
            const std::array<std::string, kWheelSlotCount>& names) {
  for (int s = 0; s < kWheelSlotCount; ++s)
    if (names[s] == split.name || names[s] == header) return s;
  return -1;
}

// "; did you mean 'alpha'? (column 3 is 'Alpha')" for a required column the header lacks, when
// one of its other columns looks like a misspelling of it.
std::string misspelling_hint(const std::vector<std::string>& header,
                             const io_detail::WheelColumns& columns,
                             const std::array<std::string, kWheelSlotCount>& names) {
  for (int s = 0; s < kWheelSlotCount; ++s) {
    if (columns.has(s)) continue;
    for (std::size_t k = 0; k < header.size(); ++k) {
      bool used = false;
      for (int t = 0; t < kWheelSlotCount; ++t) used |= columns.has(t) && columns.field[t] == k + 1;
      if (used) continue;
      const std::string name = split_header_name(header[k]).name;
      if (text::misspelling_distance(name, names[s]) != std::numeric_limits<std::size_t>::max())
        return "; did you mean '" + names[s] + "'? (column " + std::to_string(k + 1) + " is " +
               shown(header[k]) + ")";
    }
  }
  return "";
}

}  // namespace

const std::vector<std::string>& wheel_column_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (int s = 0; s < kWheelSlotCount; ++s) out.emplace_back(wheel_slot(s).name);
    return out;
  }();
  return names;
}

Dataset load_wheel_csv(const std::string& path, const DatasetReadOptions& options, DataForm* form) {
  io_detail::CsvRows csv(path);
  const std::vector<std::string>& header = csv.header();
  const auto names = wheel_lookup_names(options.columns);

  io_detail::WheelColumns columns;
  std::array<double, kWheelSlotCount> factor;
  factor.fill(1.0);
  DataForm read;
  read.form = "wheel";
  read.format = "csv";
  read.axes = axes_name(options.axes);
  Dataset data;
  data.source = path;
  std::vector<std::size_t> extra_fields;
  for (std::size_t k = 0; k < header.size(); ++k) {
    const HeaderName split = split_header_name(header[k]);
    const int s = slot_of(header[k], split, names);
    if (s >= 0) {
      if (columns.has(s))
        throw InputError(path, 1, k + 1,
                         "duplicate column " + shown(header[k]) + " for " + wheel_slot(s).name +
                             " (also column " + std::to_string(columns.field[s]) +
                             "); expected each column once");
      columns.present[s] = true;
      columns.header[s] = header[k];
      columns.field[s] = k + 1;
      factor[s] = column_unit_factor(wheel_slot(s).quantity, header[k], split, path, 1, k + 1);
      if (split.has_unit) read.units.push_back({header[k], split.unit});
    }
    // Every column but R (the native column itself) is kept as text as written, the wheel
    // form's own included: reports plot against them, batches group by them.
    if (s != io_detail::kWheelR && !header[k].empty()) {
      extra_fields.push_back(k);
      data.extra_names.push_back(header[k]);
    }
  }
  data.extra_values.resize(extra_fields.size());
  std::unique_ptr<io_detail::WheelConverter> converter;
  try {
    converter = std::make_unique<io_detail::WheelConverter>(
        path, 1, columns, options.axes, options.contact_radius, options.require_channels);
  } catch (const InputError& e) {
    if (e.line() != 1 || e.column() != 0) throw;
    throw InputError(e.file(), e.line(), e.column(),
                     e.message() + misspelling_hint(header, columns, names));
  }

  std::vector<std::string_view> fields;
  io_detail::WheelRow row;
  while (csv.next(fields)) {
    const std::size_t line = csv.line();
    for (int s = 0; s < kWheelSlotCount; ++s) {
      row.given[s] = false;
      if (!columns.has(s)) continue;
      const std::size_t field = columns.field[s];
      const std::string_view text = fields[field - 1];
      if (text.empty()) continue;
      double x = 0.0;
      if (const char* why = text::parse_double_strict(text, x))
        throw InputError(path, line, field,
                         "column " + columns.describe(s) + " has " + shown(text) + " (" + why +
                             "); expected a finite decimal number: " + wheel_slot(s).meaning);
      row.value[s] = x * factor[s];
      if (!std::isfinite(row.value[s]))
        throw InputError(path, line, field,
                         "column " + columns.describe(s) + " has " + shown(text) +
                             ", which is out of range in SI units; expected " +
                             wheel_slot(s).meaning);
      row.given[s] = true;
    }
    converter->append(row, line, data);
    for (std::size_t k = 0; k < extra_fields.size(); ++k)
      data.extra_values[k].emplace_back(fields[extra_fields[k]]);
  }
  if (data.rows() == 0)
    throw InputError(path, 1, 0,
                     "the header is not followed by any data row; expected at least one "
                     "measurement row");
  if (form) *form = std::move(read);
  return data;
}

}  // namespace frictionid
