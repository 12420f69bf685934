// Turns the --model/--pressure/--param options into a model variant with a full parameter
// vector: values the user leaves out follow from the pressure law (physics.md §3).
#pragma once

#include <array>
#include <string>

#include "identify/model_variant.hpp"
#include "model/pressure_law.hpp"

namespace frictionid::cli {

struct ModelSetup {
  ModelKind kind;
  model::PressureLaw<double> law;
  std::string law_label;
  std::array<double, kParamCount> params;
};

// Throws InputError on an unknown model, law or parameter name, or an out-of-range value.
ModelSetup make_model_setup(const std::string& model, const std::string& pressure,
                            const std::string& param_spec);

}  // namespace frictionid::cli
