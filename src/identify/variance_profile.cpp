#include "identify/variance_profile.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

#include "identify/log_sum.hpp"

// The grid's profiles four points at a time in AVX2 vectors: x86-64 with GCC or Clang, not in a
// FRICTIONID_PORTABLE build.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(FRICTIONID_PORTABLE)
#define FRICTIONID_PROFILE_LANES 1
#else
#define FRICTIONID_PROFILE_LANES 0
#endif

namespace frictionid {
namespace {

std::atomic<bool> allow_lanes{true};

constexpr double kTinyVariance = 1e-300;
// Grid: three points per decade of tau; its ends put tau z within 1e-9 of the bounds.
const double kGridStep = std::log(10.0) / 3.0;
constexpr double kBoundReach = 1e9;
constexpr double kMaxDecades = 60.0;  // at most this wide (rows with tiny |y| beyond it)
// The grid sees at most this many rows (every k-th): it only places the basins; the Newton
// search runs on every row.
constexpr std::size_t kGridRows = 4096;
constexpr int kStarts = 3;  // the grid's best local minima searched from
constexpr int kNewtonSteps = 100;
// A search gives up (give_up_above) at a point of positive curvature whose Newton step is at most
// two grid steps long where even this many times the decrease that step promises would not reach
// the bound. Where a profile levels off towards a bound (P ~ c + b e^-t) the decrease still to come
// is twice the promise; on the development corpus (the stress samples of
// tests/support/noise_stress_sample.hpp, fits of 40 to 1e5 rows) it was at most 1.95 times the
// promise at any point a search evaluated (1.2 from its first Newton step on).
constexpr double kPromiseSafety = 4.0;

// z_i: the data's part of the ratio term, h_i = (1 + tau z_i)^k the variance over A.
double ratio_data(TwoTermForm form, double y) {
  return form == TwoTermForm::Affine ? y * y : std::fabs(y);
}
int power(TwoTermForm form) {
  return form == TwoTermForm::Affine ? 1 : 2;
}

struct ProfileValue {
  double p = 0.0, dp = 0.0, d2p = 0.0;  // P(t), P'(t), P''(t)
  double floor_variance = 0.0;          // A(t)
};

// (8.10a), (8.10b) over the rows i = 0, stride, 2 stride, ...: with q_i = tau z_i/(1 + tau z_i),
// d_i = d ln h_i/dt = k q_i and c_i = d d_i/dt = k q_i (1 - q_i), u_i = e_i^2/(A h_i),
//   P' = sum d_i (1 - u_i)
//   P'' = sum u_i (d_i^2 - c_i) - (sum u_i d_i)^2/n + sum c_i
ProfileValue profile(TwoTermForm form, const std::vector<double>& y, const std::vector<double>& e,
                     double t, std::size_t stride = 1) {
  const double tau = std::exp(t);
  const int k = power(form);
  LogSum log_g;
  double n = 0.0, sum_eh = 0.0, sum_d = 0.0, sum_c = 0.0, sum_ehd = 0.0, sum_ehdc = 0.0;
  for (std::size_t i = 0; i < y.size(); i += stride) {
    const double tz = tau * ratio_data(form, y[i]), g = 1.0 + tz, q = tz / g;
    const double h = k == 1 ? g : g * g, eh = e[i] * e[i] / h;
    const double d = k * q, c = k * q * (1.0 - q);
    log_g.add(g);
    n += 1.0;
    sum_eh += eh;
    sum_d += d;
    sum_c += c;
    sum_ehd += eh * d;
    sum_ehdc += eh * (d * d - c);
  }
  ProfileValue v;
  v.floor_variance = sum_eh / n;
  const double a = std::max(v.floor_variance, kTinyVariance);
  v.p = n * std::log(a) + k * log_g.sum() + n;
  v.dp = sum_d - sum_ehd / a;
  v.d2p = sum_ehdc / a - (sum_ehd / a) * (sum_ehd / a) / n + sum_c;
  return v;
}

#if FRICTIONID_PROFILE_LANES
// P at four points t[0..3] over the rows 0, stride, 2 stride, ...: profile(form, y, e, t[l],
// stride).p for each lane l, from the same operations in the same order on each (no fused
// multiply-add: AVX2 does not bring FMA), so the same bits, in about a quarter of the time; the
// sums that only P' and P'' need are left out. False where some 1 + tau z_i is not a normal
// double (inf or nan), which LogSum takes one log at a time: the caller then uses profile().
typedef double Lanes __attribute__((vector_size(32)));
typedef unsigned long long LaneBits __attribute__((vector_size(32)));
typedef long long LaneInts __attribute__((vector_size(32)));

template <int K>
__attribute__((target("avx2"))) bool profile_lanes(const std::vector<double>& y,
                                                   const std::vector<double>& e, const double* t,
                                                   std::size_t stride, double* p) {
  const Lanes tau = {std::exp(t[0]), std::exp(t[1]), std::exp(t[2]), std::exp(t[3])};
  const Lanes one = {1.0, 1.0, 1.0, 1.0};
  const LaneBits mantissa = {LogSum::kMantissa, LogSum::kMantissa, LogSum::kMantissa,
                             LogSum::kMantissa};
  const LaneBits one_bits = {LogSum::kOne, LogSum::kOne, LogSum::kOne, LogSum::kOne};
  Lanes product = one, logs = {0.0, 0.0, 0.0, 0.0}, sum_eh = {0.0, 0.0, 0.0, 0.0};
  LaneInts exponent = {0, 0, 0, 0}, special = {0, 0, 0, 0};
  int in_block = 0;
  double n = 0.0;
  for (std::size_t i = 0; i < y.size(); i += stride) {
    const double z = K == 1 ? y[i] * y[i] : std::fabs(y[i]), e2 = e[i] * e[i];
    const Lanes g = 1.0 + tau * z;
    // LogSum::add(g) in each lane.
    LaneBits bits;
    std::memcpy(&bits, &g, sizeof bits);
    const LaneBits biased = bits >> 52;
    special |= reinterpret_cast<LaneInts>((biased == 0) | (biased >= 0x7ff));
    exponent += reinterpret_cast<LaneInts>(biased) - 1023;
    const LaneBits m_bits = (bits & mantissa) | one_bits;
    Lanes m;
    std::memcpy(&m, &m_bits, sizeof m);
    product *= m;
    if (++in_block == LogSum::kBlock) {
      for (int l = 0; l < 4; ++l) logs[l] += std::log(product[l]);
      product = one;
      in_block = 0;
    }
    n += 1.0;
    sum_eh += e2 / (K == 1 ? g : g * g);
  }
  if (special[0] | special[1] | special[2] | special[3]) return false;
  for (int l = 0; l < 4; ++l) {  // the end of profile()
    const double a = std::max(sum_eh[l] / n, kTinyVariance);
    p[l] = n * std::log(a) + K * LogSum::sum_of(exponent[l], logs[l], product[l], 0.0) + n;
  }
  return true;
}

bool profile_lanes_available() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}
#endif

// The grid: P at t_lo + j kGridStep, j < points, over the rows 0, stride, 2 stride, ...
std::vector<double> profile_grid(TwoTermForm form, const std::vector<double>& y,
                                 const std::vector<double>& e, double t_lo, int points,
                                 std::size_t stride) {
  std::vector<double> grid(points);
  int j = 0;
#if FRICTIONID_PROFILE_LANES
  if (profile_lanes_available() && allow_lanes.load(std::memory_order_relaxed)) {
    for (; j + 4 <= points; j += 4) {
      const double t[4] = {t_lo + j * kGridStep, t_lo + (j + 1) * kGridStep,
                           t_lo + (j + 2) * kGridStep, t_lo + (j + 3) * kGridStep};
      const bool done = form == TwoTermForm::Affine ? profile_lanes<1>(y, e, t, stride, &grid[j])
                                                    : profile_lanes<2>(y, e, t, stride, &grid[j]);
      if (!done)
        for (int l = 0; l < 4; ++l) grid[j + l] = profile(form, y, e, t[l], stride).p;
    }
  }
#endif
  for (; j < points; ++j) grid[j] = profile(form, y, e, t_lo + j * kGridStep, stride).p;
  return grid;
}

struct Search {
  double t = 0.0;
  ProfileValue at;
  bool interior = false, converged = false;
  bool given_up = false;  // left early: its basin's minimum lies above give_up_above
};

// From grid point t0: downhill on all rows by grid steps until a bracket [lo, hi] holds a point
// no higher than its ends (none when the descent reaches the grid's ends: a bound is the
// maximum), then Newton steps inside it, golden section where Newton leaves the bracket, has no
// positive curvature, or failed to descend the step before. Gives up (two_term_maximum) at the
// first point it evaluates in full that shows its end to lie above give_up_above.
Search search_from(TwoTermForm form, const std::vector<double>& y, const std::vector<double>& e,
                   double t0, double t_lo, double t_hi, double give_up_above) {
  const auto value = [&](double t) { return profile(form, y, e, t); };
  Search s;
  // Whether the point s.at shows that the search cannot end at or below give_up_above.
  const auto gives_up = [&] {
    const ProfileValue& v = s.at;
    if (!(v.d2p > 0.0) || !(std::fabs(v.dp / v.d2p) <= 2.0 * kGridStep)) return false;
    s.given_up = v.p - kPromiseSafety * 0.5 * v.dp * v.dp / v.d2p > give_up_above;
    return s.given_up;
  };
  s.t = t0;
  s.at = value(t0);
  if (gives_up()) return s;
  double lo = t0 - kGridStep, hi = t0 + kGridStep;
  double p_lo = value(lo).p, p_hi = value(hi).p;
  for (;;) {
    if (p_lo < s.at.p) {
      if (lo <= t_lo + 0.5 * kGridStep) return s;
      hi = s.t;
      p_hi = s.at.p;
      s.t = lo;
      s.at = value(lo);
      if (gives_up()) return s;
      lo -= kGridStep;
      p_lo = value(lo).p;
    } else if (p_hi < s.at.p) {
      if (hi >= t_hi - 0.5 * kGridStep) return s;
      lo = s.t;
      p_lo = s.at.p;
      s.t = hi;
      s.at = value(hi);
      if (gives_up()) return s;
      hi += kGridStep;
      p_hi = value(hi).p;
    } else {
      break;
    }
  }
  s.interior = true;
  bool failed = false;
  for (int step = 0; step < kNewtonSteps; ++step) {
    const ProfileValue& v = s.at;
    // Converged when a Newton step promises less than rounding, or the bracket has collapsed.
    if (v.d2p > 0.0 && 0.5 * v.dp * v.dp / v.d2p <= 1e-12 * (1.0 + std::fabs(v.p))) {
      s.converged = true;
      break;
    }
    if (hi - lo <= 1e-12 * (1.0 + std::fabs(s.t))) {
      s.converged = true;
      break;
    }
    if (gives_up()) return s;
    double trial = s.t - v.dp / v.d2p;
    if (failed || !(v.d2p > 0.0) || !(trial > lo && trial < hi)) {
      const bool left = v.dp > 0.0 || (v.dp == 0.0 && s.t - lo > hi - s.t);
      trial = left ? s.t - 0.381966 * (s.t - lo) : s.t + 0.381966 * (hi - s.t);
    }
    const ProfileValue w = value(trial);
    failed = !(w.p < v.p);
    if (!failed) {
      (trial < s.t ? hi : lo) = s.t;
      s.t = trial;
      s.at = w;
    } else {
      (trial < s.t ? lo : hi) = trial;
    }
  }
  return s;
}

}  // namespace

