// Reads a measured pressure map (--contact map:FILE) into the model's PressureMap, and names a
// contact spot the way the command line spells it ("ellipse:0.6", "map:FILE").
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <frictionid/model/contact_spot.hpp>

namespace frictionid {

// The most samples a pressure map may have: the exact model integrates along rays that cross
// every cell, so its cost per row grows with the grid; a footprint is resolved by a few
// thousand samples.
inline constexpr std::size_t kMaxPressureMapSamples = 10000;

// The map file format (docs/design.md §4.2a): a header naming the columns x, y and sigma0 (in
// any order), then one row per sample "x,y,sigma0": coordinates in units of the contact radius R,
// sigma0 finite and >= 0 in any scale. The samples form a rectangular grid: every pair (x_i, y_j)
// of the distinct x and y values appears exactly once, in any row order, with any spacing, at
// least 2 x 2. '#' comment lines and blank lines are ignored; a UTF-8 BOM and CRLF are accepted;
// at most 16 MiB. A map whose load (the integral of sigma0) is not positive and finite is
// refused. Throws InputError with file:line:column; `source` of the result is `path`.
std::shared_ptr<const model::PressureMap> load_pressure_map(const std::string& path);

// The spot as --contact spells it: "circle", "ellipse:Q" and "rect:Q" with the shortest text
// that reads back as Q, "map:FILE" with the map's source as given (model/contact_spot.hpp's,
// which the fitter uses for FitResult::contact).
using model::contact_spot_label;

}  // namespace frictionid
