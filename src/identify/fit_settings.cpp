#include <frictionid/fit_settings.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <frictionid/model_variant.hpp>

#include "identify/global_search.hpp"
#include "identify/number_text.hpp"

namespace frictionid {
namespace {

// The first problem with the law itself, or an empty string.
std::string law_problem(const model::PressureLaw<double>& law) {
  if (law.kind == model::PressureKind::Table && !law.table)
    return "the pressure law is a table but holds none";
  if (law.kind == model::PressureKind::Power && !(std::isfinite(law.n) && law.n >= 0.0))
    return "the pressure exponent n must be a finite number >= 0, not " + number_text(law.n, 6);
  return {};
}

// The first problem with one parameter's setting, or an empty string.
std::string parameter_problem(const char* name, const ParameterSetting& p) {
  const std::string n(name);
  if (std::isnan(p.lower) || std::isnan(p.upper) || !(p.lower < p.upper))
    return "the bounds of " + n + " are empty or inverted: [" + number_text(p.lower, 6) + ", " +
           number_text(p.upper, 6) + "] (lower must be < upper)";
  if (!std::isfinite(p.lower) || !std::isfinite(p.upper))
    return "the bounds of " + n + " must be finite: [" + number_text(p.lower, 6) + ", " +
           number_text(p.upper, 6) + "]";
  if (p.log_scale && !(p.lower > 0.0))
    return n + " must stay > 0: its lower bound is " + number_text(p.lower, 6);
  if (!std::isfinite(p.initial)) return "the initial value of " + n + " is not finite";
  if (p.fixed && (p.initial < p.lower || p.initial > p.upper))
    return n + " is fixed at " + number_text(p.initial, 6) + ", outside its bounds [" +
           number_text(p.lower, 6) + ", " + number_text(p.upper, 6) + "]";
  return {};
}

std::string contact_problem(const FitSettings& s) {
  const model::ContactSpot& c = s.contact;
  if (c.kind == model::SpotKind::Circle) {
    if (!s.params[kQ].fixed)
      return "q is the aspect of an ellipse or a rectangle: the circle has none to fit";
    return {};
  }
  if (s.model != ModelKind::Exact)
    return std::string("the ") + model_name(s.model) +
           " approximant knows the circular spot only: a non-circular contact needs --model exact";
  if (c.kind == model::SpotKind::Map) {
    if (!c.map) return "the contact is a pressure map but holds none";
    if (!s.params[kQ].fixed)
      return "q is the aspect of an ellipse or a rectangle: a map has none to fit";
    return {};
  }
  if (!(std::isfinite(c.q) && c.q > 0.0))
    return "the spot's aspect q must be a finite number > 0, not " + number_text(c.q, 6);
  return {};
}

std::string settings_problem(const FitSettings& s) {
  if (auto w = law_problem(s.law); !w.empty()) return w;
  if (auto w = contact_problem(s); !w.empty()) return w;
  for (int i : s.used_parameters())
    if (auto w = parameter_problem(param_names()[i], s.params[i]); !w.empty()) return w;
  for (std::size_t a = 0; a < s.channels.size(); ++a)
    for (std::size_t b = a + 1; b < s.channels.size(); ++b)
      if (s.channels[a] == s.channels[b])
        return std::string("channel ") + channel_name(s.channels[a]) + " is listed twice";
  if (s.loss != LossKind::None && !(std::isfinite(s.loss_scale) && s.loss_scale > 0.0))
    return "the loss scale must be a finite number > 0, not " + number_text(s.loss_scale, 6);
  if (s.starts < 1) return "starts must be at least 1, not " + std::to_string(s.starts);
  if (s.global) {
    const auto algorithms = global_algorithms();
    if (std::find(algorithms.begin(), algorithms.end(), s.global_algorithm) == algorithms.end())
      return "unknown global algorithm '" + s.global_algorithm +
             "' (expected crs2, isres, direct, esch or random)";
    if (s.global_evaluations < 10)
      return "global_evaluations must be at least 10, not " + std::to_string(s.global_evaluations);
    if (s.global_subsample < 1) return "global_subsample must be at least 1";
  }
  if (s.max_iterations < 1)
    return "max_iterations must be at least 1, not " + std::to_string(s.max_iterations);
  for (const auto& [name, v] : {std::pair<const char*, double>{"function", s.function_tolerance},
                                {"gradient", s.gradient_tolerance},
                                {"parameter", s.parameter_tolerance}})
    if (!(std::isfinite(v) && v >= 0.0))
      return std::string("the ") + name + " tolerance must be a finite number >= 0, not " +
             number_text(v, 6);
  if (s.threads < 0) return "threads must be 0 (every hardware thread) or more";
  if (s.bootstrap < 0 || s.bootstrap > 100000)
    return "bootstrap must be 0 (none) to 100000 replicates, not " + std::to_string(s.bootstrap);
  if (s.noise_iterations < 1)
    return "noise_iterations must be at least 1, not " + std::to_string(s.noise_iterations);
  if (!(std::isfinite(s.noise_tolerance) && s.noise_tolerance > 0.0))
    return "the noise tolerance must be a finite number > 0, not " +
           number_text(s.noise_tolerance, 6);
  return {};
}

constexpr NoiseModelKind kNoiseModelKinds[] = {NoiseModelKind::Auto,     NoiseModelKind::Constant,
                                               NoiseModelKind::Relative, NoiseModelKind::Affine,
                                               NoiseModelKind::Additive, NoiseModelKind::Columns};

}  // namespace

const char* noise_model_kind_name(NoiseModelKind kind) {
  switch (kind) {
    case NoiseModelKind::Auto:
      return "auto";
    case NoiseModelKind::Constant:
      return "constant";
    case NoiseModelKind::Relative:
      return "relative";
    case NoiseModelKind::Affine:
      return "affine";
    case NoiseModelKind::Additive:
      return "additive";
    case NoiseModelKind::Columns:
      return "columns";
  }
  return "?";
}

std::optional<NoiseModelKind> parse_noise_model_kind(const std::string& name) {
  for (NoiseModelKind k : kNoiseModelKinds)
    if (name == noise_model_kind_name(k)) return k;
  return std::nullopt;
}

std::array<ParameterSetting, kParamCount> default_parameter_settings(
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
  // The tilt across the rolling direction: like h, held at 0 unless the spot or the data asks.
  s[kHy] = {0.0, -1.0, 1.0, true, false};
  // The aspect of an ellipse or a rectangle: fixed unless freed (docs/physics.md §9.1).
  s[kQ] = {1.0, 0.05, 4.0, true, true};
  return s;
}

FitSettings FitSettings::defaults(ModelKind model, model::PressureLaw<double> law,
                                  std::string label, model::ContactSpot contact) {
  FitSettings s;
  s.model = model;
  s.params = default_parameter_settings(law);
  if (contact.kind != model::SpotKind::Circle) {
    const auto d = default_parameters(law, contact, 0.8, 1.0, 0.0);
    for (int i : {kA, kB, kM, kP0, kBTilde}) s.params[i].initial = d[i];
    s.params[kHy].fixed = false;
    s.params[kQ].initial = contact.q;
  }
  s.law = std::move(law);
  s.law_label = std::move(label);
  s.contact = std::move(contact);
  return s;
}

std::vector<int> FitSettings::used_parameters(bool tilt_y) const {
  return model_parameters(model, law.kind, contact.kind, tilt_y || !params[kHy].fixed);
}

ParameterSetting& FitSettings::parameter(std::string_view name) {
  const auto i = param_index(name);
  if (!i) throw std::invalid_argument("unknown parameter '" + std::string(name) + "'");
  return params[*i];
}

const ParameterSetting& FitSettings::parameter(std::string_view name) const {
  return const_cast<FitSettings*>(this)->parameter(name);
}

FitSettings& FitSettings::fix(std::string_view name, double value) {
  ParameterSetting& p = parameter(name);
  p.fixed = true;
  p.initial = value;
  return *this;
}

FitSettings& FitSettings::bound(std::string_view name, double lower, double upper) {
  ParameterSetting& p = parameter(name);
  p.lower = lower;
  p.upper = upper;
  return *this;
}

FitSettings& FitSettings::start(std::string_view name, double value) {
  parameter(name).initial = value;
  return *this;
}

bool FitSettings::validate(std::string* why) const {
  const std::string w = settings_problem(*this);
  if (why) *why = w;
  return w.empty();
}

}  // namespace frictionid
