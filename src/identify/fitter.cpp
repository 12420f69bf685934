// The runner: global stage, local stage from the best distinct starts, statistics, warnings.
#include "identify/fitter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

#include "identify/global_search.hpp"
#include "identify/local_stage.hpp"
#include "identify/residual_diagnostics.hpp"
#include "identify/residuals.hpp"
#include "identify/row_chunks.hpp"
#include "identify/statistics.hpp"
#include "model/coefficients.hpp"

namespace frictionid {
namespace {

using Params = ParamVector;
constexpr std::size_t kGrowthSampleRows = 50000;

struct Problem {
  const Dataset* data;
  const FitSettings* s;
  std::vector<Channel> channels;
  std::array<double, kChannelCount> scale{};
  std::vector<int> used;  // parameters the model reads
  std::vector<int> free;  // used and not fixed
};

// Map between parameters and the global stage's coordinates (log for wide positive ranges).
double to_search(const ParameterSetting& s, double v) {
  return s.log_scale ? std::log(v) : v;
}
double from_search(const ParameterSetting& s, double z) {
  return s.log_scale ? std::exp(z) : z;
}

std::string fmt_g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string join_names(const std::vector<int>& idx) {
  std::string s;
  for (std::size_t i = 0; i < idx.size(); ++i) {
    if (i) s += i + 1 == idx.size() ? " and " : ", ";
    s += param_names()[idx[i]];
  }
  return s;
}

}  // namespace

FitResult Fitter::fit(const Dataset& data, const std::atomic<bool>* cancel) const {
  const FitSettings& s = settings_;
  const auto t0 = std::chrono::steady_clock::now();
  FitResult res;
  res.model = model_name(s.model);
  res.pressure = s.law_label;
  res.rows = data.rows();
  res.loss = s.loss == LossKind::None     ? "none"
             : s.loss == LossKind::Huber  ? "huber:" + fmt_g(s.loss_scale)
             : s.loss == LossKind::Cauchy ? "cauchy:" + fmt_g(s.loss_scale)
                                          : "soft_l1:" + fmt_g(s.loss_scale);
  if (data.rows() == 0) throw std::invalid_argument("the dataset has no rows");

  Problem p;
  p.data = &data;
  p.s = &s;
  // Channels: the requested ones that some row measures, in canonical order.
  std::vector<Channel> requested = s.channels;
  if (requested.empty())
    for (Channel c : kAllChannels)
      if (data.has_channel(c)) requested.push_back(c);
  for (Channel c : kAllChannels) {
    if (std::find(requested.begin(), requested.end(), c) == requested.end()) continue;
    if (data.has_channel(c))
      p.channels.push_back(c);
    else
      res.warnings.push_back(std::string("channel ") + channel_name(c) +
                             " was requested but no row measures it; it is not fitted");
  }
  if (p.channels.empty())
    throw std::invalid_argument("no requested channel is measured by any row");
  res.channels = p.channels;

  // Whitening scales: the sigma columns, else the RMS of the measured values of the channel.
  for (Channel c : p.channels) {
    const int ci = static_cast<int>(c);
    ChannelSummary cs;
    cs.channel = c;
    double peak = 0.0, sum2 = 0.0;  // sum2 relative to peak: no overflow near the double range
    for (std::size_t i = 0; i < data.rows(); ++i)
      if (data.present[ci][i]) {
        ++cs.rows;
        peak = std::max(peak, std::fabs(data.value[ci][i]));
      }
    for (std::size_t i = 0; i < data.rows(); ++i)
      if (data.present[ci][i] && peak > 0.0) {
        const double u = data.value[ci][i] / peak;
        sum2 += u * u;
      }
    if (data.has_sigma(c)) {
      cs.scale = 1.0;
      cs.scale_source = "sigma column";
    } else {
      const double rms =
          peak * std::sqrt(sum2 / static_cast<double>(std::max<std::size_t>(cs.rows, 1)));
      cs.scale = rms > 0.0 ? rms : 1.0;
      cs.scale_source = rms > 0.0 ? "RMS of the measured values (no sigma column)"
                                  : "1 (all measured values are zero; no sigma column)";
    }
    p.scale[ci] = cs.scale;
    res.channel_summaries.push_back(cs);
  }
  const bool absolute_sigma = std::all_of(p.channels.begin(), p.channels.end(),
                                          [&](Channel c) { return data.has_sigma(c); });

  p.used = model_parameters(s.model, s.law.kind);
  for (int i : p.used)
    if (!s.params[i].fixed) p.free.push_back(i);
  LocalProblem lp;
  lp.rows.data = &data;
  lp.rows.channels = p.channels;
  lp.rows.scale = p.scale;
  lp.rows.begin = 0;
  lp.rows.end = data.rows();
  lp.settings = &s;
  lp.free = p.free;
  lp.threads = resolve_thread_count(s.threads);

  Params initial{};
  for (int i = 0; i < kParamCount; ++i)
    initial[i] = std::clamp(s.params[i].initial, s.params[i].lower, s.params[i].upper);
  for (int i = 0; i < kParamCount; ++i)
    if (s.params[i].fixed) initial[i] = s.params[i].initial;

  // The exact model with a fixed pressure law: tabulate its ring integrals once for every pass.
  if (s.model == ModelKind::Exact && !exponent_free(lp))
    lp.exact_table = ring_table_for(s.model, s.law, initial[kN], false);

  // Global stage on a deterministic subsample (every k-th row).
  std::vector<Params> starts;
  res.global.seed = s.seed;
  Dataset sub;
  LocalProblem ps = lp;  // the subsample's problem
  bool subsampled = false;
  if (s.global && !p.free.empty()) {
    const std::size_t stride =
        std::max<std::size_t>(1, (data.rows() + s.global_subsample - 1) / s.global_subsample);
    // Subsample rows are a strided view: copy them into a compact dataset.
    sub.source = data.source;
    for (std::size_t i = 0; i < data.rows(); i += stride) {
      sub.line.push_back(data.line.empty() ? 0 : data.line[i]);
      sub.v_x.push_back(data.v_x[i]);
      sub.v_y.push_back(data.v_y[i]);
      sub.omega.push_back(data.omega[i]);
      sub.N.push_back(data.N[i]);
      sub.R.push_back(data.R[i]);
      for (int c = 0; c < kChannelCount; ++c) {
        sub.value[c].push_back(data.value[c][i]);
        sub.present[c].push_back(data.present[c][i]);
        if (!data.sigma[c].empty()) sub.sigma[c].push_back(data.sigma[c][i]);
      }
    }
    ps.rows.data = &sub;
    ps.rows.end = sub.rows();
    ps.threads = 1;  // a few hundred rows: threads would cost more than they save
    subsampled = stride > 1;
    res.global.subsample_rows = sub.rows();

    GlobalSearchProblem gp;
    for (int i : p.free) {
      gp.lower.push_back(to_search(s.params[i], s.params[i].lower));
      gp.upper.push_back(to_search(s.params[i], s.params[i].upper));
    }
    long evaluations = 0;
    // The search only ranks candidates: without a table the exact model may use a coarse rule.
    LocalProblem pg = ps;
    if (!pg.exact_table) pg.quadrature = &model::coarse_rule();
    gp.objective = [&](const double* z) {
      Params x = initial;
      for (std::size_t j = 0; j < p.free.size(); ++j)
        x[p.free[j]] = std::clamp(from_search(s.params[p.free[j]], z[j]), s.params[p.free[j]].lower,
                                  s.params[p.free[j]].upper);
      ++evaluations;
      if (s.progress && evaluations % 250 == 0)
        std::fprintf(stderr, "\rfrictionid: global search %ld/%ld evaluations   ", evaluations,
                     s.global_evaluations);
      return 2.0 * problem_cost(pg, x);  // sum of squares
    };
    const GlobalSearchOutcome g = global_search(gp, s.global_algorithm, s.global_evaluations,
                                                s.seed, std::max(1, s.starts), cancel);
    res.global.algorithm = global_algorithm_label(s.global_algorithm);
    res.global.evaluations = g.evaluations;
    if (!g.failure.empty())
      res.warnings.push_back("the global stage failed after " + std::to_string(g.evaluations) +
                             " evaluations (" + g.failure + "); the local fits started from " +
                             (g.starts.empty() ? "the initial values" : "its best points so far"));
    for (const auto& z : g.starts) {
      Params x = initial;
      for (std::size_t j = 0; j < p.free.size(); ++j)
        x[p.free[j]] = std::clamp(from_search(s.params[p.free[j]], z[j]), s.params[p.free[j]].lower,
                                  s.params[p.free[j]].upper);
      starts.push_back(x);
    }
  } else {
    res.global.algorithm = "none (initial values)";
  }
  const auto t_global = std::chrono::steady_clock::now();
  if (starts.empty()) starts.push_back(initial);
  if (cancel && cancel->load()) throw FitError("interrupted");

  // Local fits from every start; the best final cost wins (ties: the earlier start). A fit
  // that Ceres ends in FAILURE has cost +inf (local_stage.hpp) and does not count.
  // On a subsampled dataset they run on the subsample, and only the best is refined on all
  // rows: the starts decide between basins, which the subsample resolves at a fraction of the
  // cost, and the final fit from a nearby point needs only a few passes over all rows.
  const LocalProblem& start_problem = subsampled ? ps : lp;
  std::vector<LocalOutcome> locals;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    locals.push_back(local_fit(start_problem, starts[k], cancel, static_cast<int>(k + 1),
                               static_cast<int>(starts.size())));
    if (cancel && cancel->load()) throw FitError("interrupted");
  }
  std::size_t best = 0;
  for (std::size_t k = 1; k < locals.size(); ++k)
    if (locals[k].cost < locals[best].cost) best = k;
  if (!std::isfinite(locals[best].cost))
    throw FitError(
        "every local fit failed: the model or its derivatives were not finite, or the solver "
        "failed, at every start");
  res.global.starts = static_cast<int>(locals.size());
  // Same cost to 1e-8, or both at rounding level (residuals ~1e-12 of their sigma: exact data).
  const double rounding_cost = 1e-24 * static_cast<double>(start_problem.rows.residual_count());
  for (const auto& l : locals)
    if (std::fabs(l.cost - locals[best].cost) <= 1e-8 * locals[best].cost + rounding_cost)
      ++res.global.reached_best;
  res.global.local_fits_on_subsample = subsampled;
  LocalOutcome L = locals[best];
  if (subsampled) {
    L = local_fit(lp, locals[best].x, cancel, static_cast<int>(starts.size()) + 1,
                  static_cast<int>(starts.size()) + 1);
    if (cancel && cancel->load()) throw FitError("interrupted");
    if (!std::isfinite(L.cost))
      throw FitError("the local fit on all rows failed (" + L.termination +
                     "): the model or its derivatives were not finite, or the solver failed");
  }
  if (s.progress) std::fprintf(stderr, "\r%80s\r", "");
  res.solver.iterations = L.iterations;
  res.solver.termination = L.termination;
  res.solver.converged = L.converged;
  // Diagnostics for performance work: Ceres' own time breakdown of the final local fit.
  if (std::getenv("FRICTIONID_CERES_REPORT")) std::fprintf(stderr, "%s\n", L.full_report.c_str());
  const Params& x = L.x;
  const auto t_local = std::chrono::steady_clock::now();

