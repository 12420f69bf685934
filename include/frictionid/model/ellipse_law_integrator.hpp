// The twelve spot integrals of an ellipse under any pressure law with a density, from those of
// the uniform ellipse (docs/physics.md §9.3, "Any law on an ellipse from the uniform one").
//
// sigma0 = law(rho_e) is a stack of uniform elliptic layers: with L(s) the law,
//   L(rho_e) = L(1) + sum over jumps J_k [rho_e < s_k] + ∫_0^1 (-L'(s)) [rho_e < s] ds,
// and the uniform ellipse of elliptic radius s is the unit one scaled by s. The direction field
// does not change under that scaling, so an integral whose weight has degree d (1, x or y, times
// x or y for the moments) is s^(2+d) U(c/s), U the unit uniform ellipse's integral, and
//   I(c) = L(1) U(c) + sum_k J_k s_k^(2+d) U(c/s_k) + ∫_0^1 (-L'(s)) s^(2+d) U(c/s) ds.   (9.8)
// U comes from its table, read along the ray c/s (SpotIntegralTable::Ray: a reading adds its
// weight times the radial Chebyshev polynomials to those of its piece, whose coefficients are
// summed against them once a point), so a point costs one 1-D integral in s instead of a 2-D one:
// the rays of SpotIntegrator cut every ray and the angular range at each of a table law's samples
// (39 ms a point for 41 samples), and left a law of more than 64 samples to their rules across its
// kinks (6e-6 of f N for 100 samples). Here the samples cut only the s-range.
//
// The s-integrand is smooth but at
//  - s = rho_e(c), where c/s crosses the rim: U goes like d^2 ln|d| there (a cut), and its
//    complex singularities come as close to the real axis as c/s comes to the rim, which for
//    a ray from the centre that meets the rim at a shallow angle (an elongated ellipse) is close
//    all along;
//  - the law's samples, where a table's L' has kinks (cuts; a step is a jump term instead);
//  - the rim s = 1, where L' ~ (1 - s^2)^(gamma - 1) for sigma0 ~ (1 - rho^2)^gamma: for
//    0 < gamma < 1 the rim piece is taken in w with 1 - s = (1 - a) w^m, m = ceil(1/gamma)
//    (Hertz: m = 2, which makes the integrand analytic), so that it is bounded.
// Each piece is halved until its singularities keep 1.3 half-lengths from its middle, by a
// lower bound on their distance (U is analytic within the distance from c/s to the rim, found
// by Newton's method), and then takes Gauss–Legendre with as many points as that distance asks for
// 1e-12; parts next to rho_e stop at 1% of it and take Gauss–Legendre in t with s = sin^2(pi
// t/2) across the part (crossing_rule: 20 points, where tanh-sinh took 51), a rim end that
// keeps a fractional power tanh-sinh. 250-650 readings of U's table a point (30-110 us) for
// ellipses of aspect 0.1-4, about 4-7 more per sample of a table; within 1e-12 A0 of the rays
// at their fine rules.
//
// A table of 64 samples or more is not cut at its samples. Its slope is
// -L' = (1 - s^2)^(gamma - 1) Q(s), Q a polynomial of degree <= 4 between two samples (g cubic,
// pressure_table.hpp), and the rest of the integrand, F = (1 - s^2)^(gamma - 1) s^(2+d) U(c/s),
// does not see them. So each part (halved until its singularities keep 2 half-lengths away)
// takes F at Chebyshev points, as many as interpolating it to e^-28 asks for, and integrates the
// interpolant against Q exactly (product integration, product_rule.hpp). The weights that
// takes depend only on the part and the number of points, so that range is split into dyadic
// parts of itself, not cut at rho_e (the part that holds it is halved until it is 1% of rho_e,
// then cut there), and the weights of the first 8 levels, the rim's (1 - s^2)^(gamma - 1)
// included, are computed once per law (DyadicProductRule), where their moments took a third of
// a table's build. Parts next to rho_e or a fractional rim stay cut at the samples within them,
// each piece by the crossing rule (tanh-sinh at a fractional rim).
// Readings no longer grow with the samples (240-570 a point for 201-1001 samples where the cuts
// took 1,200-5,600): 45-155 us a point against 225-1,200 us, within 2e-13 A0 of the cuts.
//
// A table's build (for_a_build) takes a table law of fewer samples by the ray's stretches
// through the uniform table's pieces instead (docs/physics.md (9.8a), slopes_by_stretches): on
// a piece U is a Chebyshev series in its radial coordinate, so the slopes' integral over the
// stretch is its coefficients against weights that depend on P or |c| but not on the ray's
// angle, and a table's points share their P across its angular nodes. Within 1e-14 A0 of the
// readings; a table law of 41 samples builds 1.5-3.5 times faster (experiments/README.md).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include <frictionid/model/chebyshev_values.hpp>
#include <frictionid/model/ellipse_nearest_point.hpp>
#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/product_rule.hpp>
#include <frictionid/model/shared_memo.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

