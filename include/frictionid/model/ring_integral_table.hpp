// The six ring integrals of one pressure law (ring_integrals.hpp), tabulated once over eps by
// piecewise Chebyshev interpolation, so that the exact model costs tens of nanoseconds per
// point instead of a radial quadrature of ~100 kernel evaluations. A fit evaluates the same law
// at every row of every iteration: the table pays for itself from a few thousand rows on.
//
// Construction. Each integral I_j is divided by a normaliser n_j(eps) that carries its power
// law at both ends (docs/physics.md §2 limits: I_P, I_V, I_X ~ eps and I_U ~ eps as eps -> 0,
// I_Q ~ 1/eps, I_S ~ eps^-3, I_U ~ eps^-2 as eps -> inf), so g_j = I_j/n_j is finite and
// nonzero at both ends and analytic in u = ln(eps) except at eps = 1, where the split point
// reaches the rim and terms like (1 - eps) ln|1 - eps| appear, and at eps = B for every step B of
// sigma0 (annulus:B, a table's step). Pieces in u are graded geometrically towards those points
// from both sides (widths 2^-k down to 2^-36): each piece then sits
// at a fixed relative distance from the singularity and degree-16 Chebyshev interpolation
// converges fast on it. A piece whose trailing coefficients stay above the tolerance is split
// again. Nodes are computed with the fine radial rule (~1e-15), so the table reproduces the
// exact integrals to ~1e-13 relative; beyond eps in [1e-12, 1e8] g is held at its end value
// (relative error O(eps) below, O(eps^-2) above: < 1e-12).
//
// A power law can also carry d/dn of every integral (the same quadrature with the weight
// sigma0 ln(1 - rho^2)), which a fit with a free exponent needs for its Jacobian.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/ring_integrals.hpp>
#include <frictionid/model/scalar_ops.hpp>

namespace frictionid::model {

namespace detail {
// A value with its derivative along one direction: enough arithmetic for the radial quadrature.
struct ValueSlope {
  double value = 0.0, slope = 0.0;
  ValueSlope() = default;
  explicit ValueSlope(double v, double s = 0.0) : value(v), slope(s) {}
  ValueSlope operator*(double w) const { return ValueSlope(value * w, slope * w); }
  ValueSlope& operator+=(const ValueSlope& o) {
    value += o.value;
    slope += o.slope;
    return *this;
  }
};
}  // namespace detail

// I_j = g_j(eps) * n_j(eps); n_j for (P, Q, S, U, V, X). E: a double, or a dual number.
template <typename E>
std::array<E, 6> ring_integral_normalisers(const E& eps) {
  using std::sqrt;
  // w = 1/sqrt(1 + eps^2), written to stay finite for huge eps.
  const E w =
      eps <= 1.0 ? E(1.0 / sqrt(1.0 + eps * eps)) : E(1.0 / (eps * sqrt(1.0 + 1.0 / (eps * eps))));
  const E slide = eps <= 1.0 ? E(eps * w) : E(1.0 / sqrt(1.0 + 1.0 / (eps * eps)));
  const E w3 = w * w * w;
  return {slide, w, w3, slide * w * w, slide, slide};
}

// Thrown by a table build that its `stop` check asked to stop (a cancelled fit).
class RingTableBuildStopped : public std::runtime_error {
 public:
  RingTableBuildStopped() : std::runtime_error("the ring-integral table's build was stopped") {}
};

class RingIntegralTable {
 public:
  static constexpr int kDegree = 16;
  static constexpr double kMinLogEps = -27.631021115928547;  // ln(1e-12)
  static constexpr double kMaxLogEps = 18.420680743952367;   // ln(1e8)

