// The model variants and their parameters, by name: what a fit can identify (docs/physics.md §2,
// §3). Parameter vectors everywhere share one layout, indexed by ParamIndex; names are the
// public way to refer to them.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>

namespace frictionid {

enum class ModelKind { Seed, Corrected, Exact };

// h_y and q (docs/physics.md §9): the pressure's tilt across the rolling direction and the aspect
// of an elliptic or rectangular spot.
enum ParamIndex : int { kF = 0, kKappa, kH, kA, kB, kM, kN, kP0, kBTilde, kHy, kQ, kParamCount };

inline const std::array<const char*, kParamCount>& param_names() {
  static const std::array<const char*, kParamCount> names = {
      "f", "kappa", "h", "a", "b", "m", "n", "p0", "b_tilde", "h_y", "q"};
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

// The parameters a variant reads, in report order. n appears for exact only with power:N; h_y
// for exact on any spot but the circle, or on the circle when the tilt across the rolling
// direction is asked for (tilt_y: the data has an M_tilt column); q for an ellipse or a
// rectangle. The approximants know the circle and the tilt along x only.
inline std::vector<int> model_parameters(ModelKind kind, model::PressureKind law,
                                         model::SpotKind spot = model::SpotKind::Circle,
                                         bool tilt_y = false) {
  switch (kind) {
    case ModelKind::Seed:
      return {kF, kKappa, kH, kA, kB, kM};
    case ModelKind::Corrected:
      return {kF, kKappa, kH, kA, kBTilde, kM, kP0};
    case ModelKind::Exact: {
      std::vector<int> p = {kF, kKappa, kH};
      if (spot != model::SpotKind::Circle || tilt_y) p.push_back(kHy);
      if (law == model::PressureKind::Power && spot != model::SpotKind::Map) p.push_back(kN);
      if (spot == model::SpotKind::Ellipse || spot == model::SpotKind::Rect) p.push_back(kQ);
      return p;
    }
  }
  return {};
}

}  // namespace frictionid