namespace frictionid::model {

// Uniform: the unit uniform ellipse of aspect q, anything whose ray(cx, cy) reads its twelve
// channels at c/s as ray(s) (a SpotIntegralTable).
template <typename Uniform>
class EllipseLawIntegrator {
 public:
  // by_samples: a table law's s-range cut at every sample, each piece by Gauss–Legendre, however
  // many samples (a reference for the product rule, which takes tables of 64 samples or more).
  // for_a_build: a table's build, whose points share their reference radii and angles: a table
  // law's slopes by the ray's stretches (slopes_by_stretches, below kProductSamples samples or
  // on an elongated ellipse) and the uniform table's pieces summed at each angle once
  // (Uniform::AngleRows).
  EllipseLawIntegrator(std::shared_ptr<const Uniform> uniform, const PressureLaw<double>& law,
                       double q, bool by_samples = false, bool for_a_build = false)
      : uniform_(std::move(uniform)),
        law_(law),
        q_(q),
        rim_value_(law(1.0, 0.0)),
        jumps_(law_jumps(law)) {
    const double gamma = law_rim_exponent(law);
    if (gamma > 0.0 && gamma < 1.0)
      rim_power_ = static_cast<int>(std::min(64.0, std::ceil(1.0 / gamma)));
    // The s-range's cuts: the law's breakpoints (ascending) between 0 and 1; under the product
    // rule only the last sample, where the rim piece starts.
    breaks_.push_back(0.0);
    for (double b : law.breakpoints())
      if (b > breaks_.back() && b < 1.0) breaks_.push_back(b);
    breaks_.push_back(1.0);
    const bool table = law.kind == PressureKind::Table && law.table;
    if (table) {
      gamma_ = law.table->gamma();
      for (const PressureTable::Cubic& g : law.table->cubics())
        slope_pieces_.push_back(slope_piece(g));
    }
    product_ = table && !by_samples && breaks_.size() - 2 >= kProductSamples;
    if (!product_) {
      cuts_ = breaks_;
    } else {
      cuts_ = {0.0, 1.0};
      if (rim_power_ > 1) cuts_.insert(cuts_.begin() + 1, breaks_[breaks_.size() - 2]);
      rule_ = DyadicProductRule(slope_pieces_, cuts_[0], cuts_[1], 4, rim_exponent());
    }
    density_ = law.kind == PressureKind::Hertz || law.kind == PressureKind::Parabolic ||
               law.kind == PressureKind::Table ||
               (law.kind == PressureKind::Power && value_of(law.n) > 0.0);
    // The rim piece's integrand goes like w^(m gamma - 1) (m = 1: (1 - s)^(gamma - 1)): smooth
    // when that power is a whole number.
    rim_smooth_ = gamma == 0.0 || rim_power_ * gamma == std::floor(rim_power_ * gamma);
    fractional_ = gamma != std::floor(gamma);
    // From kProductSamples on, the product rule's readings do not grow with the samples where
    // the stretches' parts would: 201 samples took 20 % longer by stretches at aspect 0.7 and
    // 1001 samples 1.4 times longer at 0.1. But on an elongated ellipse a point takes many
    // readings, where rays cross the rim at a shallow angle all along: there the stretches pay
    // up to kElongatedStretchSamples samples (201 samples at aspect 0.1 1.9 times faster, 401
    // samples 1.3 times; at 0.2 and 0.3 alike).
    const bool elongated = std::min(q, 1.0 / q) < kElongatedAspect;
    if (for_a_build && table &&
        (!product_ || (elongated && breaks_.size() - 2 <= kElongatedStretchSamples)))
      stretch_cache_ = std::make_shared<StretchCache>();
    if (for_a_build && table) angle_rows_ = std::make_shared<typename Uniform::AngleRows>();
  }

  // Whether a table law's slopes take the product rule (above).
  bool uses_product_rule() const { return product_; }

