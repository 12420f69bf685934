// The global stage: an NLopt derivative-free global algorithm over a box, which also keeps an
// archive of every point it evaluated so that the best *distinct* points can seed local fits.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace frictionid {

struct GlobalSearchProblem {
  std::vector<double> lower, upper;                // box in the search coordinates
  std::function<double(const double*)> objective;  // finite, or +inf for unusable points
};

struct GlobalSearchOutcome {
  std::vector<std::vector<double>> starts;  // best distinct points, best first
  std::vector<double> start_values;
  long evaluations = 0;
  std::string algorithm;
  std::string failure;  // why the algorithm stopped early, if it failed; empty otherwise
};

// Algorithms: "crs2" (NLopt GN_CRS2_LM, the default), "isres", "direct", "esch", "random".
// Deterministic for a given seed (NLopt's generator is seeded; one thread). `stop`, when given,
// is polled at every evaluation and ends the search early when it returns true.
GlobalSearchOutcome global_search(const GlobalSearchProblem& problem, const std::string& algorithm,
                                  long max_evaluations, unsigned long long seed, int starts,
                                  const std::function<bool()>& stop = {});

std::vector<std::string> global_algorithms();
// "NLopt GN_CRS2_LM" etc., for reports.
std::string global_algorithm_label(const std::string& algorithm);

}  // namespace frictionid
