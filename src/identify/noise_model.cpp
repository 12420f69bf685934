#include "identify/noise_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "identify/log_sum.hpp"
#include "identify/number_text.hpp"
#include "identify/variance_profile.hpp"

namespace frictionid {
namespace {

constexpr double kTiny = 1e-300;
// The gradient check's threshold (8.10c): a step that would lower -2 ln L by less than this
// changes no decision and no digit a report shows.
constexpr double kGainTolerance = 1e-6;
// Auto (two_term_noise): a two-term form is left once its -2 ln L is certain to end this far
// (times 1 + 1e-9 (n + |-2 ln L|), Fisher scoring's rounding window) above what it would need
// to be chosen. 1 is a likelihood ratio of e^0.5.
constexpr double kLossMargin = 1.0;

// What the likelihood needs of a sample beyond its length, gathered in one pass: the closed
// forms below then score the constant model and the affine model's bounds without a log per row.
// The same pass adds the sums of the one-term estimates and the search's ranges (TwoTermRange),
// each in row order as its own loop would (the results are the same to the bit).
struct SampleSums {
  double e2 = 0.0;           // sum e^2
  std::size_t nonzero = 0;   // rows with y != 0
  double log_y2 = 0.0;       // sum log y^2 over them
  double e2_over_y2 = 0.0;   // sum e^2/y^2 over them
  double zero_e2 = 0.0;      // sum e^2 over the rows with y = 0
  double min_y2 = HUGE_VAL;  // smallest nonzero y^2
  double mean_e2 = 0.0;      // mean of e^2
  double mean_y2 = 0.0;      // mean of y^2
  TwoTermRange affine, additive;
};

// peak_y, peak_e: the largest |y| and |e|. mean_y2 and mean_e2 are the mean squares, summed in
// units of the peak: no overflow near the top of the double range.
SampleSums sample_sums(const std::vector<double>& y, const std::vector<double>& e, double peak_y,
                       double peak_e) {
  SampleSums t;
  LogSum log_y2;
  double sum_y = 0.0, sum_e = 0.0, min_abs_y = HUGE_VAL;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double y2 = y[i] * y[i], e2 = e[i] * e[i];
    t.e2 += e2;
    if (y2 > 0.0) {
      ++t.nonzero;
      log_y2.add(y2);
      t.e2_over_y2 += e2 / y2;
      t.min_y2 = std::min(t.min_y2, y2);
    } else {
      t.zero_e2 += e2;
    }
    if (std::fabs(y[i]) > 0.0) min_abs_y = std::min(min_abs_y, std::fabs(y[i]));
    if (peak_y != 0.0) sum_y += (y[i] / peak_y) * (y[i] / peak_y);
    if (peak_e != 0.0) sum_e += (e[i] / peak_e) * (e[i] / peak_e);
  }
  t.log_y2 = log_y2.sum();
  const auto n = static_cast<double>(y.size());
  t.mean_y2 = peak_y == 0.0 ? 0.0 : peak_y * peak_y * sum_y / n;
  t.mean_e2 = peak_e == 0.0 ? 0.0 : peak_e * peak_e * sum_e / n;
  // max y^2 is the square of max |y| (rounding is monotone); NaNs count in neither.
  t.affine = TwoTermRange{peak_y * peak_y, t.min_y2, t.e2};
  t.additive = TwoTermRange{peak_y, min_abs_y, t.e2};
  return t;
}

// The variance sigma_i^2 of noise n at fitted value y (noise_model.hpp), in sample units (at
// most 1 in magnitude: estimate_channel_noise divides by the largest, so nothing overflows).
double variance(const ChannelNoise& n, double y) {
  switch (n.kind) {
    case NoiseModelKind::Relative: {
      const double m = n.s_rel * std::max(std::fabs(y), n.floor);
      return m * m;
    }
    case NoiseModelKind::Affine:
      return n.s_abs * n.s_abs + (n.s_rel * y) * (n.s_rel * y);
    case NoiseModelKind::Additive: {
      const double sd = n.s_abs + n.s_rel * std::fabs(y);
      return sd * sd;
    }
    default:
      return n.s_abs * n.s_abs;
  }
}

// -2 log L (without 2 pi) = sum log v_i + e_i^2/v_i, v_i = max(sigma_i^2, tiny), and the BIC.
void set_score(ChannelNoise& n, double neg2_loglik, std::size_t rows, int parameters) {
  n.neg2_loglik = neg2_loglik;
  n.bic = neg2_loglik + parameters * std::log(static_cast<double>(rows));
}

void score(ChannelNoise& n, const std::vector<double>& y, const std::vector<double>& e,
           int parameters) {
  LogSum log_v;
  double s = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double v = std::max(variance(n, y[i]), kTiny);
    log_v.add(v);
    s += e[i] * e[i] / v;
  }
  set_score(n, log_v.sum() + s, y.size(), parameters);
}