  // Whether its slopes go by the ray's stretches (for_a_build and fewer than kProductSamples
  // samples, or kElongatedStretchSamples on an elongated ellipse), and how many stretches'
  // weights it has found so far.
  bool takes_stretches() const { return stretch_cache_ != nullptr; }
  // How many pieces it has summed at an angle (for_a_build: kept for the later rays at it).
  std::size_t angle_rows_found() const { return angle_rows_ ? angle_rows_->size() : 0; }
  std::size_t stretches_found() const { return stretch_cache_ ? stretch_cache_->size() : 0; }

  SpotIntegrals operator()(double cx, double cy) const {
    double acc[12] = {};
    const Ray ray = uniform_->ray(cx, cy);  // every reading is U(c/s), summed by the ray
    if (rim_value_ != 0.0) layer(ray, 1.0, rim_value_);
    for (const PressureTable::Jump& j : jumps_) layer(ray, j.rho, j.drop);
    if (density_) {
      // By stretches up to the last cut below the rim where the law leaves a fractional power
      // of 1 - s^2 there (that piece as before), else all the way.
      thread_local std::vector<Stretch> stretches;
      const std::size_t last = cuts_.size() - 2;
      const double s_cut = fractional_ ? cuts_[last] : 1.0;
      if (stretch_cache_ && s_cut > 0.0 && ray.stretches(stretches)) {
        slopes_by_stretches(ray, stretches, s_cut);
        if (s_cut < 1.0) slopes(cx, cy, ray, last);
      } else {
        slopes(cx, cy, ray, 0);
      }
    }
    if (angle_rows_)
      ray.add_to(acc, *angle_rows_);
    else
      ray.add_to(acc);
    return SpotIntegrals::from_channels(acc);
  }

 private:
  static constexpr double kLog = 28.0;       // -ln of a Gauss–Legendre part's relative error
  static constexpr int kLeast = 4;           // a quadratic L' times s^4: degree 6
  static constexpr int kMost = 32;           // points of a part at z = kZ: 28
  static constexpr double kZ = 1.3;          // singularities this many half-lengths away: one rule
  static constexpr double kZCrossing = 3.0;  // the law's branch point this far: crossing_rule
  static constexpr double kFloor = 1e-2;     // parts next to rho_e shorter than this times rho_e
  static constexpr int kMaxDepth = 60;
  static constexpr double kNearRim = 0.9;      // rho_e this far across the rim piece: cut in w
  static constexpr double kZProduct = 2.0;     // singularities this far: one product rule
  static constexpr double kLogProduct = 28.0;  // -ln of its interpolation's relative error
  // Fewer samples: Gauss–Legendre between them costs no more than the product rule's points.
  static constexpr std::size_t kProductSamples = 64;
  // An ellipse more elongated than this takes a table law by stretches up to this many samples.
  static constexpr double kElongatedAspect = 0.2;
  static constexpr std::size_t kElongatedStretchSamples = 256;

  // U's readings along the ray c/s from one centre (SpotIntegralTable::Ray).
  using Ray = decltype(std::declval<const Uniform&>().ray(0.0, 0.0));

  using Stretch = typename Ray::Stretch;
  static constexpr int kRow = 17;  // the weights of one channel degree (Ray::add_weights)
  using StretchWeights = std::array<double, 3 * kRow>;

  // A stretch's weights by what they depend on: the ray's P (polar) or |c| (far), the root
  // cell's radial coordinate, the piece's side and the stretch's ends. Not the piece's degree:
  // the weights go to the highest a piece stores, so that pieces of one side and different
  // degrees share them (41 samples at aspect 0.1: 36 % fewer found, the build 10 % faster).
  struct StretchKey {
    std::array<double, 9> v;
    bool operator==(const StretchKey& o) const { return v == o.v; }
  };
  struct StretchKeyHash {
    std::size_t operator()(const StretchKey& k) const {
      std::uint64_t h = 0x9e3779b97f4a7c15ULL;
      for (double d : k.v) {
        const double e = d + 0.0;  // -0 and +0 compare equal: one hash
        std::uint64_t b;
        std::memcpy(&b, &e, sizeof b);
        h ^= b + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
      }
      return static_cast<std::size_t>(h);
    }
  };
  // Cleared beyond this many (~30 MB): a build evaluates its points cell by cell, and the points
  // that share a P come close together (41 samples at aspect 0.1 found 167,000).
  using StretchCache = SharedMemo<StretchKey, StretchWeights, StretchKeyHash, 50000>;

  static StretchKey key_of(const Stretch& t, double radius, double s_cut) {
    return {{t.far ? -radius : radius, t.axis.lo, t.axis.hi,
             static_cast<double>(t.axis.power * (t.axis.towards_hi ? 1 : -1)), t.a0, t.b0, t.u_lo,
             t.u_hi, s_cut}};
  }

