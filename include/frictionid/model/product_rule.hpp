// Product integration (docs/physics.md §9.3): ∫ w(s) F(s) ds over a part [s0, s1], for a
// weight w that is a polynomial of low degree on each of many pieces (a table law, which kinks
// at every sample) and an F analytic across the pieces. F is taken at n Chebyshev points and its
// interpolant p = sum_{j<n} a_j T_j(x) (x the coordinate of s in [-1, 1]) integrated against w
// exactly: sum_j a_j mu_j with the moments mu_j = ∫ w T_j(x) ds. That is a weight per point,
//   W_i = (2/n) sum'_j mu_j T_j(x_i),   x_i = cos(pi (2i + 1)/(2n))   (sum': j = 0 halved),
// and the integral is sum_i W_i F(s_i). n readings of F a part, however many pieces the part
// holds, where Gauss–Legendre between the pieces' ends takes 4-7 a piece.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <frictionid/model/gauss_legendre_rule.hpp>

namespace frictionid::model {

// sum_k c_k (s - a)^k on [a, b).
struct PolynomialPiece {
  double a, b;
  std::array<double, 5> c;
  double operator()(double s) const {
    const double u = s - a;
    return c[0] + u * (c[1] + u * (c[2] + u * (c[3] + u * c[4])));
  }
};

inline constexpr int kMostProductPoints = 48;

// The Chebyshev points for an F analytic within the Bernstein ellipse of parameter rho: the
// interpolant errs by ~rho^-n, and a polynomial factor of `degrees` takes as many more.
inline int product_points(double rho, double log_tolerance, int degrees) {
  if (!(rho > 1.0)) return kMostProductPoints;
  const double n = std::ceil(log_tolerance / std::log(rho)) + degrees;
  return n < kMostProductPoints ? std::max(8, static_cast<int>(n)) : kMostProductPoints;
}

// The moments mu_j, j < n, over [s0, s1] of the weight the pieces (sorted, disjoint) make, each a
// polynomial of at most `degree`: Gauss–Legendre on each piece within, exact for w T_j. The
// recurrence for T_j runs over all of a piece's points at once (independent chains, where one
// point at a time waits on each step).
inline void chebyshev_moments(const std::vector<PolynomialPiece>& pieces, double s0, double s1,
                              int n, int degree, double* mu) {
  std::fill(mu, mu + n, 0.0);
  const std::vector<QuadratureNode>& rule = gauss_legendre_rule((n + degree + 1) / 2);
  const std::size_t m = rule.size();
  double x[kMostProductPoints], w[kMostProductPoints], t0[kMostProductPoints],
      t1[kMostProductPoints];
  const double mid = 0.5 * (s0 + s1), inv_half = 2.0 / (s1 - s0);
  auto k = std::upper_bound(pieces.begin(), pieces.end(), s0,
                            [](double s, const PolynomialPiece& p) { return s < p.b; });
  for (; k != pieces.end() && k->a < s1; ++k) {
    const double lo = std::max(k->a, s0), hi = std::min(k->b, s1), len = hi - lo;
    if (!(len > 0.0)) continue;
    // The nodes placed in x: s rounded to its own magnitude would move them by ~1e-16 s/half.
    const double x_lo = (lo - mid) * inv_half, x_len = (hi - mid) * inv_half - x_lo;
    double m0 = 0.0, m1 = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
      x[i] = x_lo + x_len * rule[i].from_left;
      w[i] = rule[i].weight * len * (*k)(mid + 0.5 * (s1 - s0) * x[i]);
      t0[i] = 1.0;
      t1[i] = x[i];
      m0 += w[i];
      m1 += w[i] * x[i];
    }
    mu[0] += m0;
    mu[1] += m1;
    for (int j = 2; j < n; ++j) {
      double sum[2] = {0.0, 0.0};  // two chains of additions
      for (std::size_t i = 0; i < m; ++i) {
        const double t2 = 2.0 * x[i] * t1[i] - t0[i];
        sum[i % 2] += w[i] * t2;
        t0[i] = t1[i];
        t1[i] = t2;
      }
      mu[j] += sum[0] + sum[1];
    }
  }
}

// The Chebyshev points cos(pi (2i + 1)/(2n)), i < n, for n up to kMostProductPoints.
inline const double* chebyshev_points(int n) {
  static const std::vector<std::vector<double>> points = [] {
    std::vector<std::vector<double>> all(kMostProductPoints + 1);
    for (int k = 1; k <= kMostProductPoints; ++k)
      for (int i = 0; i < k; ++i)
        all[static_cast<std::size_t>(k)].push_back(std::cos(M_PI * (2 * i + 1) / (2.0 * k)));
    return all;
  }();
  return points[static_cast<std::size_t>(n)].data();
}

// The points x_i in [-1, 1] and their weights W_i from the moments (above), i < n.
inline void product_weights(const double* mu, int n, double* x, double* W) {
  const double* points = chebyshev_points(n);
  for (int i = 0; i < n; ++i) {
    x[i] = points[i];
    double t0 = 1.0, t1 = x[i], sum = 0.5 * mu[0] + mu[1] * x[i];
    for (int j = 2; j < n; ++j) {
      const double t2 = 2.0 * x[i] * t1 - t0;
      sum += mu[j] * t2;
      t0 = t1;
      t1 = t2;
    }
    W[i] = 2.0 / n * sum;
  }
}

// The weights W_i, i < n, of the part [s0, s1] (above, chebyshev_points(n) mapped onto it) for
// the weight the pieces make, times a factor (1 - s^2)^rim at their points (none for rim = 0).
inline void product_rule_weights(const std::vector<PolynomialPiece>& pieces, double s0, double s1,
                                 int n, int degree, double rim, double* W) {
  double mu[kMostProductPoints], x[kMostProductPoints];
  chebyshev_moments(pieces, s0, s1, n, degree, mu);
  product_weights(mu, n, x, W);
  if (rim != 0.0)
    for (int i = 0; i < n; ++i) {
      const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * x[i];
      W[i] *= std::pow((1.0 - s) * (1.0 + s), rim);
    }
}

