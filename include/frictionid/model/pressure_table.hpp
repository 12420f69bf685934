// A tabulated static pressure sigma0(rho) (docs/physics.md §1, LAW = table:FILE).
// Interpolation is edge-aware: when the table ends with sigma0(1) = 0 it is written as
//   sigma0 = (1 - rho^2)^gamma * g(rho),
// gamma estimated from the last two positive samples, and g interpolated by monotone cubic
// Hermite (Fritsch–Carlson, never overshoots, so sigma0 stays >= 0). A table sampled from
// (1 - rho^2)^n thus reproduces it up to the smoothness of g, instead of losing the rim's
// square-root behaviour to a linear segment (which costs ~1e-4 in m0 for 200 Hertz samples).
//
// Steps: two samples with the same rho state a jump, the value before and then after it (an
// annulus with inner radius 0.3 is 0,0 / 0.3,0 / 0.3,1 / 1,1). The samples between steps form
// runs that are interpolated independently; at the step itself sigma0 takes the value after.
// The interpolant is only C^1 at a sample and jumps at a step: breakpoints() lists both, and
// every radial integral splits there (ring_integrals.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace frictionid::model {

class PressureTable {
 public:
  // Throws std::invalid_argument naming the (0-based) sample when the table is unusable.
  PressureTable(std::vector<double> rho, std::vector<double> sigma) {
    if (rho.size() != sigma.size()) throw std::invalid_argument("rho and sigma0 differ in length");
    if (rho.size() < 2) throw std::invalid_argument("a pressure table needs at least 2 samples");
    bool any_positive = false;
    for (std::size_t i = 0; i < rho.size(); ++i) {
      if (!std::isfinite(rho[i]) || rho[i] < 0.0 || rho[i] > 1.0)
        throw std::invalid_argument("sample " + std::to_string(i) + ": rho must be in [0, 1]");
      if (i > 0 && rho[i] < rho[i - 1])
        throw std::invalid_argument("sample " + std::to_string(i) + ": rho must increase");
      if (i > 1 && rho[i] == rho[i - 1] && rho[i] == rho[i - 2])
        throw std::invalid_argument("sample " + std::to_string(i) +
                                    ": rho must increase (a step takes exactly two rows with the "
                                    "same rho: the value before and the value after)");
      if (!std::isfinite(sigma[i]) || sigma[i] < 0.0)
        throw std::invalid_argument("sample " + std::to_string(i) + ": sigma0 must be >= 0");
      any_positive = any_positive || sigma[i] > 0.0;
    }
    if (!any_positive) throw std::invalid_argument("sigma0 is zero everywhere");

    const std::size_t n = rho.size();
    gamma_ = 0.0;
    std::size_t used = n;
    if (n >= 3 && rho[n - 1] == 1.0 && sigma[n - 1] == 0.0 && sigma[n - 2] > 0.0 &&
        sigma[n - 3] > 0.0 && rho[n - 3] < rho[n - 2] && rho[n - 2] < rho[n - 1]) {
      const double g = std::log(sigma[n - 2] / sigma[n - 3]) /
                       std::log((1.0 - rho[n - 2] * rho[n - 2]) / (1.0 - rho[n - 3] * rho[n - 3]));
      if (std::isfinite(g) && g > 0.0) {
        gamma_ = std::min(g, 8.0);
        used = n - 1;  // g(1) = 0/0: extrapolate g from the interior instead
      }
    }
    rho_.assign(rho.begin(), rho.begin() + static_cast<std::ptrdiff_t>(used));
    g_.resize(used);
    for (std::size_t i = 0; i < used; ++i)
      g_[i] = sigma[i] / std::pow((1.0 - rho_[i]) * (1.0 + rho_[i]), gamma_);
    slope_.assign(used, 0.0);
    // Runs of increasing rho between steps, each with its own monotone slopes.
    std::size_t start = 0;
    for (std::size_t i = 1; i <= used; ++i) {
      if (i < used && rho_[i] > rho_[i - 1]) continue;
      const std::vector<double> x(rho_.begin() + static_cast<std::ptrdiff_t>(start),
                                  rho_.begin() + static_cast<std::ptrdiff_t>(i));
      const std::vector<double> y(g_.begin() + static_cast<std::ptrdiff_t>(start),
                                  g_.begin() + static_cast<std::ptrdiff_t>(i));
      const std::vector<double> d = monotone_slopes(x, y);
      std::copy(d.begin(), d.end(), slope_.begin() + static_cast<std::ptrdiff_t>(start));
      if (i < used && g_[i] != g_[i - 1] && rho_[i] > 0.0 && rho_[i] < 1.0) {
        steps_.push_back(rho_[i]);
        const double edge =
            gamma_ == 0.0 ? 1.0 : std::pow((1.0 - rho_[i]) * (1.0 + rho_[i]), gamma_);
        jumps_.push_back({rho_[i], edge * (g_[i - 1] - g_[i])});
      }
      start = i;
    }
    for (double r : rho_)
      if (r > 0.0 && r < 1.0 && (breakpoints_.empty() || breakpoints_.back() != r))
        breakpoints_.push_back(r);
  }

