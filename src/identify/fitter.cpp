// Ceres and NLopt adapters. The only translation unit that includes Ceres.
#include "identify/fitter.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <thread>

#include "identify/global_search.hpp"
#include "identify/residual_diagnostics.hpp"
#include "identify/residuals.hpp"
#include "identify/statistics.hpp"
#include "model/coefficients.hpp"

namespace frictionid {
namespace {

using Params = std::array<double, kParamCount>;
constexpr std::size_t kBlockRows = 1024;

// One residual block. Its parameter block holds only the free parameters (Jets as narrow as
// the fit needs); the fixed and unused ones come from `base`.
struct BlockCost {
  ResidualRows rows;
  ModelKind kind;
  const model::PressureLaw<double>* law;
  LossKind loss;
  double loss_scale;
  const std::vector<int>* free;
  Params base;
  int threads = 1;

  // Rows are split into contiguous slices, one per thread, each writing its own residuals:
  // the arithmetic is the same whatever the thread count, so results are bit-identical.
  // (Ceres' own threads sum partial costs in scheduling order, so they stay at one.)
  template <typename T>
  bool operator()(const T* z, T* r) const {
    std::array<T, kParamCount> full;
    for (int i = 0; i < kParamCount; ++i) full[i] = T(base[i]);
    for (std::size_t j = 0; j < free->size(); ++j) full[(*free)[j]] = z[j];
    const std::size_t n = rows.end - rows.begin;
    const std::size_t parts =
        std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), n / 128 + 1);
    if (parts <= 1) return evaluate_residuals(rows, kind, *law, loss, loss_scale, full.data(), r);
    std::vector<std::thread> pool;
    std::vector<char> ok(parts, 0);
    const std::size_t nc = rows.channels.size();
    for (std::size_t t = 0; t < parts; ++t) {
      ResidualRows slice = rows;
      slice.begin = rows.begin + n * t / parts;
      slice.end = rows.begin + n * (t + 1) / parts;
      T* out = r + (slice.begin - rows.begin) * nc;
      auto work = [this, slice, out, &full, &ok, t] {
        ok[t] = evaluate_residuals(slice, kind, *law, loss, loss_scale, full.data(), out);
      };
      if (t + 1 == parts)
        work();
      else
        pool.emplace_back(work);
    }
    for (auto& th : pool) th.join();
    return std::all_of(ok.begin(), ok.end(), [](char v) { return v != 0; });
  }
};

// Forward-mode autodiff over one block with Ceres' Jets: seeds the N free parameters, evaluates
// the templated residuals once, scatters values and derivatives. Ceres' generic
// AutoDiffCostFunction does the same but allocates and NaN-fills per call, which cost ~3x the
// model evaluation itself on tall blocks.
template <int N>
class BlockJetCost final : public ceres::CostFunction {
 public:
  explicit BlockJetCost(const BlockCost& c) : cost_(c) {
    set_num_residuals(static_cast<int>(c.rows.residual_count()));
    mutable_parameter_block_sizes()->push_back(N);
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    if (jacobians == nullptr || jacobians[0] == nullptr) return cost_(parameters[0], residuals);
    using Jet = ceres::Jet<double, N>;
    std::array<Jet, N> z;
    for (int j = 0; j < N; ++j) z[j] = Jet(parameters[0][j], j);
    thread_local std::vector<Jet> out;
    const std::size_t n = cost_.rows.residual_count();
    out.resize(n);
    if (!cost_(z.data(), out.data())) return false;
    double* jac = jacobians[0];
    for (std::size_t i = 0; i < n; ++i) {
      residuals[i] = out[i].a;
      for (int j = 0; j < N; ++j) jac[i * N + static_cast<std::size_t>(j)] = out[i].v[j];
    }
    return true;
  }

 private:
  BlockCost cost_;
};

template <int N>
ceres::CostFunction* make_cost_n(const BlockCost& c) {
  return new BlockJetCost<N>(c);
}