void allow_profile_lanes(bool allow) {
  allow_lanes.store(allow, std::memory_order_relaxed);
}

TwoTermRange two_term_range(TwoTermForm form, const std::vector<double>& y,
                            const std::vector<double>& e) {
  TwoTermRange r;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double z = ratio_data(form, y[i]);
    r.z_max = std::max(r.z_max, z);
    if (z > 0.0) r.z_min = std::min(r.z_min, z);
    r.e2 += e[i] * e[i];
  }
  return r;
}

TwoTermMaximum two_term_maximum(TwoTermForm form, const std::vector<double>& y,
                                const std::vector<double>& e) {
  return two_term_maximum(form, y, e, two_term_range(form, y, e), HUGE_VAL);
}

TwoTermMaximum two_term_maximum(TwoTermForm form, const std::vector<double>& y,
                                const std::vector<double>& e, const TwoTermRange& range,
                                double give_up_above) {
  TwoTermMaximum out;
  const double z_max = range.z_max, z_min = range.z_min;
  // No residual or no fitted value off zero: the bounds are all there is.
  if (!(range.e2 > 0.0) || !(z_max > 0.0)) return out;
  const double t_lo = std::log(1.0 / (kBoundReach * z_max));
  const double t_hi = std::min(std::log(kBoundReach / z_min), t_lo + kMaxDecades * std::log(10.0));
  const int points = static_cast<int>(std::ceil((t_hi - t_lo) / kGridStep)) + 1;
  const std::size_t stride = y.size() / kGridRows + 1;
  const std::vector<double> grid = profile_grid(form, y, e, t_lo, points, stride);
  // Interior local minima of the grid, best first (the ends stand for the bounds).
  std::vector<int> minima;
  for (int j = 1; j + 1 < points; ++j)
    if (grid[j] < grid[j - 1] && grid[j] <= grid[j + 1]) minima.push_back(j);
  std::sort(minima.begin(), minima.end(), [&](int a, int b) { return grid[a] < grid[b]; });
  if (minima.size() > kStarts) minima.resize(kStarts);
  Search best;
  for (int j : minima) {
    const Search s = search_from(form, y, e, t_lo + j * kGridStep, t_lo,
                                 t_lo + (points - 1) * kGridStep, give_up_above);
    if (s.given_up) {
      ++out.given_up;
      continue;
    }
    if (s.interior && (!best.interior || s.at.p < best.at.p)) best = s;
  }
  if (!best.interior) return out;
  const double a = best.at.floor_variance, tau = std::exp(best.t);
  out.found = a > 0.0;
  out.s_abs = std::sqrt(a);
  out.s_rel = form == TwoTermForm::Affine ? std::sqrt(a * tau) : std::sqrt(a) * tau;
  out.neg2_loglik = best.at.p;
  out.converged = best.converged;
  return out;
}