  // The slopes' integral ∫ (-L'(s)) s^(2+d) U(c/s) ds over s in (0, 1] stretch by stretch: U
  // is a Chebyshev series in each piece's radial coordinate x, so the integral is the piece's
  // coefficients against W_k = ∫ (-L'(s)) s^(2+d) T_k(x(s)) ds over the stretch, cut at the
  // samples (stretch_weights). The weights depend on P or |c| and the stretch, not on the ray's
  // angle, and the points of a table share their P across its angular nodes: each stretch's
  // weights are found once. Exact for the table's interpolant of U where the readings of
  // slopes() integrate it to ~1e-12 A0.
  void slopes_by_stretches(const Ray& ray, const std::vector<Stretch>& stretches,
                           double s_cut) const {
    const double P = ray.reference_radius(), r = ray.radius();
    thread_local std::vector<StretchKey> keys;
    thread_local std::vector<StretchWeights> found;
    const std::size_t n = stretches.size();
    keys.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      keys[i] = key_of(stretches[i], stretches[i].far ? r : P, s_cut);
    stretch_cache_->get(keys, found,
                        [&](std::size_t i) { return stretch_weights(stretches[i], P, r, s_cut); });
    for (std::size_t i = 0; i < n; ++i)
      ray.add_weights(stretches[i].leaf, stretches[i].s1, found[i].data());
  }

  // One stretch's weights over s <= s_cut: cut at the law's samples, each part by
  // Gauss–Legendre (in_parts).
  StretchWeights stretch_weights(const Stretch& t, double P, double r, double s_cut) const {
    StretchWeights W{};
    auto u_of_s = [&](double s) { return t.far ? s / r : P / s; };
    // The stretch in s: u in [u_lo, u_hi] is s in [P/u_hi, P/u_lo] (P/P = 1 exactly), or
    // [|c| u_lo, |c| u_hi] on the far patch; no more than s_cut.
    double s_lo = t.far ? r * t.u_lo : P / t.u_hi, s_hi = t.far ? r * t.u_hi : P / t.u_lo;
    s_hi = std::min(s_hi, s_cut);
    if (!(s_hi > s_lo)) return W;
    std::vector<double> cuts = {s_lo};
    for (std::size_t k = 1; k + 1 < breaks_.size(); ++k)
      if (breaks_[k] > s_lo && breaks_[k] < s_hi) cuts.push_back(breaks_[k]);
    cuts.push_back(s_hi);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double sa = cuts[k], sb = cuts[k + 1];
      const PolynomialPiece* piece = slope_piece_at(0.5 * (sa + sb));
      if (t.axis.power == 1) {
        const auto in_s = [&](double s) { return PartNode{t.x_of(u_of_s(s)), s, 1.0}; };
        const auto mid = [&](double a, double b) {  // geometric towards the pole s = 0
          return t.far ? 0.5 * (a + b) : std::sqrt(a) * std::sqrt(b);
        };
        in_parts(t, sa, sb, in_s, mid, piece, W.data(), 0);
      } else {
        const auto in_x = [&](double x) {
          double du = 0.0;
          const double u = t.u_at(x, du);
          return t.far ? PartNode{x, r * u, r * du} : PartNode{x, P / u, P * du / (u * u)};
        };
        const auto mid = [](double a, double b) { return 0.5 * (a + b); };
        in_parts(t, t.x_of(u_of_s(t.far ? sa : sb)), t.x_of(u_of_s(t.far ? sb : sa)), in_x, mid,
                 piece, W.data(), 0);
      }
    }
    return W;
  }

  // The integrand's weights at x, times `weight`, added to W (3 rows of kRow).
  static void add_powers(double x, double s, double w, double* W) {
    const double w2 = w * s * s, w3 = w2 * s, w4 = w3 * s;
    double tx[kRow];
    chebyshev_values(x, kRow - 1, tx);
    for (int k = 0; k < kRow; ++k) {
      W[k] += w2 * tx[k];
      W[kRow + k] += w3 * tx[k];
      W[2 * kRow + k] += w4 * tx[k];
    }
  }

  // Whether a part [sa, sb] of s is to be halved before its rule: on the polar patch x is a
  // function of u = P/s, whose pole s = 0 then keeps beyond the part's length (Bernstein
  // parameter >= 3 + sqrt 8: 5.8^-24 of the error of 12 points); the law's (1 - s^2)^(gamma - 1)
  // has a branch point at s = 1, kept twice the length away. Between them the integrand is the
  // piece's polynomials (T_k of degree <= 16, the law's Q of degree 4) times powers of s.
  bool halve(const Stretch& t, double sa, double sb, int depth) const {
    if (depth >= kMaxStretchDepth) return false;
    const bool pole = !t.far && sb > 2.0 * sa;
    const bool branch = fractional_ && 1.0 - sb < 2.0 * (sb - sa);
    return pole || branch;
  }

