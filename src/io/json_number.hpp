// JSON has no NaN or Inf: every double a report writes goes through json_number, which gives
// null for a non-finite or absent value (nlohmann would print null anyway; this keeps the rule
// visible and in one place).
#pragma once

#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

namespace frictionid {

inline nlohmann::ordered_json json_number(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}
inline nlohmann::ordered_json json_number(const std::optional<double>& x) {
  return x ? json_number(*x) : nlohmann::ordered_json(nullptr);
}

}  // namespace frictionid
