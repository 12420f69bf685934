// The twelve spot integrals (spot_integrals.hpp) of a pressure map at one centre of rotation c
// (docs/physics.md §9.1, §9.3). The cells within kReach of their own sides from c are summed in
// closed form, by the corner sums of map_corner_sums.hpp, as far as their cancellation allows
// (~(D/h)^4); every other cell by the rules below. Both ways agree with the two-dimensional
// oracle of the tests to 2e-13 of fN and fNR on random grids, centres on and next to grid lines
// and nodes included, and with each other to 5e-12 of the load (2e-12 measured). On the 13 x 9
// footprint a point of the table's build costs ~7 us of CPU, against ~36 us cell by cell (100
// x-pieces, 700 closed-form strips) and ~3 ms for the rays of SpotIntegrator (experiments/
// README.md, "Contact spots").
//
// Cell by cell: inside a cell sigma0 is bilinear, for fixed x linear in y, so with a = x - c_x,
// eta = y - c_y and rho = sqrt(a^2 + eta^2)
//   ∫ sigma0 {1, y, y^2} e_x dy = -∫ (A + B eta) {1, y, y^2} eta/rho deta,
//   ∫ sigma0 {1, y} e_y dy = a ∫ (A + B eta) {1, y} deta/rho
// need the primitives of eta^k/rho for k <= 4: ln(eta + rho), rho, (eta rho - a^2 J0)/2,
// rho^3/3 - a^2 rho and (eta^3 rho - 3 a^2 J2)/4, formed between the cell's edges without
// cancellation (log1p where both edges lie on one side of c_y). The x-integral is by
// Gauss–Legendre on pieces graded geometrically towards c_x: the y-integral is analytic in x but
// for a ln|a| at x = c_x when c_y lies in the cell, and branch points at c_x +- i|eta| of the
// cell's edges; each piece is at most as long as its distance from the nearest of them, and
// takes the number of points that its Bernstein ellipse asks for 1e-16. A cell more than
// kFarCells of its sides from c has an analytic integrand: a product Gauss–Legendre rule takes
// it, 7 x 7 points at 3 sides, 6 x 6 at 5 to 9 (the closed forms' terms would cancel there,
// growing like the square of the distance, and their strips cost more). Blocks of 4 x 4 cells and
// more at least their side from c and clear of the window take one rule each instead
// (map_block_rules.hpp): a point then costs the log of the cells, not the cells.
// Cells whose four samples are zero are skipped.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/map_block_rules.hpp>
#include <frictionid/model/map_corner_sums.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

namespace frictionid::model {

class MapStripIntegrator {
 public:
  explicit MapStripIntegrator(const PressureMap& map)
      : x_(map.x),
        y_(map.y),
        index_((map.nx() - 1) * (map.ny() - 1), -1),
        blocks_(std::make_shared<LazyBlocks>(map)) {
    for (std::size_t j = 0; j + 1 < map.ny(); ++j)
      for (std::size_t i = 0; i + 1 < map.nx(); ++i) {
        Cell c{x_[i],
               x_[i + 1],
               y_[j],
               y_[j + 1],
               {map.sample(i, j), map.sample(i + 1, j), map.sample(i, j + 1),
                map.sample(i + 1, j + 1)},
               {},
               i,
               j};
        if (c.s[0] == 0.0 && c.s[1] == 0.0 && c.s[2] == 0.0 && c.s[3] == 0.0) continue;
        // sigma0 about each corner (ix, iy): its sample + beta dx + gamma dy + delta dx dy,
        // with the corner's sign in the cell's corner sum (+ at (x0, y0) and (x1, y1)).
        const double hx = c.x1 - c.x0, hy = c.y1 - c.y0;
        const double twist = c.s[0] - c.s[1] - c.s[2] + c.s[3];
        for (int iy = 0; iy < 2; ++iy)
          for (int ix = 0; ix < 2; ++ix) {
            const double sign = ix == iy ? 1.0 : -1.0;
            c.corner[iy * 2 + ix] = {sign * c.s[static_cast<std::size_t>(iy * 2 + ix)],
                                     sign * (c.s[1] - c.s[0] + twist * iy) / hx,
                                     sign * (c.s[2] - c.s[0] + twist * ix) / hy,
                                     sign * twist / (hx * hy)};
          }
        index_[j * (x_.size() - 1) + i] = static_cast<int>(cells_.size());
        cells_.push_back(c);
      }
  }

