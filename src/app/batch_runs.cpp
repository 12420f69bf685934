#include "app/batch_runs.hpp"

#include <glob.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/tydex_reader.hpp>
#include <frictionid/parameters.hpp>
#include "app/data_input.hpp"
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"
#include "app/request_json.hpp"
#include "io/file_fingerprint.hpp"

namespace frictionid::app {

namespace {

namespace fs = std::filesystem;

// One file to fit, before --group-by splits it.
struct BatchEntry {
  std::string path, label;
  FitRequest options;
  std::vector<Covariate> covariates;
};

// FNV-1a, 64 bit: a stable hash (std::hash may differ between builds) for the journal's keys.
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

// The fields of one CSV line: comma separated, optionally double-quoted ("" is a quote),
// spaces and tabs around a field dropped. Enough for a manifest, whose cells are short text.
std::vector<std::string> csv_fields(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  for (auto& f : out) {
    const auto b = f.find_first_not_of(" \t");
    const auto e = f.find_last_not_of(" \t");
    f = b == std::string::npos ? "" : f.substr(b, e - b + 1);
  }
  return out;
}

std::vector<std::string> header_of(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte-order mark
  return csv_fields(line);
}

bool is_manifest(const std::string& path) {
  const auto header = header_of(path);
  return std::find(header.begin(), header.end(), "path") != header.end();
}

// A data file a directory holds: a CSV file, or a TYDEX file (io/tydex_reader.hpp).
bool is_data_file(const fs::path& p) {
  return p.extension() == ".csv" || has_tydex_extension(p.string());
}

std::string stem_of(const std::string& path) {
  const fs::path p(path);
  return is_data_file(p) ? p.stem().string() : p.filename().string();
}

// Why `path` cannot be read as a batch input file, or "" when it can (a regular file, also
// through symbolic links).
std::string not_an_input(const std::string& path) {
  struct stat sb;
  if (::stat(path.c_str(), &sb) != 0)
    return errno == ELOOP    ? "a loop of symbolic links"
           : errno == EACCES ? "permission denied"
           : errno == ENOENT ? "no such file or directory"
                             : std::strerror(errno);
  const std::string kind = non_regular_kind(sb.st_mode);
  if (kind.empty() || kind == "a directory") return kind;
  return kind == "something else" ? "not a regular file" : "not a regular file (" + kind + ")";
}

std::string listing_error(const std::error_code& ec) {
  return ec == std::errc::permission_denied ? "permission denied" : ec.message();
}

// The *.csv and *.tdx files of a directory, sorted; the ones that cannot be inputs (a FIFO, a
// device, a loop of links) are left out and named in `skipped`.
std::vector<std::string> csv_files_in(const std::string& dir, std::vector<std::string>& skipped) {
  std::vector<std::string> out;
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) throw InputError(dir, 0, 0, "cannot list this directory: " + listing_error(ec));
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) throw InputError(dir, 0, 0, "cannot list this directory: " + listing_error(ec));
    const fs::path& p = it->path();
    if (!is_data_file(p)) continue;
    const std::string why = not_an_input(p.string());
    if (why.empty())
      out.push_back(p.string());
    else
      skipped.push_back(p.string() + ": " + why);
  }
  if (ec) throw InputError(dir, 0, 0, "cannot list this directory: " + listing_error(ec));
  std::sort(out.begin(), out.end());
  std::sort(skipped.begin(), skipped.end());
  return out;
}

