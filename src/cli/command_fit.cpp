// frictionid fit: identify a model's parameters from a dataset and write a report.
#include <unistd.h>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "identify/fitter.hpp"
#include "io/dataset_csv.hpp"
#include "io/input_error.hpp"
#include "io/option_parsers.hpp"
#include "io/pressure_spec.hpp"
#include "io/report_writer.hpp"

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

int model_param_index(const std::string& option, const std::string& name,
                      const std::vector<int>& used, const std::string& model) {
  const auto i = param_index(name);
  if (!i) throw InputError(option + ": unknown parameter '" + name + "'");
  if (std::find(used.begin(), used.end(), *i) == used.end()) {
    std::string list;
    for (int u : used) list += std::string(list.empty() ? "" : ", ") + param_names()[u];
    throw InputError(option + ": model " + model + " has no parameter '" + name +
                     "' (its parameters: " + list + ")");
  }
  return *i;
}

}  // namespace

int run_fit(const FitOptions& o) {
  if (o.report.empty()) throw InputError("fit needs --report DIR");
  if (o.starts < 1) throw InputError("--starts must be at least 1");
  if (o.global_evaluations < 10) throw InputError("--global-evaluations must be at least 10");
  if (o.global_subsample < 1) throw InputError("--global-subsample must be at least 1");
  FitSettings s;
  const auto kind = parse_model_kind(o.model);
  if (!kind) throw InputError("--model '" + o.model + "': expected seed, corrected or exact");
  s.model = *kind;
  s.law = parse_pressure_law(o.pressure);
  s.law_label = pressure_law_label(s.law, o.pressure);
  s.params = default_parameter_settings(s.law);
  const auto used = model_parameters(s.model, s.law.kind);
  if (!o.initial.empty())
    for (const auto& [name, v] : parse_assignments("--param", o.initial)) {
      auto& p = s.params[model_param_index("--param", name, used, o.model)];
      p.initial = v;
    }
  if (!o.bounds.empty())
    for (const auto& [name, lohi] : parse_bounds("--bounds", o.bounds)) {
      const int i = model_param_index("--bounds", name, used, o.model);
      if (s.params[i].log_scale && !(lohi.first > 0.0))
        throw InputError("--bounds: " + name + " must stay > 0 (lower bound > 0)");
      s.params[i].lower = lohi.first;
      s.params[i].upper = lohi.second;
    }
  if (!o.fix.empty())
    for (const auto& [name, v] : parse_assignments("--fix", o.fix)) {
      const int i = model_param_index("--fix", name, used, o.model);
      s.params[i].fixed = true;
      s.params[i].initial = v;
    }
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
  s.threads = std::max(1, o.threads);
  s.progress = o.progress || ::isatty(STDERR_FILENO);

  const Dataset data = load_dataset_csv(o.data, parse_column_map(o.columns));

  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  FitResult r;
  try {
    r = Fitter(s).fit(data, &g_interrupted);
  } catch (const FitError& e) {
    std::fprintf(stderr, "frictionid: fit failed: %s; no report written\n", e.what());
    return g_interrupted.load() ? kExitInterrupted : kExitFitFailed;
  } catch (const std::invalid_argument& e) {
    throw InputError(o.data, 0, 0, e.what());
  }
  if (g_interrupted.load()) {
    std::fprintf(stderr, "frictionid: interrupted; no report written\n");
    return kExitInterrupted;
  }
  const auto files = write_report(o.report, r, data);

  std::printf("model %s, pressure %s, %zu rows, channels", r.model.c_str(), r.pressure.c_str(),
              r.rows);
  for (Channel c : r.channels) std::printf(" %s", channel_name(c));
  std::printf("\n");
  for (const auto& p : r.parameters) {
    if (p.fixed)
      std::printf("  %-8s %.10g (fixed)\n", p.name.c_str(), p.value);
    else if (p.std_error)
      std::printf("  %-8s %.10g +- %.3g%s\n", p.name.c_str(), p.value, *p.std_error,
                  p.at_bound ? "  (at bound)" : "");
    else
      std::printf("  %-8s %.10g (not determined)\n", p.name.c_str(), p.value);
  }
  std::printf("cost %.6g, reduced chi2 %.6g, %d of %d starts reached the best, %s in %.2f s\n",
              r.cost, r.reduced_chi2, r.global.reached_best, r.global.starts,
              r.solver.termination.c_str(), r.solver.time_s);
  for (const auto& w : r.warnings) std::printf("warning: %s\n", w.c_str());
  std::printf("report: %s/report.md (%zu files)\n", o.report.c_str(), files.size());
  return kExitOk;
}

}  // namespace frictionid::cli
