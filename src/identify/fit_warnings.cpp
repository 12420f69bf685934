#include "identify/fit_warnings.hpp"
#include "identify/number_text.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>

#include <frictionid/model/coefficients.hpp>

#include "identify/noise_reweighting.hpp"
#include "identify/profile_intervals.hpp"
#include "identify/residual_diagnostics.hpp"
#include "identify/statistics.hpp"

namespace frictionid {
namespace {

// A rank correlation sorts: on large data every k-th measured row (at most ~50,000) tells as
// much about the trend.
constexpr std::size_t kGrowthSampleRows = 50000;

// The runs test needs this many rows of a channel, and warns below this z (one-sided: too few
// runs; a Gaussian gives 3e-5).
constexpr std::size_t kRunsTestRows = 20;
constexpr double kRunsTestZ = 4.0;

double rms_fitted(const FitResult& res, const Dataset& d, int c) {
  double scale = 0.0;
  for (std::size_t i = 0; i < d.rows(); ++i)
    if (d.present[c][i]) scale = std::max(scale, std::fabs(res.fitted[c][i]));
  if (scale == 0.0) return 0.0;
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < d.rows(); ++i)
    if (d.present[c][i]) {
      const double v = res.fitted[c][i] / scale;
      sum += v * v;
      ++n;
    }
  return n ? scale * std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

// The one-sided tail of 3 sigma of a normal: the coefficient-vs-law test's threshold.
constexpr double kLawTail = 0.0013498980316301;

// A coefficient correlated beyond this with another parameter lies in a curved cost valley,
// where the law warning confirms the linear test by the cost's profile.
constexpr double kCurvedValley = 0.95;

// A coefficient whose standard error exceeds this share of its value is poorly determined.
constexpr double kPoorRelativeError = 0.1;

std::string join_names(const std::vector<int>& idx) {
  std::string s;
  for (std::size_t i = 0; i < idx.size(); ++i) {
    if (i) s += i + 1 == idx.size() ? " and " : ", ";
    s += param_names()[idx[i]];
  }
  return s;
}

bool all_zero(const Dataset& data, Channel c) {
  const int ci = static_cast<int>(c);
  for (std::size_t i = 0; i < data.rows(); ++i)
    if (data.present[ci][i] && data.value[ci][i] != 0.0) return false;
  return true;
}

void warn_zero_and_growing_channels(const Dataset& data, FitResult& res) {
  std::string growing, growth_values;
  for (const auto& cs : res.channel_summaries) {
    const int c = static_cast<int>(cs.channel);
    if (all_zero(data, cs.channel)) {
      res.warnings.push_back("every measured value of " + std::string(channel_name(cs.channel)) +
                             " is zero: the channel only asks the model to predict zero there");
      continue;
    }
    // Sigma columns and a noise model that grows with the signal take care of it. Exact fits
    // (noise-free data) leave rounding residuals, which do grow with the values.
    if ((data.has_sigma(cs.channel) && !cs.noise) ||
        (cs.noise && cs.noise->kind != NoiseModelKind::Constant) || cs.rows < 20 ||
        !(cs.rmse > 1e-9 * cs.scale))
      continue;
    std::vector<double> fitted, measured;
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
    growth_values += (growth_values.empty() ? "" : ", ") + number_text(growth);
  }
  if (!growing.empty())
    res.warnings.push_back(
        "the residuals of " + growing + " grow with the measured magnitude (rank correlation " +
        growth_values +
        ") but their noise model is constant: the standard errors assume equal noise on every "
        "row and are likely wrong; " +
        (res.noise_model == "auto"
             ? std::string("auto chose the constant model by BIC, so ask for another: "
                           "--noise-model relative, affine or additive, or per-row sigma columns, "
                           "would weight the rows by their noise")
             : std::string("a relative, affine or additive noise model (or auto), or per-row "
                           "sigma columns, would weight the rows by their noise")));
}

// Rows whose whitened residual is beyond 6 sigma: a Gaussian gives one in 5e8, so they are
// outliers, and one of them can inflate its channel's noise estimate until the channel carries
// no weight. The worst is named.
void warn_outliers(const LocalProblem& lp, FitResult& res) {
  const Dataset& d = *lp.rows.data;
  for (Channel c : lp.rows.channels) {
    const int ci = static_cast<int>(c);
    std::size_t count = 0, worst = 0;
    double worst_r = 0.0;
    for (std::size_t i = 0; i < d.rows(); ++i) {
      const double w = lp.rows.inverse_sigma(c, i);
      if (w == 0.0) continue;
      const double r = std::fabs((res.fitted[ci][i] - d.value[ci][i]) * w);
      if (!(r > 6.0)) continue;
      ++count;
      if (r > worst_r) {
        worst_r = r;
        worst = i;
      }
    }
    if (count == 0) continue;
    const std::string where = worst < d.line.size() && d.line[worst] > 0
                                  ? "line " + std::to_string(d.line[worst])
                                  : "row " + std::to_string(worst + 1);
    const std::size_t rows =
        static_cast<std::size_t>(std::count(d.present[ci].begin(), d.present[ci].end(), true));
    // Outliers are few; a tenth of the rows beyond 6 sigma is the model missing the channel.
    if (count >= 5 && 10 * count >= rows) {
      res.warnings.push_back(
          std::to_string(count) + " of " + std::to_string(rows) + " rows of " + channel_name(c) +
          " (" + number_text(100.0 * static_cast<double>(count) / static_cast<double>(rows)) +
          " %) lie beyond 6 sigma of the fit, far more than outliers (a Gaussian gives one in "
          "5e8): the model misses this channel. Check its sign convention, its units and the "
          "columns' names, or compare models; a robust loss would hide the misfit, not fix it");
      continue;
    }
    res.warnings.push_back(
        std::to_string(count) + " row" + (count > 1 ? "s" : "") + " of " + channel_name(c) +
        " lie beyond 6 sigma of the fit; the worst, at " + where + " (" + channel_name(c) + " = " +
        number_text(d.value[ci][worst]) + ", " + number_text(worst_r) +
        " sigma), looks like an outlier: it inflates the channel's noise estimate and takes "
        "weight from the channel. Check that row, or use a robust loss (huber, cauchy, soft_l1)");
  }
}

void warn_undetermined_and_correlated(const LocalProblem& lp, const std::vector<int>& undetermined,
                                      FitResult& res) {
  if (!undetermined.empty()) {
    std::string w = "not determined by the data: " + join_names(undetermined) +
                    " (the Jacobian is rank deficient along a combination of them); no standard "
                    "error is reported for them";
    const bool has_ty = std::find(lp.rows.channels.begin(), lp.rows.channels.end(), Channel::T_y) !=
                        lp.rows.channels.end();
    if (!has_ty)
      w += ". No fitted channel is T_y, the only one that carries b, b_tilde and p0, and h enters "
           "the rest only through M_roll and tilt terms";
    res.warnings.push_back(w);
  }
  const std::size_t n = res.correlation_names.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const double c = res.correlation[a][b];
      if (std::fabs(c) <= kStrongCorrelation) continue;
      const std::string na = res.correlation_names[a], nb = res.correlation_names[b];
      std::string w = na + " and " + nb + " are strongly correlated (r = " + number_text(c) +
                      "): the data determine mainly a combination of them";
      if (std::set<std::string>{na, nb} == std::set<std::string>{"h", "kappa"})
        w +=
            "; T_y carries them only as h*kappa, M_roll (h alone) or M_z with a known pressure law "
            "separates them";
      // Their symmetric intervals can miss on one side; the profile ones were computed.
      if (res.intervals != IntervalMethod::Profile) {
        std::string profiles;
        for (const std::string& name : {na, nb}) {
          const ParameterEstimate* e = res.parameter(name);
          if (!e || !e->ci95_profile) continue;
          profiles += (profiles.empty() ? "" : ", ") + name + " [" +
                      number_text((*e->ci95_profile)[0]) + ", " +
                      number_text((*e->ci95_profile)[1]) + "]";
        }
        if (!profiles.empty() && res.intervals == IntervalMethod::Model)
          w += ". Their symmetric intervals may miss on one side, so the reports show their "
               "profile intervals (ci95_profile): " +
               profiles + "; use --intervals profile to have every parameter's";
        else if (!profiles.empty())
          w += ". Their symmetric " + res.interval_method +
               " intervals may miss on one side; the profile intervals (ci95_profile) are " +
               profiles + ": use --intervals profile to report them first";
      }
      res.warnings.push_back(w);
    }
}

// Whether the noise is one sigma pooled over the channels' fixed scales (noise_pooled). The
// standard errors then rest on scales that may weigh the channels wrongly (SD/s.e. up to 2.8
// with 8 rows and different noise per channel: experiments/README.md, "Identification study").
bool noise_pooled(const LocalProblem& lp, const FitResult& res) {
  return noise_pooled(*lp.settings, *lp.rows.data, res.channel_summaries, lp.free.size());
}

// Too few rows per channel for a noise model: the fit says that its standard errors rest on the
// channels' fixed scales.
void warn_pooled_noise(const LocalProblem& lp, FitResult& res) {
  if (res.dof == 0 || !noise_pooled(lp, res)) return;
  std::size_t fewest = SIZE_MAX;
  for (const auto& cs : res.channel_summaries) fewest = std::min(fewest, cs.rows);
  res.warnings.push_back(
      "too few rows to estimate each channel's noise (" + std::to_string(fewest) +
      " in a channel, for " + std::to_string(lp.free.size()) +
      " free parameters; more than k + 2 are needed): one sigma is pooled over the channels' "
      "scales (their median magnitudes), so the standard errors hold only if the noise is "
      "proportional to those scales; with noise that differs between channels they were off "
      "by up to 3x (docs/physics.md section 8.10). Give sigma columns, or fit more rows");
}

// Whether channel cs sits at its sigma floor: an estimated noise model, residuals at most
// kNoiseFreeSigma of its RMS fitted value (whose RMS is returned in rms).
bool noise_free(const Dataset& d, const FitResult& res, const ChannelSummary& cs, double& rms) {
  if (!cs.noise || !cs.rmse) return false;
  rms = rms_fitted(res, d, static_cast<int>(cs.channel));
  return rms > 0.0 && !(*cs.rmse > kNoiseFreeSigma * rms);
}

bool any_noise_free_channel(const Dataset& d, const FitResult& res) {
  double rms = 0.0;
  return std::any_of(res.channel_summaries.begin(), res.channel_summaries.end(),
                     [&](const ChannelSummary& cs) { return noise_free(d, res, cs, rms); });
}

// A closed form's coefficient i is poorly determined when it has no standard error or one
// above a tenth of its value.
bool poorly_determined(const FitResult& res, int i) {
  const ParameterEstimate* e = res.parameter(param_names()[i]);
  return e && !e->fixed &&
         (!e->std_error || !(*e->std_error <= kPoorRelativeError * std::fabs(e->value)));
}

// The closed forms' slope coefficients: where the data inform them, and how far they are from
// what the pressure law implies.
void warn_closed_form_coefficients(const LocalProblem& lp, const ParamVector& x,
                                   const FitStatisticsDetail* detail, FitResult& res) {
  const FitSettings& s = *lp.settings;
  if (s.model == ModelKind::Exact) return;
  std::size_t inner = 0, outer = 0;
  for (double e : res.eps) {
    if (e < 1.0) ++inner;
    if (e > 1.0) ++outer;
  }
  auto is_free = [&](int i) {
    return std::find(lp.free.begin(), lp.free.end(), i) != lp.free.end();
  };
  // Without rows on one side of eps = 1 the coefficients acting there rest on the other side's
  // curvature alone; whether that determines them is what their standard errors say.
  if (inner == 0 && is_free(kA) && poorly_determined(res, kA))
    res.warnings.push_back(
        "a is poorly determined: no row has eps = v/(|omega| R) < 1, where the small-slip slope a "
        "acts");
  if (outer == 0) {
    std::vector<int> poor;
    for (int i : {kM, kB, kBTilde})
      if (is_free(i) && poorly_determined(res, i)) poor.push_back(i);
    if (!poor.empty())
      res.warnings.push_back(join_names(poor) + (poor.size() > 1 ? " are" : " is") +
                             " poorly determined: no row has eps > 1, where the small-spin slopes "
                             "act");
  }
  const auto law_c = model::coefficients(model::law_moments(s.law), x[kKappa]);
  const bool seed = s.model == ModelKind::Seed;
  const std::pair<int, double> implied[] = {
      {kA, law_c.a}, {kM, law_c.m}, {seed ? kB : kBTilde, seed ? law_c.b : law_c.b_tilde}};
  // The law's value depends on the fitted kappa: the gap's standard error includes kappa's
  // variance and its covariance with the coefficient (delta method, §8.9).
  auto law_value = [&](int i, double kappa) {
    const auto c = model::coefficients(model::law_moments(s.law), kappa);
    return i == kA ? c.a : i == kM ? c.m : i == kB ? c.b : c.b_tilde;
  };
  auto free_column = [&](int i) {
    return static_cast<Eigen::Index>(std::find(lp.free.begin(), lp.free.end(), i) -
                                     lp.free.begin());
  };
  // Whether parameter i has |r| > kCurvedValley with another free parameter (true when the
  // covariance is not at hand).
  auto strongly_correlated = [&](int i) {
    const auto k = static_cast<Eigen::Index>(lp.free.size());
    if (!detail || detail->covariance.rows() != k) return true;
    const Eigen::Index ci = free_column(i);
    const Eigen::MatrixXd& c = detail->covariance;
    for (Eigen::Index j = 0; j < k; ++j) {
      if (j == ci) continue;
      const double r = c(ci, j) / std::sqrt(c(ci, ci) * c(j, j));
      if (!(std::fabs(r) <= kCurvedValley)) return true;
    }
    return false;
  };
  // A difference the standard error explains is no news: warn beyond 3 standard errors. Not
  // where the noise is pooled over too few rows per channel: those standard errors do not carry
  // a 3-sigma test (it fired in 28-41 % of 8-row fits of data that follow the law).
  if (noise_pooled(lp, res)) return;
  for (const auto& [i, v] : implied) {
    const ParameterEstimate* e = res.parameter(param_names()[i]);
    if (!is_free(i) || !e || !e->std_error) continue;
    double se = *e->std_error;
    if (detail && detail->covariance.rows() == static_cast<Eigen::Index>(lp.free.size())) {
      const Eigen::Index ci = free_column(i);
      std::optional<double> cov_kk, cov_ik;
      if (is_free(kKappa)) {
        const Eigen::Index ck = free_column(kKappa);
        if (!detail->determined[static_cast<std::size_t>(ck)]) continue;
        cov_kk = detail->covariance(ck, ck);
        cov_ik = detail->covariance(ci, ck);
      }
      const double step = 1e-6 * x[kKappa];
      const double slope =
          (law_value(i, x[kKappa] + step) - law_value(i, x[kKappa] - step)) / (2.0 * step);
      const auto gap = law_gap_std_error(detail->covariance(ci, ci), cov_kk, cov_ik, slope);
      if (!gap) continue;
      se = *gap;
    }
    // Three standard errors, as a Student t quantile (the same tail, 0.135 %) on the
    // parameter's interval degrees of freedom: on few rows the noise is itself estimated.
    double z = 3.0;
    if (detail && detail->interval_dof.size() == lp.free.size()) {
      const double nu = detail->interval_dof[static_cast<std::size_t>(free_column(i))];
      if (nu >= 1.0) z = student_t_quantile(1.0 - kLawTail, nu);
    }
    if (!(std::fabs(x[i] - v) > z * se)) continue;
    // Nearly collinear coefficients (kappa, b, m on eps > 1 alone) have a curved cost valley
    // where the linear standard error misleads: the profile of the cost at the law's value
    // (the likelihood ratio, kappa and the rest refitted) must agree that it lies beyond the
    // same threshold. Elsewhere the valley is close to its quadratic model and the refit (a
    // local fit over all rows) is not worth its cost.
    if (strongly_correlated(i) && v > s.params[i].lower && v < s.params[i].upper) {
      ParamVector warm = x;
      const double scale = res.covariance_scaled_by_reduced_chi2 ? res.reduced_chi2 : 1.0;
      const double held = profile_cost(lp, i, v, warm, nullptr);
      if (std::isfinite(held) && !(2.0 * (held - res.cost) > z * z * scale)) continue;
    }
    res.warnings.push_back(
        std::string(param_names()[i]) + " = " + number_text(x[i]) + " differs from the value " +
        number_text(v) + " that the " + s.law_label + " pressure implies at this fit's kappa = " +
        number_text(x[kKappa]) + " by " + number_text(std::fabs(x[i] - v) / se) +
        " standard errors (of the difference, kappa's uncertainty included): the closed forms "
        "are approximations (errors of tens of percent near eps = 1, docs/physics.md section 3), "
        "so fitted coefficients need not equal the matched ones");
  }
}

// The sandwich and the model-based standard error of a parameter disagree. With a correct
// noise model HC3's variance is ~ E chi²_nu/nu, E and nu from the leverages (§8.11): a high
// leverage makes HC3 larger than the model's variance and few effective rows make it noisy, so
// the warning needs the ratio to E beyond both 25 % in the standard error and HC3's own 0.1 %
// tails.
// Not with a noise-free channel: its floored sigma makes the model's standard errors stated
// bounds, and HC3 sees its rounding-level residuals (the comparison fired in 85-100 % of such
// fits).
void warn_sandwich(const LocalProblem& lp, const FitStatisticsDetail* detail, FitResult& res) {
  if (any_noise_free_channel(*lp.rows.data, res)) return;
  for (const auto& e : res.parameters) {
    if (!e.std_error || !e.std_error_sandwich || e.at_bound) continue;
    if (detail && detail->sandwich_expected.size() == lp.free.size()) {
      const auto j = static_cast<std::size_t>(
          std::find(lp.free.begin(), lp.free.end(), *param_index(e.name)) - lp.free.begin());
      if (j >= lp.free.size() || !detail->sandwich_expected[j]) continue;
      const double ratio =
          *e.std_error_sandwich * *e.std_error_sandwich / *detail->sandwich_expected[j];
      if (!sandwich_disagrees(ratio, *detail->sandwich_dof[j])) continue;
    } else if (!(std::fabs(*e.std_error_sandwich - *e.std_error) > 0.25 * *e.std_error)) {
      continue;
    }
    res.warnings.push_back(
        "the standard error of " + e.name + " from the noise model (" + number_text(*e.std_error) +
        ") and the HC3 sandwich (" + number_text(*e.std_error_sandwich) + ") differ by " +
        number_text(100.0 * std::fabs(*e.std_error_sandwich / *e.std_error - 1.0)) +
        " %, more than the rows' leverage and HC3's own sampling error explain: the noise model "
        "may not describe the data's noise, or the model misses a shape; the sandwich does not "
        "rely on either");
  }
}

// A channel fitted to within its sigma floor: noise-free (or nearly), treated as exact to the
// floor, which the warning states.
void warn_noise_free_channels(const Dataset& d, FitResult& res) {
  for (const auto& cs : res.channel_summaries) {
    double rms = 0.0;
    if (!noise_free(d, res, cs, rms)) continue;
    const std::string name = channel_name(cs.channel);
    res.warnings.push_back(
        "the residuals of " + name + " are at rounding level (RMSE " + number_text(*cs.rmse) +
        ", " + number_text(*cs.rmse / rms) +
        " of its RMS fitted value): the channel is noise-free, and is treated "
        "as exact with its sigma floored at " +
        number_text(kNoiseFreeSigma) + " of its RMS fitted value (" +
        number_text(kNoiseFreeSigma * rms) +
        "); the standard errors it informs are upper bounds, not compared with the HC3 sandwich. "
        "Check that " +
        name + " is measured rather than computed");
  }
}

// A two-term noise estimate that failed its gradient check (§8.10): the rows' weights, and the
// standard errors that rely on them, come from a variance function short of its maximum.
void warn_noise_estimates(FitResult& res) {
  for (const auto& cs : res.channel_summaries)
    if (cs.noise && !cs.noise->problem.empty())
      res.warnings.push_back("the " + cs.noise->model + " noise estimate of " +
                             channel_name(cs.channel) + " is " + cs.noise->problem +
                             "; the weights of its rows and the standard errors may be off");
}

// The rows in sweeps: rows with the same load, radius, slip direction, spin sign and tilt sign
// form one sweep, ordered by eps (ties by row). Every channel's sweeps are this order with its
// missing rows left out, so it is sorted once.
struct SweepOrder {
  using Key = std::array<double, 5>;
  std::vector<std::pair<Key, std::size_t>> rows;
};

SweepOrder sweep_order(const Dataset& d, const FitResult& res) {
  SweepOrder o;
  o.rows.reserve(d.rows());
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const double angle = std::round(std::atan2(d.v_y[i], d.v_x[i]) * 1e6);
    o.rows.push_back(
        {SweepOrder::Key{d.N[i], d.R[i], angle, d.omega[i] < 0.0 ? -1.0 : 1.0, d.tilt_sign_at(i)},
         i});
  }
  std::sort(o.rows.begin(), o.rows.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    if (res.eps[a.second] != res.eps[b.second]) return res.eps[a.second] < res.eps[b.second];
    return a.second < b.second;
  });
  return o;
}