  // Tabulates the law's integrals (and, for a power law with with_n_slope, their derivatives
  // with respect to the exponent n). The build asks `stop` between nodes and throws
  // RingTableBuildStopped when it says so: a table of many samples takes seconds, and Ctrl-C must
  // not wait for it.
  explicit RingIntegralTable(const PressureLaw<double>& law, bool with_n_slope = false,
                             std::function<bool()> stop = {})
      : law_(law),
        slopes_(with_n_slope && law.kind == PressureKind::Power),
        stop_(std::move(stop)) {
    std::vector<double> breaks = {kMinLogEps, -16.0, -8.0, -4.0, -2.0, -1.0,
                                  0.0,        1.0,   2.0,  4.0,  8.0,  kMaxLogEps};
    graded_towards(0.0, breaks);
    // A step of sigma0 at rho = B puts (eps - B)^2 ln|eps - B| into the integrals: graded too.
    // Kinks and a table's C^1 samples are milder; the adaptive splitting below resolves them.
    for (double b : law.steps()) graded_towards(std::log(b), breaks);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(
        std::unique(breaks.begin(), breaks.end(), [](double x, double y) { return y - x < 1e-15; }),
        breaks.end());
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) build(breaks[i], breaks[i + 1], 0);
    stop_ = nullptr;  // only the build asks it; what it captured may not outlive the caller
  }

  const PressureLaw<double>& law() const { return law_; }
  bool has_n_slope() const { return slopes_; }