  // The integrals for the centre of rotation at physical (cx, cy), units of R.
  SpotIntegrals operator()(double cx, double cy) const { return integrate(cx, cy, true); }

  // The same with every cell outside the window by its own rule (the reference for the blocks'
  // tests).
  SpotIntegrals without_blocks(double cx, double cy) const { return integrate(cx, cy, false); }

  // The nodes of the grid cells [i0, i1) x [j0, j1) (those with a nonzero sample), with sigma0
  // about each summed over its cells among them: their corner sums (MapCornerMoments) are those
  // cells' integrals wherever c lies. A map's table adds the cells next to c this way.
  std::vector<MapCornerNode> corner_nodes(std::size_t i0, std::size_t i1, std::size_t j0,
                                          std::size_t j1) const {
    std::vector<MapCornerNode> out;
    for_each_node(
        i0, i1, j0, j1,
        [=](std::size_t i, std::size_t j) { return i >= i0 && i < i1 && j >= j0 && j < j1; },
        [&out](const MapCornerNode& n) { out.push_back(n); });
    return out;
  }

  // Whether the far cells' blocks are set up (at the first point that asks for them).
  bool blocks_set_up() const { return blocks_->ready(); }

  // How many grid cells around c the corner sums take (0: none, every cell by itself).
  std::size_t window_cells(double cx, double cy) const { return window(cx, cy).cells(); }

  // The same, every cell by itself (the reference for the corner sums' tests).
  SpotIntegrals cell_by_cell(double cx, double cy) const {
    double acc[12] = {};
    for (const Cell& c : cells_) cell(c, cx, cy, acc);
    return SpotIntegrals::from_channels(acc);
  }

 private:
  SpotIntegrals integrate(double cx, double cy, bool blocks) const {
    double acc[12] = {};
    const Window w = window(cx, cy);
    if (w.i1 > w.i0) corner_sums(cx, cy, w, acc);
    const MapBlockRules* rules = blocks ? &blocks_->get() : nullptr;
    if (!rules || !rules->any()) {
      for (const Cell& c : cells_)
        if (!w.holds(c.i, c.j)) cell(c, cx, cy, acc);
      return SpotIntegrals::from_channels(acc);
    }
    // The blocks far from c by their rules, the other cells by theirs, in the same order as
    // without blocks; the blocks' sums added last.
    thread_local std::vector<int> leaves;
    leaves.clear();
    const std::size_t nx = x_.size() - 1;
    double far[12] = {};
    rules->sum(
        cx, cy,
        [&w](std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1) {
          return w.touches(i0, i1, j0, j1);
        },
        [&](std::size_t i, std::size_t j) {
          if (!w.holds(i, j)) leaves.push_back(index_[j * nx + i]);
        },
        far);
    std::sort(leaves.begin(), leaves.end());
    for (int k : leaves) cell(cells_[static_cast<std::size_t>(k)], cx, cy, acc);
    for (std::size_t k = 0; k < 12; ++k) acc[k] += far[k];
    return SpotIntegrals::from_channels(acc);
  }

  struct Corner {
    double alpha, beta, gamma, delta;  // sigma0 about the corner, times its sign (MapCornerNode)
  };
  struct Cell {
    double x0, x1, y0, y1;
    std::array<double, 4> s;       // samples at (x0, y0), (x1, y0), (x0, y1), (x1, y1)
    std::array<Corner, 4> corner;  // in the same order
    std::size_t i, j;              // its place in the grid
  };

  // The window: the cells whose farthest corner lies within kReach cell sides from c, counted
  // in that cell's own sides along x and y. A cell's corner sums lose ~(D/h)^4 of the precision
  // (map_corner_sums.hpp); on random grids (samples 0 or up to 1.5, side by side, lines jittered
  // by a third) they then stay within 2e-12 of the load of the cells' own rules. The test is
  // separable: a column's share (its farthest x / its width)^2 plus a row's. No cell where c lies
  // farther outside the grid than kOutside of its width along x or y: the channels weighted by
  // x and y grow as |c|^2 there, and a table's tolerance is of A0 (on a one-cell map the reach
  // alone would let the sums run 9 map widths out).
  static constexpr double kReach = 9.0;
  static constexpr double kOutside = 0.5;

