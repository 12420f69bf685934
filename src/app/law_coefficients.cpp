#include "app/law_coefficients.hpp"

#include <cmath>

#include <fmt/format.h>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/io/pressure_map_reader.hpp>
#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/spot_coefficients.hpp>
#include "app/model_setup.hpp"
#include "app/option_parsers.hpp"

namespace frictionid::app {

namespace {

// A spot other than the circle: its coefficients by the same slope matching, for slip along x
// (model::spot_coefficients); q is the spot's, a map is its own pressure.
nlohmann::ordered_json spot_coefficients_json(const CoefficientsRequest& r,
                                              const model::PressureLaw<double>& law,
                                              const model::ContactSpot& spot) {
  if (r.alpha != 0.0)
    throw InputError(
        "--alpha: the coefficients of a contact spot other than the circle are "
        "matched for slip along x only; leave --alpha out with --contact " +
        r.contact);
  const auto c = model::spot_coefficients(spot, law, spot.q, r.kappa);
  for (double v : {c.a, c.b, c.m, c.b_tilde, c.p0, c.mu_M, c.rho_roll})
    if (!std::isfinite(v))
      throw InputError("--kappa " + fmt::format("{:g}", r.kappa) +
                       " is too small: the coefficients of --contact " + r.contact +
                       " are not finite");
  return {{"pressure", law_label_for(law, r.pressure, spot)},
          {"contact", contact_spot_label(spot)},
          {"kappa", r.kappa},
          {"alpha", r.alpha},
          {"a", c.a},
          {"b", c.b},
          {"m", c.m},
          {"b_tilde", c.b_tilde},
          {"p0", c.p0},
          {"mu_M", c.mu_M},
          {"M_roll_per_hNR", c.rho_roll}};
}

}  // namespace

nlohmann::ordered_json law_coefficients(const CoefficientsRequest& r) {
  if (!(r.kappa > 0.0) || !std::isfinite(r.kappa))
    throw InputError("--kappa must be a finite number > 0");
  if (!std::isfinite(r.alpha)) throw InputError("--alpha must be a finite angle in radians");
  const auto law = parse_pressure_option(r.pressure);
  const model::ContactSpot spot = checked_contact(r.contact, r.pressure_given, ModelKind::Exact);
  if (spot.kind != model::SpotKind::Circle) return spot_coefficients_json(r, law, spot);
  const auto mo = model::law_moments(law);
  const auto c = model::coefficients(mo, r.kappa, r.alpha);
  for (double v : {c.a, c.b, c.m, c.b_tilde, c.p0, c.mu_M, c.rho_roll})
    if (!std::isfinite(v))
      throw InputError("--kappa " + fmt::format("{:g}", r.kappa) +
                       " is too small: m = ((1+kappa) m2/(d22 m3))^2 overflows");
  const auto ok = model::check_consistency(c, r.kappa, r.alpha);
  return {{"pressure", pressure_law_label(law, r.pressure)},
          {"kappa", r.kappa},
          {"alpha", r.alpha},
          {"m0", mo[0]},
          {"m1", mo[1]},
          {"m2", mo[2]},
          {"m3", mo[3]},
          {"a", c.a},
          {"b", c.b},
          {"m", c.m},
          {"b_tilde", c.b_tilde},
          {"p0", c.p0},
          {"mu_M", c.mu_M},
          {"M_roll_per_hNR", c.rho_roll},
          {"consistency",
           {{"a_at_most_4", ok.a_at_most_4},
            {"b_at_least_4", ok.b_at_least_4},
            {"m_lower_bound", ok.m_lower},
            {"m_upper_bound", ok.m_upper},
            {"all", ok.all()}}}};
}

}  // namespace frictionid::app