std::vector<std::vector<std::size_t>> eps_sweeps(const Dataset& d, const SweepOrder& o, int c) {
  std::vector<std::vector<std::size_t>> groups;
  const SweepOrder::Key* last = nullptr;
  for (const auto& [key, i] : o.rows) {
    if (!d.present[c][i]) continue;
    if (!last || key != *last) groups.emplace_back();
    groups.back().push_back(i);
    last = &key;
  }
  return groups;
}

// Residuals with structure against eps: within each sweep, ordered by eps, the signs of noise
// alternate at random, while a shape the model misses keeps them on one side over stretches
// (Wald-Wolfowitz runs test, §8.9). Whatever the noise model: an estimated noise absorbs a
// misfit's size, not its order.
void warn_structured_residuals(const LocalProblem& lp, FitResult& res) {
  const Dataset& d = *lp.rows.data;
  std::optional<SweepOrder> order;
  for (const auto& cs : res.channel_summaries) {
    const int c = static_cast<int>(cs.channel);
    if (cs.rows < kRunsTestRows || !cs.rmse ||
        !(*cs.rmse > kNoiseFreeSigma * rms_fitted(res, d, c)))
      continue;
    if (!order) order = sweep_order(d, res);
    auto sweeps = eps_sweeps(d, *order, c);
    std::size_t grouped = 0;
    for (const auto& g : sweeps) grouped += g.size() > 1 ? g.size() : 0;
    // Rows that share no sweep (a load per row, say): one sequence ordered by eps.
    if (grouped < kRunsTestRows) {
      std::vector<std::size_t> all;
      for (const auto& g : sweeps) all.insert(all.end(), g.begin(), g.end());
      std::stable_sort(all.begin(), all.end(),
                       [&](std::size_t a, std::size_t b) { return res.eps[a] < res.eps[b]; });
      sweeps.assign(1, all);
    }
    std::vector<std::vector<double>> residuals;
    for (const auto& g : sweeps) {
      residuals.emplace_back();
      for (std::size_t i : g) residuals.back().push_back(res.fitted[c][i] - d.value[c][i]);
    }
    const RunsTest t = residual_runs(residuals);
    if (t.rows < kRunsTestRows || !(t.z < -kRunsTestZ)) continue;
    res.warnings.push_back(
        "the residuals of " + std::string(channel_name(cs.channel)) +
        " have structure against eps: ordered by eps within each sweep, their signs form " +
        number_text(t.runs) + " runs where noise would give about " + number_text(t.expected) +
        " (runs test, z = " + number_text(t.z) +
        "). This is a misfit whatever the noise model: the model misses a shape of the channel "
        "(a sign convention, a column that is absent or misspelt such as v_y, or the wrong "
        "model)");
  }
}

}  // namespace

