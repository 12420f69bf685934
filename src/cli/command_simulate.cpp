// frictionid simulate: a flat body sliding and spinning to rest on a plane under the friction of
// any model variant (docs/physics.md §4); JSON summary on stdout, trajectory CSV on request.
#include <iostream>

#include "app/simulation.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "io/atomic_file.hpp"

namespace frictionid::cli {

int run_simulate(const app::SimulateRequest& r) {
  app::SimulationOutcome out = app::simulate(r);
  if (!r.output.empty()) {
    write_file_atomically(r.output, app::trajectory_csv(out.sim));
    out.summary["trajectory_rows"] = out.sim.trajectory.size();
  }
  std::cout << out.summary.dump(2) << "\n";
  if (!out.sim.stopped) {
    std::cerr << "frictionid: error: the integration did not reach the stop within --max-steps "
              << r.max_steps << " steps (or the step size underflowed)\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace frictionid::cli
