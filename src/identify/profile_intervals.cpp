#include "identify/profile_intervals.hpp"
#include "identify/local_stage.hpp"
#include "identify/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <frictionid/fit_error.hpp>

#include "identify/statistics.hpp"

namespace frictionid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One side of the profile (direction d = -1 or +1): steps of half a standard error until the
// cost rises above `target`, then bisection between the last two steps. Returns the crossing, or
// the bound (closed = false) when the profile stays below the target up to it.
double profile_side(const LocalProblem& lp, int i, const ParamVector& x, double se, double target,
                    int d, bool& closed, FitObserver* observer) {
  const ParameterSetting& ps = lp.settings->params[i];
  const double bound = d < 0 ? ps.lower : ps.upper;
  ParamVector warm = x;
  double inside = x[i], outside = bound;
  closed = false;
  for (int k = 1; k <= 40; ++k) {
    double v = x[i] + d * 0.5 * k * se;
    const bool at_bound = d < 0 ? v <= bound : v >= bound;
    if (at_bound) v = bound;
    const double c = profile_cost(lp, i, v, warm, observer);
    if (c > target) {
      outside = v;
      closed = true;
      break;
    }
    inside = v;
    if (at_bound) break;
  }
  if (!closed) return bound;
  // Bisection on the crossing, warm-started from the inner side.
  ParamVector inner_warm = warm;
  for (int it = 0; it < 30 && std::fabs(outside - inside) > 1e-6 * se; ++it) {
    const double mid = 0.5 * (inside + outside);
    ParamVector w = inner_warm;
    const double c = profile_cost(lp, i, mid, w, observer);
    if (c > target) {
      outside = mid;
    } else {
      inside = mid;
      inner_warm = w;
    }
  }
  return 0.5 * (inside + outside);
}

}  // namespace

std::vector<std::string> strongly_correlated_parameters(const FitResult& res) {
  std::vector<std::string> out;
  const std::size_t n = res.correlation_names.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      if (a != b && std::fabs(res.correlation[a][b]) > kStrongCorrelation) {
        out.push_back(res.correlation_names[a]);
        break;
      }
  return out;
}

double profile_cost(const LocalProblem& lp, int i, double v, ParamVector& warm,
                    FitObserver* observer) {
  LocalProblem held = lp;
  held.free.erase(std::remove(held.free.begin(), held.free.end(), i), held.free.end());
  warm[i] = v;
  if (held.free.empty()) return problem_cost(held, warm);
  const LocalOutcome o = local_fit(held, warm, observer, 1, 1);
  if (observer && observer->cancelled()) throw FitError("interrupted");
  if (!std::isfinite(o.cost)) return kInf;
  warm = o.x;
  return o.cost;
}

void add_profile_intervals(const LocalProblem& lp, const ParamVector& x, FitResult& res,
                           FitObserver* observer, const std::vector<std::string>* only) {
  if (res.dof == 0) return;
  const double tq = student_t_quantile(0.975, static_cast<double>(res.dof));
  const double scale = res.covariance_scaled_by_reduced_chi2 ? res.reduced_chi2 : 1.0;
  // Costs are 1/2 sum of squares: the sum rises by t^2 scale where the cost rises by half that.
  const double target = res.cost + 0.5 * tq * tq * scale;
  for (auto& e : res.parameters) {
    if (e.fixed || !e.std_error || !(*e.std_error > 0.0)) continue;
    if (only && std::find(only->begin(), only->end(), e.name) == only->end()) continue;
    const int i = *param_index(e.name);
    std::array<double, 2> ci{};
    for (int side = 0; side < 2; ++side) {
      bool closed = true;
      ci[side] = profile_side(lp, i, x, *e.std_error, target, side == 0 ? -1 : 1, closed, observer);
      e.profile_closed[side] = closed;
      if (!closed)
        res.warnings.push_back("the profile of " + e.name + " does not close inside its " +
                               (side == 0 ? "lower" : "upper") + " bound " + number_text(ci[side]) +
                               ": the data do not exclude values beyond it at 95 %, so the " +
                               "interval ends at the bound");
    }
    e.ci95_profile = ci;
  }
}

}  // namespace frictionid