// A channel the fit explains little of: with an estimated noise model a misfit is absorbed as
// noise (reduced chi² near 1), so only the share of the variation explained tells. Either the
// signal is below the noise, or the model misses it.
void warn_unexplained_channels(FitResult& res) {
  for (const auto& cs : res.channel_summaries)
    if (cs.r2 && *cs.r2 < 0.5)
      res.warnings.push_back(
          "the fit explains " +
          (*cs.r2 > 0.0 ? "only " + number_text(100.0 * *cs.r2) + " %" : std::string("none")) +
          " of the variation of " + channel_name(cs.channel) + " (R^2 = " + number_text(*cs.r2) +
          "): either its signal is below its noise, or the model misses it (a sign convention, "
          "a column that is absent or misspelt such as v_y, or the wrong model)");
}

std::optional<double> law_gap_std_error(double var_coefficient, std::optional<double> var_kappa,
                                        std::optional<double> cov_coefficient_kappa, double slope) {
  double v = var_coefficient;
  if (var_kappa && cov_coefficient_kappa)
    v += slope * slope * *var_kappa - 2.0 * slope * *cov_coefficient_kappa;
  if (!(std::isfinite(v) && v > 0.0)) return std::nullopt;
  return std::sqrt(v);
}

double chi2_quantile(double p, double nu) {
  // Wilson-Hilferty: (chi²_nu/nu)^(1/3) is close to normal with mean 1 - 2/(9 nu) and variance
  // 2/(9 nu); within a few percent of the exact quantile down to nu = 1 in the far tails used.
  const double z = p > 0.5 ? kNormalQuantile999 : -kNormalQuantile999;
  const double c = 2.0 / (9.0 * nu);
  const double cube = 1.0 - c + z * std::sqrt(c);
  return cube > 0.0 ? nu * cube * cube * cube : 0.0;
}

