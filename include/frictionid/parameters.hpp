// The model variants and their parameters, by name: what a fit can identify (docs/physics.md §2,
// §3). Parameter vectors everywhere share one layout, indexed by ParamIndex; names are the
// public way to refer to them.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <frictionid/model/pressure_law.hpp>

namespace frictionid {

enum class ModelKind { Seed, Corrected, Exact };

enum ParamIndex : int { kF = 0, kKappa, kH, kA, kB, kM, kN, kP0, kBTilde, kParamCount };

inline const std::array<const char*, kParamCount>& param_names() {
  static const std::array<const char*, kParamCount> names = {"f", "kappa", "h",  "a",      "b",
                                                             "m", "n",     "p0", "b_tilde"};
  return names;
}

inline std::optional<int> param_index(std::string_view name) {
  for (int i = 0; i < kParamCount; ++i)
    if (name == param_names()[i]) return i;
  return std::nullopt;
}

inline const char* model_name(ModelKind k) {
  switch (k) {
    case ModelKind::Seed:
      return "seed";
    case ModelKind::Corrected:
      return "corrected";
    case ModelKind::Exact:
      return "exact";
  }
  return "?";
}

inline std::optional<ModelKind> parse_model_kind(const std::string& s) {
  if (s == "seed") return ModelKind::Seed;
  if (s == "corrected") return ModelKind::Corrected;
  if (s == "exact") return ModelKind::Exact;
  return std::nullopt;
}

// The parameters a variant reads, in report order. n appears for exact only with power:N.
inline std::vector<int> model_parameters(ModelKind kind, model::PressureKind law) {
  switch (kind) {
    case ModelKind::Seed:
      return {kF, kKappa, kH, kA, kB, kM};
    case ModelKind::Corrected:
      return {kF, kKappa, kH, kA, kBTilde, kM, kP0};
    case ModelKind::Exact:
      if (law == model::PressureKind::Power) return {kF, kKappa, kH, kN};
      return {kF, kKappa, kH};
  }
  return {};
}

}  // namespace frictionid
