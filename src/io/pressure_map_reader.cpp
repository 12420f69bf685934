#include <frictionid/io/pressure_map_reader.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include <frictionid/io/input_error.hpp>
#include "io/small_file.hpp"
#include "io/text.hpp"

namespace frictionid {
namespace {

using text::shown;

std::string point_text(double x, double y) {
  return "(x, y) = (" + text::shortest_number(x) + ", " + text::shortest_number(y) + ")";
}

// The fields of a line split at commas, each trimmed of spaces and tabs.
std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(text::trim(line.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

struct Sample {
  double x, y, sigma0;
  std::size_t line;
};

}  // namespace

std::shared_ptr<const model::PressureMap> load_pressure_map(const std::string& path) {
  std::istringstream file(io::read_small_file(path, "a pressure map file (x,y,sigma0)",
                                              "pressure map file", "a pressure map (x,y,sigma0)"));
  static const std::array<const char*, 3> kNames = {"x", "y", "sigma0"};
  std::array<std::size_t, 3> field_of{};  // the field (0-based) of x, y, sigma0
  std::size_t header_line = 0, field_count = 0;
  std::vector<Sample> samples;
  std::string line;
  std::size_t lineno = 0;
  while (std::getline(file, line)) {
    ++lineno;
    if (lineno == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find('\r') != std::string::npos)
      throw InputError(path, lineno, 0,
                       "the line contains a carriage return (CR): the file seems to use CR-only "
                       "(classic Mac) line ends; expected LF or CRLF line ends");
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    const std::vector<std::string_view> fields = fields_of(line);
    if (header_line == 0) {
      header_line = lineno;
      field_count = fields.size();
      for (std::size_t k = 0; k < kNames.size(); ++k) {
        const auto it = std::find(fields.begin(), fields.end(), kNames[k]);
        if (it == fields.end() || field_count != 3)
          throw InputError(path, lineno, 1,
                           "expected the header 'x,y,sigma0' (three columns, in any order), "
                           "found " +
                               shown(line));
        field_of[k] = static_cast<std::size_t>(it - fields.begin());
      }
      continue;
    }
    if (fields.size() != field_count)
      throw InputError(path, lineno, std::min(fields.size(), field_count) + 1,
                       "expected 3 comma-separated fields as in the header, found " +
                           std::to_string(fields.size()) + " in " + shown(line));
    double value[3];
    for (std::size_t k = 0; k < kNames.size(); ++k) {
      const std::string_view field = fields[field_of[k]];
      if (const char* why = text::parse_double_strict(field, value[k]))
        throw InputError(path, lineno, field_of[k] + 1,
                         std::string(kNames[k]) + ": expected a finite number, found " +
                             shown(field) + " (" + why + ")");
    }
    if (value[2] < 0.0)
      throw InputError(path, lineno, field_of[2] + 1,
                       "sigma0 is " + text::shortest_number(value[2]) + " at " +
                           point_text(value[0], value[1]) +
                           "; expected a pressure >= 0 (no tension in the contact)");
    if (samples.size() == kMaxPressureMapSamples)
      throw InputError(path, lineno, 0,
                       "more than " + std::to_string(kMaxPressureMapSamples) +
                           " samples: a map's table and each row's integral grow with its "
                           "cells; resample the map (a few thousand samples resolve a "
                           "footprint)");
    samples.push_back({value[0], value[1], value[2], lineno});
  }
  if (header_line == 0) throw InputError(path, 0, 0, "the pressure map is empty");
  if (samples.empty())
    throw InputError(path, header_line, 1,
                     "the header is not followed by any sample; expected a grid of at least 2 x 2 "
                     "samples");

  // The grid: the distinct x and y values; every pair must be given exactly once.
  std::vector<double> xs, ys;
  for (const Sample& s : samples) {
    xs.push_back(s.x);
    ys.push_back(s.y);
  }
  for (auto* grid : {&xs, &ys}) {
    std::sort(grid->begin(), grid->end());
    grid->erase(std::unique(grid->begin(), grid->end()), grid->end());
  }
  if (xs.size() < 2 || ys.size() < 2) {
    const bool in_x = xs.size() < 2;
    throw InputError(path, samples.back().line, field_of[in_x ? 0 : 1] + 1,
                     std::string("only one distinct ") + (in_x ? "x" : "y") + " value (" +
                         text::shortest_number(in_x ? xs.front() : ys.front()) +
                         "); expected a grid of at least 2 x 2 samples (found " +
                         std::to_string(xs.size()) + " x " + std::to_string(ys.size()) + ")");
  }
  const auto index_of = [](const std::vector<double>& grid, double v) {
    return static_cast<std::size_t>(std::lower_bound(grid.begin(), grid.end(), v) - grid.begin());
  };
  auto map = std::make_shared<model::PressureMap>();
  map->x = xs;
  map->y = ys;
  map->source = path;
  map->sigma0.assign(xs.size() * ys.size(), 0.0);
  std::vector<std::size_t> line_of(xs.size() * ys.size(), 0);
  for (const Sample& s : samples) {
    const std::size_t k = index_of(ys, s.y) * xs.size() + index_of(xs, s.x);
    if (line_of[k] != 0)
      throw InputError(path, s.line, field_of[0] + 1,
                       "duplicate point " + point_text(s.x, s.y) + ", first given on line " +
                           std::to_string(line_of[k]) + "; expected every grid point exactly once");
    line_of[k] = s.line;
    map->sigma0[k] = s.sigma0;
  }
  for (std::size_t j = 0; j < ys.size(); ++j)
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (line_of[j * xs.size() + i] != 0) continue;
      // Name the missing point at a line of its grid row (same y), where it would belong.
      std::size_t near = 0;
      for (std::size_t k = 0; k < xs.size() && near == 0; ++k) near = line_of[j * xs.size() + k];
      throw InputError(path, near, field_of[0] + 1,
                       "the grid has no point " + point_text(xs[i], ys[j]) +
                           ": the row y = " + text::shortest_number(ys[j]) +
                           " (on this line) lacks x = " + text::shortest_number(xs[i]) +
                           "; expected every x value with every y value (" +
                           std::to_string(xs.size()) + " x " + std::to_string(ys.size()) +
                           " points, found " + std::to_string(samples.size()) + ")");
    }
  const model::SpotMoments<double> m = model::map_moments(*map);
  if (!(m.A0 > 0.0) || !std::isfinite(m.A0)) {
    const bool zero =
        std::all_of(map->sigma0.begin(), map->sigma0.end(), [](double s) { return s == 0.0; });
    throw InputError(path, header_line, field_of[2] + 1,
                     zero ? "sigma0 is 0 at every sample: the map carries no load; expected "
                            "some sigma0 > 0"
                          : "the map's load (the integral of sigma0) is not a finite positive "
                            "number; expected moderate sigma0 values, e.g. scaled to a maximum "
                            "of 1");
  }
  for (double v : {m.Ax, m.Ay, m.Axx, m.Axy, m.Ayy})
    if (!std::isfinite(v))
      throw InputError(path, header_line, 0,
                       "the map's moments are not finite; expected moderate coordinates (units "
                       "of R) and sigma0 values");
  return map;
}

}  // namespace frictionid