// Files named by one input: itself, a directory's *.csv, or a glob's matches (sorted). What a
// directory or a glob holds that cannot be fitted is skipped and named; a file named directly
// that cannot be read is an error.
std::vector<std::string> expand_input(const std::string& input, std::vector<std::string>& skipped) {
  std::error_code ec;
  const std::string why = not_an_input(input);
  if (why.empty()) return {input};
  if (why == "a directory") {
    std::vector<std::string> skipped_here;
    auto files = csv_files_in(input, skipped_here);
    skipped.insert(skipped.end(), skipped_here.begin(), skipped_here.end());
    if (files.empty())
      throw InputError(input, 0, 0,
                       skipped_here.empty() ? "no *.csv file (nor *.tdx) in this directory"
                                            : "no *.csv or *.tdx file here can be read (" +
                                                  skipped_here.front() + ")");
    return files;
  }
  if (why != "no such file or directory") throw InputError(input, 0, 0, why);
  if (input.find_first_of("*?[") != std::string::npos) {
    glob_t g{};
    const int rc = ::glob(input.c_str(), 0, nullptr, &g);
    std::vector<std::string> out;
    if (rc == 0)
      for (std::size_t i = 0; i < g.gl_pathc; ++i) out.push_back(g.gl_pathv[i]);
    ::globfree(&g);
    std::vector<std::string> files;
    for (const auto& m : out) {
      const std::string reason = not_an_input(m);
      if (reason.empty()) {
        files.push_back(m);
      } else if (reason == "a directory") {
        std::vector<std::string> skipped_here;
        const auto inside = csv_files_in(m, skipped_here);
        if (inside.empty() && skipped_here.empty())
          skipped_here.push_back(m + ": no *.csv file (nor *.tdx) in this directory");
        skipped.insert(skipped.end(), skipped_here.begin(), skipped_here.end());
        files.insert(files.end(), inside.begin(), inside.end());
      } else {
        skipped.push_back(m + ": " + reason);
      }
    }
    if (files.empty())
      throw InputError(input, 0, 0, "the pattern matches no CSV file (nor TYDEX file)");
    return files;
  }
  throw InputError(input, 0, 0, "no such file or directory");
}

// Checks o as `fit` would, naming `where` (a manifest line) in the message.
void check_options(const FitRequest& o, const std::string& file, std::size_t line) {
  try {
    (void)fit_settings(o, o.model);
  } catch (const InputError& e) {
    if (file.empty()) throw;
    throw InputError(file, line, 0, e.what());
  }
}

std::vector<BatchEntry> manifest_entries(const std::string& manifest, const FitRequest& o) {
  std::ifstream in(manifest);
  std::string text;
  std::getline(in, text);
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  const auto header = csv_fields(text);
  const auto column = [&header](const char* name) -> int {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  };
  const int path_col = column("path"), label_col = column("label");
  for (const auto& name : header)
    if (name != "path" && name != "label") check_covariate_name(name, manifest);
  const int pressure_col = column("pressure"), fix_col = column("fix");
  const int contact_col = column("contact");
  const int channels_col = column("channels");
  const fs::path base = fs::path(manifest).parent_path();
  std::vector<BatchEntry> out;
  for (std::size_t line = 2; std::getline(in, text); ++line) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = csv_fields(text);
    if (cells.size() != header.size())
      throw InputError(manifest, line, 0,
                       "expected " + std::to_string(header.size()) +
                           " fields as in the header, "
                           "found " +
                           std::to_string(cells.size()));
    const std::string& rel = cells[path_col];
    if (rel.empty())
      throw InputError(manifest, line, path_col + 1, "empty path; expected a CSV file");
    const fs::path p = fs::path(rel).is_absolute() ? fs::path(rel) : base / rel;
    if (const std::string why = not_an_input(p.string()); !why.empty())
      throw InputError(manifest, line, path_col + 1,
                       why == "no such file or directory"
                           ? "no such file '" + rel + "' (paths are relative to the manifest)"
                           : "'" + rel + "': " + why);
    BatchEntry e;
    e.path = p.lexically_normal().string();
    e.label = label_col >= 0 && !cells[label_col].empty() ? cells[label_col] : stem_of(rel);
    e.options = o;
    if (pressure_col >= 0 && !cells[pressure_col].empty()) {
      e.options.pressure = cells[pressure_col];
      e.options.pressure_given = true;
    }
    if (contact_col >= 0 && !cells[contact_col].empty()) e.options.contact = cells[contact_col];
    try {
      if (fix_col >= 0 && !cells[fix_col].empty())
        e.options.fix = parse_assignments("--fix", cells[fix_col]);
      if (channels_col >= 0 && !cells[channels_col].empty())
        e.options.channels = parse_name_list("--channels", cells[channels_col]);
    } catch (const InputError& error) {
      throw InputError(manifest, line, 0, error.what());
    }
    check_options(e.options, manifest, line);
    for (std::size_t k = 0; k < header.size(); ++k)
      if (static_cast<int>(k) != path_col && static_cast<int>(k) != label_col)
        e.covariates.push_back({header[k], cells[k]});
    out.push_back(std::move(e));
  }
  return out;
}

