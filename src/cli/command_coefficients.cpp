// frictionid coefficients: the moments of a pressure law and the approximant coefficients they
// imply (docs/physics.md §3).
#include <fmt/format.h>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/model/coefficients.hpp>
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/option_parsers.hpp"

namespace frictionid::cli {

int run_coefficients(const CoefficientsOptions& o) {
  if (!(o.kappa > 0.0) || !std::isfinite(o.kappa))
    throw InputError("--kappa must be a finite number > 0");
  if (!std::isfinite(o.alpha)) throw InputError("--alpha must be a finite angle in radians");
  const auto law = parse_pressure_option(o.pressure);
  const auto mo = model::law_moments(law);
  const auto c = model::coefficients(mo, o.kappa, o.alpha);
  for (double v : {c.a, c.b, c.m, c.b_tilde, c.p0, c.mu_M, c.rho_roll})
    if (!std::isfinite(v))
      throw InputError("--kappa " + fmt::format("{:g}", o.kappa) +
                       " is too small: m = ((1+kappa) m2/(d22 m3))^2 overflows");
  const auto ok = model::check_consistency(c, o.kappa, o.alpha);

  const nlohmann::ordered_json j = {{"pressure", pressure_law_label(law, o.pressure)},
                                    {"kappa", o.kappa},
                                    {"alpha", o.alpha},
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

  if (o.format == "json") {
    std::cout << j.dump(2) << "\n";
    return kExitOk;
  }
  std::printf("pressure law   %s   (kappa = %.6g, alpha = %.6g rad)\n",
              j["pressure"].get<std::string>().c_str(), o.kappa, o.alpha);
  std::printf("moments        m0 = %.10g  m1 = %.10g  m2 = %.10g  m3 = %.10g\n", mo[0], mo[1],
              mo[2], mo[3]);
  std::printf("a       %-16.10g small-v slope of T_par          (a <= 4: %s)\n", c.a,
              ok.a_at_most_4 ? "holds" : "VIOLATED");
  std::printf("b       %-16.10g small-u slope of seed T_perp    (b >= 4: %s)\n", c.b,
              ok.b_at_least_4 ? "holds" : "VIOLATED");
  std::printf("m       %-16.10g small-u slope of M_z            (bounds: %s)\n", c.m,
              ok.m_lower && ok.m_upper ? "hold" : "VIOLATED");
  std::printf("b_tilde %-16.10g corrected T_perp slope\n", c.b_tilde);
  std::printf("p0      %-16.10g pure-spin T_perp / (h kappa f N)\n", c.p0);
  std::printf("mu_M    %-16.10g M0 / (f N R) at kappa = 1\n", c.mu_M);
  std::printf("M_roll  %-16.10g M_roll / (h N R)\n", c.rho_roll);
  return kExitOk;
}

}  // namespace frictionid::cli
