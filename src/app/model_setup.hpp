// Turns a ModelRequest (--model, --pressure, --param) into a model variant with a full parameter
// vector: values the user leaves out follow from the pressure law (docs/physics.md §3).
#pragma once

#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model_variant.hpp>
#include "app/requests.hpp"

namespace frictionid::app {

struct ModelSetup {
  ModelKind kind;
  model::PressureLaw<double> law;
  std::string law_label;
  std::array<double, kParamCount> params;
};

// Throws InputError on an unknown model, law or parameter name, or an out-of-range value.
ModelSetup make_model_setup(const ModelRequest& r);

// The model, the pressure law's label and the model's parameters by name, as the JSON outputs
// (simulate, the truth file of generate) start.
nlohmann::ordered_json model_json(const ModelSetup& s);

}  // namespace frictionid::app
