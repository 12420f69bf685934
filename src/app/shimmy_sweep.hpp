// The stability map of a towed wheel (docs/physics.md §10.6): --speed-sweep A:B:N runs N speeds,
// each continued from the previous speed's limit cycle; the speeds where the outcome turns from
// stable (rest, decaying) to shimmy (limit cycle, growing) are refined by bisection; with
// --sweep-param NAME:A:B:M the whole sweep is repeated for M values of a wheel parameter.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/requests.hpp"
#include "app/shimmy.hpp"

namespace frictionid::app {

struct SweepRange {
  double a = 0.0, b = 0.0;
  int n = 0;
  double at(int i) const { return a + (b - a) * i / (n - 1); }
};

// "A:B:N" with A < B and N >= 2 (an integer up to 10000). Throws InputError naming `option`.
SweepRange parse_sweep_range(const std::string& option, const std::string& text);

struct SweepPoint {
  double speed = 0.0, param = 0.0;
  std::string outcome;
  std::string detail;  // why a `duration` run is not judged (holding, decaying, ...); else empty
  double amplitude = 0.0, frequency = 0.0;
  bool shimmy = false;  // limit_cycle or growing
};

struct SweepOnset {
  double param = 0.0;
  double speed = 0.0;         // the middle of the final bracket
  double lo = 0.0, hi = 0.0;  // the bracket, hi - lo <= the tolerance
  bool shimmy_above = false;  // shimmy on the side of the higher speed
};

struct SweepResult {
  std::string param_name;  // empty for a 1-D sweep
  std::vector<SweepPoint> points;
  std::vector<SweepOnset> onsets;
  double onset_tol = 0.0;
  nlohmann::ordered_json summary;
};

// Throws InputError on bad input. progress(done, total) after each run; table_progress while
// the contact spot's table is built, before the first (ShimmyCase).
SweepResult shimmy_sweep(const ShimmyRequest& r, const std::function<void(int, int)>& progress = {},
                         const TableProgress& table_progress = {});

// V,outcome,amplitude,frequency (and the parameter's column after V in a 2-D sweep).
std::string sweep_csv(const SweepResult& s);

// Amplitude of psi against V, stable and shimmy runs in two colours, the onsets marked; a 2-D
// sweep has one curve per parameter value and a table of the outcomes.
std::string sweep_html(const SweepResult& s, const std::string& title);

}  // namespace frictionid::app
