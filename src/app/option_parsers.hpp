// Parsers for command-line option values ("f=0.8,kappa=1.2", "f=0.1:2", "T_x,M_z", "1e-3").
// Every rejection is an InputError whose file() is the option name (e.g. "--param") and whose
// message quotes the offending text and says what was expected. Which names are valid is the
// caller's business: these parsers only check the shape (identifier-like, non-empty, unique).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>

namespace frictionid {

// --threads: 0 (every hardware thread) or more; an InputError naming the option otherwise.
void check_thread_option(int threads);

// "f=0.8,kappa=1.2" -> {f: 0.8, kappa: 1.2}. For --param and --fix.
std::map<std::string, double> parse_assignments(const std::string& option, const std::string& spec);

// "f=0.1:2,h=-0.5:0.5" -> {f: (0.1, 2), h: (-0.5, 0.5)}; finite, lo < hi. For --bounds.
std::map<std::string, std::pair<double, double>> parse_bounds(const std::string& option,
                                                              const std::string& spec);

// "v_x=speed,omega=spin" -> ColumnMap (for --columns). Canonical names are validated (with a
// did-you-mean hint); a canonical name or a header name given twice is an InputError. An empty
// spec is an empty map.
ColumnMap parse_column_map(const std::string& spec);

// The LAW of --pressure (io's parse_pressure_law), its messages prefixed with the option; a
// table file's errors keep naming the file, line and column.
model::PressureLaw<double> parse_pressure_option(const std::string& spec);

// The SPOT of --contact: circle, ellipse:Q or rect:Q (0 < Q <= 4: the semi-axis or half-width
// along y over R) or map:FILE (io's load_pressure_map), its messages prefixed with the option; a
// map file's errors keep naming the file, line and column.
model::ContactSpot parse_contact_option(const std::string& spec);

// The spot as reports name it (contact_spot_label of io/pressure_map_reader.hpp): "ellipse:.70"
// -> "ellipse:0.7", "map:FILE" as given, without reading the map's file again.
std::string contact_label(const std::string& spec);

// "circle,ellipse:0.7" -> {"circle", "ellipse:0.7"}, each checked by parse_contact_option
// (compare's list of spots; a map's file name cannot hold a comma there).
std::vector<std::string> parse_contact_list(const std::string& option, const std::string& spec);

// The checks of parse_column_map for a map built elsewhere (Python's dict); messages quote it as
// canonical=header,... text.
ColumnMap column_map(const std::map<std::string, std::string>& canonical_to_header);

// The checks parse_assignments and parse_bounds make of each value, for values given as numbers
// (Python): finite, and lo < hi. Names are checked by whoever knows them (the fit settings).
void check_values(const std::string& option, const std::map<std::string, double>& values);
void check_bounds(const std::string& option,
                  const std::map<std::string, std::pair<double, double>>& bounds);

// The checks parse_name_list makes of a list given as names: none empty, none twice.
void check_names(const std::string& option, const std::vector<std::string>& names);

// "2000,4000" -> {2000, 4000}: strict finite numbers (parse_number). For --loads, --slip-angles.
std::vector<double> parse_number_list(const std::string& option, const std::string& spec);

// "T_x,M_z" -> {"T_x", "M_z"} in the given order. For --channels.
std::vector<std::string> parse_name_list(const std::string& option, const std::string& spec);

// One strict, finite decimal number; surrounding spaces are allowed. `what` names the option or
// quantity for the message (e.g. "--vx").
double parse_number(const std::string& what, const std::string& text);

// A whole number in [lo, hi] written with decimal digits only (surrounding spaces allowed): a
// sign, a fraction, an exponent or a value past hi is rejected with the allowed range, never
// wrapped or clamped. For counts and seeds (--rows, --seed, --global-subsample).
std::uint64_t parse_whole_number(const std::string& option, const std::string& text,
                                 std::uint64_t lo, std::uint64_t hi);

}  // namespace frictionid