  // A node of a part's rule: the piece's coordinate x, s, and ds/dv for the part's variable v.
  struct PartNode {
    double x, s, ds;
  };

  // The part [va, vb] of a variable v, s(v) monotone (at(v): its node), halved at mid(va, vb)
  // until halve() lets it take Gauss–Legendre in v (kStretchNodes or kShortStretchNodes). On a
  // linear root cell v is s itself: nodes placed in s keep their relative precision where P is
  // small (in x, whose -1 lies at u = 0, a part near x = -1 lost it). On a graded root cell (about
  // the uniform rim u = 1) v is its coordinate x, where u is a polynomial (in s a cube root at the
  // rim).
  template <typename At, typename Mid>
  void in_parts(const Stretch& t, double va, double vb, const At& at, const Mid& mid,
                const PolynomialPiece* piece, double* W, int depth) const {
    const PartNode a = at(va), b = at(vb);
    if (halve(t, std::min(a.s, b.s), std::max(a.s, b.s), depth)) {
      const double vm = mid(va, vb);
      in_parts(t, va, vm, at, mid, piece, W, depth + 1);
      in_parts(t, vm, vb, at, mid, piece, W, depth + 1);
      return;
    }
    const double len = vb - va;
    const int points = std::fabs(b.x - a.x) <= kShortSpan ? kShortStretchNodes : kStretchNodes;
    for (const QuadratureNode& g : gauss_legendre_rule(points)) {
      const PartNode n = at(va + len * g.from_left);
      add_powers(n.x, n.s, -g.weight * len * n.ds * slope(piece, n.s, 1.0 - n.s), W);
    }
  }

  // w times the uniform ellipse of elliptic radius s, w s^(2+d) U(c/s), added to the ray's sums
  // (Ray::add; operator() adds those to the channels).
  static void layer(const Ray& ray, double s, double w) {
    if (w == 0.0 || !(s > 1e-100)) return;  // below that its share underflows
    ray.add(s, w);
  }

  // A piece of the s-range in the variable w in [0, 1]: s = a + len w, or at the rim, for
  // 0 < gamma < 1, 1 - s = len w^m.
  struct Piece {
    double a, len;
    int m;
    bool dyadic = false;  // [a, a + len] is rule_'s interval: its parts' weights are stored
    double one_minus_s(double w) const { return m == 1 ? (1.0 - a - len * w) : len * power(w, m); }
    double s(double w) const { return m == 1 ? a + len * w : 1.0 - one_minus_s(w); }
    double ds_dw(double w) const { return m == 1 ? len : len * m * power(w, m - 1); }
    static double power(double w, int k) {  // w^k by squaring (std::pow took 7% of a build)
      double r = 1.0;
      for (; k > 0; k >>= 1, w *= w)
        if (k & 1) r *= w;
      return r;
    }
    // A radius about w free of singularities, given one of rs about s(w).
    double radius(double w, double rs) const {
      return m == 1 ? rs / len : std::pow(std::pow(w, m) + rs / len, 1.0 / m) - w;
    }
  };

  struct Centre {
    double cx, cy, norm, re;  // c, |c| and rho_e(c)
    const Ray* ray;
  };

  // Lower bounds on the distance from s to the nearest complex singularity of the integrand
  // (docs/physics.md §9.3). Along the ray p = lambda c/|c|, U is analytic within the distance D
  // from p to the rim, and no singular lambda exceeds the spot's largest radius. A law
  // (1 - s^2)^gamma g(s) of fractional gamma has branch points at s = -1 and, unless the piece
  // ends there (its rule takes that end), s = 1.
  double singular_radius(const Centre& c, double s) const {
    if (c.norm == 0.0) return HUGE_VAL;  // U(0) s^(2+d), a polynomial
    const double beyond = c.norm / std::max(1.0, q_) - s;
    // D is at most the distance from c/s to the rim along its own ray, |c/s| |1 - 1/rho|
    // (rho = rho_e(c/s)): when even that leaves `beyond` the larger, the nearest rim point
    // (a third of a table law's build) is not needed.
    const double rho = c.re / s, most = c.norm / s * std::fabs(rho - 1.0) / rho;
    if (beyond >= s * s * most / (c.norm + s * most)) return beyond;
    const double D = rim_distance(c.cx / s, c.cy / s);
    return std::max(s * s * D / (c.norm + s * D), beyond);
  }
  double law_radius(double s, bool ends_at_rim) const {
    return fractional_ ? std::min(1.0 + s, ends_at_rim ? HUGE_VAL : 1.0 - s) : HUGE_VAL;
  }

