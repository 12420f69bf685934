#include "identify/noise_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frictionid {
namespace {

constexpr double kTiny = 1e-300;

// -2 log L (without 2 pi) and the BIC of noise n on the sample.
void score(ChannelNoise& n, const std::vector<double>& y, const std::vector<double>& e,
           int parameters) {
  double s = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double v = std::max(noise_sigma(n, y[i]) * noise_sigma(n, y[i]), kTiny);
    s += std::log(v) + e[i] * e[i] / v;
  }
  n.neg2_loglik = s;
  n.bic = s + parameters * std::log(static_cast<double>(y.size()));
}

double mean_square(const std::vector<double>& v) {
  double peak = 0.0;
  for (double x : v) peak = std::max(peak, std::fabs(x));
  if (peak == 0.0) return 0.0;
  double s = 0.0;
  for (double x : v) s += (x / peak) * (x / peak);
  return peak * peak * s / static_cast<double>(v.size());
}

ChannelNoise constant_noise(const std::vector<double>& y, const std::vector<double>& e) {
  ChannelNoise n;
  n.kind = NoiseModelKind::Constant;
  n.s_abs = std::sqrt(mean_square(e));
  score(n, y, e, 1);
  return n;
}

ChannelNoise relative_noise(const std::vector<double>& y, const std::vector<double>& e) {
  ChannelNoise n;
  n.kind = NoiseModelKind::Relative;
  n.floor = 1e-3 * std::sqrt(mean_square(y));
  double s = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double m = std::max(std::fabs(y[i]), n.floor);
    if (m > 0.0) s += (e[i] / m) * (e[i] / m);
  }
  n.s_rel = std::sqrt(s / static_cast<double>(y.size()));
  score(n, y, e, 1);
  return n;
}

// Fisher scoring of the Gaussian likelihood in (a, b) = (s_abs^2, s_rel^2): weighted least
// squares of e^2 on (1, y^2) with weights 1/sigma^4, a and b kept >= 0 (an active bound drops to
// the one-parameter model, which is then the affine model's estimate).
ChannelNoise affine_noise(const std::vector<double>& y, const std::vector<double>& e) {
  const ChannelNoise c = constant_noise(y, e);
  double a = c.s_abs * c.s_abs, b = 0.0;
  // Start halfway between the pure forms so that neither bound is active at the start.
  const ChannelNoise r = relative_noise(y, e);
  a *= 0.5;
  b = 0.5 * r.s_rel * r.s_rel;
  const double ym2 = mean_square(y);
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
      ChannelNoise ta{NoiseModelKind::Affine, std::sqrt(a_only), 0.0, 0.0, 0.0, 0.0};
      ChannelNoise tb{NoiseModelKind::Affine, 0.0, std::sqrt(b_only), 0.0, 0.0, 0.0};
      score(ta, y, e, 2);
      score(tb, y, e, 2);
      na = ta.neg2_loglik <= tb.neg2_loglik ? a_only : 0.0;
      nb = ta.neg2_loglik <= tb.neg2_loglik ? 0.0 : b_only;
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
  score(n, y, e, 2);
  return n;
}

}  // namespace

double noise_sigma(const ChannelNoise& n, double y) {
  switch (n.kind) {
    case NoiseModelKind::Relative:
      return n.s_rel * std::max(std::fabs(y), n.floor);
    case NoiseModelKind::Affine:
      return std::hypot(n.s_abs, n.s_rel * y);
    default:
      return n.s_abs;
  }
}

ChannelNoise estimate_channel_noise(const std::vector<double>& fitted_in,
                                    const std::vector<double>& residual_in, NoiseModelKind kind,
                                    double dof_factor) {
  // Estimated in units of the sample's largest magnitude: variances of values near the top of
  // the double range must not overflow.
  double unit = 0.0;
  for (std::size_t i = 0; i < fitted_in.size(); ++i)
    unit = std::max({unit, std::fabs(fitted_in[i]), std::fabs(residual_in[i])});
  if (!(unit > 0.0) || !std::isfinite(unit)) unit = 1.0;
  std::vector<double> fitted(fitted_in.size()), residual(residual_in.size());
  for (std::size_t i = 0; i < fitted.size(); ++i) {
    fitted[i] = fitted_in[i] / unit;
    residual[i] = residual_in[i] / unit;
  }
  ChannelNoise n;
  switch (kind) {
    case NoiseModelKind::Constant:
      n = constant_noise(fitted, residual);
      break;
    case NoiseModelKind::Relative:
      n = relative_noise(fitted, residual);
      break;
    case NoiseModelKind::Affine:
      n = affine_noise(fitted, residual);
      break;
    default: {  // Auto: the smallest BIC; ties go to the simpler model
      const ChannelNoise c = constant_noise(fitted, residual);
      const ChannelNoise r = relative_noise(fitted, residual);
      const ChannelNoise a = affine_noise(fitted, residual);
      n = c;
      if (r.bic < n.bic) n = r;
      if (a.bic < n.bic) n = a;
    }
  }
  const double f = std::sqrt(std::max(dof_factor, 1.0));
  n.s_abs *= f * unit;
  n.s_rel *= f;
  n.floor *= unit;
  return n;
}

const char* noise_model_name(NoiseModelKind kind) {
  switch (kind) {
    case NoiseModelKind::Auto:
      return "auto";
    case NoiseModelKind::Constant:
      return "constant";
    case NoiseModelKind::Relative:
      return "relative";
    case NoiseModelKind::Affine:
      return "affine";
    case NoiseModelKind::Columns:
      return "columns";
  }
  return "?";
}

}  // namespace frictionid
