// The twelve integrals of a rectangle |x| <= 1, |y| <= q whose pressure sigma0(|x|) is uniform
// across y (docs/physics.md §9.1), by the y-integral in closed form and a 1-D quadrature in x.
// With a = x - c_x, eta = y - c_y and rho = sqrt(a^2 + eta^2),
//   ∫ e_x dy = -∫ eta/rho deta,   ∫ e_y dy = a ∫ deta/rho,
// whose primitives in eta are rho, ln(eta + rho), (eta rho - a^2 ln(eta + rho))/2 and
// rho^3/3 - a^2 rho (the weights y and y^2 expand in powers of eta), formed between the edges
// eta0 = -q - c_y and eta1 = q - c_y without cancellation. The x-integrand is smooth but for
// a ln|a| at x = c_x and the law's rim and breakpoints, where the x-range is cut; the fine
// tanh-sinh rule reaches ~1e-14 A0 on every piece. Far from the rectangle (more than 2 max(1, q)
// away) the closed forms' terms would cancel (they grow like |c|^2); there the y-integrand is
// analytic over the strip and 4-10 Gauss–Legendre points take it. 10-30 us a point, against
// 100-300 us for the ray integration of SpotIntegrator, whose default angular rule also errs by
// up to 5e-9 A0 within 1e-4 of a corner, where this has no difficulty. Not for the ring law (no
// density).
//
// A table of 64 samples or more is not cut at its samples: its sigma0 is (1 - x^2)^gamma g(|x|)
// with g a cubic between two samples, and the rest of the x-integrand, (1 - x^2)^gamma times
// the y-integrals, is analytic across them. The halves of the x-range are split into dyadic
// parts [k, k + 1]/2^L, halved towards c_x and (gamma fractional) the rim until their
// singularities keep 2 half-lengths away; each takes that factor at Chebyshev points and
// integrates it against g exactly (product_rule.hpp), with weights that depend only on the part
// and the number of points, computed once per law (0.5 MB; 16 ms for 201 samples, 57 ms for
// 1001). Parts of level 7 (1/128 long) next to c_x or the rim stay cut at the samples
// within, and at c_x.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model/product_rule.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

namespace frictionid::model {

class RectStripIntegrator {
 public:
  // The x-range is cut at every breakpoint of the law, however many: a table is a cubic between
  // two samples. A piece that ends at c_x or at the rim takes the fine tanh-sinh rule; any
  // other Gauss–Legendre with as many points as its distance from the nearest singularity asks
  // for (c_x +- i dist(c_y, |y| <= q), and +-1 where sigma0 ~ (1 - x^2)^gamma, gamma
  // fractional): 4-8 for most of a fine table's pieces. by_samples: so for a table of any
  // number of samples too (a reference for the product rule).
  RectStripIntegrator(const PressureLaw<double>& law, double q, bool by_samples = false)
      : law_(law), q_(q) {
    for (double b : law_.breakpoints())
      if (b > 0.0 && b < 1.0) {
        breaks_.push_back(b);
        signed_breaks_.push_back(b);
        signed_breaks_.push_back(-b);
      }
    std::sort(signed_breaks_.begin(), signed_breaks_.end());
    const double gamma = law_rim_exponent(law_);
    fractional_ = gamma != std::floor(gamma);
    product_ = law.kind == PressureKind::Table && law.table && !by_samples &&
               breaks_.size() >= kProductSamples;
    if (product_) {
      gamma_ = law.table->gamma();
      std::vector<PolynomialPiece> g_pieces;  // g on [0, 1]
      for (const PressureTable::Cubic& g : law.table->cubics())
        g_pieces.push_back({g.a, g.b, {g.c[0], g.c[1], g.c[2], g.c[3], 0.0}});
      // The weights of every dyadic part of [0, 1], with the rim's (1 - x^2)^gamma; a part of
      // [-1, 0] mirrors one of them.
      rule_ = DyadicProductRule(std::move(g_pieces), 0.0, 1.0, 3, gamma_);
    }
  }

  // Whether a table law takes the product rule (above).
  bool uses_product_rule() const { return product_; }

  SpotIntegrals operator()(double cx, double cy) const {
    const Frame f = frame(cx, cy);
    double acc[12] = {};
    if (!product_) {
      std::vector<double> cuts = signed_breaks_;
      cuts.insert(cuts.end(), {-1.0, 0.0, 1.0});
      if (cx > -1.0 && cx < 1.0) cuts.push_back(cx);
      std::sort(cuts.begin(), cuts.end());
      cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
      by_cuts(f, cuts, acc);
      return SpotIntegrals::from_channels(acc);
    }
    part(f, 0, 0, +1, acc);
    part(f, 0, 0, -1, acc);
    return SpotIntegrals::from_channels(acc);
  }