double remaining_gain(TwoTermForm form, double s_abs, double s_rel, const std::vector<double>& y,
                      const std::vector<double>& e) {
  if (!(s_abs > 0.0) && !(s_rel > 0.0)) return 0.0;
  // D_i = d ln sigma_i^2 / d(ln s_abs, ln s_rel), or d/d(s_abs^2, s_rel^2) (affine) and
  // d/d(s_abs, s_rel) (additive) for a parameter at 0.
  double g0 = 0.0, g1 = 0.0, f00 = 0.0, f01 = 0.0, f11 = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    double d0, d1, v;
    if (form == TwoTermForm::Affine) {
      const double a = s_abs * s_abs, b = s_rel * s_rel * y[i] * y[i];
      v = std::max(a + b, kTinyVariance);
      d0 = s_abs > 0.0 ? 2.0 * a / v : 1.0 / v;
      d1 = s_rel > 0.0 ? 2.0 * b / v : y[i] * y[i] / v;
    } else {
      const double b = s_rel * std::fabs(y[i]), sd = std::max(s_abs + b, 1e-150);
      v = sd * sd;
      d0 = s_abs > 0.0 ? 2.0 * s_abs / sd : 2.0 / sd;
      d1 = s_rel > 0.0 ? 2.0 * b / sd : 2.0 * std::fabs(y[i]) / sd;
    }
    const double r = 1.0 - e[i] * e[i] / v;
    g0 += r * d0;
    g1 += r * d1;
    f00 += d0 * d0;
    f01 += d0 * d1;
    f11 += d1 * d1;
  }
  // A parameter at 0 whose inward derivative does not descend is held.
  const bool free0 = s_abs > 0.0 || g0<0.0, free1 = s_rel> 0.0 || g1 < 0.0;
  if (free0 && free1) {
    const double det = f00 * f11 - f01 * f01;
    if (det > 0.0) return 0.5 * (f11 * g0 * g0 - 2.0 * f01 * g0 * g1 + f00 * g1 * g1) / det;
  }
  double gain = 0.0;
  if (free0 && f00 > 0.0) gain = std::max(gain, 0.5 * g0 * g0 / f00);
  if (free1 && f11 > 0.0) gain = std::max(gain, 0.5 * g1 * g1 / f11);
  return gain;
}

}  // namespace frictionid