  // The whitened Jacobian at the optimum (free columns), as its triangular factor.
  const std::size_t k = p.free.size();
  Eigen::MatrixXd jacobian_r(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  if (k == 0) {
    res.cost = problem_cost(lp, x);
    if (!std::isfinite(res.cost))
      throw FitError("the model is not finite at the fitted parameters");
  } else {
    const auto jf = jacobian_factor(lp, x);
    if (!jf) throw FitError("the model is not finite at the fitted parameters");
    jacobian_r = jf->r;
    res.cost = jf->cost;
  }

  // Observations: measured values of fitted channels (unmeasured cells hold residual 0).
  std::size_t nobs = 0;
  for (const auto& cs : res.channel_summaries) nobs += cs.rows;
  res.residuals = nobs;
  res.dof = nobs > k ? nobs - k : 0;
  // chi2 without the loss, cost with it.
  {
    FitSettings plain_settings = s;
    plain_settings.loss = LossKind::None;
    LocalProblem plain = lp;
    plain.settings = &plain_settings;
    res.chi2 = 2.0 * problem_cost(plain, x);
  }
  res.reduced_chi2 = res.dof > 0 ? res.chi2 / static_cast<double>(res.dof) : 0.0;
  const double n = static_cast<double>(std::max<std::size_t>(nobs, 1));
  const double kk = static_cast<double>(k);
  if (absolute_sigma) {
    res.aic = res.chi2 + 2 * kk;
    res.bic = res.chi2 + kk * std::log(n);
  } else {
    const double ll = n * std::log(std::max(res.chi2, 1e-300) / n);
    res.aic = ll + 2 * kk;
    res.bic = ll + kk * std::log(n);
  }
  res.covariance_scaled_by_reduced_chi2 = !absolute_sigma;

  const JacobianCovariance cov = covariance_from_jacobian(jacobian_r);
  const double cov_scale = absolute_sigma ? 1.0 : res.reduced_chi2;
  const double tq = res.dof > 0 ? student_t_quantile(0.975, static_cast<double>(res.dof)) : 0.0;
  std::vector<int> undetermined;
  for (int i : p.used) {
    ParameterEstimate e;
    e.name = param_names()[i];
    e.value = x[i];
    e.initial = starts[best][i];
    e.lower = s.params[i].lower;
    e.upper = s.params[i].upper;
    e.fixed = s.params[i].fixed;
    const auto it = std::find(p.free.begin(), p.free.end(), i);
    if (!e.fixed) {
      const double span = e.upper - e.lower;
      e.at_bound = x[i] - e.lower <= 1e-9 * span || e.upper - x[i] <= 1e-9 * span;
      const auto j = static_cast<std::size_t>(it - p.free.begin());
      const double var =
          cov.covariance(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)) * cov_scale;
      if (cov.determined[j] && res.dof > 0 && std::isfinite(var) && var >= 0.0) {
        e.std_error = std::sqrt(var);
        e.ci95 = std::array<double, 2>{x[i] - tq * *e.std_error, x[i] + tq * *e.std_error};
      } else if (!cov.determined[j]) {
        undetermined.push_back(i);
      }
    }
    res.parameters.push_back(e);
  }