  struct Window {
    std::vector<double> fx, fy;                  // each column's and row's share of kReach^2
    std::size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;  // the bounding box of its cells
    bool holds(std::size_t i, std::size_t j) const {
      return i >= i0 && i < i1 && j >= j0 && j < j1 && fx[i] + fy[j] <= kReach * kReach;
    }
    // Whether any of the cells [i0, i1) x [j0, j1) is the window's.
    bool touches(std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1) const {
      if (fx.empty()) return false;
      const double mx = *std::min_element(fx.begin() + static_cast<std::ptrdiff_t>(i0),
                                          fx.begin() + static_cast<std::ptrdiff_t>(i1));
      const double my = *std::min_element(fy.begin() + static_cast<std::ptrdiff_t>(j0),
                                          fy.begin() + static_cast<std::ptrdiff_t>(j1));
      return mx + my <= kReach * kReach;
    }
    std::size_t cells() const {
      std::size_t n = 0;
      for (std::size_t j = j0; j < j1; ++j)
        for (std::size_t i = i0; i < i1; ++i) n += holds(i, j) ? 1 : 0;
      return n;
    }
  };

  Window window(double cx, double cy) const {
    Window w;
    const double wx = x_.back() - x_.front(), wy = y_.back() - y_.front();
    const double gx = std::max({0.0, x_.front() - cx, cx - x_.back()});
    const double gy = std::max({0.0, y_.front() - cy, cy - y_.back()});
    if (!(gx <= kOutside * wx && gy <= kOutside * wy)) return w;
    auto shares = [](const std::vector<double>& g, double c) {
      std::vector<double> f(g.size() - 1);
      for (std::size_t i = 0; i + 1 < g.size(); ++i) {
        const double d = std::max(std::fabs(g[i] - c), std::fabs(g[i + 1] - c)) / (g[i + 1] - g[i]);
        f[i] = d * d;
      }
      return f;
    };
    w.fx = shares(x_, cx);
    w.fy = shares(y_, cy);
    const double R2 = kReach * kReach;
    const double min_x = *std::min_element(w.fx.begin(), w.fx.end());
    const double min_y = *std::min_element(w.fy.begin(), w.fy.end());
    // The bounding box of its cells: the columns whose share leaves room for the smallest row's,
    // and the rows likewise.
    auto run = [R2](const std::vector<double>& f, double other, std::size_t& lo, std::size_t& hi) {
      lo = f.size();
      hi = 0;
      for (std::size_t i = 0; i < f.size(); ++i)
        if (f[i] + other <= R2) {
          lo = std::min(lo, i);
          hi = i + 1;
        }
      if (lo >= hi) lo = hi = 0;
    };
    run(w.fx, min_y, w.i0, w.i1);  // (a column runs with the smallest row and so that row with
    run(w.fy, min_x, w.j0, w.j1);  // the smallest column: both empty or neither)
    return w;
  }

  // Corner sums over the window's nonzero cells, node by node.
  void corner_sums(double cx, double cy, const Window& w, double* acc) const {
    MapCornerMoments moments(cx, cy);
    for_each_node(
        w.i0, w.i1, w.j0, w.j1, [&w](std::size_t i, std::size_t j) { return w.holds(i, j); },
        [&moments](const MapCornerNode& n) { moments.add(n); });
    moments.add_channels(acc);
  }

  // Every node of the cells [i0, i1) x [j0, j1) that `holds` admits (nonzero cells only), with
  // sigma0 about it summed over those of its four cells with their corners' signs, to `sink`.
  template <typename Holds, typename Sink>
  void for_each_node(std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1,
                     const Holds& holds, const Sink& sink) const {
    const std::size_t nx = x_.size() - 1;
    for (std::size_t j = j0; j <= j1; ++j)
      for (std::size_t i = i0; i <= i1; ++i) {
        MapCornerNode n{x_[i], y_[j], 0.0, 0.0, 0.0, 0.0};
        bool any = false;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            // The cell whose corner (1 - dx, 1 - dy) is this node.
            if ((dx == 0 && i == 0) || (dy == 0 && j == 0)) continue;
            const std::size_t ci = i + static_cast<std::size_t>(dx) - 1;
            const std::size_t cj = j + static_cast<std::size_t>(dy) - 1;
            if (!holds(ci, cj)) continue;
            const int k = index_[cj * nx + ci];
            if (k < 0) continue;
            const Corner& q = cells_[static_cast<std::size_t>(k)].corner[(1 - dy) * 2 + (1 - dx)];
            n.alpha += q.alpha;
            n.beta += q.beta;
            n.gamma += q.gamma;
            n.delta += q.delta;
            any = true;
          }
        if (any) sink(n);
      }
  }

