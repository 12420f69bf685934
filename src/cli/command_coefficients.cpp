// frictionid coefficients: the moments of a pressure law and the approximant coefficients they
// imply (docs/physics.md §3), as JSON or a table.
#include <cstdio>
#include <iostream>

#include "app/law_coefficients.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "io/text.hpp"

namespace frictionid::cli {

int run_coefficients(const app::CoefficientsRequest& r, const std::string& format) {
  const nlohmann::ordered_json j = app::law_coefficients(r);
  if (format == "json") {
    std::cout << j.dump(2) << "\n";
    return kExitOk;
  }
  const auto v = [&j](const char* key) { return j[key].get<double>(); };
  if (j.contains("contact")) {
    // A spot other than the circle: its slope-matched coefficients, without the circle's bounds.
    std::printf("contact spot   %s, pressure %s   (kappa = %.6g, slip along x)\n",
                text::for_terminal(j["contact"].get<std::string>()).c_str(),
                text::for_terminal(j["pressure"].get<std::string>()).c_str(), r.kappa);
    std::printf("a       %-16.10g small-v slope of T_par\n", v("a"));
    std::printf("b       %-16.10g small-u slope of seed T_perp\n", v("b"));
    std::printf("m       %-16.10g small-u slope of M_z\n", v("m"));
    std::printf("b_tilde %-16.10g corrected T_perp slope\n", v("b_tilde"));
    std::printf("p0      %-16.10g pure-spin T_perp / (h kappa f N)\n", v("p0"));
    std::printf("mu_M    %-16.10g M0 / (f N R) at kappa = 1\n", v("mu_M"));
    std::printf("M_roll  %-16.10g M_roll / (h N R)\n", v("M_roll_per_hNR"));
    return kExitOk;
  }
  const auto& ok = j["consistency"];
  const auto holds = [&ok](const char* key) { return ok[key].get<bool>(); };
  std::printf("pressure law   %s   (kappa = %.6g, alpha = %.6g rad)\n",
              text::for_terminal(j["pressure"].get<std::string>()).c_str(), r.kappa, r.alpha);
  std::printf("moments        m0 = %.10g  m1 = %.10g  m2 = %.10g  m3 = %.10g\n", v("m0"), v("m1"),
              v("m2"), v("m3"));
  std::printf("a       %-16.10g small-v slope of T_par          (a <= 4: %s)\n", v("a"),
              holds("a_at_most_4") ? "holds" : "VIOLATED");
  std::printf("b       %-16.10g small-u slope of seed T_perp    (b >= 4: %s)\n", v("b"),
              holds("b_at_least_4") ? "holds" : "VIOLATED");
  std::printf("m       %-16.10g small-u slope of M_z            (bounds: %s)\n", v("m"),
              holds("m_lower_bound") && holds("m_upper_bound") ? "hold" : "VIOLATED");
  std::printf("b_tilde %-16.10g corrected T_perp slope\n", v("b_tilde"));
  std::printf("p0      %-16.10g pure-spin T_perp / (h kappa f N)\n", v("p0"));
  std::printf("mu_M    %-16.10g M0 / (f N R) at kappa = 1\n", v("mu_M"));
  std::printf("M_roll  %-16.10g M_roll / (h N R)\n", v("M_roll_per_hNR"));
  return kExitOk;
}

}  // namespace frictionid::cli