  double gamma() const { return gamma_; }
  // The samples' rho, a step's rho twice (the rim sample is dropped when gamma > 0).
  const std::vector<double>& nodes() const { return rho_; }
  // Distinct rho in (0, 1) where sigma0 or its derivatives jump: every sample.
  const std::vector<double>& breakpoints() const { return breakpoints_; }
  // The rho in (0, 1) where sigma0 itself jumps (steps with different values).
  const std::vector<double>& steps() const { return steps_; }

  // sigma0 at rho, with one_minus_rho = 1 - rho given to full precision near the rim.
  double operator()(double rho, double one_minus_rho) const {
    const double edge = gamma_ == 0.0 ? 1.0 : std::pow(one_minus_rho * (1.0 + rho), gamma_);
    return edge * interpolate(rho);
  }

  // d sigma0/d rho at rho (0 < rho < 1), on the run that holds rho (the one after a step at
  // rho itself). Near the rim with gamma > 0 it grows like (1 - rho^2)^(gamma - 1).
  double slope(double rho, double one_minus_rho) const {
    const double g = interpolate(rho), dg = interpolate_slope(rho);
    if (gamma_ == 0.0) return dg;
    const double rim = one_minus_rho * (1.0 + rho);
    const double edge = std::pow(rim, gamma_);
    return edge * dg - 2.0 * gamma_ * rho * (edge / rim) * g;
  }

  // Where sigma0 jumps, and by how much it drops there: sigma0 just inside minus just outside.
  struct Jump {
    double rho, drop;
  };
  const std::vector<Jump>& jumps() const { return jumps_; }

  // g as a cubic in u = rho - a on each interval [a, b) between two samples of a run, and as a
  // constant below the first sample and from the last on (sigma0 = (1 - rho^2)^gamma g): the
  // interpolant, piece by piece, for integrals that take it exactly (ellipse_law_integrator.hpp).
  struct Cubic {
    double a, b;
    std::array<double, 4> c;  // g = c0 + c1 u + c2 u^2 + c3 u^3
  };
  std::vector<Cubic> cubics() const {
    std::vector<Cubic> out;
    if (rho_.front() > 0.0) out.push_back({0.0, rho_.front(), {g_.front(), 0.0, 0.0, 0.0}});
    for (std::size_t i = 0; i + 1 < rho_.size(); ++i) {
      const double h = rho_[i + 1] - rho_[i];
      if (!(h > 0.0)) continue;  // a step: the next run starts here
      const double d = (g_[i + 1] - g_[i]) / h;
      out.push_back({rho_[i],
                     rho_[i + 1],
                     {g_[i], slope_[i], (3.0 * d - 2.0 * slope_[i] - slope_[i + 1]) / h,
                      (slope_[i] + slope_[i + 1] - 2.0 * d) / (h * h)}});
    }
    if (rho_.back() < 1.0) out.push_back({rho_.back(), 1.0, {g_.back(), 0.0, 0.0, 0.0}});
    return out;
  }