  // One cell's integrals by the rules below, added to acc.
  void cell(const Cell& c, double cx, double cy, double* acc) const {
    const double hx = c.x1 - c.x0, hy = c.y1 - c.y0;
    const double gx = std::max({0.0, c.x0 - cx, cx - c.x1});
    const double gy = std::max({0.0, c.y0 - cy, cy - c.y1});
    const double gap = std::sqrt(gx * gx + gy * gy);
    if (gap > kFarCells * std::max(hx, hy))
      far_cell(c, cx, cy, gap, acc);
    else
      near_cell(c, cx, cy, gx, gy, acc);
  }

  static constexpr double kFarCells = 3.0;  // a cell this many sides away: product rule
  static constexpr double kFloor = 1e-7;    // the first piece at a true singularity / cell width
  static constexpr double kLog = 26.0;      // -ln of a cell's error bound (5e-12 of it)
  static constexpr double kGrowth = 2.0;    // a graded piece's length / its distance from c
  static constexpr int kFloorPoints = 8;
  // A singularity within kSingular kNearEnd of a piece's end: the piece's first kNearEnd by
  // tanh-sinh, which errs by ~exp(-2 pi w/h) of the singularity's share, w ~ (pi/2)/ln(width/
  // distance): < 1e-13 of the cell for any distance (51 nodes where the grading takes 180 at
  // 1e-9 of the cell).
  static constexpr double kNearEnd = 0.05;
  static constexpr double kSingular = 0.01;  // a ln|a| over a piece 1e-7 wide: ~1e-20 of the cell
  static constexpr int kMaxPoints = 24;

  // Points for a piece of that length whose nearest singularity lies at (re, im) from its start:
  // the Bernstein ellipse through it, and the analytic factor is multiplied by a cubic (sigma0
  // times x^2), which the rule's degree 2n - 1 must carry too.
  static int points_for(double re, double im, double length, int least) {
    const double zr = (2.0 * re - length) / length, zi = 2.0 * im / length;
    return points_for_rho(bernstein_parameter_through(zr, zi), least);
  }
  static int points_for_rho(double rho, int least) {
    // The error of n points is ~ rho^-(2n - 3): the cubic factor takes three of the degrees.
    const double n = std::ceil(gauss_legendre_points(rho, kLog, 3));
    return n < kMaxPoints ? std::max(least, static_cast<int>(n)) : kMaxPoints;
  }

  // Points for a side of length h of a cell `gap` from c: the singularities of either inner
  // integrand lie at least gap from the side in the complex plane, and of the Bernstein ellipses
  // that keep that distance the narrowest is the one through the point gap off the side's
  // middle, with ln rho = asinh(2 gap / h). So n points suffice from the d = 2 gap / h at
  // which kLog / ln rho = 2n - 3 (points_for_rho): the thresholds sinh(kLog / (2n - 3)), found
  // once (the Bernstein parameter by two hypots at every cell and point took a sixth of a
  // map's build).
  static int far_points(double gap, double h) {
    static const std::array<double, kMaxPoints + 1> threshold = [] {
      std::array<double, kMaxPoints + 1> t{};
      for (int n = 2; n <= kMaxPoints; ++n)
        t[static_cast<std::size_t>(n)] = std::sinh(kLog / (2.0 * n - 3.0));
      return t;
    }();
    const double d = 2.0 * gap / h;
    int n = 2;
    while (n < kMaxPoints && d < threshold[static_cast<std::size_t>(n)]) ++n;
    return n;
  }