  // Correlation among parameters with a standard error.
  std::vector<std::size_t> cj;
  for (std::size_t j = 0; j < p.free.size(); ++j)
    if (cov.determined[j] && res.dof > 0) cj.push_back(j);
  for (std::size_t a : cj) res.correlation_names.push_back(param_names()[p.free[a]]);
  for (std::size_t a : cj) {
    std::vector<double> row;
    for (std::size_t b : cj) {
      const double caa = cov.covariance(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(a));
      const double cbb = cov.covariance(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(b));
      const double cab = cov.covariance(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
      row.push_back(caa > 0 && cbb > 0 ? cab / std::sqrt(caa * cbb) : (a == b ? 1.0 : 0.0));
    }
    res.correlation.push_back(row);
  }

  // Per-channel fit quality in the channel's own units, and predictions for plots.
  const ModelEvaluator<double> model(s.model, s.law, x.data(), pass_table(lp, x, false));
  res.eps.resize(data.rows());
  for (auto& f : res.fitted) f.assign(data.rows(), 0.0);
  for_each_chunk(chunk_count(data.rows()), lp.threads, [&](std::size_t chunk) {
    const std::size_t end = std::min(data.rows(), (chunk + 1) * kChunkRows);
    for (std::size_t i = chunk * kChunkRows; i < end; ++i) {
      const model::Kinematics kin{data.v_x[i], data.v_y[i], data.omega[i], data.N[i], data.R[i]};
      res.eps[i] = model::slip_geometry(kin).eps;
      const auto pr = model(kin);
      const double pred[kChannelCount] = {pr.T_x, pr.T_y, pr.M_z, pr.M_roll};
      for (int c = 0; c < kChannelCount; ++c) res.fitted[c][i] = pred[c];
    }
  });
  // Two passes, sums taken relative to the channel's largest magnitude: loads near the top of
  // the double range must not overflow the sums of squares, nor a large mean cancel R^2.
  for (auto& cs : res.channel_summaries) {
    const int c = static_cast<int>(cs.channel);
    std::size_t cnt = 0;
    double scale = 0.0, mean = 0.0;
    for (std::size_t i = 0; i < data.rows(); ++i) {
      if (!data.present[c][i]) continue;
      scale = std::max({scale, std::fabs(data.value[c][i]), std::fabs(res.fitted[c][i])});
      ++cnt;
    }
    if (cnt == 0) continue;
    if (scale == 0.0) scale = 1.0;
    for (std::size_t i = 0; i < data.rows(); ++i)
      if (data.present[c][i]) mean += data.value[c][i] / scale;
    mean /= static_cast<double>(cnt);
    double ss_res = 0.0, ss_tot = 0.0;
    for (std::size_t i = 0; i < data.rows(); ++i) {
      if (!data.present[c][i]) continue;
      const double d = res.fitted[c][i] / scale - data.value[c][i] / scale;
      const double t = data.value[c][i] / scale - mean;
      ss_res += d * d;
      ss_tot += t * t;
    }
    cs.rmse = scale * std::sqrt(ss_res / static_cast<double>(cnt));
    if (ss_tot > 0.0) cs.r2 = 1.0 - ss_res / ss_tot;
  }

  // Warnings, in words.
  if (!res.solver.converged)
    res.warnings.push_back("the local solver did not converge (" + res.solver.termination +
                           " after " + std::to_string(res.solver.iterations) +
                           " iterations): the estimates may not be at the optimum");
  std::string growing, growth_values;
  for (const auto& cs : res.channel_summaries) {
    const int c = static_cast<int>(cs.channel);
    // Exact fits (noise-free data) leave rounding residuals, which do grow with the values.
    if (data.has_sigma(cs.channel) || cs.rows < 20 || !(cs.rmse > 1e-9 * cs.scale)) continue;
    std::vector<double> fitted, measured;
    // A rank correlation sorts: on large data every k-th measured row (at most ~50,000) tells
    // as much about the trend.
    const std::size_t stride = cs.rows / kGrowthSampleRows + 1;
    std::size_t seen = 0;
    for (std::size_t i = 0; i < data.rows(); ++i)
      if (data.present[c][i] && seen++ % stride == 0) {
        fitted.push_back(res.fitted[c][i]);
        measured.push_back(data.value[c][i]);
      }
    const double growth = residual_growth(fitted, measured);
    if (growth <= kResidualGrowthWarning) continue;
    growing += (growing.empty() ? "" : ", ") + std::string(channel_name(cs.channel));
    growth_values += (growth_values.empty() ? "" : ", ") + fmt_g(growth);
  }
  if (!growing.empty())
    res.warnings.push_back(
        "the residuals of " + growing + " grow with the measured magnitude (rank correlation " +
        growth_values +
        "): noise proportional to the signal, or a shape the model misses. Without sigma_<channel> "
        "columns every row of a channel is weighted alike and the standard errors assume equal "
        "noise on every row, so they are likely too small; give per-row sigma columns");
  if (!undetermined.empty()) {
    std::string w = "not determined by the data: " + join_names(undetermined) +
                    " (the Jacobian is rank deficient along a combination of them); no standard "
                    "error is reported for them";
    const bool has_ty =
        std::find(p.channels.begin(), p.channels.end(), Channel::T_y) != p.channels.end();
    if (!has_ty)
      w += ". No fitted channel is T_y, the only one that carries b, b_tilde and p0, and h enters "
           "the rest only through M_roll and tilt terms";
    res.warnings.push_back(w);
  }
  for (std::size_t a = 0; a < cj.size(); ++a)
    for (std::size_t b = a + 1; b < cj.size(); ++b) {
      const double c = res.correlation[a][b];
      if (std::fabs(c) <= 0.99) continue;
      const std::string na = res.correlation_names[a], nb = res.correlation_names[b];
      std::string w = na + " and " + nb + " are strongly correlated (r = " + fmt_g(c) +
                      "): the data determine mainly a combination of them";
      const std::set<std::string> pair{na, nb};
      if (pair == std::set<std::string>{"h", "kappa"})
        w +=
            "; T_y carries them only as h*kappa, M_roll (h alone) or M_z with a known pressure law "
            "separates them";
      res.warnings.push_back(w);
    }
  for (const auto& e : res.parameters)
    if (e.at_bound)
      res.warnings.push_back(e.name + " = " + fmt_g(e.value) + " is at its " +
                             (e.value - e.lower <= e.upper - e.value ? "lower" : "upper") +
                             " bound; its standard error is not meaningful");
  // Data ranges that inform the approximants' slope coefficients.
  std::size_t inner = 0, outer = 0;
  for (double e : res.eps) {
    if (e < 1.0) ++inner;
    if (e > 1.0) ++outer;
  }
  auto is_free = [&](int i) { return std::find(p.free.begin(), p.free.end(), i) != p.free.end(); };
  if (s.model != ModelKind::Exact) {
    if (inner == 0 && is_free(kA))
      res.warnings.push_back(
          "a is poorly determined: no row has eps = v/(|omega| R) < 1, where "
          "the small-slip slope a acts");
    if (outer == 0 && (is_free(kM) || is_free(kB) || is_free(kBTilde)))
      res.warnings.push_back(
          "m and b are poorly determined: no row has eps > 1, where the "
          "small-spin slopes act");
    const auto law_c = model::coefficients(model::law_moments(s.law), x[kKappa]);
    const std::pair<int, double> implied[] = {
        {kA, law_c.a},
        {kM, law_c.m},
        {s.model == ModelKind::Seed ? kB : kBTilde,
         s.model == ModelKind::Seed ? law_c.b : law_c.b_tilde}};
    for (const auto& [i, v] : implied) {
      if (!is_free(i) || !(std::fabs(x[i] - v) > 0.05 * v)) continue;
      if (std::find(undetermined.begin(), undetermined.end(), i) != undetermined.end()) continue;
      res.warnings.push_back(
          std::string(param_names()[i]) + " = " + fmt_g(x[i]) + " differs from the value " +
          fmt_g(v) + " that the " + s.law_label +
          " pressure implies: the closed forms are approximations (errors of tens of percent "
          "near eps = 1, physics.md §3), so fitted coefficients need not equal the matched ones");
    }
  }
  const auto t_end = std::chrono::steady_clock::now();
  using seconds = std::chrono::duration<double>;
  res.solver.time_s = seconds(t_end - t0).count();
  res.solver.global_time_s = seconds(t_global - t0).count();
  res.solver.local_time_s = seconds(t_local - t_global).count();
  res.solver.statistics_time_s = seconds(t_end - t_local).count();
  return res;
}

}  // namespace frictionid