// [lo, hi] cut at the sorted breaks strictly within and at `at` if it lies within: the pieces a
// part next to a singularity is integrated on, each by a rule that takes its ends.
inline std::vector<double> cuts_within(const std::vector<double>& breaks, double lo, double hi,
                                       double at) {
  std::vector<double> cuts = {lo};
  for (auto b = std::upper_bound(breaks.begin(), breaks.end(), lo); b != breaks.end() && *b < hi;
       ++b)
    cuts.push_back(*b);
  if (at > lo && at < hi) cuts.push_back(at);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

// The product rule on the dyadic parts of one interval [lo, hi] for one weight: part k of level L
// is [lo + (hi - lo) k/2^L, lo + (hi - lo)(k + 1)/2^L]. A part's weights W_i depend only on the
// part, the weight and n, not on F, so they are computed once, for every part of the first kLevels
// levels and every n in kPoints (~0.5 MB; 16 ms for a table of 201 samples), and read at every
// point, where the moments alone took a third of a table law's build. A deeper part's weights are
// computed when asked for. Rules built for the same weight share their weights (kept_weights).
// A factor (1 - s^2)^e of the integrand, which the weight leaves out because it is singular at
// s = 1 (a table's rim, docs/physics.md §9.3), is the same at a part's points for every F: the
// weights carry it (pow at every point took a fifth of a build).
class DyadicProductRule {
 public:
  static constexpr int kLevels = 8;
  static constexpr std::array<int, 11> kPoints = {8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48};

  DyadicProductRule() = default;
  // The weight: `pieces` (sorted, disjoint), each a polynomial of at most `degree`, and the
  // factor (1 - s^2)^rim (none for rim = 0; 0 <= lo < hi <= 1 otherwise).
  DyadicProductRule(std::vector<PolynomialPiece> pieces, double lo, double hi, int degree,
                    double rim = 0.0)
      : pieces_(std::move(pieces)), lo_(lo), hi_(hi), degree_(degree), rim_(rim) {
    weights_ = kept_weights();
  }

  // The least n of kPoints >= want (or the most).
  static int points(int want) {
    for (int n : kPoints)
      if (n >= want) return n;
    return kPoints.back();
  }

  double part_lo(int level, long k) const {
    return k == 0 ? lo_ : lo_ + (hi_ - lo_) * std::ldexp(static_cast<double>(k), -level);
  }
  double part_hi(int level, long k) const {
    const double at = std::ldexp(static_cast<double>(k + 1), -level);
    return at == 1.0 ? hi_ : lo_ + (hi_ - lo_) * at;
  }

  // The n weights (n from kPoints) of part k of `level`, for the points chebyshev_points(n)
  // mapped onto the part, the factor included; `scratch` (kMostProductPoints long) holds those
  // of a deeper part.
  const double* weights(int level, long k, int n, double* scratch) const {
    if (level >= kLevels || !weights_) {
      compute(level, k, n, scratch);
      return scratch;
    }
    std::size_t at =
        ((static_cast<std::size_t>(1) << level) - 1 + static_cast<std::size_t>(k)) * kPointsSum;
    for (int p : kPoints) {
      if (p == n) break;
      at += static_cast<std::size_t>(p);
    }
    return weights_->data() + at;
  }

 private:
  static constexpr std::size_t kKept = 8;

  bool same(const DyadicProductRule& o) const {
    if (lo_ != o.lo_ || hi_ != o.hi_ || degree_ != o.degree_ || rim_ != o.rim_ ||
        pieces_.size() != o.pieces_.size())
      return false;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      const PolynomialPiece &p = pieces_[i], &r = o.pieces_[i];
      if (p.a != r.a || p.b != r.b || p.c != r.c) return false;
    }
    return true;
  }

  // The stored weights, shared with the last kKept rules of the same weight: a model is made for
  // every evaluation a fit asks for (spot_model.hpp), each with its integrator and this rule, and
  // computing them takes 16 ms for 201 samples (a fit of 10,000 rows took 45 s instead of 1).
  std::shared_ptr<const std::vector<double>> kept_weights() const {
    static std::mutex mutex;
    static std::vector<std::pair<DyadicProductRule, std::shared_ptr<const std::vector<double>>>>
        kept;
    const std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [rule, weights] : kept)
      if (same(rule)) return weights;
    auto weights = std::make_shared<std::vector<double>>();
    for (int level = 0; level < kLevels; ++level)
      for (int k = 0; k < (1 << level); ++k)
        for (int n : kPoints) {
          double W[kMostProductPoints];
          compute(level, k, n, W);
          weights->insert(weights->end(), W, W + n);
        }
    if (kept.size() == kKept) kept.erase(kept.begin());
    kept.emplace_back(*this, weights);  // (its own weights_ not yet set)
    return weights;
  }

  void compute(int level, long k, int n, double* W) const {
    product_rule_weights(pieces_, part_lo(level, k), part_hi(level, k), n, degree_, rim_, W);
  }

  static constexpr std::size_t kPointsSum = 252;  // the sum of kPoints
  std::vector<PolynomialPiece> pieces_;
  double lo_ = 0.0, hi_ = 1.0;
  int degree_ = 0;
  double rim_ = 0.0;
  // Part k of level L at (2^L - 1 + k) kPointsSum, n by n.
  std::shared_ptr<const std::vector<double>> weights_;
};

}  // namespace frictionid::model