  // A cell far from c: sigma0 {1, x, y} times the analytic direction field, by a product rule
  // (degree 3 of the polynomial part in each variable, hence at least 2 points).
  void far_cell(const Cell& c, double cx, double cy, double gap, double* acc) const {
    const double hx = c.x1 - c.x0, hy = c.y1 - c.y0;
    const std::vector<QuadratureNode>& rx = gauss_legendre_rule(far_points(gap, hx));
    const std::vector<QuadratureNode>& ry = gauss_legendre_rule(far_points(gap, hy));
    // What the y-nodes share across the x-nodes: eta, its weights towards y0 and y1, eta y and
    // eta y^2, y.
    const std::size_t n = ry.size();
    double eta[kMaxPoints], w0[kMaxPoints], w1[kMaxPoints], ey[kMaxPoints], eyy[kMaxPoints],
        ys[kMaxPoints];
    for (std::size_t k = 0; k < n; ++k) {
      const QuadratureNode& gy = ry[k];
      const double y = c.y0 + hy * gy.from_left;
      eta[k] = y - cy;
      w0[k] = gy.weight * gy.from_right;
      w1[k] = gy.weight * gy.from_left;
      ys[k] = y;
      ey[k] = eta[k] * y;
      eyy[k] = ey[k] * y;
    }
    for (const QuadratureNode& gx : rx) {
      const double x = c.x0 + hx * gx.from_left, a = x - cx;
      const double lo = c.s[0] * gx.from_right + c.s[1] * gx.from_left;
      const double hi = c.s[2] * gx.from_right + c.s[3] * gx.from_left;
      double e0 = 0.0, e1 = 0.0, e2 = 0.0, f0 = 0.0, f1 = 0.0;  // ∫{1,y,y^2} e_x, ∫{1,y} e_y / a
      for (std::size_t k = 0; k < n; ++k) {
        const double w = (lo * w0[k] + hi * w1[k]) / std::sqrt(a * a + eta[k] * eta[k]);
        e0 -= w * eta[k];
        e1 -= w * ey[k];
        e2 -= w * eyy[k];
        f0 += w;
        f1 += w * ys[k];
      }
      add(acc, gx.weight * hx * hy, x, e0, e1, e2, f0 * a, f1 * a);
    }
  }

  // sum W {ex: E0, x E0, E1; ey: F0, x F0, F1; x_ey: x F0, x^2 F0, x F1; y_ex: E1, x E1, E2}.
  static void add(double* acc, double W, double x, double e0, double e1, double e2, double f0,
                  double f1) {
    acc[0] += W * e0;
    acc[1] += W * x * e0;
    acc[2] += W * e1;
    acc[3] += W * f0;
    acc[4] += W * x * f0;
    acc[5] += W * f1;
    acc[6] += W * x * f0;
    acc[7] += W * x * x * f0;
    acc[8] += W * x * f1;
    acc[9] += W * e1;
    acc[10] += W * x * e1;
    acc[11] += W * e2;
  }

  // A cell near c: the y-integral in closed form at each x, x on graded pieces. gx, gy: the
  // distances of c from the cell's x- and y-ranges.
  void near_cell(const Cell& c, double cx, double cy, double gx, double gy, double* acc) const {
    const double hx = c.x1 - c.x0;
    const double eta0 = c.y0 - cy, eta1 = c.y1 - cy;
    // Sides of c_x within the cell: each runs from p (the point of the cell nearest c_x) away.
    if (cx > c.x0 && cx < c.x1) {
      side(c, cy, eta0, eta1, cx, c.x1 - cx, +1.0, 0.0, gy, acc);
      side(c, cy, eta0, eta1, cx, cx - c.x0, -1.0, 0.0, gy, acc);
    } else if (cx <= c.x0) {
      side(c, cy, eta0, eta1, c.x0, hx, +1.0, gx, gy, acc);
    } else {
      side(c, cy, eta0, eta1, c.x1, hx, -1.0, gx, gy, acc);
    }
  }

  // x = p + dir t for t in [0, length]; the singularities lie `e` beyond p along x and `d` off
  // the real axis (d = 0: c_y within the cell, a ln|a| at x = c_x).
  void side(const Cell& c, double cy, double eta0, double eta1, double p, double length, double dir,
            double e, double d, double* acc) const {
    if (!(length > 0.0)) return;
    const double hx = c.x1 - c.x0, H = c.y1 - c.y0;
    auto piece = [&](double t, double len, const std::vector<QuadratureNode>& nodes) {
      for (const QuadratureNode& g : nodes) {
        const double off = t + len * g.from_left;  // from p, exact near p
        const double x = p + dir * off;
        const double a = dir * (off + e);  // x - c_x, exact next to c_x
        const double tx = (x - c.x0) / hx;
        const double lo = c.s[0] + (c.s[1] - c.s[0]) * tx;  // sigma0 at y0 and y1
        const double hi = c.s[2] + (c.s[3] - c.s[2]) * tx;
        strip(acc, g.weight * len, x, a, cy, eta0, eta1, H, lo, hi);
      }
    };
    double t = 0.0;
    if (std::sqrt(e * e + d * d) < kSingular * kNearEnd * length) {
      // A singularity this close to p: tanh-sinh over [0, kNearEnd length] (its nodes crowd
      // towards p double-exponentially), graded pieces beyond.
      t = kNearEnd * length;
      piece(0.0, t, radial_rule());
    }
    while (t < length) {
      const double dist = std::sqrt((t + e) * (t + e) + d * d);
      const bool floor = dist < kFloor * hx;
      const double end = std::min(length, t + (floor ? kFloor * hx : kGrowth * dist));
      const double len = end - t;
      piece(t, len, gauss_legendre_rule(floor ? kFloorPoints : points_for(-e - t, d, len, 3)));
      t = end;
    }
  }

