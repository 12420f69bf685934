// A dataset in any form (include/frictionid/io/dataset_reader.hpp, io/data_form.hpp).
#include <frictionid/io/dataset_reader.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/tydex_reader.hpp>
#include <frictionid/io/units.hpp>
#include <frictionid/io/wheel_form.hpp>
#include "io/csv_fields.hpp"
#include "io/text.hpp"

namespace frictionid {

namespace {

bool is_regular(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

// The first line of a regular file that is not blank begins with **HEADER (TYDEX).
bool begins_with_tydex_header(const std::string& path) {
  if (!is_regular(path)) return false;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int k = 0; k < 16 && std::getline(in, line); ++k) {
    if (k == 0 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    const std::string_view t = text::trim(line);
    if (t.empty() || t == "\r") continue;
    return t.rfind("**HEADER", 0) == 0 || t.rfind("**header", 0) == 0;
  }
  return false;
}

std::string name_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// How a file is to be read.
struct Choice {
  bool tydex = false;
  bool wheel = false;
  std::string reason;
  DatasetReadOptions native, wheel_options;  // each with its form's renames only
};

Choice choose(const std::string& path, const DatasetReadOptions& options) {
  Choice c;
  c.native = options;
  c.wheel_options = options;
  c.native.columns = {};
  c.wheel_options.columns = {};
  const auto& native_names = dataset_column_names();
  const auto& wheel_names = wheel_column_names();
  for (const auto& [canonical, header] : options.columns.canonical_to_header) {
    const bool native =
        std::find(native_names.begin(), native_names.end(), canonical) != native_names.end();
    const bool wheel =
        std::find(wheel_names.begin(), wheel_names.end(), canonical) != wheel_names.end();
    if (!native && !wheel)
      throw InputError("column map", 0, 0,
                       "unknown canonical column '" + canonical +
                           "'; expected one of the native form's " + name_list(native_names) +
                           " or the wheel form's " + name_list(wheel_names));
    if (native) c.native.columns.canonical_to_header[canonical] = header;
    if (wheel) c.wheel_options.columns.canonical_to_header[canonical] = header;
  }

  const bool tdx_name = has_tydex_extension(path);
  c.tydex = tdx_name || begins_with_tydex_header(path);
  if (c.tydex) {
    if (options.form == InputForm::Native)
      throw InputError(path, 0, 0,
                       "--input-form native, but this is a TYDEX file, which frictionid reads "
                       "as the wheel form; use --input-form wheel or auto");
    c.wheel = true;
    c.reason = options.form == InputForm::Wheel
                   ? "--input-form wheel; a TYDEX file"
                   : std::string("auto: a TYDEX file (") +
                         (tdx_name ? "its name ends in .tdx)" : "it begins with **HEADER)");
    return c;
  }
  if (options.form != InputForm::Auto) {
    c.wheel = options.form == InputForm::Wheel;
    c.reason = std::string("--input-form ") + input_form_name(options.form);
    return c;
  }
  if (!is_regular(path)) {
    c.reason =
        "auto: not a regular file (a pipe, a FIFO), read as the native form without looking "
        "at it first; --input-form wheel reads the wheel form";
    return c;
  }
  std::vector<std::string> header;
  try {
    header = io_detail::csv_header(path);
  } catch (const InputError&) {
    c.reason = "auto: the header could not be read as the wheel form's";
    return c;  // the native reader names what is wrong with the file
  }
  const auto lookup = [&](const DatasetReadOptions& o, const std::string& canonical) {
    const auto it = o.columns.canonical_to_header.find(canonical);
    const std::string name = it == o.columns.canonical_to_header.end() ? canonical : it->second;
    return std::any_of(header.begin(), header.end(), [&](const std::string& h) {
      return h == name || split_header_name(h).name == name;
    });
  };
  const bool has_V = lookup(c.wheel_options, "V");
  const bool has_alpha = lookup(c.wheel_options, "alpha");
  const bool has_vx = lookup(c.native, "v_x");
  c.wheel = has_V && has_alpha && !has_vx;
  c.reason = c.wheel  ? "auto: the header has V and alpha and no v_x"
             : has_vx ? "auto: the header has v_x"
             : !has_V ? "auto: the header has no V (the wheel form needs V and alpha)"
                      : "auto: the header has no alpha (the wheel form needs V and alpha)";
  return c;
}

// The units a native CSV header gives its canonical columns, as written.
std::vector<ColumnUnit> header_units(const std::vector<std::string>& header,
                                     const std::vector<std::string>& canonical,
                                     const ColumnMap& columns) {
  std::vector<ColumnUnit> units;
  for (const auto& h : header) {
    const HeaderName split = split_header_name(h);
    if (!split.has_unit) continue;
    for (const auto& name : canonical) {
      const auto it = columns.canonical_to_header.find(name);
      const std::string looked_up = it == columns.canonical_to_header.end() ? name : it->second;
      if (split.name == looked_up || h == looked_up) {
        units.push_back({h, split.unit});
        break;
      }
    }
  }
  return units;
}

}  // namespace

const char* input_form_name(InputForm f) {
  switch (f) {
    case InputForm::Auto:
      return "auto";
    case InputForm::Native:
      return "native";
    case InputForm::Wheel:
      return "wheel";
  }
  return "?";
}

const char* axes_name(Axes a) {
  return a == Axes::Sae ? "sae" : "iso";
}

nlohmann::ordered_json data_form_json(const DataForm& f) {
  nlohmann::ordered_json j;
  j["form"] = f.form;
  j["format"] = f.format;
  j["axes"] = f.axes.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(f.axes);
  j["reason"] = f.reason;
  nlohmann::ordered_json units = nlohmann::ordered_json::object();
  for (const auto& u : f.units) units[u.column] = u.unit;
  j["units"] = units;
  return j;
}

std::string data_form_text(const DataForm& f) {
  std::string out = f.form + " form (" + (f.format == "tydex" ? "TYDEX" : "CSV");
  if (!f.axes.empty()) out += f.axes == "sae" ? ", SAE J670 axes" : ", ISO axes";
  out += "): " + f.reason + "; ";
  if (f.units.empty()) return out + "every column in SI units";
  out += "units";
  for (std::size_t k = 0; k < f.units.size(); ++k)
    out += (k ? ", " : " ") + f.units[k].column + " in " + f.units[k].unit;
  return out + ", the other columns SI";
}

namespace {

// The wheel form's options say nothing about a native file: given for one, they are a mistake
// (a file read in the wrong form), not something to ignore.
void check_native_options(const std::string& path, const Choice& c,
                          const DatasetReadOptions& options) {
  if (c.wheel) return;
  const std::string why =
      " applies to the wheel form, and this file is read in the native form (" + c.reason + ")";
  if (options.axes == Axes::Sae)
    throw InputError(path, 0, 0,
                     "--axes sae" + why +
                         ", whose columns are the contact's own (docs/design.md "
                         "§4.1); use --input-form wheel for a wheel-form file");
  if (options.contact_radius)
    throw InputError(path, 0, 0, "--contact-radius" + why + ", whose R column gives the radius");
}

}  // namespace

LoadedDataset read_dataset(const std::string& path, const DatasetReadOptions& options) {
  const Choice c = choose(path, options);
  check_native_options(path, c, options);
  LoadedDataset out;
  if (c.tydex) {
    out.data = load_tydex(path, c.wheel_options, &out.form);
  } else if (c.wheel) {
    out.data = load_wheel_csv(path, c.wheel_options, &out.form);
  } else {
    out.data = load_dataset_csv(path, c.native.columns, options.require_channels);
    out.form.form = "native";
    out.form.format = "csv";
    if (is_regular(path))
      out.form.units =
          header_units(io_detail::csv_header(path), dataset_column_names(), c.native.columns);
  }
  out.form.reason = c.reason;
  return out;
}

DataForm inspect_dataset_form(const std::string& path, const DatasetReadOptions& options) {
  const Choice c = choose(path, options);
  check_native_options(path, c, options);
  if (c.tydex) return read_dataset(path, options).form;
  DataForm f;
  f.form = c.wheel ? "wheel" : "native";
  f.format = "csv";
  if (c.wheel) f.axes = axes_name(options.axes);
  f.reason = c.reason;
  if (is_regular(path))
    f.units = c.wheel ? header_units(io_detail::csv_header(path), wheel_column_names(),
                                     c.wheel_options.columns)
                      : header_units(io_detail::csv_header(path), dataset_column_names(),
                                     c.native.columns);
  return f;
}

}  // namespace frictionid