  // The distance from (x, y) to the rim x^2 + (y/q)^2 = 1, from inside or outside.
  double rim_distance(double x, double y) const { return nearest_rim_point(q_, x, y).distance; }

  // The pieces between cuts_[first] and 1.
  void slopes(double cx, double cy, const Ray& ray, std::size_t first) const {
    const Centre c{cx, cy, std::hypot(cx, cy), std::hypot(cx, cy / q_), &ray};
    for (std::size_t k = first; k + 1 < cuts_.size(); ++k) {
      const double a = cuts_[k], b = cuts_[k + 1];
      const bool inside = c.re > a && c.re < b;  // rho_e cuts this piece
      if (b == 1.0 && rim_power_ > 1 && inside && c.re - a > kNearRim * (1.0 - a)) {
        // rho_e next to the rim: cut in w (w = 0 at the rim), where it keeps its distance from
        // the law's branch point there however close it comes.
        const Piece p{a, b - a, rim_power_};
        const double we = std::pow((1.0 - c.re) / p.len, 1.0 / p.m);
        subdivide(c, p, 0.0, we, End::Rim, End::Centre, 0);
        subdivide(c, p, we, 1.0, End::Centre, End::None, 0);
      } else if (b == 1.0 && rim_power_ > 1) {
        const double a1 = inside ? c.re : a;
        if (inside) subdivide(c, {a, c.re - a, 1}, 0.0, 1.0, End::None, End::Centre, 0);
        subdivide(c, {a1, 1.0 - a1, rim_power_}, 0.0, 1.0, End::Rim,
                  inside ? End::Centre : End::None, 0);
      } else if (product_ && k == 0) {
        // The product rule's piece, in dyadic parts whatever rho_e (the part that holds it is
        // halved until it is cut there, by_samples): their weights are stored (rule_).
        subdivide(c, Piece{a, b - a, 1, true}, 0.0, 1.0, End::None, b == 1.0 ? End::Rim : End::None,
                  0);
      } else {
        const Piece p{a, b - a, 1};
        const End last = b == 1.0 ? End::Rim : End::None;
        const double we = inside ? (c.re - a) / p.len : 1.0;
        subdivide(c, p, 0.0, we, End::None, inside ? End::Centre : last, 0);
        if (inside) subdivide(c, p, we, 1.0, End::Centre, last, 0);
      }
    }
  }

  // What lies at an end of a part of a piece: nothing singular, s = rho_e(c) (where c/s
  // crosses the rim) or the rim s = 1.
  enum class End { None, Centre, Rim };

