// The moments of a pressure law and the approximant coefficients they imply (docs/physics.md §3),
// as `frictionid coefficients` prints them and `frictionid.coefficients()` returns them.
#pragma once

#include <nlohmann/json.hpp>

#include "app/requests.hpp"

namespace frictionid::app {

// {pressure, kappa, alpha, m0..m3, a, b, m, b_tilde, p0, mu_M, M_roll_per_hNR, consistency}.
// Throws InputError for a bad law, a kappa that is not finite and > 0, or one so small that the
// coefficients overflow.
nlohmann::ordered_json law_coefficients(const CoefficientsRequest& r);

}  // namespace frictionid::app