  // One x: the closed-form y-integrals over eta in [eta0, eta1] of sigma0 = lo + (hi - lo)
  // (eta - eta0)/H.
  static void strip(double* acc, double W, double x, double a, double cy, double eta0, double eta1,
                    double H, double lo, double hi) {
    const double a2 = a * a;
    const double r0 = std::sqrt(a2 + eta0 * eta0), r1 = std::sqrt(a2 + eta1 * eta1);
    // [rho] and [ln(eta + rho)] between the edges: log1p where both lie on one side of c_y.
    const double D1 = H * (eta1 + eta0) / (r1 + r0);
    double D0;
    if (eta0 >= 0.0)
      D0 = std::log1p((H + D1) / (eta0 + r0));
    else if (eta1 <= 0.0)
      D0 = std::log1p((H - D1) / (r1 - eta1));
    else
      D0 = a == 0.0 ? 0.0 : std::log((eta1 + r1) * (r0 - eta0) / a2);
    const double aD0 = a == 0.0 ? 0.0 : a * D0;
    const double a2D0 = a == 0.0 ? 0.0 : a2 * D0;
    const double D2 = 0.5 * (eta1 * r1 - eta0 * r0 - a2D0);
    const double D3 = D1 * ((r1 * r1 + r1 * r0 + r0 * r0) / 3.0 - a2);
    const double D4 = 0.25 * (eta1 * eta1 * eta1 * r1 - eta0 * eta0 * eta0 * r0 - 3.0 * a2 * D2);
    // sigma0 = A + B eta.
    const double B = (hi - lo) / H, A = lo - B * eta0;
    // ∫ sigma0 eta^k/rho, k = 1..3, and a ∫ sigma0 eta^k/rho, k = 0..1.
    const double S1 = A * D1 + B * D2;          // ∫ sigma0 eta/rho
    const double S2 = A * D2 + B * D3;          // ∫ sigma0 eta^2/rho
    const double S3 = A * D3 + B * D4;          // ∫ sigma0 eta^3/rho
    const double T0 = A * aD0 + B * a * D1;     // a ∫ sigma0/rho
    const double T1 = A * a * D1 + B * a * D2;  // a ∫ sigma0 eta/rho
    // y = eta + c_y.
    const double e0 = -S1;
    const double e1 = -(S2 + cy * S1);
    const double e2 = -(S3 + 2.0 * cy * S2 + cy * cy * S1);
    const double f0 = T0;
    const double f1 = T1 + cy * T0;
    add(acc, W, x, e0, e1, e2, f0, f1);
  }

  std::vector<double> x_, y_;
  std::vector<int> index_;  // of each grid cell (j (nx - 1) + i) in cells_, -1 for a zero cell
  std::vector<Cell> cells_;

  // The far cells' blocks, set up at the first point that asks (0.015 s for 30 x 30 cells, 0.17 s
  // for 100 x 100): a fit makes an integrator at every pass and reads its rows from a cache.
  class LazyBlocks {
   public:
    explicit LazyBlocks(const PressureMap& map) : map_(map) {}
    const MapBlockRules& get() {
      std::call_once(once_, [this] {
        rules_.emplace(map_);
        map_ = PressureMap{};
        done_ = true;
      });
      return *rules_;
    }

    bool ready() const { return done_.load(); }

   private:
    std::atomic<bool> done_{false};
    std::once_flag once_;
    PressureMap map_;  // until the blocks are set up
    std::optional<MapBlockRules> rules_;
  };
  std::shared_ptr<LazyBlocks> blocks_;
};

}  // namespace frictionid::model
