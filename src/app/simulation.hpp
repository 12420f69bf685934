// A flat body sliding and spinning to rest on a plane under any model's friction
// (docs/physics.md §4): `frictionid simulate`, `frictionid.simulate()`.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include <frictionid/model/sliding_spinning_body.hpp>
#include "app/requests.hpp"

namespace frictionid::app {

struct SimulationOutcome {
  model::BodySimulation sim;
  nlohmann::ordered_json summary;  // the model, the body, the start, how and when it stopped
};

// Checks the request and integrates. Throws InputError naming the option. The trajectory is
// recorded when r.trajectory or r.output is set.
SimulationOutcome simulate(const SimulateRequest& r);

// t,v_x,v_y,omega,eps,T_x,T_y,M_z,energy: one row per accepted step, %.17g.
std::string trajectory_csv(const model::BodySimulation& sim);

}  // namespace frictionid::app
