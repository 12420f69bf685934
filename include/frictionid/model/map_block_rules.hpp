// The far field of a pressure map in blocks of grid cells (docs/physics.md §9.3): a quadtree of
// blocks of 2^L x 2^L cells (L >= kFirstLevel), each with one product rule of kPoints x kPoints
// nodes on the bounding box of its nonzero cells. Far from c the direction field e3 x d/|d| is
// analytic over a block; interpolated there by a polynomial of degree kPoints - 1 in each
// variable (Chebyshev points of the first kind), its integral against sigma0 m, m in {1, x, y,
// xy, x^2, y^2}, is a sum over the nodes with the weights
//   w_pq^m = ∫ sigma0 m L_p(x) L_q(y) dS,
// exact for the bilinear cells (Gauss–Legendre on each cell of the first level, then each
// parent's from its children's: L_p of the parent is a polynomial of degree kPoints - 1, which
// the child's interpolation reproduces, so w_parent = sum of Tx^T w_child Ty, exactly).
//
// Why: a cell far from c costs its own product rule of 4 x 4 to 7 x 7 nodes (map_strip_
// integrator.hpp), so a point summed every cell of the map, and a map's table, ~100 points a
// grid cell, grew as the square of the cells (a 64 x 64 map: 95 s before `shimmy`'s first step).
// A block of side S whose gap from c is at least kSeparation S takes kPoints^2 nodes for all of
// its cells: a walk down the tree accepts 20-80 blocks (a 30 x 30 to a 100 x 100 grid), so a
// point costs about the log of the cells, not the cells.
//
// Error: the interpolation error of a function analytic inside the Bernstein ellipse of
// parameter rho falls as rho^-n; the branch points of 1/|d| lie at least the gap off the block,
// so ln rho >= asinh(2 gap / S) = asinh 2 at gap = S, a bound of ~1e-10 for 16 points that the
// worst case (one branch point next to a corner of the box) does not approach: within 9e-14 of
// the load of the cells' own rules on random grids (tests/model/map_block_rules_test.cpp; 12
// points from 1.5 S: 1.4e-13, 16 from 0.75 S: 9e-13, experiments/README.md, "Contact spots").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/gauss_legendre_rule.hpp>

namespace frictionid::model {

class MapBlockRules {
 public:
  static constexpr int kPoints = 16;          // nodes a side of a block's rule
  static constexpr int kFirstLevel = 2;       // the smallest blocks: 4 x 4 cells
  static constexpr double kSeparation = 1.0;  // the least gap from c, in the block's longer side

  explicit MapBlockRules(const PressureMap& map)
      : nxc_(map.nx() < 2 ? 0 : map.nx() - 1), nyc_(map.ny() < 2 ? 0 : map.ny() - 1) {
    for (int p = 0; p < kPoints; ++p) {
      const double angle = M_PI * (2.0 * p + 1.0) / (2.0 * kPoints);
      t_[static_cast<std::size_t>(p)] = std::cos(angle);
      lambda_[static_cast<std::size_t>(p)] = (p % 2 == 0 ? 1.0 : -1.0) * std::sin(angle);
    }
    if (nxc_ == 0 || nyc_ == 0) return;  // no map (a table of another spot holds an empty one)
    std::size_t top = 0;
    while ((std::size_t{1} << top) < std::max(nxc_, nyc_)) ++top;
    if (static_cast<int>(top) < kFirstLevel) return;  // too small for a block: nothing to do
    levels_.resize(top + 1);
    for (std::size_t L = 0; L <= top; ++L) {
      Level& level = levels_[L];
      const std::size_t side = std::size_t{1} << L;
      level.nbx = (nxc_ + side - 1) / side;
      level.nby = (nyc_ + side - 1) / side;
      level.blocks.resize(level.nbx * level.nby);
      for (std::size_t bj = 0; bj < level.nby; ++bj)
        for (std::size_t bi = 0; bi < level.nbx; ++bi) {
          Block& b = level.blocks[bj * level.nbx + bi];
          b.i0 = bi * side;
          b.i1 = std::min(b.i0 + side, nxc_);
          b.j0 = bj * side;
          b.j1 = std::min(b.j0 + side, nyc_);
          if (L == 0) {
            b.empty = map.sample(bi, bj) == 0.0 && map.sample(bi + 1, bj) == 0.0 &&
                      map.sample(bi, bj + 1) == 0.0 && map.sample(bi + 1, bj + 1) == 0.0;
            b.x0 = map.x[bi];
            b.x1 = map.x[bi + 1];
            b.y0 = map.y[bj];
            b.y1 = map.y[bj + 1];
            continue;
          }
          // The bounding box of the nonzero children.
          for (const Block* c : children(L, bi, bj)) {
            if (c->empty) continue;
            if (b.empty) {
              b.x0 = c->x0;
              b.x1 = c->x1;
              b.y0 = c->y0;
              b.y1 = c->y1;
            } else {
              b.x0 = std::min(b.x0, c->x0);
              b.x1 = std::max(b.x1, c->x1);
              b.y0 = std::min(b.y0, c->y0);
              b.y1 = std::max(b.y1, c->y1);
            }
            b.empty = false;
          }
          if (L < static_cast<std::size_t>(kFirstLevel) || b.empty) continue;
          b.rule = rules_.size();
          rules_.emplace_back();
          Rule& r = rules_.back();
          for (int p = 0; p < kPoints; ++p) {
            r.x[static_cast<std::size_t>(p)] = along(b.x0, b.x1, t_[static_cast<std::size_t>(p)]);
            r.y[static_cast<std::size_t>(p)] = along(b.y0, b.y1, t_[static_cast<std::size_t>(p)]);
          }
          r.w.assign(kPoints * kPoints * kMonomials, 0.0);
          if (L == static_cast<std::size_t>(kFirstLevel))
            weights_from_cells(map, b, r);
          else
            for (const Block* c : children(L, bi, bj))
              if (!c->empty) weights_from_child(b, r, rules_[c->rule]);
        }
    }
  }