 private:
  static constexpr double kLog = 30.0;                       // -ln of a piece's relative error
  static constexpr int kLeast = 4;                           // a cubic sigma0 times x^2: degree 5
  static constexpr int kMost = 24;                           // beyond: the fine rule
  static constexpr std::size_t kProductSamples = 64;         // fewer: cut at them (as cheap)
  static constexpr double kProductRho = 3.7320508075688772;  // singularities 2 half-lengths away
  // A part 1/128 long next to c_x or the rim: cut (its weights are the last level stored).
  static constexpr int kMaxLevel = DyadicProductRule::kLevels - 1;

  // One centre's y-integrals: its edges' offsets, and far away the rule across the strip.
  struct Frame {
    double cx, cy, e0, e1, gap_y;
    const std::vector<QuadratureNode>* y_rule;  // far away; null: the closed forms
  };
  Frame frame(double cx, double cy) const {
    const double q = q_;
    const double gap =
        std::hypot(std::max(0.0, std::fabs(cx) - 1.0), std::max(0.0, std::fabs(cy) - q));
    // Far away the y-integrand's branch points c_y +- i|a| keep at least `gap` from the strip:
    // Gauss–Legendre with as many points as that asks for (y^2 takes three of its degrees).
    const bool far = gap > 2.0 * std::max(1.0, q);
    return {cx,
            cy,
            -q - cy,
            q - cy,
            std::max(0.0, std::fabs(cy) - q),  // the branch points' offset
            far ? &gauss_legendre_rule(points_for(gap, 2.0 * q, 3)) : nullptr};
  }

  // The x-range cut at `cuts`, each piece by Gauss–Legendre or, ending at c_x or the rim,
  // end_rule (tanh-sinh).
  void by_cuts(const Frame& f, const std::vector<double>& cuts, double* acc,
               const std::vector<QuadratureNode>& end_rule = fine_rule()) const {
    const double cx = f.cx;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double lo = cuts[k], hi = cuts[k + 1], len = hi - lo;
      const bool ends = lo == cx || hi == cx || lo == -1.0 || hi == 1.0;
      double distance = std::hypot(std::max({0.0, lo - cx, cx - hi}), f.gap_y);
      if (fractional_) distance = std::min(distance, 1.0 - std::max(std::fabs(lo), std::fabs(hi)));
      const int n = ends ? 0 : points_for(distance, len);
      for (const QuadratureNode& node : n > 0 ? gauss_legendre_rule(n) : end_rule) {
        const double x = lo + len * node.from_left;
        // a = x - c_x and 1 - |x| to full precision next to the cut and the rim.
        const double a = lo == cx   ? len * node.from_left
                         : hi == cx ? -len * node.from_right
                                    : x - cx;
        const double ax = std::fabs(x);
        const double rim = hi == 1.0    ? len * node.from_right
                           : lo == -1.0 ? len * node.from_left
                                        : 1.0 - ax;
        const double W = node.weight * len * law_(std::min(1.0, ax), rim);
        if (W != 0.0) strip(f, x, a, W, acc);
      }
    }
  }

  // The dyadic part k/2^L of one half of the x-range (side +1: [k, k + 1]/2^L, -1: its mirror
  // image) under the product rule: one rule where its singularities keep 2 half-lengths from
  // its middle, cut at the samples (and c_x) at level kMaxLevel, else two halves.
  void part(const Frame& f, int level, int k, double side, double* acc) const {
    const double a = std::ldexp(k, -level), b = std::ldexp(k + 1, -level);
    const double lo = side > 0.0 ? a : -b, hi = side > 0.0 ? b : -a;
    const double h = 0.5 * (hi - lo), m = lo + h;
    double rho = bernstein_parameter_through((f.cx - m) / h, f.gap_y / h);
    if (fractional_) rho = std::min(rho, bernstein_parameter_through((side - m) / h, 0.0));
    if (rho >= kProductRho) {
      product(f, level, k, side, rho, acc);
      return;
    }
    if (level == kMaxLevel) {
      const std::vector<double> cuts = cuts_within(signed_breaks_, lo, hi, f.cx);
      // A part this short carries little: the radial rule (51 nodes where the fine rule's 105
      // took two fifths of a table's build) is within 1e-14 A0 of it here, where over the whole
      // x-range (the cuts without the product rule, which keep the fine rule) it differs by 1e-11.
      by_cuts(f, cuts, acc, radial_rule());
      return;
    }
    part(f, level + 1, 2 * k, side, acc);
    part(f, level + 1, 2 * k + 1, side, acc);
  }