  // How strongly sigma0 kinks at each sample inside a run: the jump of its second derivative
  // there (its interpolant is C^1), largest first. A spot's table grades its cells at the
  // strongest of them (spot_integral_table.hpp).
  struct Kink {
    double rho, strength;
  };
  std::vector<Kink> kinks() const {
    std::vector<Kink> out;
    for (std::size_t i = 1; i + 1 < rho_.size(); ++i) {
      if (rho_[i] == rho_[i - 1] || rho_[i + 1] == rho_[i]) continue;  // a step's sample
      const double h0 = rho_[i] - rho_[i - 1], h1 = rho_[i + 1] - rho_[i];
      // g'' at the end of the piece before and at the start of the piece after.
      const double before =
          (6.0 * (g_[i - 1] - g_[i]) + 2.0 * h0 * slope_[i - 1] + 4.0 * h0 * slope_[i]) / (h0 * h0);
      const double after =
          (-6.0 * (g_[i] - g_[i + 1]) - 4.0 * h1 * slope_[i] - 2.0 * h1 * slope_[i + 1]) /
          (h1 * h1);
      const double edge = gamma_ == 0.0 ? 1.0 : std::pow((1.0 - rho_[i]) * (1.0 + rho_[i]), gamma_);
      out.push_back({rho_[i], edge * std::fabs(after - before)});
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Kink& a, const Kink& b) { return a.strength > b.strength; });
    return out;
  }

  // The law's moments m_0..m_5 (pressure_law.hpp), computed once by `compute` and kept: they
  // depend only on the samples, and a fit asks for them at every evaluation of every start,
  // which cost a pass over every sample each time (a 5000-sample table took minutes to fit).
  template <typename Compute>
  const std::array<double, 6>& moments(Compute compute) const {
    std::call_once(moments_once_, [&] { moments_ = compute(); });
    return moments_;
  }

 private:
  mutable std::once_flag moments_once_;
  mutable std::array<double, 6> moments_{};

  double interpolate(double x) const {
    // Constant extension outside the samples: sigma0 is even in the spot's centre.
    if (x < rho_.front()) return g_.front();
    if (x >= rho_.back()) return g_.back();
    // rho_[i] <= x < rho_[i + 1], both in one run (a step's second sample starts a run).
    const auto it = std::upper_bound(rho_.begin(), rho_.end(), x);
    const std::size_t i = static_cast<std::size_t>(it - rho_.begin()) - 1;
    const double h = rho_[i + 1] - rho_[i];
    const double t = (x - rho_[i]) / h;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * g_[i] + (t3 - 2 * t2 + t) * h * slope_[i] +
           (-2 * t3 + 3 * t2) * g_[i + 1] + (t3 - t2) * h * slope_[i + 1];
  }

  // The derivative of interpolate(): zero outside the samples, where g is held constant.
  double interpolate_slope(double x) const {
    if (x < rho_.front() || x >= rho_.back()) return 0.0;
    const auto it = std::upper_bound(rho_.begin(), rho_.end(), x);
    const std::size_t i = static_cast<std::size_t>(it - rho_.begin()) - 1;
    const double h = rho_[i + 1] - rho_[i];
    const double t = (x - rho_[i]) / h;
    const double t2 = t * t;
    return ((6 * t2 - 6 * t) * (g_[i] - g_[i + 1])) / h + (3 * t2 - 4 * t + 1) * slope_[i] +
           (3 * t2 - 2 * t) * slope_[i + 1];
  }

  static std::vector<double> monotone_slopes(const std::vector<double>& x,
                                             const std::vector<double>& y) {
    const std::size_t n = x.size();
    std::vector<double> d(n, 0.0), s(n > 1 ? n - 1 : 0);
    if (n < 2) return d;  // a run of one sample: a constant
    for (std::size_t i = 0; i + 1 < n; ++i) s[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
    if (n == 2) {
      d[0] = d[1] = s[0];
      return d;
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
      if (s[i - 1] * s[i] <= 0.0) continue;  // local extremum: flat
      const double w1 = 2 * (x[i + 1] - x[i]) + (x[i] - x[i - 1]);
      const double w2 = (x[i + 1] - x[i]) + 2 * (x[i] - x[i - 1]);
      d[i] = (w1 + w2) / (w1 / s[i - 1] + w2 / s[i]);  // weighted harmonic mean
    }
    auto end_slope = [](double h0, double h1, double s0, double s1) {
      double e = ((2 * h0 + h1) * s0 - h0 * s1) / (h0 + h1);
      if (e * s0 <= 0.0) return 0.0;
      if (s0 * s1 <= 0.0 && std::fabs(e) > std::fabs(3 * s0)) return 3 * s0;
      return e;
    };
    d[0] = end_slope(x[1] - x[0], x[2] - x[1], s[0], s[1]);
    d[n - 1] = end_slope(x[n - 1] - x[n - 2], x[n - 2] - x[n - 3], s[n - 2], s[n - 3]);
    return d;
  }

  double gamma_ = 0.0;
  std::vector<double> rho_, g_, slope_;
  std::vector<double> breakpoints_, steps_;
  std::vector<Jump> jumps_;  // at the steps: sigma0 just inside minus just outside
};

}  // namespace frictionid::model