  bool any() const { return !levels_.empty(); }

  // Adds to acc the twelve channels (SpotIntegrals::channels order) of every block at least
  // kSeparation of its side from c that `open` (given a block's cells [i0, i1) x [j0, j1)) does
  // not hold open, the largest first, and hands every nonzero cell of no such block to
  // leaf(i, j).
  template <typename Open, typename Leaf>
  void sum(double cx, double cy, const Open& open, const Leaf& leaf, double* acc) const {
    if (levels_.empty()) return;
    struct Visit {
      std::size_t level, bi, bj;
    };
    Visit stack[4 * 64];
    std::size_t depth = 0;
    stack[depth++] = Visit{levels_.size() - 1, 0, 0};
    while (depth > 0) {
      const Visit v = stack[--depth];
      const Level& level = levels_[v.level];
      const Block& b = level.blocks[v.bj * level.nbx + v.bi];
      if (b.empty) continue;
      if (v.level == 0) {
        leaf(b.i0, b.j0);
        continue;
      }
      if (v.level >= static_cast<std::size_t>(kFirstLevel) && far(b, cx, cy) &&
          !open(b.i0, b.i1, b.j0, b.j1)) {
        apply(rules_[b.rule], cx, cy, acc);
        continue;
      }
      const Level& below = levels_[v.level - 1];
      for (std::size_t dj = 2; dj-- > 0;)
        for (std::size_t di = 2; di-- > 0;) {
          const std::size_t ci = 2 * v.bi + di, cj = 2 * v.bj + dj;
          if (ci < below.nbx && cj < below.nby) stack[depth++] = Visit{v.level - 1, ci, cj};
        }
    }
  }

 private:
  static constexpr int kMonomials = 6;  // 1, x, y, xy, x^2, y^2
  // Gauss–Legendre points a side of a cell: sigma0 m L_p has degree kPoints + 2 in each
  // variable, which 2 g - 1 must reach.
  static constexpr int kCellPoints = (kPoints + 4) / 2;

  struct Block {
    std::size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;     // its grid cells [i0, i1) x [j0, j1)
    double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;  // the box of its nonzero cells
    bool empty = true;
    std::size_t rule = 0;  // in rules_ (levels >= kFirstLevel)
  };
  struct Level {
    std::size_t nbx = 0, nby = 0;
    std::vector<Block> blocks;
  };
  struct Rule {
    std::array<double, kPoints> x{}, y{};  // the nodes along x and y
    std::vector<double> w;                 // w[(m kPoints + q) kPoints + p]
  };

