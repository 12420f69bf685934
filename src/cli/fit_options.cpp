#include "cli/fit_options.hpp"

#include <unistd.h>

#include <algorithm>
#include <csignal>

#include "io/input_error.hpp"
#include "io/option_parsers.hpp"
#include "io/pressure_spec.hpp"

namespace frictionid::cli {

namespace {

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) {
  g_interrupted.store(true);
}

LossKind parse_loss(const std::string& spec, double& scale) {
  const auto colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  scale = 1.0;
  if (colon != std::string::npos) {
    scale = parse_number("--loss", spec.substr(colon + 1));
    if (!(scale > 0.0)) throw InputError("--loss " + spec + ": the scale S must be > 0");
  }
  if (name == "none" && colon == std::string::npos) return LossKind::None;
  if (name == "huber") return LossKind::Huber;
  if (name == "cauchy") return LossKind::Cauchy;
  if (name == "soft_l1") return LossKind::SoftL1;
  throw InputError("--loss '" + spec + "': expected none, huber:S, cauchy:S or soft_l1:S");
}

// The parameter index of name, or -1 when the model does not use it and lenient is set.
int model_param_index(const std::string& option, const std::string& name,
                      const std::vector<int>& used, const std::string& model, bool lenient) {
  const auto i = param_index(name);
  if (!i) throw InputError(option + ": unknown parameter '" + name + "'");
  if (std::find(used.begin(), used.end(), *i) == used.end()) {
    if (lenient) return -1;
    std::string list;
    for (int u : used) list += std::string(list.empty() ? "" : ", ") + param_names()[u];
    throw InputError(option + ": model " + model + " has no parameter '" + name +
                     "' (its parameters: " + list + ")");
  }
  return *i;
}

}  // namespace

const std::atomic<bool>* install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  return &g_interrupted;
}

FitSettings fit_settings_from_options(const FitOptions& o, const std::string& model, bool lenient) {
  if (o.report.empty()) throw InputError("fit needs --report DIR");
  if (o.starts < 1) throw InputError("--starts must be at least 1");
  if (o.global_evaluations < 10) throw InputError("--global-evaluations must be at least 10");
  if (o.global_subsample < 1) throw InputError("--global-subsample must be at least 1");
  FitSettings s;
  const auto kind = parse_model_kind(model);
  if (!kind) throw InputError("--model '" + model + "': expected seed, corrected or exact");
  s.model = *kind;
  s.law = parse_pressure_law(o.pressure);
  s.law_label = pressure_law_label(s.law, o.pressure);
  s.params = default_parameter_settings(s.law);
  const auto used = model_parameters(s.model, s.law.kind);
  if (!o.initial.empty())
    for (const auto& [name, v] : parse_assignments("--param", o.initial)) {
      const int i = model_param_index("--param", name, used, model, lenient);
      if (i >= 0) s.params[i].initial = v;
    }
  if (!o.bounds.empty())
    for (const auto& [name, lohi] : parse_bounds("--bounds", o.bounds)) {
      const int i = model_param_index("--bounds", name, used, model, lenient);
      if (i < 0) continue;
      if (s.params[i].log_scale && !(lohi.first > 0.0))
        throw InputError("--bounds: " + name + " must stay > 0 (lower bound > 0)");
      s.params[i].lower = lohi.first;
      s.params[i].upper = lohi.second;
    }
  if (!o.fix.empty())
    for (const auto& [name, v] : parse_assignments("--fix", o.fix)) {
      const int i = model_param_index("--fix", name, used, model, lenient);
      if (i < 0) continue;
      s.params[i].fixed = true;
      s.params[i].initial = v;
    }
  // The exact model fits the exponent of a power law: the report names the law without the
  // number given on the command line, which was only a shape to start from.
  if (s.model == ModelKind::Exact && s.law.kind == model::PressureKind::Power &&
      !s.params[kN].fixed)
    s.law_label = "power:n (n fitted)";
  for (int i : used)
    if (s.params[i].fixed && s.params[i].log_scale && !(s.params[i].initial > 0.0))
      throw InputError(std::string("--fix: ") + param_names()[i] + " must be > 0");
  if (!o.channels.empty())
    for (const auto& name : parse_name_list("--channels", o.channels)) {
      bool found = false;
      for (Channel c : kAllChannels)
        if (name == channel_name(c)) {
          s.channels.push_back(c);
          found = true;
        }
      if (!found)
        throw InputError("--channels: unknown channel '" + name +
                         "' (expected T_x, T_y, M_z, M_roll)");
    }
  s.loss = parse_loss(o.loss, s.loss_scale);
  s.starts = o.starts;
  s.seed = o.seed;
  s.global = !o.no_global;
  s.global_algorithm = o.global_algorithm;
  s.global_evaluations = o.global_evaluations;
  s.global_subsample = o.global_subsample;
  if (o.threads < 0) throw InputError("--threads must be 0 (every hardware thread) or more");
  s.threads = o.threads;
  s.progress = o.progress || ::isatty(STDERR_FILENO);

  return s;
}

}  // namespace frictionid::cli