// The same sum where the variance is one constant a for every row.
double constant_neg2_loglik(double a, std::size_t rows, const SampleSums& t) {
  const double v = std::max(a, kTiny);
  return static_cast<double>(rows) * std::log(v) + t.e2 / v;
}

// The same over the rows with y != 0 for v_i = b y_i^2 (the affine model with s_abs = 0);
// nullopt where b y^2 would fall below tiny for some of them: only the sum row by row is exact.
std::optional<double> proportional_neg2_loglik(double b, const SampleSums& t) {
  if (t.nonzero == 0) return 0.0;
  if (!(b * t.min_y2 >= kTiny)) return std::nullopt;
  return static_cast<double>(t.nonzero) * std::log(b) + t.log_y2 + t.e2_over_y2 / b;
}

ChannelNoise constant_noise(const std::vector<double>& e, const SampleSums& t) {
  ChannelNoise n;
  n.kind = NoiseModelKind::Constant;
  n.s_abs = std::sqrt(t.mean_e2);
  set_score(n, constant_neg2_loglik(n.s_abs * n.s_abs, e.size(), t), e.size(), 1);
  return n;
}

ChannelNoise relative_noise(const std::vector<double>& y, const std::vector<double>& e,
                            const SampleSums& t) {
  ChannelNoise n;
  n.kind = NoiseModelKind::Relative;
  n.floor = 1e-3 * std::sqrt(t.mean_y2);
  double s = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double m = std::max(std::fabs(y[i]), n.floor);
    if (m > 0.0) s += (e[i] / m) * (e[i] / m);
  }
  n.s_rel = std::sqrt(s / static_cast<double>(y.size()));
  score(n, y, e, 1);
  return n;
}

// -2 log L of a two-term model on a bound, with variance a (b = 0: the constant model) or b y^2
// (a = 0: proportional, unfloored; rows with y = 0 get the variance tiny): closed forms where
// they are exact. Affine and additive models share both bounds.
double bound_neg2_loglik(double a_only, double b_only, const std::vector<double>& y,
                         const std::vector<double>& e, const SampleSums& t) {
  if (b_only == 0.0) return constant_neg2_loglik(a_only, y.size(), t);
  if (const auto s = proportional_neg2_loglik(b_only, t))
    return *s + static_cast<double>(y.size() - t.nonzero) * std::log(kTiny) + t.zero_e2 / kTiny;
  ChannelNoise n;
  n.kind = NoiseModelKind::Affine;
  n.s_abs = std::sqrt(a_only);
  n.s_rel = std::sqrt(b_only);
  score(n, y, e, 2);
  return n.neg2_loglik;
}

