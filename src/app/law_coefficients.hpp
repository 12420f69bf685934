// The moments of a pressure law and the approximant coefficients they imply (docs/physics.md §3),
// as `frictionid coefficients` prints them and `frictionid.coefficients()` returns them.
#pragma once

#include <nlohmann/json.hpp>

#include "app/requests.hpp"

namespace frictionid::app {

// {pressure, kappa, alpha, m0..m3, a, b, m, b_tilde, p0, mu_M, M_roll_per_hNR, consistency}.
// On a contact spot other than the circle (r.contact) the spot's own slope-matched coefficients
// for slip along x: {pressure, contact, kappa, alpha, a, b, m, b_tilde, p0, mu_M,
// M_roll_per_hNR} (the circle's moments and bounds do not apply there).
// Throws InputError for a bad law or spot, a kappa that is not finite and > 0, or one so small
// that the coefficients overflow.
nlohmann::ordered_json law_coefficients(const CoefficientsRequest& r);

}  // namespace frictionid::app
