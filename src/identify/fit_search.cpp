#include "identify/fit_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <frictionid/fit_error.hpp>

#include "identify/fit_problem.hpp"
#include "identify/global_search.hpp"
#include "identify/local_stage.hpp"

namespace frictionid {
namespace {

// Map between parameters and the global stage's coordinates (log for wide positive ranges).
double to_search(const ParameterSetting& s, double v) {
  return s.log_scale ? std::log(v) : v;
}
double from_search(const ParameterSetting& s, double z) {
  return s.log_scale ? std::exp(z) : z;
}

ParamVector from_search_point(const FitSettings& s, const std::vector<int>& free,
                              const ParamVector& initial, const double* z) {
  ParamVector x = initial;
  for (std::size_t j = 0; j < free.size(); ++j)
    x[free[j]] = std::clamp(from_search(s.params[free[j]], z[j]), s.params[free[j]].lower,
                            s.params[free[j]].upper);
  return x;
}

void throw_if_cancelled(const FitObserver* observer) {
  if (observer && observer->cancelled()) throw FitError("interrupted");
}

// The global stage on the subsample problem `ps`: the best distinct points, best first.
std::vector<ParamVector> global_starts(const LocalProblem& ps, const ParamVector& initial,
                                       FitResult& res, FitObserver* observer) {
  const FitSettings& s = *ps.settings;
  // A free aspect q stays at its start here: every other parameter enters through sums of the
  // spot integrals, which the fit's cache holds for that q (spot_cache.hpp), while a new q
  // integrates every row again (~100 us each). The local fits then free q.
  std::vector<int> free;
  for (int i : ps.free)
    if (i != kQ) free.push_back(i);
  if (free.empty()) {
    res.global.algorithm = "none (initial values)";
    return {};
  }
  GlobalSearchProblem gp;
  for (int i : free) {
    gp.lower.push_back(to_search(s.params[i], s.params[i].lower));
    gp.upper.push_back(to_search(s.params[i], s.params[i].upper));
  }
  long evaluations = 0;
  // The search only ranks candidates: without a table the exact model may use a coarse rule.
  LocalProblem pg = ps;
  if (!pg.exact_table) pg.quadrature = &model::coarse_rule();
  const RepeatedCost cost(pg);
  gp.objective = [&](const double* z) {
    ++evaluations;
    if (observer && evaluations % 250 == 0) {
      FitProgress p;
      p.stage = FitStage::GlobalSearch;
      p.done = evaluations;
      p.total = s.global_evaluations;
      observer->on_progress(p);
    }
    return 2.0 * cost(from_search_point(s, free, initial, z));  // sum of squares
  };
  const std::function<bool()> stop = [observer] { return observer && observer->cancelled(); };
  const GlobalSearchOutcome g = global_search(gp, s.global_algorithm, s.global_evaluations, s.seed,
                                              std::max(1, s.starts), stop);
  res.global.algorithm = global_algorithm_label(s.global_algorithm);
  res.global.evaluations = g.evaluations;
  if (!g.failure.empty())
    res.warnings.push_back("the global stage failed after " + std::to_string(g.evaluations) +
                           " evaluations (" + g.failure + "); the local fits started from " +
                           (g.starts.empty() ? "the initial values" : "its best points so far"));
  std::vector<ParamVector> starts;
  for (const auto& z : g.starts) starts.push_back(from_search_point(s, free, initial, z.data()));
  return starts;
}

}  // namespace

SearchOutcome search_optimum(const LocalProblem& lp, const ParamVector& initial, FitResult& res,
                             FitObserver* observer) {
  const FitSettings& s = *lp.settings;
  const Dataset& data = *lp.rows.data;
  res.global.seed = s.seed;
  const auto t0 = std::chrono::steady_clock::now();
  // Global stage on a deterministic subsample (every k-th row).
  std::vector<ParamVector> starts;
  Dataset sub;
  LocalProblem ps = lp;
  bool subsampled = false;
  if (s.global && !lp.free.empty()) {
    sub = data.subsample(s.global_subsample);
    ps = problem_on(lp, sub);
    ps.threads = 1;  // a few hundred rows: threads would cost more than they save
    subsampled = sub.rows() < data.rows();
    res.global.subsample_rows = sub.rows();
    starts = global_starts(ps, initial, res, observer);
  } else {
    res.global.algorithm = "none (initial values)";
  }
  res.solver.global_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (starts.empty()) starts.push_back(initial);
  throw_if_cancelled(observer);

  // Local fits from every start; the best final cost wins (ties: the earlier start). A fit
  // that Ceres ends in FAILURE has cost +inf (local_stage.hpp) and does not count.
  // On a subsampled dataset they run on the subsample, and only the best is refined on all
  // rows: the starts decide between basins, which the subsample resolves at a fraction of the
  // cost, and the final fit from a nearby point needs only a few passes over all rows.
  const LocalProblem& start_problem = subsampled ? ps : lp;
  const int total = static_cast<int>(starts.size()) + (subsampled ? 1 : 0);
  std::vector<LocalOutcome> locals;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    locals.push_back(local_fit(start_problem, starts[k], observer, static_cast<int>(k + 1), total));
    throw_if_cancelled(observer);
  }
  std::size_t best = 0;
  for (std::size_t k = 1; k < locals.size(); ++k)
    if (locals[k].cost < locals[best].cost) best = k;
  if (!std::isfinite(locals[best].cost)) {
    const std::string where = first_nonfinite_row(start_problem, starts[0]);
    throw FitError(
        "every local fit failed: the model or its derivatives were not finite, or the solver "
        "failed, at every start" +
        (where.empty() ? std::string() : " (first non-finite row: " + where + ")"));
  }
  res.global.starts = static_cast<int>(locals.size());
  // Same cost to 1e-8, or both at rounding level (residuals ~1e-12 of their sigma: exact data).
  const double rounding_cost = 1e-24 * static_cast<double>(start_problem.rows.residual_count());
  for (const auto& l : locals)
    if (std::fabs(l.cost - locals[best].cost) <= 1e-8 * locals[best].cost + rounding_cost)
      ++res.global.reached_best;
  res.global.local_fits_on_subsample = subsampled;
  SearchOutcome out{locals[best], starts[best]};
  if (subsampled) {
    out.best = local_fit(lp, locals[best].x, observer, total, total);
    throw_if_cancelled(observer);
    if (!std::isfinite(out.best.cost)) {
      const std::string where = first_nonfinite_row(lp, locals[best].x);
      throw FitError("the local fit on all rows failed (" + out.best.termination +
                     "): the model or its derivatives were not finite, or the solver failed" +
                     (where.empty() ? std::string() : " (first non-finite row: " + where + ")"));
    }
  }
  if (observer) observer->on_log(out.best.full_report);
  return out;
}

}  // namespace frictionid