  static double along(double lo, double hi, double t) {
    return 0.5 * (lo + hi) + 0.5 * (hi - lo) * t;
  }

  std::array<const Block*, 4> children(std::size_t L, std::size_t bi, std::size_t bj) const {
    static const Block none;
    const Level& below = levels_[L - 1];
    std::array<const Block*, 4> out{&none, &none, &none, &none};
    for (std::size_t dj = 0; dj < 2; ++dj)
      for (std::size_t di = 0; di < 2; ++di) {
        const std::size_t ci = 2 * bi + di, cj = 2 * bj + dj;
        if (ci < below.nbx && cj < below.nby) out[dj * 2 + di] = &below.blocks[cj * below.nbx + ci];
      }
    return out;
  }

  // The Lagrange basis of the Chebyshev points on [lo, hi] at X (barycentric form).
  std::array<double, kPoints> basis(double lo, double hi, double X) const {
    std::array<double, kPoints> L{};
    const double t = (2.0 * X - lo - hi) / (hi - lo);
    double sum = 0.0;
    for (std::size_t p = 0; p < static_cast<std::size_t>(kPoints); ++p) {
      const double d = t - t_[p];
      if (d == 0.0) {
        L.fill(0.0);
        L[p] = 1.0;
        return L;
      }
      L[p] = lambda_[p] / d;
      sum += L[p];
    }
    for (double& v : L) v /= sum;
    return L;
  }

  bool far(const Block& b, double cx, double cy) const {
    const double gx = std::max({0.0, b.x0 - cx, cx - b.x1});
    const double gy = std::max({0.0, b.y0 - cy, cy - b.y1});
    const double side = std::max(b.x1 - b.x0, b.y1 - b.y0);
    return gx * gx + gy * gy >= kSeparation * kSeparation * side * side;
  }

  // The first level's weights: each nonzero cell by Gauss–Legendre, separably.
  void weights_from_cells(const PressureMap& map, const Block& b, Rule& r) const {
    const std::vector<QuadratureNode>& g = gauss_legendre_rule(kCellPoints);
    constexpr std::size_t G = kCellPoints, P = kPoints, M = kMonomials;
    for (std::size_t j = b.j0; j < b.j1; ++j)
      for (std::size_t i = b.i0; i < b.i1; ++i) {
        const double s00 = map.sample(i, j), s10 = map.sample(i + 1, j);
        const double s01 = map.sample(i, j + 1), s11 = map.sample(i + 1, j + 1);
        if (s00 == 0.0 && s10 == 0.0 && s01 == 0.0 && s11 == 0.0) continue;
        const double x0 = map.x[i], hx = map.x[i + 1] - x0;
        const double y0 = map.y[j], hy = map.y[j + 1] - y0;
        std::array<std::array<double, P>, G> Lx{}, Ly{};
        std::array<double, G> xs{}, ys{};
        for (std::size_t k = 0; k < G; ++k) {
          xs[k] = x0 + hx * g[k].from_left;
          ys[k] = y0 + hy * g[k].from_left;
          Lx[k] = basis(b.x0, b.x1, xs[k]);
          Ly[k] = basis(b.y0, b.y1, ys[k]);
        }
        // B[a][m][q] = sum over the y-nodes of the weighted sigma0 m at (x_a, y_c) times L_q(y_c)
        std::vector<double> B(G * M * P, 0.0);
        for (std::size_t a = 0; a < G; ++a) {
          const double x = xs[a];
          const double lo = s00 * g[a].from_right + s10 * g[a].from_left;
          const double hi = s01 * g[a].from_right + s11 * g[a].from_left;
          for (std::size_t c = 0; c < G; ++c) {
            const double y = ys[c];
            const double v =
                g[a].weight * g[c].weight * hx * hy * (lo * g[c].from_right + hi * g[c].from_left);
            const double m[M] = {v, v * x, v * y, v * x * y, v * x * x, v * y * y};
            for (std::size_t mm = 0; mm < M; ++mm)
              for (std::size_t q = 0; q < P; ++q) B[(a * M + mm) * P + q] += m[mm] * Ly[c][q];
          }
        }
        for (std::size_t a = 0; a < G; ++a)
          for (std::size_t q = 0; q < P; ++q)
            for (std::size_t p = 0; p < P; ++p)
              for (std::size_t mm = 0; mm < M; ++mm)
                r.w[(mm * P + q) * P + p] += Lx[a][p] * B[(a * M + mm) * P + q];
      }
  }