bool sandwich_disagrees(double ratio, double nu) {
  if (!(std::fabs(std::sqrt(ratio) - 1.0) > 0.25)) return false;
  return ratio < chi2_quantile(0.001, nu) / nu || ratio > chi2_quantile(0.999, nu) / nu;
}

RunsTest residual_runs(const std::vector<std::vector<double>>& groups) {
  RunsTest t;
  for (const auto& g : groups) {
    double pos = 0.0, neg = 0.0, runs = 0.0;
    int last = 0;
    for (double r : g) {
      const int sign = r > 0.0 ? 1 : r < 0.0 ? -1 : 0;
      if (sign == 0) continue;
      (sign > 0 ? pos : neg) += 1.0;
      if (sign != last) runs += 1.0;
      last = sign;
    }
    const double n = pos + neg;
    if (n < 2.0) continue;
    t.rows += static_cast<std::size_t>(n);
    t.runs += runs;
    t.expected += 1.0 + 2.0 * pos * neg / n;
    t.variance += 2.0 * pos * neg * (2.0 * pos * neg - n) / (n * n * (n - 1.0));
  }
  if (t.variance > 0.0) t.z = (t.runs - t.expected) / std::sqrt(t.variance);
  return t;
}

void add_fit_warnings(const LocalProblem& lp, const ParamVector& x,
                      const std::vector<int>& undetermined, FitResult& res,
                      const FitStatisticsDetail* detail) {
  if (!res.solver.converged)
    res.warnings.push_back("the local solver did not converge (" + res.solver.termination +
                           " after " + std::to_string(res.solver.iterations) +
                           " iterations): the estimates may not be at the optimum");
  if (res.dof == 0)
    res.warnings.push_back(
        "no degree of freedom is left: " + std::to_string(res.residuals) +
        " measured values for as many or more free parameters, so the fit passes through the "
        "data and says nothing of its noise; the reduced chi2 and the standard errors are "
        "undefined (null). Fit more rows or hold parameters fixed");
  warn_zero_and_growing_channels(*lp.rows.data, res);
  warn_noise_estimates(res);
  warn_pooled_noise(lp, res);
  warn_noise_free_channels(*lp.rows.data, res);
  warn_outliers(lp, res);
  warn_unexplained_channels(res);
  warn_structured_residuals(lp, res);
  warn_undetermined_and_correlated(lp, undetermined, res);
  // The model-based standard error trusts the noise model; the sandwich does not.
  warn_sandwich(lp, detail, res);
  for (const auto& e : res.parameters)
    if (e.at_bound)
      res.warnings.push_back(e.name + " = " + number_text(e.value) + " is at its " +
                             (e.value - e.lower <= e.upper - e.value ? "lower" : "upper") +
                             " bound; its standard error is not meaningful");
  warn_closed_form_coefficients(lp, x, detail, res);
}

}  // namespace frictionid