// Fisher scoring of the affine likelihood in (a, b) = (s_abs^2, s_rel^2): weighted least
// squares of e^2 on (1, y^2) with weights 1/sigma^4, a and b kept >= 0 (an active bound drops to
// the one-parameter model, which is then the affine model's estimate). c and r: the constant
// and relative estimates of the same sample, where it starts. It can stop on a bound or cycle
// short of the maximum; two_term_noise checks it.
ChannelNoise fisher_scoring_affine(const std::vector<double>& y, const std::vector<double>& e,
                                   const ChannelNoise& c, const ChannelNoise& r,
                                   const SampleSums& t) {
  // Start halfway between the pure forms so that neither bound is active at the start.
  double a = 0.5 * c.s_abs * c.s_abs, b = 0.5 * r.s_rel * r.s_rel;
  const double ym2 = t.mean_y2;
  for (int it = 0; it < 100; ++it) {
    double s00 = 0, s01 = 0, s11 = 0, t0 = 0, t1 = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double y2 = y[i] * y[i];
      const double v = std::max(a + b * y2, kTiny);
      const double w = 1.0 / (v * v);
      const double e2 = e[i] * e[i];
      s00 += w;
      s01 += w * y2;
      s11 += w * y2 * y2;
      t0 += w * e2;
      t1 += w * y2 * e2;
    }
    const double det = s00 * s11 - s01 * s01;
    double na = det > 0 ? (s11 * t0 - s01 * t1) / det : -1.0;
    double nb = det > 0 ? (s00 * t1 - s01 * t0) / det : -1.0;
    if (na < 0.0 || nb < 0.0) {  // a bound is active: the better one-parameter solution
      const double a_only = std::max(t0 / s00, 0.0), b_only = s11 > 0 ? std::max(t1 / s11, 0.0) : 0;
      const bool keep_a =
          bound_neg2_loglik(a_only, 0.0, y, e, t) <= bound_neg2_loglik(0.0, b_only, y, e, t);
      na = keep_a ? a_only : 0.0;
      nb = keep_a ? 0.0 : b_only;
    }
    const double change = std::fabs(na - a) / std::max(na + nb * ym2, kTiny) +
                          std::fabs(nb - b) * ym2 / std::max(na + nb * ym2, kTiny);
    a = na;
    b = nb;
    if (change < 1e-10) break;
  }
  ChannelNoise n;
  n.kind = NoiseModelKind::Affine;
  n.s_abs = std::sqrt(a);
  n.s_rel = std::sqrt(b);
  if (a == 0.0 || b == 0.0)
    set_score(n, bound_neg2_loglik(a, b, y, e, t), y.size(), 2);
  else
    score(n, y, e, 2);
  return n;
}

// The maximum likelihood of a two-term model (affine or additive): the best of its two bounds
// and the profile search's interior maximum (variance_profile.hpp). For the affine model, Fisher
// scoring, the estimator before the profile search, is kept where it reached the maximum (within
// rounding of the best -2 log L, and passing the gradient check (8.10c)), so that the fits it
// served stay as they were to the last digit. A failed gradient check is kept as the estimate's
// problem.
//
// beat_bic (Auto): the smallest BIC among the forms before this one. Where this form's -2 ln L
// clearly cannot bring its BIC below it (by kLossMargin, more than any rounding), nullopt: the
// estimate would not be chosen, and the work that only refines it (the rest of the search,
// Fisher scoring, the gradient checks) is left out. Otherwise the estimate, the same to the bit
// as without beat_bic.
std::optional<ChannelNoise> two_term_noise(NoiseModelKind kind, const std::vector<double>& y,
                                           const std::vector<double>& e, const ChannelNoise& c,
                                           const ChannelNoise& r, const SampleSums& t,
                                           double beat_bic = HUGE_VAL) {
  const TwoTermForm form =
      kind == NoiseModelKind::Affine ? TwoTermForm::Affine : TwoTermForm::Additive;
  const auto rows = static_cast<double>(y.size());
  // The -2 ln L above which this form loses to beat_bic by the margin (inf: no bound).
  const double beat = beat_bic - 2.0 * std::log(rows);
  const double give_up_above =
      std::isfinite(beat) ? beat + kLossMargin * (1.0 + 1e-9 * (rows + std::fabs(beat))) : HUGE_VAL;
  ChannelNoise best;
  best.kind = kind;
  best.s_abs = c.s_abs;
  set_score(best, bound_neg2_loglik(c.s_abs * c.s_abs, 0.0, y, e, t), y.size(), 2);
  if (t.nonzero > 0) {
    ChannelNoise p;
    p.kind = kind;
    const double b = t.e2_over_y2 / static_cast<double>(t.nonzero);
    p.s_rel = std::sqrt(b);
    set_score(p, bound_neg2_loglik(0.0, b, y, e, t), y.size(), 2);
    if (p.neg2_loglik < best.neg2_loglik) best = p;
  }
  const TwoTermMaximum m = two_term_maximum(
      form, y, e, form == TwoTermForm::Affine ? t.affine : t.additive, give_up_above);
  if (m.found) {
    ChannelNoise in;
    in.kind = kind;
    in.s_abs = m.s_abs;
    in.s_rel = m.s_rel;
    score(in, y, e, 2);
    if (in.neg2_loglik < best.neg2_loglik) best = in;
  }
  // The searches given up ended above give_up_above: had one gone on, it would not have beaten
  // a best at or below it.
  if (best.neg2_loglik > give_up_above) return std::nullopt;
  if (kind == NoiseModelKind::Affine) {
    const ChannelNoise f = fisher_scoring_affine(y, e, c, r, t);
    const double rounding = 1e-9 * (static_cast<double>(y.size()) + std::fabs(best.neg2_loglik));
    if (f.neg2_loglik <= best.neg2_loglik + rounding &&
        remaining_gain(form, f.s_abs, f.s_rel, y, e) <= kGainTolerance)
      return f;
  }
  const double gain = remaining_gain(form, best.s_abs, best.s_rel, y, e);
  if (!(gain <= kGainTolerance))
    best.problem = "not at the likelihood maximum: one more step would lower -2 ln L by " +
                   number_text(gain) +
                   (m.found && !m.converged ? " (the Newton search hit its step limit)" : "");
  return best;
}

}  // namespace

