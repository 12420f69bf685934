// A towed wheel or nose landing gear under a model's friction (docs/physics.md §10):
// `frictionid shimmy`, `frictionid.shimmy()`. One run here; speed sweeps in shimmy_sweep.hpp.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/model/kinematics.hpp>
#include <frictionid/model/shimmy_simulation.hpp>
#include "app/model_setup.hpp"
#include "app/requests.hpp"

namespace frictionid::app {

// The points a contact spot's table has computed so far, every kTablePointsStep of them
// (model_variant.hpp) while ShimmyCase builds it (a rough map's table takes seconds to minutes:
// its build grows as the square of the cells). Called from the build's threads, one call at a
// time.
using TableProgress = std::function<void(std::size_t points)>;

// The checked request turned into what the integrator needs: the model (from --param or a
// report.json), the wheel, the settings and the friction as a callable.
class ShimmyCase {
 public:
  // Throws InputError (one line, naming the option) on bad input.
  explicit ShimmyCase(const ShimmyRequest& r, const TableProgress& table_progress = {});
  ~ShimmyCase();
  ShimmyCase(const ShimmyCase&) = delete;
  ShimmyCase& operator=(const ShimmyCase&) = delete;

  const ModelSetup& setup() const { return setup_; }
  const model::ShimmyWheel& wheel() const { return wheel_; }
  const model::ShimmySettings& settings() const { return settings_; }
  model::ShimmyStart start() const { return start_; }

  // One run of `wheel` (the request's, or a sweep's variation) from `start`; rows go to `row`
  // when settings.record.
  model::ShimmyRun run(const model::ShimmyWheel& wheel, const model::ShimmyStart& start,
                       const model::ShimmySettings& settings,
                       const std::function<void(const model::ShimmyRow&)>& row) const;

  // The model, the wheel and the start as the JSON summaries begin.
  nlohmann::ordered_json description(const model::ShimmyWheel& wheel) const;

 private:
  struct Friction;
  ModelSetup setup_;
  model::ShimmyWheel wheel_;
  model::ShimmySettings settings_;
  model::ShimmyStart start_;
  int table_directions_ = 0;
  std::unique_ptr<Friction> friction_;
};

struct ShimmyResult {
  model::ShimmyRun run;
  std::vector<model::ShimmyRow> rows;  // when r.trajectory or r.output
  nlohmann::ordered_json summary;      // the model, the wheel, the final state, outcome, energy
};

// Checks the request and integrates one run.
ShimmyResult shimmy(const ShimmyRequest& r, const TableProgress& table_progress = {});

// The JSON of how a run ended: final state, outcome (with amplitude and frequency), energy.
nlohmann::ordered_json run_json(const model::ShimmyRun& run);

// t,y,y_dot,psi,psi_dot,u_y,T_y,M_z, %.17g.
std::string shimmy_csv(const std::vector<model::ShimmyRow>& rows);

}  // namespace frictionid::app