  // The product rule on a dyadic part: (1 - x^2)^gamma times the strips at Chebyshev points,
  // against g(|x|), with the weights of the part's mirror image in [0, 1] for x < 0 (the rim's
  // factor in them).
  void product(const Frame& f, int level, int k, double side, double rho, double* acc) const {
    const int n = DyadicProductRule::points(product_points(rho, kLog, 3));  // x^2 and a margin
    double scratch[kMostProductPoints];
    const double* W = rule_.weights(level, k, n, scratch);
    const double* x = chebyshev_points(n);
    const double a = std::ldexp(k, -level), b = std::ldexp(k + 1, -level);
    const double mid = side * 0.5 * (a + b), half = 0.5 * (b - a);
    for (int i = 0; i < n; ++i) {
      const double xi = mid + half * x[i];
      // (The mirror image's weight at x_i is the part's at -x_i = x_(n - 1 - i).)
      strip(f, xi, xi - f.cx, side > 0.0 ? W[i] : W[n - 1 - i], acc);
    }
  }

  // W times the y-integrals at x (a = x - c_x) and their weights 1, x, x^2, into acc.
  void strip(const Frame& f, double x, double a, double W, double* acc) const {
    const double q = q_, cy = f.cy, e0 = f.e0, e1 = f.e1;
    double ex[3], ey[2];  // ∫ {1, y, y^2} e_x dy and ∫ {1, y} e_y dy over |y| <= q
    if (f.y_rule) {
      ex[0] = ex[1] = ex[2] = ey[0] = ey[1] = 0.0;
      for (const QuadratureNode& g : *f.y_rule) {
        const double y = q * (g.from_left - g.from_right), w = 2.0 * q * g.weight;
        const double eta = y - cy, inv = w / std::hypot(a, eta);
        ex[0] -= eta * inv;
        ex[1] -= y * eta * inv;
        ex[2] -= y * y * eta * inv;
        ey[0] += a * inv;
        ey[1] += a * y * inv;
      }
    } else {
      const double a2 = a * a;
      const double r0 = std::sqrt(a2 + e0 * e0), r1 = std::sqrt(a2 + e1 * e1);
      // [rho] and [ln(eta + rho)] between the edges (eta1 - eta0 = 2q): log1p where both
      // edges lie on one side, the product where they straddle c_y.
      const double d1 = -4.0 * q * cy / (r0 + r1);
      double d0;
      if (e0 >= 0.0)
        d0 = std::log1p((2.0 * q + d1) / (e0 + r0));
      else if (e1 <= 0.0)
        d0 = std::log1p((2.0 * q - d1) / (r1 - e1));
      else
        d0 = a == 0.0 ? 0.0 : std::log((e1 + r1) * (r0 - e0) / a2);
      const double ad0 = a == 0.0 ? 0.0 : a * d0;
      // [eta rho - a^2 ln(eta + rho)]/2 and [rho^3/3 - a^2 rho]: their terms cancel to
      // eps |a| |eta| at worst, negligible this near the strip.
      const double d2 = 0.5 * (e1 * r1 - e0 * r0 - (a == 0.0 ? 0.0 : a2 * d0));
      const double d3 = d1 * ((r1 * r1 + r1 * r0 + r0 * r0) / 3.0 - a2);
      ex[0] = -d1;
      ex[1] = -(d2 + cy * d1);
      ex[2] = -(d3 + 2.0 * cy * d2 + cy * cy * d1);
      ey[0] = ad0;
      ey[1] = a * d1 + cy * ad0;
    }
    acc[0] += W * ex[0];
    acc[1] += W * x * ex[0];
    acc[2] += W * ex[1];
    acc[3] += W * ey[0];
    acc[4] += W * x * ey[0];
    acc[5] += W * ey[1];
    acc[6] += W * x * ey[0];
    acc[7] += W * x * x * ey[0];
    acc[8] += W * x * ey[1];
    acc[9] += W * ex[1];
    acc[10] += W * x * ex[1];
    acc[11] += W * ex[2];
  }

  // Gauss–Legendre points for a piece whose nearest singularity lies `distance` from it (the
  // Bernstein ellipse through a point that far beyond an end; the polynomial factor takes
  // `degrees` of the rule's), 0 when it would take more than kMost.
  static int points_for(double distance, double length, int degrees = 6) {
    const double z = 1.0 + 2.0 * distance / length;
    const double n = std::ceil(gauss_legendre_points(bernstein_parameter(z), kLog, degrees));
    return n <= kMost ? std::max(kLeast, static_cast<int>(n)) : 0;
  }

  PressureLaw<double> law_;
  double q_;
  bool fractional_ = false;  // sigma0 ~ (1 - x^2)^gamma with gamma fractional: branch points at +-1
  std::vector<double> breaks_;
  bool product_ = false;               // a table law by the product rule
  double gamma_ = 0.0;                 // its rim exponent
  std::vector<double> signed_breaks_;  // +-breaks_, ascending
  DyadicProductRule rule_;             // a table law's weights on the dyadic parts of [0, 1]
};

}  // namespace frictionid::model