double noise_sigma(const ChannelNoise& n, double y) {
  // In data units, where a square may overflow: no variance() here.
  if (n.kind == NoiseModelKind::Relative) return n.s_rel * std::max(std::fabs(y), n.floor);
  if (n.kind == NoiseModelKind::Additive) return n.s_abs + n.s_rel * std::fabs(y);
  if (n.kind != NoiseModelKind::Affine) return n.s_abs;
  // hypot guards against overflow and underflow at a cost; within these bounds a sqrt is exact
  // enough, and it is called for every row of every refit.
  const double p = std::fabs(n.s_rel * y), big = std::max(n.s_abs, p);
  return big < 1e150 && big > 1e-150 ? std::sqrt(n.s_abs * n.s_abs + p * p)
                                     : std::hypot(n.s_abs, p);
}

ChannelNoise estimate_channel_noise(std::vector<double> fitted, std::vector<double> residual,
                                    NoiseModelKind kind, double dof_factor) {
  // Estimated in units of the sample's largest magnitude: variances of values near the top of
  // the double range must not overflow.
  double unit = 0.0;
  for (std::size_t i = 0; i < fitted.size(); ++i)
    unit = std::max({unit, std::fabs(fitted[i]), std::fabs(residual[i])});
  if (!(unit > 0.0) || !std::isfinite(unit)) unit = 1.0;
  double peak_y = 0.0, peak_e = 0.0;
  for (std::size_t i = 0; i < fitted.size(); ++i) {
    fitted[i] /= unit;
    residual[i] /= unit;
    peak_y = std::max(peak_y, std::fabs(fitted[i]));
    peak_e = std::max(peak_e, std::fabs(residual[i]));
  }
  ChannelNoise n;
  const SampleSums sums = sample_sums(fitted, residual, peak_y, peak_e);
  switch (kind) {
    case NoiseModelKind::Constant:
      n = constant_noise(residual, sums);
      break;
    case NoiseModelKind::Relative:
      n = relative_noise(fitted, residual, sums);
      break;
    case NoiseModelKind::Affine:
    case NoiseModelKind::Additive:
      n = *two_term_noise(kind, fitted, residual, constant_noise(residual, sums),
                          relative_noise(fitted, residual, sums), sums);
      break;
    default: {  // Auto: the smallest BIC; ties go to the earlier (simpler, then older) model
      const ChannelNoise c = constant_noise(residual, sums);
      const ChannelNoise r = relative_noise(fitted, residual, sums);
      n = c;
      if (r.bic < n.bic) n = r;
      // Too few rows for a two-term variance function: one sigma pooled over the channel's
      // rows, constant or proportional (§8.10).
      if (fitted.size() < kTwoTermNoiseRows) break;
      // A two-term form is estimated in full only where it may beat the best so far.
      const auto a = two_term_noise(NoiseModelKind::Affine, fitted, residual, c, r, sums, n.bic);
      if (a && a->bic < n.bic) n = *a;
      const auto d = two_term_noise(NoiseModelKind::Additive, fitted, residual, c, r, sums, n.bic);
      if (d && d->bic < n.bic) n = *d;
    }
  }
  const double f = std::sqrt(std::max(dof_factor, 1.0));
  n.s_abs *= f * unit;
  n.s_rel *= f;
  n.floor *= unit;
  return n;
}

int noise_parameters(NoiseModelKind kind) {
  return kind == NoiseModelKind::Affine || kind == NoiseModelKind::Additive ? 2 : 1;
}

const char* noise_model_name(NoiseModelKind kind) {
  return noise_model_kind_name(kind);
}

}  // namespace frictionid
