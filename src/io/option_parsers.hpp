// Parsers for command-line option values ("f=0.8,kappa=1.2", "f=0.1:2", "T_x,M_z", "1e-3").
// Every rejection is an InputError whose file() is the option name (e.g. "--param") and whose
// message quotes the offending text and says what was expected. Which names are valid is the
// caller's business: these parsers only check the shape (identifier-like, non-empty, unique).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frictionid {

// "f=0.8,kappa=1.2" -> {f: 0.8, kappa: 1.2}. For --param and --fix.
std::map<std::string, double> parse_assignments(const std::string& option, const std::string& spec);

// "f=0.1:2,h=-0.5:0.5" -> {f: (0.1, 2), h: (-0.5, 0.5)}; finite, lo < hi. For --bounds.
std::map<std::string, std::pair<double, double>> parse_bounds(const std::string& option,
                                                              const std::string& spec);

// "T_x,M_z" -> {"T_x", "M_z"} in the given order. For --channels.
std::vector<std::string> parse_name_list(const std::string& option, const std::string& spec);

// One strict, finite decimal number; surrounding spaces are allowed. `what` names the option or
// quantity for the message (e.g. "--vx").
double parse_number(const std::string& what, const std::string& text);

// The number grammar shared by the option parsers and the CSV reader, without allocation:
// optional leading '+' or '-', decimal digits with optional fraction and exponent (what
// std::from_chars accepts in chars_format::general); the whole text must be consumed.
// Rejects empty text, trailing characters, NaN/Inf spellings, hexadecimal floats and values
// outside the double range (overflow, or underflow to zero of a non-zero literal). Subnormal
// results are accepted. The conversion is correctly rounded, so a value written with %.17g
// reads back bit-identical. Returns nullptr on success, else a short reason for messages.
const char* parse_double_strict(std::string_view text, double& out);

}  // namespace frictionid
