// The runner: settings checked, problem set up, search, statistics, warnings.
#include <frictionid/fitter.hpp>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include <frictionid/model/contact_spot.hpp>
#include "identify/bootstrap_intervals.hpp"
#include "identify/fit_problem.hpp"
#include "identify/fit_search.hpp"
#include "identify/fit_statistics.hpp"
#include "identify/fit_warnings.hpp"
#include "identify/fitted_run.hpp"
#include "identify/local_stage.hpp"
#include "identify/noise_model.hpp"
#include "identify/noise_reweighting.hpp"
#include "identify/number_text.hpp"
#include "identify/profile_intervals.hpp"
#include "identify/spot_cache.hpp"

namespace frictionid {
namespace {

std::string loss_label(const FitSettings& s) {
  if (s.loss == LossKind::None) return "none";
  const char* name = s.loss == LossKind::Huber    ? "huber:"
                     : s.loss == LossKind::Cauchy ? "cauchy:"
                                                  : "soft_l1:";
  return name + number_text(s.loss_scale);
}

}  // namespace

FitResult Fitter::fit(const Dataset& data, FitObserver* observer) const {
  return fit_keeping_problem(settings_, data, observer).result;
}

FittedRun fit_keeping_problem(const FitSettings& settings, const Dataset& data,
                              FitObserver* observer) {
  FittedRun run;
  run.settings = std::make_unique<FitSettings>(settings);
  const FitSettings& s = *run.settings;
  std::string why;
  if (!s.validate(&why)) throw std::invalid_argument("invalid fit settings: " + why);
  if (data.rows() == 0) throw std::invalid_argument("the dataset has no rows");
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  FitResult& res = run.result;
  res.model_kind = s.model;
  res.model = model_name(s.model);
  res.pressure = s.law_label;
  res.contact = model::contact_spot_label(s.contact);
  res.rows = data.rows();
  res.loss = loss_label(s);

  LocalProblem lp = make_fit_problem(data, s, res);
  const ParamVector initial = initial_parameters(s);
  // The exact model with a fixed pressure law: tabulate its ring integrals once for every pass.
  // A table law of many samples takes seconds: the build asks the observer, so that Ctrl-C acts.
  if (s.model == ModelKind::Exact && !exponent_free(lp)) {
    try {
      lp.exact_table = ring_table_for(s.model, s.law, initial[kN], false, [observer] {
        return observer != nullptr && observer->cancelled();
      });
    } catch (const model::RingTableBuildStopped&) {
      throw FitError("interrupted");
    }
  }

  // A non-circular spot with its aspect and pressure shape fixed: integrate every row once.
  if (auto cache = spot_cache_for_rows(data, s, lp.threads, observer)) {
    run.settings->contact.cache = std::move(cache);
  }

  res.noise_model = noise_model_name(s.noise_model);
  const SearchOutcome search = search_optimum(lp, initial, res, observer);
  LocalOutcome best = search.best;
  // With an estimated noise model the statistics see the data weighted by it.
  NoiseRefinement noise;
  NoiseTerms noise_terms;
  run.problem = lp;
  // Every channel to be estimated needs more than k + 2 rows (a degree of freedom left after
  // its share of the k parameters and its own sigma), or none is (noise_pooled).
  const bool any_estimated =
      std::any_of(res.channel_summaries.begin(), res.channel_summaries.end(),
                  [&](const ChannelSummary& cs) { return noise_estimated(s, data, cs.channel); });
  if (any_estimated && !noise_pooled(s, data, res.channel_summaries, lp.free.size())) {
    noise = refine_noise(lp, best, res, observer);
    best = noise.fit;
    run.noise_sigma =
        std::make_unique<std::array<std::vector<double>, kChannelCount>>(std::move(noise.sigma));
    run.problem = lp;
    run.problem.rows.sigma = run.noise_sigma.get();
    for (Channel c : run.problem.rows.channels) run.problem.rows.scale[static_cast<int>(c)] = 1.0;
    noise_terms = {noise.log_det, noise.parameters};
  }
  const auto t_local = clock::now();
  res.solver.iterations = best.iterations;
  res.solver.termination = best.termination;
  res.solver.converged = best.converged;

  run.x = best.x;
  const LocalProblem* final_problem = &run.problem;
  FitStatisticsDetail detail;
  const std::vector<int> undetermined =
      add_fit_statistics(*final_problem, best.x, search.start, noise_terms, res, &detail);
  res.intervals = s.intervals;
  res.interval_method = s.intervals == IntervalMethod::Model      ? "model"
                        : s.intervals == IntervalMethod::Sandwich ? "sandwich"
                                                                  : "profile";
  if (s.intervals == IntervalMethod::Profile) {
    add_profile_intervals(*final_problem, best.x, res, observer);
  } else {
    // Nearly collinear parameters: their symmetric intervals may miss on one side; the profile
    // follows the cost's valley (§8.12), so it is computed for them whatever the method.
    const auto correlated = strongly_correlated_parameters(res);
    if (!correlated.empty())
      add_profile_intervals(*final_problem, best.x, res, observer, &correlated);
  }
  add_bootstrap_intervals(*final_problem, best.x, s.bootstrap, s.seed, res, observer);
  add_fit_warnings(*final_problem, best.x, undetermined, res, &detail);

  using seconds = std::chrono::duration<double>;
  const auto t_end = clock::now();
  res.solver.time_s = seconds(t_end - t0).count();
  res.solver.local_time_s = seconds(t_local - t0).count() - res.solver.global_time_s;
  res.solver.statistics_time_s = seconds(t_end - t_local).count();
  return run;
}

}  // namespace frictionid
