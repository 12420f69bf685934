// The option values that the command lines (frictionid, python3 -m frictionid batch) take as
// text ("f=0.8,kappa=1.2", "T_x,M_z") turned into the typed fields of the app's requests. Each
// rejection is an InputError naming the option, as the value parsers word it
// (app/option_parsers.hpp).
#pragma once

#include <string>

#include "app/requests.hpp"

namespace frictionid::app {

// The text of the fit options shared by fit, compare and batch.
struct FitText {
  std::string fix, bounds, start, channels, columns;
  std::string free;  // --free P[,P]: parameters fitted although held by default (h_y, q)
};
void apply(const FitText& text, FitRequest& r);

// --param of eval, generate and simulate ("" when not given).
ParameterValues parameter_values(const std::string& param_text);

// --shared P[,P]: the parameter names, none empty.
std::vector<std::string> shared_names(const std::string& text);

// A comma-separated list of names ("" when not given: an empty list).
std::vector<std::string> name_list(const std::string& option, const std::string& text);

}  // namespace frictionid::app