// Jet width is a compile-time constant: dispatch on the number of free parameters.
std::unique_ptr<ceres::CostFunction> make_cost_function(const BlockCost& c) {
  using Maker = ceres::CostFunction* (*)(const BlockCost&);
  static constexpr Maker makers[kParamCount] = {make_cost_n<1>, make_cost_n<2>, make_cost_n<3>,
                                                make_cost_n<4>, make_cost_n<5>, make_cost_n<6>,
                                                make_cost_n<7>, make_cost_n<8>, make_cost_n<9>};
  const std::size_t k = c.free->size();
  if (k < 1 || k > kParamCount) throw std::logic_error("free parameter count out of range");
  return std::unique_ptr<ceres::CostFunction>(makers[k - 1](c));
}

struct Problem {
  const Dataset* data;
  const FitSettings* s;
  std::vector<Channel> channels;
  std::array<double, kChannelCount> scale{};
  std::vector<ResidualRows> blocks;
  std::vector<int> used;  // parameters the model reads
  std::vector<int> free;  // used and not fixed
};

std::vector<ResidualRows> make_blocks(const Problem& p, const std::vector<std::size_t>& rows_begin,
                                      std::size_t rows_end) {
  std::vector<ResidualRows> out;
  for (std::size_t b : rows_begin) {
    ResidualRows r;
    r.data = p.data;
    r.channels = p.channels;
    r.scale = p.scale;
    r.begin = b;
    r.end = std::min(b + kBlockRows, rows_end);
    out.push_back(r);
  }
  return out;
}

// Sum of squared (robustified) residuals over the given blocks: twice Ceres' cost.
double sum_of_squares(const Problem& p, const std::vector<ResidualRows>& blocks, const Params& x) {
  double total = 0.0;
  std::vector<double> r;
  for (const auto& b : blocks) {
    r.resize(b.residual_count());
    if (!evaluate_residuals(b, p.s->model, p.s->law, p.s->loss, p.s->loss_scale, x.data(),
                            r.data()))
      return std::numeric_limits<double>::infinity();
    for (double v : r) total += v * v;
  }
  return total;
}

class Callback : public ceres::IterationCallback {
 public:
  Callback(const std::atomic<bool>* cancel, bool progress, int start, int starts)
      : cancel_(cancel), progress_(progress), start_(start), starts_(starts) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& it) override {
    if (progress_)
      std::fprintf(stderr, "\rfrictionid: local fit %d/%d, iteration %d, cost %.6e   ", start_,
                   starts_, it.iteration, it.cost);
    if (cancel_ && cancel_->load()) return ceres::SOLVER_ABORT;
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::atomic<bool>* cancel_;
  bool progress_;
  int start_, starts_;
};

struct LocalOutcome {
  Params x{};
  double cost = std::numeric_limits<double>::infinity();
  ceres::Solver::Summary summary;
};