  // The six integrals at eps in [0, inf) (P, Q, S, U, V, X), and with slopes their derivatives
  // with respect to n. eps = inf (pure sliding) is the caller's: every integral is a moment.
  // eps may be a dual number: the values then carry the interpolant's derivative along it.
  template <typename E>
  void evaluate(const E& eps, E* values, E* n_slopes = nullptr) const {
    using std::log;
    const E u = eps > 0.0 ? std::clamp(E(log(eps)), E(kMinLogEps), E(kMaxLogEps)) : E(kMinLogEps);
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), value_of(u));
    const Piece& piece = pieces_[static_cast<std::size_t>(
        std::max<std::ptrdiff_t>(0, std::distance(starts_.begin(), it) - 1))];
    const E x =
        std::clamp(E((2.0 * u - (piece.u0 + piece.u1)) / (piece.u1 - piece.u0)), E(-1.0), E(1.0));
    // Clenshaw's recurrence for every channel at once.
    E b1[kChannels] = {}, b2[kChannels] = {};
    const int channels = slopes_ ? kChannels : 6;
    for (int k = kDegree; k >= 1; --k) {
      const double* c = &piece.coeff[static_cast<std::size_t>(k) * kChannels];
      for (int j = 0; j < channels; ++j) {
        const E b0 = 2.0 * x * b1[j] - b2[j] + c[j];
        b2[j] = b1[j];
        b1[j] = b0;
      }
    }
    const auto n = ring_integral_normalisers(eps);
    for (int j = 0; j < 6; ++j) values[j] = (x * b1[j] - b2[j] + piece.coeff[j]) * n[j];
    if (n_slopes != nullptr)
      for (int j = 0; j < 6; ++j)
        n_slopes[j] = slopes_ ? E((x * b1[6 + j] - b2[6 + j] + piece.coeff[6 + j]) * n[j]) : E(0.0);
  }

 private:
  static constexpr int kChannels = 12;  // six integrals, then their n-slopes
  static constexpr int kGradingLevels = 36;
  static constexpr int kMaxDepth = 12;
  static constexpr double kTolerance = 1e-13;

  struct Piece {
    double u0, u1;
    std::vector<double> coeff;  // (kDegree + 1) x kChannels, degree-major
  };

  // Breaks at u0 +- 2^-k, k = 1..kGradingLevels: pieces at a fixed relative distance from a
  // singular point u0.
  static void graded_towards(double u0, std::vector<double>& breaks) {
    for (int k = 1; k <= kGradingLevels; ++k) {
      breaks.push_back(u0 - std::ldexp(1.0, -k));
      breaks.push_back(u0 + std::ldexp(1.0, -k));
    }
  }

  // g_j at one node: the quadrature divided by the normalisers.
  std::array<double, kChannels> node_values(double eps) {
    std::array<double, kChannels> g{};
    const auto n = ring_integral_normalisers(eps);
    if (slopes_) {
      const double nn = law_.n;
      const auto weight = [nn](double rho, double one_minus_rho) {
        const double rim = one_minus_rho * (1.0 + rho);
        if (!(rim > 0.0)) return detail::ValueSlope(nn == 0.0 ? 1.0 : 0.0, 0.0);
        const double lr = std::log(rim), s = std::exp(nn * lr);
        return detail::ValueSlope(s, s * lr);  // d/dn (1 - rho^2)^n
      };
      const auto in = weighted_ring_integrals<detail::ValueSlope>(weight, eps, fine_rule());
      const detail::ValueSlope v[6] = {in.P, in.Q, in.S, in.U, in.V, in.X};
      for (int j = 0; j < 6; ++j) {
        g[static_cast<std::size_t>(j)] = v[j].value / n[static_cast<std::size_t>(j)];
        g[static_cast<std::size_t>(6 + j)] = v[j].slope / n[static_cast<std::size_t>(j)];
      }
    } else {
      const auto in = law_ring_integrals(law_, eps, fine_rule());
      const double v[6] = {in.P, in.Q, in.S, in.U, in.V, in.X};
      for (int j = 0; j < 6; ++j)
        g[static_cast<std::size_t>(j)] = v[j] / n[static_cast<std::size_t>(j)];
    }
    return g;
  }

  void build(double u0, double u1, int depth) {
    constexpr int d = kDegree;
    std::array<std::array<double, kChannels>, d + 1> f;
    for (int i = 0; i <= d; ++i) {
      if (stop_ && stop_()) throw RingTableBuildStopped();
      // Chebyshev extreme points, ordered from u1 down to u0.
      const double x = std::cos(M_PI * i / d);
      f[static_cast<std::size_t>(i)] = node_values(std::exp(0.5 * (u0 + u1) + 0.5 * (u1 - u0) * x));
    }
    Piece piece{u0, u1, std::vector<double>(static_cast<std::size_t>((d + 1) * kChannels), 0.0)};
    // Discrete Chebyshev transform on the extreme points (halved end terms).
    for (int k = 0; k <= d; ++k)
      for (int j = 0; j < kChannels; ++j) {
        double sum = 0.0;
        for (int i = 0; i <= d; ++i) {
          const double w = (i == 0 || i == d) ? 0.5 : 1.0;
          sum += w * f[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] *
                 std::cos(M_PI * k * i / d);
        }
        const double ck = (k == 0 || k == d ? 1.0 : 2.0) * sum / d;
        piece.coeff[static_cast<std::size_t>(k * kChannels + j)] = ck;
      }
    // Converged when the last two coefficients are negligible against the channel's size.
    bool converged = true;
    for (int j = 0; j < (slopes_ ? kChannels : 6); ++j) {
      double size = 0.0;
      for (int i = 0; i <= d; ++i)
        size =
            std::max(size, std::fabs(f[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]));
      const double tail = std::fabs(piece.coeff[static_cast<std::size_t>(d * kChannels + j)]) +
                          std::fabs(piece.coeff[static_cast<std::size_t>((d - 1) * kChannels + j)]);
      if (tail > kTolerance * size) converged = false;
    }
    if (!converged && depth < kMaxDepth) {
      const double mid = 0.5 * (u0 + u1);
      build(u0, mid, depth + 1);
      build(mid, u1, depth + 1);
      return;
    }
    starts_.push_back(u0);
    pieces_.push_back(std::move(piece));
  }

  PressureLaw<double> law_;
  bool slopes_;
  std::function<bool()> stop_;  // asked between nodes of the build; empty: never stops
  std::vector<double> starts_;  // u0 of every piece, increasing
  std::vector<Piece> pieces_;
};

}  // namespace frictionid::model