  // The part w in [w0, w1] of a piece: one rule where the singularities keep kZ half-lengths
  // from its middle, else two halves. Parts next to rho_e(c) shrink to kFloor rho_e and take
  // tanh-sinh, which absorbs U's d^2 ln|d| at that end; so does a rim end where the law leaves
  // a fractional power.
  void subdivide(const Centre& c, const Piece& p, double w0, double w1, End end0, End end1,
                 int depth) const {
    const double h = 0.5 * (w1 - w0), wm = w0 + h;
    const bool at_rim = end0 == End::Rim || end1 == End::Rim;
    // In tau (m > 1) the rim's branch point is gone; a fractional power of w remains at w = 0,
    // which only the part that ends there sees closer than its length.
    const double sm = p.s(wm);
    // The product rule interpolates the smooth factor, which keeps the law's branch point at the
    // rim: its parts shrink towards it too, down to kFloor.
    const bool product = product_ && p.m == 1;
    const bool rule_takes_rim = at_rim && !product;
    double z_law = p.radius(wm, law_radius(sm, rule_takes_rim || p.m > 1)) / h;
    if (p.m > 1 && !rim_smooth_ && !at_rim) z_law = std::min(z_law, wm / h);
    const double z = std::min(z_law, p.radius(wm, singular_radius(c, sm)) / h);
    // Next to rho_e(c) (or just beyond the rim from it) U's singularities crowd towards the real
    // axis: a part that short is left to tanh-sinh, unless the law's own branch point is near.
    const double s0 = p.s(w0), s1 = p.s(w1), s_length = std::fabs(s1 - s0);
    const double from_re =
        std::max(0.0, std::max(std::min(s0, s1) - c.re, c.re - std::max(s0, s1)));
    const bool tiny = (s_length < kFloor * c.re && from_re <= s_length && z_law >= kZ) ||
                      (product && at_rim && !rim_smooth_ && s_length < kFloor);
    if (z >= (product ? kZProduct : kZ) || tiny || depth >= kMaxDepth) {
      const bool fractional_rim = at_rim && !rim_smooth_;
      const bool singular = tiny || end0 == End::Centre || end1 == End::Centre || fractional_rim;
      if (product) {
        if (singular)
          by_samples(c, s0, s1, end1 == End::Rim);
        else
          product_rule(c, p, depth, w0, s0, s1, z);
        return;
      }
      // The crossing rule where the law's branch point keeps a part's length beyond its ends.
      const std::vector<QuadratureNode>& rule = fractional_rim || (singular && z_law < kZCrossing)
                                                    ? radial_rule()
                                                : singular ? crossing_rule()
                                                           : gauss_legendre_rule(points_for(z));
      const PolynomialPiece* piece = slope_piece_at(sm);
      for (const QuadratureNode& g : rule) {
        const double w = w0 + 2.0 * h * g.from_left;
        // 1 - s to full precision next to the rim.
        const double omr =
            p.m == 1 && end1 == End::Rim ? 2.0 * h * p.len * g.from_right : p.one_minus_s(w);
        const double s = p.m == 1 ? p.s(w) : 1.0 - omr;
        layer(*c.ray, s, -g.weight * 2.0 * h * p.ds_dw(w) * slope(piece, s, omr));
      }
      return;
    }
    subdivide(c, p, w0, wm, end0, End::None, depth + 1);
    subdivide(c, p, wm, w1, End::None, end1, depth + 1);
  }

