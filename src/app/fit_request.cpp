#include "app/fit_request.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <vector>

#include <frictionid/fitter.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/io/pressure_map_reader.hpp>
#include "app/data_input.hpp"
#include "app/model_setup.hpp"
#include "app/option_parsers.hpp"
#include "identify/fitted_run.hpp"

namespace frictionid::app {

namespace {

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

NoiseModelKind parse_noise_model(const std::string& name) {
  if (const auto kind = parse_noise_model_kind(name)) return *kind;
  throw InputError("--noise-model '" + name +
                   "': expected auto, constant, relative, affine, additive or columns");
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

std::string g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// No start value or bound is ignored or changed silently: what the fit would
// not honour is an error.
void check_option_semantics(const FitRequest& o, const FitSettings& s, const std::vector<int>& used,
                            const std::vector<bool>& start_given,
                            const std::vector<bool>& bounds_given) {
  if (!o.start.empty() && !o.no_global)
    throw InputError(
        "--param sets where the local fit starts, which only --no-global uses (the global stage "
        "chooses its own starts); add --no-global or leave --param out");
  for (int i : used) {
    const ParameterSetting& p = s.params[i];
    const std::string name = param_names()[i];
    const bool inside = p.initial >= p.lower && p.initial <= p.upper;
    const std::string range = "[" + g(p.lower) + ", " + g(p.upper) + "]";
    if (p.fixed && bounds_given[i] && !inside)
      throw InputError("--fix " + name + "=" + g(p.initial) + " lies outside --bounds " + name +
                       "=" + g(p.lower) + ":" + g(p.upper) +
                       "; a fixed parameter is not fitted, so drop one of the two");
    if (!p.fixed && start_given[i] && !inside)
      throw InputError("--param " + name + "=" + g(p.initial) + " lies outside " + name +
                       "'s bounds " + range + (bounds_given[i] ? "" : " (the defaults)") +
                       "; the fit cannot start there: change --param or widen --bounds");
  }
}

}  // namespace

FitSettings fit_settings(const FitRequest& o, const std::string& model, bool lenient) {
  if (o.starts < 1) throw InputError("--starts must be at least 1");
  if (o.global_evaluations < 10) throw InputError("--global-evaluations must be at least 10");
  if (o.global_subsample < 1) throw InputError("--global-subsample must be at least 1");
  const auto kind = parse_model_kind(model);
  if (!kind) throw InputError("--model '" + model + "': expected seed, corrected or exact");
  const model::ContactSpot contact = checked_contact(o.contact, o.pressure_given, *kind);
  const std::string contact_label = contact_spot_label(contact);
  const auto law = parse_pressure_option(o.pressure);
  FitSettings s =
      FitSettings::defaults(*kind, law, law_label_for(law, o.pressure, contact), contact);
  // Every parameter the model can read on this spot: h_y is one of the exact model's on the
  // circle too, fitted when the data measure M_tilt or --free asks for it.
  const auto used = model_parameters(s.model, s.law.kind, contact.kind, /*tilt_y=*/true);
  for (const auto& name : o.free)
    if (name == "q" && !contact.has_aspect())
      throw InputError(std::string("--free q: q is the aspect of --contact ellipse:Q or "
                                   "rect:Q; ") +
                       (contact.kind == model::SpotKind::Map ? "a pressure map" : "the circle") +
                       " has none to fit");
  check_names("--free", o.free);
  std::vector<bool> start_given(s.params.size(), false), bounds_given(s.params.size(), false);
  check_values("--param", o.start);
  check_bounds("--bounds", o.bounds);
  check_values("--fix", o.fix);
  check_names("--channels", o.channels);
  if (o.fix.count("q"))
    throw InputError(
        "--fix q=...: q is the aspect of the contact spot; give it as --contact "
        "ellipse:Q or rect:Q");
  for (const auto& [name, v] : o.fix)
    if (std::find(o.free.begin(), o.free.end(), name) != o.free.end())
      throw InputError("--free " + name + " and --fix " + name +
                       "=...: a parameter is either fitted or held; drop one of the two");
  for (const auto& name : o.free) {
    const int i = model_param_index("--free", name, used, model, lenient);
    if (i >= 0) s.params[i].fixed = false;
  }
  for (const auto& [name, v] : o.start) {
    const int i = model_param_index("--param", name, used, model, lenient);
    if (i < 0) continue;
    // A parameter held by default (h_y, q) is started only where it is fitted: h_y on the
    // circle may still be freed by the data (fit_settings with the dataset applies it then).
    if (s.params[i].fixed && (i == kHy || i == kQ)) {
      if (i == kQ)
        throw InputError("--param q=...: q is held at the spot's aspect (--contact " +
                         contact_label + "); add --free q to fit it from --param's value");
      continue;
    }
    s.params[i].initial = v;
    start_given[i] = true;
  }
  for (const auto& [name, lohi] : o.bounds) {
    const int i = model_param_index("--bounds", name, used, model, lenient);
    if (i < 0) continue;
    if (s.params[i].log_scale && !(lohi.first > 0.0))
      throw InputError("--bounds: " + name + " must stay > 0 (lower bound > 0)");
    s.params[i].lower = lohi.first;
    s.params[i].upper = lohi.second;
    bounds_given[i] = true;
  }
  for (const auto& [name, v] : o.fix) {
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
  check_option_semantics(o, s, used, start_given, bounds_given);
  check_tilt(o.fix.count("h") || o.fix.count("h_y") ? "--fix" : "--param", s.contact, contact_label,
             s.params[kQ].initial, s.params[kH].initial, s.params[kHy].initial);
  for (const auto& name : o.channels) {
    bool found = false;
    for (Channel c : kAllChannels)
      if (name == channel_name(c)) {
        s.channels.push_back(c);
        found = true;
      }
    if (!found)
      throw InputError("--channels: unknown channel '" + name +
                       "' (expected T_x, T_y, M_z, M_roll, M_tilt)");
  }
  s.loss = parse_loss(o.loss, s.loss_scale);
  s.noise_model = parse_noise_model(o.noise_model);
  s.intervals = o.intervals == "sandwich"  ? IntervalMethod::Sandwich
                : o.intervals == "profile" ? IntervalMethod::Profile
                : o.intervals == "model"
                    ? IntervalMethod::Model
                    : throw InputError("--intervals '" + o.intervals +
                                       "': expected model, sandwich or profile");
  if (o.bootstrap < 0 || o.bootstrap > 100000)
    throw InputError("--bootstrap must be 0 (none) to 100000 replicates");
  s.bootstrap = o.bootstrap;
  s.starts = o.starts;
  if (o.seed > kMaxFitSeed)
    throw InputError("--seed", 0, 0,
                     "got '" + std::to_string(o.seed) +
                         "' (too large); expected a whole number from 0 to " +
                         std::to_string(kMaxFitSeed));
  s.seed = o.seed;
  s.global = !o.no_global;
  static const char* const kAlgorithms[] = {"crs2", "isres", "direct", "esch", "random"};
  if (std::find(std::begin(kAlgorithms), std::end(kAlgorithms), o.global_algorithm) ==
      std::end(kAlgorithms))
    throw InputError("--global-algorithm '" + o.global_algorithm +
                     "': expected crs2, isres, direct, esch or random");
  s.global_algorithm = o.global_algorithm;
  s.global_evaluations = o.global_evaluations;
  s.global_subsample = o.global_subsample;
  check_thread_option(o.threads);
  s.threads = o.threads;

  return s;
}

FitSettings fit_settings(const FitRequest& o, const std::string& model, const Dataset& data,
                         bool lenient) {
  FitSettings s = fit_settings(o, model, lenient);
  ParameterSetting& h_y = s.params[kHy];
  // A circle's fit takes the tilt across the rolling direction in when the data measure it
  // (and --channels does not leave M_tilt out).
  const bool fits_tilt = data.has_channel(Channel::M_tilt) &&
                         (s.channels.empty() || std::find(s.channels.begin(), s.channels.end(),
                                                          Channel::M_tilt) != s.channels.end());
  if (s.model == ModelKind::Exact && fits_tilt && !o.fix.count("h_y")) h_y.fixed = false;
  if (const auto start = o.start.find("h_y"); start != o.start.end()) {
    if (h_y.fixed) {
      if (lenient) return s;
      throw InputError(
          "--param h_y=...: h_y is held at 0 here (a circle whose data have no "
          "M_tilt column); add --free h_y to fit it from --param's value");
    }
    h_y.initial = start->second;
    if (!(h_y.initial >= h_y.lower && h_y.initial <= h_y.upper))
      throw InputError("--param h_y=" + g(h_y.initial) + " lies outside h_y's bounds [" +
                       g(h_y.lower) + ", " + g(h_y.upper) +
                       "]; the fit cannot start there: change --param or widen --bounds");
    check_tilt("--param", s.contact, contact_spot_label(s.contact), s.params[kQ].initial,
               s.params[kH].initial, h_y.initial);
  }
  return s;
}

std::vector<std::string> request_input_files(const FitRequest& r) {
  if (r.contact.rfind("map:", 0) == 0 && r.contact.size() > 4) return {r.contact.substr(4)};
  return {};
}

FitResult fit_dataset(const FitSettings& s, const Dataset& data, FitObserver* observer) {
  check_rolling_direction(s, data);
  try {
    return Fitter(s).fit(data, observer);
  } catch (const std::invalid_argument& e) {
    throw InputError(data.source, 0, 0, e.what());
  }
}

FitResult fit_dataset(const FitSettings& s, const Dataset& data, FitObserver* observer,
                      RowSigmas& sigma) {
  check_rolling_direction(s, data);
  FittedRun run;
  try {
    run = fit_keeping_problem(s, data, observer);  // Fitter::fit's result, and its problem
  } catch (const std::invalid_argument& e) {
    throw InputError(data.source, 0, 0, e.what());
  }
  const ResidualRows& rows = run.problem.rows;
  for (auto& v : sigma) v.clear();
  for (Channel c : rows.channels) {
    auto& out = sigma[static_cast<int>(c)];
    out.resize(data.rows());
    const double* column = rows.sigma_column(c);  // as ResidualRows::inverse_sigma reads it
    const double scale = rows.scale[static_cast<int>(c)];
    for (std::size_t i = 0; i < data.rows(); ++i)
      out[i] = !data.present[static_cast<int>(c)][i] ? std::nan("") : column ? column[i] : scale;
  }
  return std::move(run.result);
}

}  // namespace frictionid::app