  // A parent's weights from a child's: the child's nodes interpolate the parent's basis exactly.
  void weights_from_child(const Block& b, Rule& r, const Rule& c) const {
    constexpr std::size_t P = kPoints, M = kMonomials;
    std::array<std::array<double, P>, P> Tx{}, Ty{};  // T[p'][p] = L_p of the parent at node p'
    for (std::size_t k = 0; k < P; ++k) {
      Tx[k] = basis(b.x0, b.x1, c.x[k]);
      Ty[k] = basis(b.y0, b.y1, c.y[k]);
    }
    std::vector<double> C(P * P * M, 0.0);  // C[q'][p][m]
    for (std::size_t qc = 0; qc < P; ++qc)
      for (std::size_t pc = 0; pc < P; ++pc)
        for (std::size_t p = 0; p < P; ++p)
          for (std::size_t mm = 0; mm < M; ++mm)
            C[(qc * P + p) * M + mm] += Tx[pc][p] * c.w[(mm * P + qc) * P + pc];
    for (std::size_t qc = 0; qc < P; ++qc)
      for (std::size_t q = 0; q < P; ++q)
        for (std::size_t p = 0; p < P; ++p)
          for (std::size_t mm = 0; mm < M; ++mm)
            r.w[(mm * P + q) * P + p] += Ty[qc][q] * C[(qc * P + p) * M + mm];
  }

  // One block's rule at c: e = (-eta, a)/|d| at every node, against its six weights. A row of
  // nodes at a time, its directions first (a loop the compiler runs two or four nodes at a time),
  // then each weight's dot product with them in pairs of nodes.
  static void apply(const Rule& r, double cx, double cy, double* acc) {
    constexpr std::size_t P = kPoints;
    double s[10][2] = {};
    double a[P], ex[P], ey[P];
    for (std::size_t p = 0; p < P; ++p) a[p] = r.x[p] - cx;
    for (std::size_t q = 0; q < P; ++q) {
      const double eta = r.y[q] - cy;
      for (std::size_t p = 0; p < P; ++p) {
        const double inv = 1.0 / std::sqrt(a[p] * a[p] + eta * eta);
        ex[p] = -eta * inv;
        ey[p] = a[p] * inv;
      }
      const double* w = r.w.data() + q * P;  // w[m P^2 + q P + p]
      auto dot = [&](std::size_t m, const double* e, double* out) {
        const double* wm = w + m * P * P;
        for (std::size_t p = 0; p < P; p += 2) {
          out[0] += wm[p] * e[p];
          out[1] += wm[p + 1] * e[p + 1];
        }
      };
      dot(0, ex, s[0]);  // ∫ sigma0 e_x
      dot(1, ex, s[1]);  // x e_x
      dot(2, ex, s[2]);  // y e_x
      dot(3, ex, s[3]);  // xy e_x
      dot(5, ex, s[4]);  // y^2 e_x
      dot(0, ey, s[5]);  // e_y
      dot(1, ey, s[6]);  // x e_y
      dot(2, ey, s[7]);  // y e_y
      dot(4, ey, s[8]);  // x^2 e_y
      dot(3, ey, s[9]);  // xy e_y
    }
    double t[10];
    for (std::size_t k = 0; k < 10; ++k) t[k] = s[k][0] + s[k][1];
    // The channels' order (MapStripIntegrator::add): ex {1, x, y}, ey {1, x, y},
    // x_ey {x, x^2, xy}, y_ex {y, xy, y^2}.
    acc[0] += t[0];
    acc[1] += t[1];
    acc[2] += t[2];
    acc[3] += t[5];
    acc[4] += t[6];
    acc[5] += t[7];
    acc[6] += t[6];
    acc[7] += t[8];
    acc[8] += t[9];
    acc[9] += t[2];
    acc[10] += t[3];
    acc[11] += t[4];
  }

  std::size_t nxc_, nyc_;                       // cells along x and y
  std::array<double, kPoints> t_{}, lambda_{};  // Chebyshev points on [-1, 1], their weights
  std::vector<Level> levels_;                   // levels_[L]: blocks of 2^L x 2^L cells
  std::vector<Rule> rules_;
};

}  // namespace frictionid::model
