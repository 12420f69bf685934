#include "app/model_setup.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/io/pressure_map_reader.hpp>
#include "app/option_parsers.hpp"
#include "io/text.hpp"

namespace frictionid::app {

namespace {

std::string parameter_list() {
  std::string list;
  for (const char* name : param_names()) list += std::string(list.empty() ? "" : ", ") + name;
  return list;
}

}  // namespace

model::ContactSpot checked_contact(const std::string& contact, bool pressure_given,
                                   ModelKind kind) {
  model::ContactSpot spot = parse_contact_option(contact);
  if (spot.kind == model::SpotKind::Map && pressure_given)
    throw InputError("--pressure", 0, 0,
                     "a pressure map (--contact " + contact +
                         ") is the pressure itself; leave --pressure out with map:FILE");
  if (spot.kind != model::SpotKind::Circle && kind != ModelKind::Exact)
    throw InputError("--contact", 0, 0,
                     "'" + contact + "': the " + model_name(kind) +
                         " approximant knows the circular spot only; a non-circular contact needs "
                         "--model exact");
  return spot;
}

std::string law_label_for(const model::PressureLaw<double>& law, const std::string& pressure,
                          const model::ContactSpot& contact) {
  return contact.kind == model::SpotKind::Map ? "map" : pressure_law_label(law, pressure);
}

void check_tilt(const std::string& option, const model::ContactSpot& contact,
                const std::string& contact_label, double q, double h, double h_y) {
  const model::TiltViolation v = model::tilt_violation(contact, q, h, h_y);
  if (!v.negative) return;
  throw InputError(option, 0, 0,
                   "h = " + text::shortest_number(h) + ", h_y = " + text::shortest_number(h_y) +
                       " make the pressure 1 + h x + h_y y negative at (x, y) = (" +
                       text::shortest_number(v.x) + ", " + text::shortest_number(v.y) +
                       ") of the contact spot " + contact_label +
                       "; expected a tilt that keeps it >= 0 on the whole spot");
}

ModelSetup make_model_setup(const ModelRequest& r) {
  const std::string& model = r.model;
  const std::string& pressure = r.pressure;
  ModelSetup s;
  const auto kind = parse_model_kind(model);
  if (!kind) throw InputError("--model '" + model + "': expected seed, corrected or exact");
  s.kind = *kind;
  s.contact = checked_contact(r.contact, r.pressure_given, s.kind);
  s.contact_label = contact_spot_label(s.contact);
  s.law = parse_pressure_option(pressure);
  const ParameterValues& given = r.params;
  check_values("--param", given);
  for (const auto& [name, value] : given) {
    if (!param_index(name))
      throw InputError("--param: unknown parameter '" + name + "' (expected " + parameter_list() +
                       ")");
    (void)value;
  }
  if (given.count("q"))
    throw InputError(
        "--param q=...: q is the aspect of the contact spot; give it as --contact "
        "ellipse:Q or rect:Q");
  if (given.count("h_y") && given.at("h_y") != 0.0 && s.kind != ModelKind::Exact)
    throw InputError(std::string("--param h_y=...: the ") + model_name(s.kind) +
                     " approximant has no tilt across the rolling direction; use --model exact");
  if (given.count("n")) {
    if (s.law.kind != model::PressureKind::Power || s.contact.kind == model::SpotKind::Map)
      throw InputError("--param n=...: n is the exponent of --pressure power:N only");
    if (given.at("n") < 0.0) throw InputError("--param n must be >= 0");
    s.law.n = given.at("n");
  }
  s.law_label = law_label_for(s.law, pressure, s.contact);
  const double kappa = given.count("kappa") ? given.at("kappa") : 1.0;
  if (!(kappa > 0.0)) throw InputError("--param kappa must be > 0");
  s.params = default_parameters(s.law, s.contact, 1.0, kappa, 0.0);
  for (const auto& [name, value] : given) s.params[*param_index(name)] = value;
  if (!(s.params[kF] > 0.0)) throw InputError("--param f must be > 0");
  for (int i : {kA, kB, kM, kBTilde, kP0})
    if (!(s.params[i] > 0.0))
      throw InputError(std::string("--param ") + param_names()[i] + " must be > 0");
  check_tilt("--param", s.contact, s.contact_label, s.params[kQ], s.params[kH], s.params[kHy]);
  return s;
}

bool shows_tilt(const ModelSetup& s) {
  return s.contact.kind != model::SpotKind::Circle || s.params[kHy] != 0.0;
}

nlohmann::ordered_json model_json(const ModelSetup& s) {
  nlohmann::ordered_json params;
  for (int i : model_parameters(s.kind, s.law.kind, s.contact.kind, s.params[kHy] != 0.0))
    params[param_names()[i]] = s.params[i];
  nlohmann::ordered_json j = {{"model", model_name(s.kind)}, {"pressure", s.law_label}};
  if (s.contact.kind != model::SpotKind::Circle) j["contact"] = s.contact_label;
  j["parameters"] = params;
  return j;
}

}  // namespace frictionid::app