// The shortest text that reads back as x, for labels made of numeric group values.
std::string shortest(double x) {
  char buf[32];
  if (x == std::floor(x) && std::abs(x) < 1e15) {  // a load level 2000, not 2e+03
    std::snprintf(buf, sizeof buf, "%.0f", x);
    return buf;
  }
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

// The group-by column's value in each row, as text.
std::vector<std::string> column_text(const Dataset& d, const std::string& name,
                                     const std::string& path) {
  for (std::size_t k = 0; k < d.extra_names.size(); ++k)
    if (d.extra_names[k] == name) return d.extra_values[k];
  const std::vector<std::pair<const char*, const std::vector<double>*>> numeric = {
      {"v_x", &d.v_x}, {"v_y", &d.v_y}, {"omega", &d.omega}, {"N", &d.N}, {"R", &d.R}};
  for (const auto& [n, values] : numeric)
    if (name == n && values->size() == d.rows()) {
      std::vector<std::string> out;
      for (double x : *values) out.push_back(shortest(x));
      return out;
    }
  std::string known;
  for (const auto& [n, values] : numeric)
    if (values->size() == d.rows()) known += std::string(known.empty() ? "" : ", ") + n;
  for (const auto& n : d.extra_names) known += ", " + n;
  throw InputError(path, 1, 0, "--group-by: no column '" + name + "' (columns: " + known + ")");
}

// The options, and the bytes of the request's own files (a pressure map): a changed map refits
// the run.
std::string options_text(const FitRequest& o) {
  std::string text = fit_request_json(o).dump();
  for (const auto& path : request_input_files(o)) text += '\x1d' + fingerprint_file(path).sha256;
  return text;
}

// A label as a directory name: characters outside [A-Za-z0-9._+=-] become '_', and a leading
// dot is escaped, so that no label names a hidden file, a parent or a subdirectory.
std::string directory_name(const std::string& label) {
  std::string out;
  for (char c : label) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '+' || c == '=' || c == '-';
    out += safe ? c : '_';
  }
  if (out.empty() || out[0] == '.') out = "_" + out;
  return out;
}

}  // namespace

void check_covariate_name(const std::string& name, const std::string& where) {
  static const char* const reserved[] = {"label",        "status",      "rows",  "cost",
                                         "reduced_chi2", "warnings",    "error", "mean_N",
                                         "mean_speed",   "mean_omega_R"};
  bool taken = std::find(std::begin(reserved), std::end(reserved), name) != std::end(reserved) ||
               name.rfind("noise_", 0) == 0;
  for (const char* p : param_names())
    for (const char* suffix : {"", "_stderr", "_ci95_lo", "_ci95_hi"})
      taken = taken || name == std::string(p) + suffix;
  if (taken)
    throw InputError(where, 0, 0,
                     "column '" + name +
                         "' would clash with the summary table's own column of "
                         "that name; rename it");
}

Dataset select_rows(const Dataset& d, const std::vector<std::size_t>& rows) {
  Dataset out;
  out.source = d.source;
  out.extra_names = d.extra_names;
  out.extra_values.resize(d.extra_values.size());
  auto take = [&rows](const auto& column, auto& to) {
    if (column.empty()) return;  // an absent optional column stays absent
    for (std::size_t i : rows) to.push_back(column[i]);
  };
  take(d.line, out.line);
  take(d.v_x, out.v_x);
  take(d.v_y, out.v_y);
  take(d.omega, out.omega);
  take(d.N, out.N);
  take(d.R, out.R);
  take(d.tilt_sign, out.tilt_sign);
  for (int c = 0; c < kChannelCount; ++c) {
    take(d.value[c], out.value[c]);
    take(d.present[c], out.present[c]);
    take(d.sigma[c], out.sigma[c]);
  }
  for (std::size_t k = 0; k < d.extra_values.size(); ++k)
    take(d.extra_values[k], out.extra_values[k]);
  return out;
}