  // A part [s0, s1] next to a singularity of the smooth factor under the product rule: cut at
  // the samples within and at rho_e, each piece by tanh-sinh, which absorbs the singularity at
  // an end.
  void by_samples(const Centre& c, double s0, double s1, bool to_rim) const {
    const std::vector<double> cuts = cuts_within(breaks_, s0, s1, c.re);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double lo = cuts[k], hi = cuts[k + 1], len = hi - lo;
      const bool rim = to_rim && hi == s1;
      // tanh-sinh at a fractional rim, or where the law's branch point is nearer than subdivide
      // allows the crossing rule.
      const bool branch =
          (rim && !rim_smooth_) || law_radius(0.5 * (lo + hi), rim) / (0.5 * len) < kZCrossing;
      const PolynomialPiece* piece = slope_piece_at(0.5 * (lo + hi));
      for (const QuadratureNode& g : branch ? radial_rule() : crossing_rule()) {
        const double s = lo + len * g.from_left;
        const double omr = rim ? len * g.from_right : 1.0 - s;
        layer(*c.ray, s, -g.weight * len * slope(piece, s, omr));
      }
    }
  }

  // The product rule on a part [s0, s1] (above, product_rule.hpp): w in [w0, w0 + 2^-depth] of
  // the piece p, whose weights rule_ holds when p is its interval.
  void product_rule(const Centre& c, const Piece& p, int depth, double w0, double s0, double s1,
                    double z) const {
    const int want = product_points(bernstein_parameter(z), kLogProduct, 4);  // s^(2+d): four
    // The weights carry the rim's (1 - s^2)^(gamma - 1).
    const int n = p.dyadic ? DyadicProductRule::points(want) : want;
    double scratch[kMostProductPoints];
    const double* W = scratch;
    if (p.dyadic)
      W = rule_.weights(depth, static_cast<long>(std::ldexp(w0, depth)), n, scratch);
    else
      product_rule_weights(slope_pieces_, s0, s1, n, 4, rim_exponent(), scratch);
    const double* x = chebyshev_points(n);
    const double mid = 0.5 * (s0 + s1), half = 0.5 * (s1 - s0);
    for (int i = 0; i < n; ++i) layer(*c.ray, mid + half * x[i], W[i]);
  }

  // The rule of a part with rho_e(c) at (or within its length of) an end, where U goes like
  // d^2 ln|d|: Gauss–Legendre in t with s = sin^2(pi t/2) across the part, d^2 ln d turning into
  // t^5 ln t. 20 points where tanh-sinh took 51, within 2e-14 A0 of it for aspects 0.05-4 and
  // tables of 20-63 samples.
  static const std::vector<QuadratureNode>& crossing_rule() {
    static const std::vector<QuadratureNode> rule = make_sine_squared_rule(20);
    return rule;
  }

  // A table law's slope polynomial on the piece that holds s (between two cuts: the piece of
  // every part), or none for the other laws.
  const PolynomialPiece* slope_piece_at(double s) const {
    if (slope_pieces_.empty()) return nullptr;
    const auto it = std::upper_bound(slope_pieces_.begin() + 1, slope_pieces_.end(), s,
                                     [](double v, const PolynomialPiece& q) { return v < q.a; });
    return &*(it - 1);
  }

  // L'(s), 1 - s = omr: a table's from its piece's polynomial, -(1 - s^2)^(gamma - 1) Q (the
  // interpolant's two searches and pow took a fifth of a table's build), others from the law.
  double slope(const PolynomialPiece* piece, double s, double omr) const {
    if (!piece) return law_slope(law_, s, omr);
    const double Q = (*piece)(s);
    return gamma_ > 0.0 ? -std::exp((gamma_ - 1.0) * std::log(omr * (1.0 + s))) * Q : -Q;
  }

  // The exponent of the rim's factor (1 - s^2)^(gamma - 1) that the product rule's weights carry
  // (0: none).
  double rim_exponent() const { return gamma_ > 0.0 ? gamma_ - 1.0 : 0.0; }

  // Q on [a, b) as a polynomial in u = s - a: 2 gamma s g - (1 - s^2) g' (gamma = 0: -g').
  PolynomialPiece slope_piece(const PressureTable::Cubic& g) const {
    const double a = g.a;
    const std::array<double, 3> dg = {g.c[1], 2.0 * g.c[2], 3.0 * g.c[3]};
    PolynomialPiece out{g.a, g.b, {}};
    if (!(gamma_ > 0.0)) {
      for (std::size_t i = 0; i < 3; ++i) out.c[i] = -dg[i];
      return out;
    }
    const std::array<double, 3> rim = {(1.0 - a) * (1.0 + a), -2.0 * a, -1.0};  // 1 - s^2
    for (std::size_t i = 0; i < 4; ++i) {                                       // 2 gamma s g
      out.c[i] += 2.0 * gamma_ * a * g.c[i];
      out.c[i + 1] += 2.0 * gamma_ * g.c[i];
    }
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) out.c[i + j] -= rim[i] * dg[j];
    return out;
  }

  // Gauss–Legendre points for a piece whose nearest singularity lies z half-lengths from its
  // middle: Bernstein ellipse parameter z + sqrt(z^2 - 1); the polynomial factor (L' times
  // s^(2+d), degree 6) takes six of the rule's degrees.
  static int points_for(double z) {
    if (!(z > 1.0)) return kMost;
    const double n = std::ceil(gauss_legendre_points(bernstein_parameter(z), kLog, 6));
    return n < kMost ? std::max(kLeast, static_cast<int>(n)) : kMost;
  }

  std::shared_ptr<const Uniform> uniform_;
  PressureLaw<double> law_;
  double q_;
  double rim_value_;
  std::vector<PressureTable::Jump> jumps_;
  std::vector<double> cuts_;
  std::vector<double> breaks_;  // 0, the law's breakpoints, 1
  bool product_ = false;        // a table law's slopes by the product rule
  double gamma_ = 0.0;          // its rim exponent
  std::vector<PolynomialPiece> slope_pieces_;
  DyadicProductRule rule_;  // the weights of the dyadic parts of [cuts_[0], cuts_[1]]
  bool density_ = false;
  int rim_power_ = 1;
  bool rim_smooth_ = true;
  bool fractional_ = false;                                  // gamma not a whole number
  std::shared_ptr<StretchCache> stretch_cache_;              // for_a_build: the stretches' weights
  std::shared_ptr<typename Uniform::AngleRows> angle_rows_;  // and the pieces at each angle
  static constexpr int kMaxStretchDepth = 60;  // halvings of a part (geometric in s from P up)
  // Gauss–Legendre points of a stretch's part: 16, or 12 where the part spans no more than a
  // quarter of its piece (kShortSpan in x), as between two of 41 samples. Within 8e-14 A0 of 28
  // points at aspects 0.1-4, tables of 2-201 samples, rim exponents 0.3-1.5 (12 points on
  // every part erred by 5e-10 on a table of 2 samples, whose parts span whole pieces).
  static constexpr int kStretchNodes = 16;
  static constexpr int kShortStretchNodes = 12;
  static constexpr double kShortSpan = 0.5;
};

}  // namespace frictionid::model
