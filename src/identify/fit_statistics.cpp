#include "identify/fit_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <frictionid/fit_error.hpp>

#include "identify/local_stage.hpp"
#include "identify/row_chunks.hpp"
#include "identify/statistics.hpp"

namespace frictionid {
namespace {

Eigen::Index idx(std::size_t i) {
  return static_cast<Eigen::Index>(i);
}

void add_parameter_estimates(const LocalProblem& lp, const ParamVector& x, const ParamVector& start,
                             const JacobianCovariance& cov, double cov_scale,
                             const std::vector<double>& interval_dof, FitResult& res,
                             std::vector<int>& undetermined) {
  const FitSettings& s = *lp.settings;
  const double tq = res.dof > 0 ? student_t_quantile(0.975, static_cast<double>(res.dof)) : 0.0;
  for (int i : lp.used) {
    std::optional<double> var;
    double tq_i = tq;
    if (!s.params[i].fixed) {
      const auto j =
          static_cast<std::size_t>(std::find(lp.free.begin(), lp.free.end(), i) - lp.free.begin());
      if (cov.determined[j] && res.dof > 0) var = cov.covariance(idx(j), idx(j)) * cov_scale;
      if (!cov.determined[j]) undetermined.push_back(i);
      if (res.dof > 0 && j < interval_dof.size() && interval_dof[j] < static_cast<double>(res.dof))
        tq_i = student_t_quantile(0.975, interval_dof[j]);
    }
    ParameterEstimate e = parameter_estimate(s, i, x[i], var, tq_i);
    e.initial = start[i];
    res.parameters.push_back(e);
  }
}

// The degrees of freedom of each free parameter's variance when channels' noise was estimated
// (§8.10): var theta_j = sum_c a_jc with a_jc = (B J_c^T J_c B)_jj the share of channel c, whose
// sigma rests on nu_c = n_c - k_c - p_c degrees of freedom (k_c = tr(B J_c^T J_c), its share of
// the k parameters; p_c its noise parameters). Satterthwaite: nu_j = (sum_c a_jc)^2 /
// sum_c a_jc^2/nu_c over the estimated channels (sigma columns are known). Empty when no channel's
// noise was estimated or a robust loss couples the channels of a row.
std::vector<double> satterthwaite_dof(const LocalProblem& lp, const ParamVector& x,
                                      const JacobianCovariance& cov, const FitResult& res) {
  const std::size_t k = lp.free.size();
  if (k == 0 || res.dof == 0 || lp.settings->loss != LossKind::None) return {};
  if (std::none_of(res.channel_summaries.begin(), res.channel_summaries.end(),
                   [](const ChannelSummary& cs) { return cs.noise.has_value(); }))
    return {};
  // nu_j >= min_c nu_c, and nu_c >= n_c - k - 2 (its share of the parameters is at most k):
  // when every estimated channel has more than kLargeDof rows beyond that, t(0.975, nu_j)
  // exceeds t(0.975, dof) by less than 0.013 % and the per-channel passes are not worth their
  // cost (they would double a large fit's statistics).
  constexpr double kLargeDof = 1e4;
  if (std::all_of(res.channel_summaries.begin(), res.channel_summaries.end(),
                  [&](const ChannelSummary& cs) {
                    return !cs.noise ||
                           static_cast<double>(cs.rows) - static_cast<double>(k) - 2.0 > kLargeDof;
                  }))
    return {};
  const Eigen::MatrixXd& b = cov.covariance;
  Eigen::VectorXd total = Eigen::VectorXd::Zero(idx(k)), spread = Eigen::VectorXd::Zero(idx(k));
  for (const auto& cs : res.channel_summaries) {
    if (std::find(lp.rows.channels.begin(), lp.rows.channels.end(), cs.channel) ==
        lp.rows.channels.end())
      continue;
    LocalProblem one = lp;
    one.rows.channels = {cs.channel};
    const auto jf = jacobian_factor(one, x);
    if (!jf) return {};
    const Eigen::MatrixXd g = jf->r.transpose() * jf->r;
    const Eigen::MatrixXd bgb = b * g * b;
    total += bgb.diagonal();
    if (!cs.noise) continue;
    const double p =
        cs.noise->kind == NoiseModelKind::Constant || cs.noise->kind == NoiseModelKind::Relative
            ? 1.0
            : 2.0;
    const double nu = std::max(1.0, static_cast<double>(cs.rows) - (b * g).trace() - p);
    spread += bgb.diagonal().cwiseAbs2() / nu;
  }
  std::vector<double> out(k, static_cast<double>(res.dof));
  for (std::size_t j = 0; j < k; ++j)
    if (spread(idx(j)) > 0.0 && total(idx(j)) > 0.0)
      out[j] = std::min(out[j], total(idx(j)) * total(idx(j)) / spread(idx(j)));
  return out;
}

// Correlation among the parameters with a standard error.
void add_correlation(const LocalProblem& lp, const JacobianCovariance& cov, FitResult& res) {
  std::vector<std::size_t> cj;
  for (std::size_t j = 0; j < lp.free.size(); ++j)
    if (cov.determined[j] && res.dof > 0) cj.push_back(j);
  for (std::size_t a : cj) res.correlation_names.push_back(param_names()[lp.free[a]]);
  for (std::size_t a : cj) {
    std::vector<double> row;
    for (std::size_t b : cj) {
      const double caa = cov.covariance(idx(a), idx(a));
      const double cbb = cov.covariance(idx(b), idx(b));
      const double cab = cov.covariance(idx(a), idx(b));
      row.push_back(caa > 0 && cbb > 0 ? cab / std::sqrt(caa * cbb) : (a == b ? 1.0 : 0.0));
    }
    res.correlation.push_back(row);
  }
}

// HC3 standard errors for the determined free parameters.
void add_sandwich_errors(const LocalProblem& lp, const ParamVector& x,
                         const JacobianCovariance& cov, double cov_scale, FitResult& res,
                         FitStatisticsDetail* detail) {
  if (lp.free.empty() || res.dof == 0) return;
  Eigen::MatrixXd spread;
  const auto meat = sandwich_meat(lp, x, cov.covariance, &spread);
  if (!meat) return;
  if (detail)
    for (std::size_t j = 0; j < lp.free.size(); ++j) {
      const double sum_q = spread(idx(j), 0), sum_q2 = spread(idx(j), 1);
      if (!cov.determined[j] || !(sum_q > 0.0 && sum_q2 > 0.0)) continue;
      detail->sandwich_expected[j] = sum_q * cov_scale;
      detail->sandwich_dof[j] = sum_q * sum_q / sum_q2;
    }
  const Eigen::MatrixXd sandwich = cov.covariance * *meat * cov.covariance;
  for (std::size_t j = 0; j < lp.free.size(); ++j) {
    if (!cov.determined[j]) continue;
    const double v = sandwich(idx(j), idx(j));
    if (!(std::isfinite(v) && v >= 0.0)) continue;
    const double tq = student_t_quantile(0.975, static_cast<double>(res.dof));
    for (auto& e : res.parameters)
      if (e.name == param_names()[lp.free[j]]) {
        e.std_error_sandwich = std::sqrt(v);
        e.ci95_sandwich = std::array<double, 2>{e.value - tq * *e.std_error_sandwich,
                                                e.value + tq * *e.std_error_sandwich};
      }
  }
}

// eps and the fitted predictions of every row, for plots and the per-channel figures.
void add_predictions(const LocalProblem& lp, const ParamVector& x, FitResult& res) {
  const FitSettings& s = *lp.settings;
  const Dataset& data = *lp.rows.data;
  const ModelEvaluator<double> model(s.model, s.law, x.data(), pass_table(lp, x, false), nullptr,
                                     s.contact);
  res.eps.resize(data.rows());
  for (auto& f : res.fitted) f.assign(data.rows(), 0.0);
  for_each_chunk(chunk_count(data.rows()), lp.threads, [&](std::size_t chunk) {
    const std::size_t end = std::min(data.rows(), (chunk + 1) * kChunkRows);
    for (std::size_t i = chunk * kChunkRows; i < end; ++i) {
      const model::Kinematics kin{data.v_x[i], data.v_y[i], data.omega[i],
                                  data.N[i],   data.R[i],   data.tilt_sign_at(i)};
      res.eps[i] = model::slip_geometry(kin).eps;
      const auto pr = model(kin);
      const double pred[kChannelCount] = {pr.T_x, pr.T_y, pr.M_z, pr.M_roll, pr.M_tilt};
      for (int c = 0; c < kChannelCount; ++c) res.fitted[c][i] = pred[c];
    }
  });
}

// RMSE and R² in the channel's own units. Two passes, sums taken relative to the channel's
// largest magnitude: loads near the top of the double range must not overflow the sums of
// squares, nor a large mean cancel R².
void add_channel_fit_quality(const Dataset& data, FitResult& res) {
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
}

}  // namespace

double plain_chi2(const LocalProblem& lp, const ParamVector& x) {
  FitSettings plain_settings = *lp.settings;
  plain_settings.loss = LossKind::None;
  LocalProblem plain = lp;
  plain.settings = &plain_settings;
  return 2.0 * problem_cost(plain, x);
}

ParameterEstimate parameter_estimate(const FitSettings& s, int i, double value,
                                     std::optional<double> variance, double tq) {
  ParameterEstimate e;
  e.name = param_names()[i];
  e.value = value;
  e.initial = value;
  e.lower = s.params[i].lower;
  e.upper = s.params[i].upper;
  e.fixed = s.params[i].fixed;
  if (!e.fixed) {
    e.at_bound = at_bound(value, e.lower, e.upper);
    if (variance && std::isfinite(*variance) && *variance >= 0.0) {
      e.std_error = std::sqrt(*variance);
      e.ci95 = std::array<double, 2>{value - tq * *e.std_error, value + tq * *e.std_error};
    }
  }
  return e;
}

bool at_bound(double x, double lower, double upper) {
  return x - lower <= 1e-9 * (1.0 + std::fabs(lower)) ||
         upper - x <= 1e-9 * (1.0 + std::fabs(upper));
}

InformationCriteria information_criteria(double chi2, std::size_t n, std::size_t k,
                                         bool absolute_sigma, const NoiseTerms& noise) {
  const double nn = static_cast<double>(std::max<std::size_t>(n, 1));
  const double kk = static_cast<double>(k) + noise.parameters;
  const double m2ll =
      (absolute_sigma ? chi2 : nn * std::log(std::max(chi2, 1e-300) / nn)) + noise.log_det;
  return {m2ll + 2 * kk, m2ll + kk * std::log(nn)};
}

std::vector<int> add_fit_statistics(const LocalProblem& lp, const ParamVector& x,
                                    const ParamVector& start, const NoiseTerms& noise,
                                    FitResult& res, FitStatisticsDetail* detail) {
  const Dataset& data = *lp.rows.data;
  // The whitened Jacobian at the optimum (free columns), as its triangular factor.
  const std::size_t k = lp.free.size();
  Eigen::MatrixXd jacobian_r(idx(k), idx(k));
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
  const bool absolute_sigma = std::all_of(res.channels.begin(), res.channels.end(),
                                          [&](Channel c) { return lp.rows.has_sigma(c); });

  // Observations: measured values of fitted channels (unmeasured cells hold residual 0).
  std::size_t nobs = 0;
  for (const auto& cs : res.channel_summaries) nobs += cs.rows;
  res.residuals = nobs;
  res.dof = nobs > k ? nobs - k : 0;
  res.chi2 = plain_chi2(lp, x);
  // With no degree of freedom left there is no reduced chi² (it is not 0): NaN, null in reports.
  res.reduced_chi2 = res.dof > 0 ? res.chi2 / static_cast<double>(res.dof)
                                 : std::numeric_limits<double>::quiet_NaN();
  const InformationCriteria ic = information_criteria(res.chi2, nobs, k, absolute_sigma, noise);
  res.aic = ic.aic;
  res.bic = ic.bic;
  res.covariance_scaled_by_reduced_chi2 = !absolute_sigma;

  const JacobianCovariance cov = covariance_from_jacobian(jacobian_r);
  std::vector<int> undetermined;
  const double cov_scale = absolute_sigma ? 1.0 : res.reduced_chi2;
  const std::vector<double> interval_dof = satterthwaite_dof(lp, x, cov, res);
  add_parameter_estimates(lp, x, start, cov, cov_scale, interval_dof, res, undetermined);
  add_correlation(lp, cov, res);
  if (detail) {
    detail->covariance = cov.covariance * (res.dof > 0 ? cov_scale : 0.0);
    detail->determined = cov.determined;
    detail->sandwich_expected.assign(k, std::nullopt);
    detail->sandwich_dof.assign(k, std::nullopt);
    detail->interval_dof.assign(k, static_cast<double>(res.dof));
    for (std::size_t j = 0; j < interval_dof.size() && j < k; ++j)
      detail->interval_dof[j] = interval_dof[j];
  }
  add_sandwich_errors(lp, x, cov, cov_scale, res, detail);
  add_predictions(lp, x, res);
  add_channel_fit_quality(data, res);
  return undetermined;
}

}  // namespace frictionid