std::vector<BatchRun> plan_batch_runs(const std::vector<std::string>& inputs, const FitRequest& o,
                                      const std::vector<std::string>& group_columns,
                                      const std::string& key_extra,
                                      std::vector<std::string>* skipped) {
  std::vector<BatchEntry> entries;
  std::vector<std::string> skipped_here;
  for (const auto& input : inputs)
    for (const auto& file : expand_input(input, skipped_here)) {
      if (is_manifest(file)) {
        auto more = manifest_entries(file, o);
        entries.insert(entries.end(), more.begin(), more.end());
      } else {
        entries.push_back({file, stem_of(file), o, {}});
      }
    }
  if (skipped) *skipped = std::move(skipped_here);
  if (entries.empty()) throw InputError("batch: no CSV file to fit among the inputs");

  check_names("--group-by", group_columns);
  for (const auto& name : group_columns) check_covariate_name(name, "--group-by");
  check_names("--keep", o.keep);
  for (const auto& name : o.keep) {
    check_covariate_name(name, "--keep");
    if (std::find(group_columns.begin(), group_columns.end(), name) != group_columns.end())
      throw InputError("--keep " + name +
                       ": the column is a --group-by column, which the summary has "
                       "already");
  }
  std::vector<BatchRun> runs;
  for (auto& e : entries) {
    // Hashed as a stream: planning memory does not grow with the file.
    const FileFingerprint input = fingerprint_file(e.path);
    const std::uint64_t file_key =
        fnv1a(options_text(e.options) + '\x1e' + key_extra, fnv1a(input.sha256));
    if (group_columns.empty()) {
      runs.push_back({e.label, "", e.path, e.options, nullptr, {}, e.covariates, file_key, input});
      continue;
    }
    auto data = std::make_shared<const Dataset>(load_fit_data(e.options, e.path).data);
    std::vector<std::vector<std::string>> columns;
    for (const auto& name : group_columns) columns.push_back(column_text(*data, name, e.path));
    std::map<std::vector<std::string>, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < data->rows(); ++i) {
      std::vector<std::string> values;
      for (const auto& c : columns) values.push_back(c[i]);
      groups[values].push_back(i);
    }
    for (auto& [values, rows] : groups) {
      std::string joined;
      for (const auto& v : values) joined += (joined.empty() ? "" : "_") + v;
      BatchRun run;
      run.label = entries.size() == 1 ? joined : e.label + "_" + joined;
      run.path = e.path;
      run.options = e.options;
      run.file_data = data;
      run.group_rows = std::move(rows);
      run.covariates = e.covariates;
      std::string group_text;
      for (std::size_t k = 0; k < values.size(); ++k) {
        run.covariates.push_back({group_columns[k], values[k]});
        group_text += group_columns[k] + '\x1f' + values[k] + '\x1e';
      }
      run.key = fnv1a(group_text, file_key);
      run.input = input;
      runs.push_back(std::move(run));
    }
  }

  std::sort(runs.begin(), runs.end(),
            [](const BatchRun& a, const BatchRun& b) { return a.label < b.label; });
  std::map<std::string, const BatchRun*> by_directory;
  for (auto& run : runs) {
    run.directory = directory_name(run.label);
    const auto [it, fresh] = by_directory.emplace(run.directory, &run);
    if (!fresh)
      throw InputError("batch: two runs would share the label '" + run.label + "' (from " +
                       it->second->path + " and " + run.path +
                       "); give them distinct labels with a manifest's label column");
  }
  return runs;
}

void check_trend_x(const std::string& name, const std::vector<BatchRun>& runs) {
  std::vector<std::string> known = dataset_covariate_names();
  for (const auto& run : runs)
    for (const auto& c : run.covariates)
      if (std::find(known.begin(), known.end(), c.name) == known.end()) known.push_back(c.name);
  if (std::find(known.begin(), known.end(), name) != known.end()) return;
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  throw InputError("--trend-x: no covariate '" + name + "'; the covariates are: " + list);
}

}  // namespace frictionid::app
