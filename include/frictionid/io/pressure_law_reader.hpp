// Parses the LAW argument (uniform, hertz, parabolic, power:N, annulus:B, ring, table:FILE) into
// a pressure law.
#pragma once

#include <cstddef>

#include <string>

#include <frictionid/model/pressure_law.hpp>

namespace frictionid {

// The most samples a pressure table may have: the exact model's set-up (its ring-integral table)
// grows with every sample, and past this it takes longer than the fit itself.
inline constexpr std::size_t kMaxPressureTableSamples = 20000;

// Throws InputError naming the argument (or the table file, line and column) on bad input.
model::PressureLaw<double> parse_pressure_law(const std::string& spec);

// The table file format: header line, then "rho,sigma0" rows (comma separated; '#' comments and
// blank lines ignored; two rows with the same rho state a step). Throws InputError with
// file:line:column.
model::PressureLaw<double> load_pressure_table(const std::string& path);

// The canonical text of a law for reports: "hertz", "power:1.7", "annulus:0.3", "table:FILE".
std::string pressure_law_label(const model::PressureLaw<double>& law, const std::string& spec);

}  // namespace frictionid