LocalOutcome local_fit(const Problem& p, const Params& start, const std::atomic<bool>* cancel,
                       int start_index, int starts) {
  LocalOutcome out;
  out.x = start;
  ceres::Problem::Options po;
  ceres::Problem problem(po);
  if (p.free.empty()) {
    out.cost = 0.5 * sum_of_squares(p, p.blocks, out.x);
    out.summary.termination_type = ceres::CONVERGENCE;
    return out;
  }
  std::vector<double> z;
  for (int i : p.free) z.push_back(out.x[i]);
  for (const auto& b : p.blocks)
    problem.AddResidualBlock(
        make_cost_function(BlockCost{b, p.s->model, &p.s->law, p.s->loss, p.s->loss_scale, &p.free,
                                     out.x, p.s->threads})
            .release(),
        nullptr, z.data());
  for (std::size_t j = 0; j < p.free.size(); ++j) {
    problem.SetParameterLowerBound(z.data(), static_cast<int>(j), p.s->params[p.free[j]].lower);
    problem.SetParameterUpperBound(z.data(), static_cast<int>(j), p.s->params[p.free[j]].upper);
  }
  ceres::Solver::Options o;
  // A tall, thin Jacobian (rows x <= 9): normal equations cost O(m k^2) and are well enough
  // conditioned for Levenberg-Marquardt's damped system.
  o.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  // Ceres' projected line search under bounds costs one more Jacobian per iteration; bounds
  // stay enforced by projecting the trust-region step, so skip it.
  o.max_num_line_search_step_size_iterations = 0;
  o.max_num_iterations = p.s->max_iterations;
  o.function_tolerance = p.s->function_tolerance;
  o.gradient_tolerance = p.s->gradient_tolerance;
  o.parameter_tolerance = p.s->parameter_tolerance;
  o.num_threads = 1;  // see BlockCost: our own row slices keep results thread-count invariant
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  Callback cb(cancel, p.s->progress, start_index, starts);
  o.callbacks.push_back(&cb);
  ceres::Solve(o, &problem, &out.summary);
  for (std::size_t j = 0; j < p.free.size(); ++j) out.x[p.free[j]] = z[j];
  // Diagnostics for performance work: Ceres' own time breakdown of every local fit.
  if (std::getenv("FRICTIONID_CERES_REPORT"))
    std::fprintf(stderr, "%s\n", out.summary.FullReport().c_str());
  out.cost = out.summary.final_cost;
  if (!std::isfinite(out.cost)) out.cost = std::numeric_limits<double>::infinity();
  return out;
}

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
  std::vector<std::size_t> begins;
  for (std::size_t b = 0; b < data.rows(); b += kBlockRows) begins.push_back(b);
  p.blocks = make_blocks(p, begins, data.rows());

  Params initial{};
  for (int i = 0; i < kParamCount; ++i)
    initial[i] = std::clamp(s.params[i].initial, s.params[i].lower, s.params[i].upper);
  for (int i = 0; i < kParamCount; ++i)
    if (s.params[i].fixed) initial[i] = s.params[i].initial;

  // Global stage on a deterministic subsample (every k-th row).
  std::vector<Params> starts;
  res.global.seed = s.seed;
  if (s.global && !p.free.empty()) {
    Dataset sub;
    const std::size_t stride =
        std::max<std::size_t>(1, (data.rows() + s.global_subsample - 1) / s.global_subsample);
    Problem ps = p;
    std::vector<std::size_t> sub_begins;
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
    ps.data = &sub;
    for (std::size_t b = 0; b < sub.rows(); b += kBlockRows) sub_begins.push_back(b);
    ps.blocks = make_blocks(ps, sub_begins, sub.rows());
    res.global.subsample_rows = sub.rows();

    GlobalSearchProblem gp;
    for (int i : p.free) {
      gp.lower.push_back(to_search(s.params[i], s.params[i].lower));
      gp.upper.push_back(to_search(s.params[i], s.params[i].upper));
    }
    long evaluations = 0;
    gp.objective = [&](const double* z) {
      Params x = initial;
      for (std::size_t j = 0; j < p.free.size(); ++j)
        x[p.free[j]] = std::clamp(from_search(s.params[p.free[j]], z[j]), s.params[p.free[j]].lower,
                                  s.params[p.free[j]].upper);
      ++evaluations;
      if (s.progress && evaluations % 250 == 0)
        std::fprintf(stderr, "\rfrictionid: global search %ld/%ld evaluations   ", evaluations,
                     s.global_evaluations);
      return sum_of_squares(ps, ps.blocks, x);
    };
    const GlobalSearchOutcome g = global_search(gp, s.global_algorithm, s.global_evaluations,
                                                s.seed, std::max(1, s.starts), cancel);
    res.global.algorithm = global_algorithm_label(s.global_algorithm);
    res.global.evaluations = g.evaluations;
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

  // Local stage from every start; the best final cost wins (ties: the earlier start).
  std::vector<LocalOutcome> locals;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    locals.push_back(
        local_fit(p, starts[k], cancel, static_cast<int>(k + 1), static_cast<int>(starts.size())));
    if (cancel && cancel->load()) throw FitError("interrupted");
  }
  if (s.progress) std::fprintf(stderr, "\r%80s\r", "");
  std::size_t best = 0;
  for (std::size_t k = 1; k < locals.size(); ++k)
    if (locals[k].cost < locals[best].cost) best = k;
  const LocalOutcome& L = locals[best];
  if (!std::isfinite(L.cost))
    throw FitError("every local fit failed: the model produced non-finite values at every start");
  res.global.starts = static_cast<int>(locals.size());
  for (const auto& l : locals)
    if (std::fabs(l.cost - L.cost) <= 1e-8 * std::max(L.cost, 1e-300) + 1e-300)
      ++res.global.reached_best;
  res.solver.iterations = static_cast<int>(L.summary.iterations.size()) - 1;
  res.solver.termination = ceres::TerminationTypeToString(L.summary.termination_type);
  res.solver.converged = L.summary.termination_type == ceres::CONVERGENCE ||
                         L.summary.termination_type == ceres::USER_SUCCESS;
  const Params& x = L.x;
  const auto t_local = std::chrono::steady_clock::now();

  // Jacobian and residuals at the optimum (whitened, robustified), free columns only.
  std::size_t nres = 0;
  for (const auto& b : p.blocks) nres += b.residual_count();
  Eigen::MatrixXd J(static_cast<Eigen::Index>(nres), static_cast<Eigen::Index>(p.free.size()));
  Eigen::VectorXd r(static_cast<Eigen::Index>(nres));
  {
    std::size_t off = 0;
    std::vector<double> jac, rr;
    for (const auto& b : p.blocks) {
      const std::size_t n = b.residual_count();
      const std::size_t k = p.free.size();
      jac.assign(n * std::max<std::size_t>(k, 1), 0.0);
      rr.assign(n, 0.0);
      std::vector<double> z;
      for (int i : p.free) z.push_back(x[i]);
      const BlockCost cost{b, s.model, &s.law, s.loss, s.loss_scale, &p.free, x, s.threads};
      if (k == 0) {
        if (!evaluate_residuals(b, s.model, s.law, s.loss, s.loss_scale, x.data(), rr.data()))
          throw FitError("the model is not finite at the fitted parameters");
      } else {
        const auto cf = make_cost_function(cost);
        const double* params[] = {z.data()};
        double* jacs[] = {jac.data()};
        if (!cf->Evaluate(params, rr.data(), jacs))
          throw FitError("the model is not finite at the fitted parameters");
      }
      for (std::size_t i = 0; i < n; ++i) {
        r[static_cast<Eigen::Index>(off + i)] = rr[i];
        for (std::size_t j = 0; j < p.free.size(); ++j)
          J(static_cast<Eigen::Index>(off + i), static_cast<Eigen::Index>(j)) =
              jac[i * p.free.size() + j];
      }
      off += n;
    }
  }

  // Observations: measured values of fitted channels (unmeasured cells hold residual 0).
  std::size_t nobs = 0;
  for (const auto& cs : res.channel_summaries) nobs += cs.rows;
  const std::size_t k = p.free.size();
  res.residuals = nobs;
  res.dof = nobs > k ? nobs - k : 0;
  // chi2 without the loss, cost with it.
  {
    ResidualRows all;
    all.data = &data;
    all.channels = p.channels;
    all.scale = p.scale;
    all.begin = 0;
    all.end = data.rows();
    std::vector<double> plain(all.residual_count());
    evaluate_residuals(all, s.model, s.law, LossKind::None, 1.0, x.data(), plain.data());
    res.chi2 = 0.0;
    for (double v : plain) res.chi2 += v * v;
  }
  res.cost = 0.5 * r.squaredNorm();
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

  const JacobianCovariance cov = covariance_from_jacobian(J);
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
  const ModelEvaluator<double> model(s.model, s.law, x.data());
  res.eps.resize(data.rows());
  for (auto& f : res.fitted) f.assign(data.rows(), 0.0);
  for (std::size_t i = 0; i < data.rows(); ++i) {
    const model::Kinematics kin{data.v_x[i], data.v_y[i], data.omega[i], data.N[i], data.R[i]};
    res.eps[i] = model::slip_geometry(kin).eps;
    const auto pr = model(kin);
    const double pred[kChannelCount] = {pr.T_x, pr.T_y, pr.M_z, pr.M_roll};
    for (int c = 0; c < kChannelCount; ++c) res.fitted[c][i] = pred[c];
  }
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
    for (std::size_t i = 0; i < data.rows(); ++i)
      if (data.present[c][i]) {
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
