// Everything a fit needs besides the data: model, parameter table, loss, channels, search.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "identify/dataset.hpp"
#include "identify/model_variant.hpp"
#include "model/pressure_law.hpp"

namespace frictionid {

enum class LossKind { None, Huber, Cauchy, SoftL1 };

struct ParameterSetting {
  double initial = 0.0;  // used when the global stage is off, and as the fixed value
  double lower = 0.0, upper = 0.0;
  bool fixed = false;
  bool log_scale = false;  // the global stage samples it uniformly in log (positive, wide range)
};

struct FitSettings {
  ModelKind model = ModelKind::Seed;
  model::PressureLaw<double> law = model::PressureLaw<double>::hertz();
  std::string law_label = "hertz";
  std::array<ParameterSetting, kParamCount> params{};
  std::vector<Channel> channels;  // empty: every channel some row measures

  LossKind loss = LossKind::None;
  double loss_scale = 1.0;  // in whitened units (sigmas)

  // Global stage: NLopt over the bounds box, then Ceres from the best distinct points.
  bool global = true;
  std::string global_algorithm = "crs2";  // see global_search.hpp and experiments/global_search
  int starts = 4;                         // local fits from the global stage's best distinct points
  long global_evaluations = 3000;         // objective budget of the global stage
  std::size_t global_subsample = 400;     // rows the global stage sees (deterministic subsample)
  unsigned long long seed = 1;

  int max_iterations = 200;
  double function_tolerance = 1e-15;
  double gradient_tolerance = 1e-15;
  double parameter_tolerance = 1e-13;
  int threads = 0;        // threads for the passes over the rows; 0: every hardware thread
  bool progress = false;  // one updating line on stderr during the search
};

// Bounds that respect physics.md §3 and the pressure's positivity (|h| <= 1 keeps
// sigma0 (1 + h rho cos theta) >= 0); initial values from the pressure law.
inline std::array<ParameterSetting, kParamCount> default_parameter_settings(
    const model::PressureLaw<double>& law) {
  const auto d = default_parameters(law, 0.8, 1.0, 0.0);
  std::array<ParameterSetting, kParamCount> s{};
  s[kF] = {d[kF], 0.01, 5.0, false, true};
  s[kKappa] = {1.0, 0.05, 20.0, false, true};
  s[kH] = {0.0, -1.0, 1.0, false, false};
  s[kA] = {d[kA], 1e-3, 4.0, false, true};
  s[kB] = {d[kB], 4.0, 1e4, false, true};
  s[kM] = {d[kM], 1.0, 1e4, false, true};
  s[kN] = {d[kN], 0.0, 8.0, false, false};
  s[kP0] = {d[kP0], 1e-3, 0.5, false, true};
  s[kBTilde] = {d[kBTilde], 1.0, 1e4, false, true};
  return s;
}

}  // namespace frictionid
