#include "app/model_setup.hpp"

#include <cmath>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include "app/option_parsers.hpp"

namespace frictionid::app {

ModelSetup make_model_setup(const ModelRequest& r) {
  const std::string& model = r.model;
  const std::string& pressure = r.pressure;
  ModelSetup s;
  const auto kind = parse_model_kind(model);
  if (!kind) throw InputError("--model '" + model + "': expected seed, corrected or exact");
  s.kind = *kind;
  s.law = parse_pressure_option(pressure);
  const ParameterValues& given = r.params;
  check_values("--param", given);
  for (const auto& [name, value] : given) {
    if (!param_index(name))
      throw InputError("--param: unknown parameter '" + name +
                       "' (expected f, kappa, h, a, b, m, n, p0, b_tilde)");
    (void)value;
  }
  if (given.count("n")) {
    if (s.law.kind != model::PressureKind::Power)
      throw InputError("--param n=...: n is the exponent of --pressure power:N only");
    if (given.at("n") < 0.0) throw InputError("--param n must be >= 0");
    s.law.n = given.at("n");
  }
  s.law_label = pressure_law_label(s.law, pressure);
  const double kappa = given.count("kappa") ? given.at("kappa") : 1.0;
  if (!(kappa > 0.0)) throw InputError("--param kappa must be > 0");
  s.params = default_parameters(s.law, 1.0, kappa, 0.0);
  for (const auto& [name, value] : given) s.params[*param_index(name)] = value;
  if (!(s.params[kF] > 0.0)) throw InputError("--param f must be > 0");
  for (int i : {kA, kB, kM, kBTilde, kP0})
    if (!(s.params[i] > 0.0))
      throw InputError(std::string("--param ") + param_names()[i] + " must be > 0");
  return s;
}

nlohmann::ordered_json model_json(const ModelSetup& s) {
  nlohmann::ordered_json params;
  for (int i : model_parameters(s.kind, s.law.kind)) params[param_names()[i]] = s.params[i];
  return {{"model", model_name(s.kind)}, {"pressure", s.law_label}, {"parameters", params}};
}

}  // namespace frictionid::app
