#include "app/batch_warm_start.hpp"

#include <algorithm>
#include <cmath>

#include <frictionid/fitter.hpp>
#include <frictionid/parameters.hpp>

namespace frictionid::app {

std::optional<double> channel_misfit(const FitResult& r, Channel c) {
  for (const ChannelSummary& cs : r.channel_summaries)
    if (cs.channel == c && cs.r2 && std::isfinite(*cs.r2))
      return std::sqrt(std::max(0.0, 1.0 - *cs.r2));
  return std::nullopt;
}

WarmStart warm_start_from(const std::string& label, const FitResult& r) {
  WarmStart w;
  w.label = label;
  for (const ParameterEstimate& p : r.parameters) w.values.emplace_back(p.name, p.value);
  for (Channel c : r.channels) w.misfit[static_cast<int>(c)] = channel_misfit(r, c);
  return w;
}

std::optional<FitResult> fit_warm(const FitSettings& s, const WarmStart& warm, const Dataset& data,
                                  FitObserver* observer) {
  FitSettings w = s;
  w.global = false;
  for (const auto& [name, value] : warm.values) {
    const std::optional<int> i = param_index(name);
    if (!i || w.params[*i].fixed) continue;
    w.params[*i].initial = std::clamp(value, w.params[*i].lower, w.params[*i].upper);
  }
  FitResult r;
  try {
    r = Fitter(w).fit(data, observer);
  } catch (const FitError&) {
    if (observer && observer->cancelled()) throw;
    return std::nullopt;  // the full search may still succeed
  }
  if (!r.solver.converged) return std::nullopt;
  bool compared = false;
  for (Channel c : r.channels) {
    const auto& reference = warm.misfit[static_cast<int>(c)];
    const std::optional<double> m = channel_misfit(r, c);
    if (!reference || !m) continue;
    // The slack covers noise-free runs, whose misfit is rounding.
    if (!(*m <= kWarmMisfitRatio * *reference + 1e-12)) return std::nullopt;
    compared = true;
  }
  if (!compared) return std::nullopt;
  r.global.algorithm = "none: warm start from run '" + warm.label + "' (batch --warm-start)";
  return r;
}

}  // namespace frictionid::app
