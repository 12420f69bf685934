// The corner sums of a pressure map (map_corner_sums.hpp), which MapStripIntegrator takes over a
// window of cells around the centre of rotation, against its cell-by-cell rules (themselves
// checked against the two-dimensional oracle in map_strip_integrator_test.cpp, and bounded by
// 5e-12 of a cell by construction; in practice ~1e-13): on one cell with the centre in it, on its
// edges and at its corners, and on grids of 6 to 20 lines a side with jittered lines, zero samples
// and jumps at the rim, for centres inside cells, on grid lines and nodes and outside the map (up
// to half its height, where the window ends, and beyond, where every cell takes its own rule).
#include <frictionid/model/map_corner_sums.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/map_strip_integrator.hpp>

#include "model/spot_cases.hpp"

namespace frictionid::model::map_corner_sums_test {
namespace {

namespace sc = frictionid::testing::spot_cases;

// The largest difference over the twelve channels.
double difference(const SpotIntegrals& a, const SpotIntegrals& b) {
  const auto u = a.channels(), v = b.channels();
  double d = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) d = std::max(d, std::fabs(u[k] - v[k]));
  return d;
}

// nx x ny lines over about [-1.2, 1.2] x [-1, 1], each interior line moved by up to a third of
// its spacing; samples in [0, 1.5], one in five zero, the rim zero or not.
PressureMap random_map(sc::Uniform& u, std::size_t nx, std::size_t ny, bool zero_rim) {
  auto lines = [&u](std::size_t n, double half) {
    std::vector<double> out;
    for (std::size_t k = 0; k < n; ++k) {
      const double jitter = k == 0 || k + 1 == n ? 0.0 : u.in(-1.0, 1.0) / 3.0;
      out.push_back(-half + 2.0 * half * (static_cast<double>(k) + jitter) / (n - 1.0));
    }
    return out;
  };
  PressureMap m;
  m.x = lines(nx, u.in(0.8, 1.2));
  m.y = lines(ny, u.in(0.5, 1.0));
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const bool rim = i == 0 || j == 0 || i + 1 == nx || j + 1 == ny;
      m.sigma0.push_back((zero_rim && rim) || u.u01() < 0.2 ? 0.0 : u.in(0.0, 1.5));
    }
  return m;
}

TEST(MapCornerSums, OneCellEqualsItsCellRuleTo1e12OfTheLoadWithTheCentreOnItOrInIt) {
  sc::Uniform u(3);
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    PressureMap m;
    const double x0 = u.in(-1.0, 0.0), y0 = u.in(-1.0, 0.0);
    m.x = std::vector<double>{x0, x0 + u.in(0.1, 1.5)};
    m.y = std::vector<double>{y0, y0 + u.in(0.1, 1.5)};
    m.sigma0 = std::vector<double>{u.in(0.0, 2.0), u.in(0.0, 2.0), u.in(0.0, 2.0), u.in(0.0, 2.0)};
    const MapStripIntegrator map(m);
    const double load = 0.25 * (m.x[1] - m.x[0]) * (m.y[1] - m.y[0]) *
                        (m.sigma0[0] + m.sigma0[1] + m.sigma0[2] + m.sigma0[3]);
    // Inside, on each edge, at each corner, and outside (within half its width: the window).
    const double cx[] = {u.in(m.x[0], m.x[1]), m.x[0], m.x[1], m.x[0] - 1e-9, m.x[1] + 0.3};
    const double cy[] = {u.in(m.y[0], m.y[1]), m.y[0], m.y[1], m.y[1] + 1e-9, m.y[0] - 0.2};
    for (double x : cx)
      for (double y : cy) {
        if (map.window_cells(x, y) == 0) continue;
        const double d = difference(map(x, y), map.cell_by_cell(x, y)) / load;
        EXPECT_LT(d, 1e-12) << "cell " << k << " at (" << x << ", " << y << ")";
        worst = std::max(worst, d);
      }
  }
  std::cout << "[ worst    ] one cell, corner sums vs its rule, of the load: " << worst << "\n";
}

TEST(MapCornerSums, MatchTheCellRulesOnRandomGridsTo5e12OfTheLoad) {
  sc::Uniform u(29);
  double worst = 0.0;
  int windows = 0, points = 0, outside = 0;
  for (int grid = 0; grid < 12; ++grid) {
    const std::size_t nx = 6 + u.index(15), ny = 6 + u.index(15);
    const PressureMap m = random_map(u, nx, ny, grid % 2 == 0);
    const MapStripIntegrator map(m);
    double load = 0.0;  // ∫ sigma0, for the scale
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i)
        load += 0.25 * (m.x[i + 1] - m.x[i]) * (m.y[j + 1] - m.y[j]) *
                (m.sample(i, j) + m.sample(i + 1, j) + m.sample(i, j + 1) + m.sample(i + 1, j + 1));
    auto line = [&u](const std::vector<double>& v) { return v[u.index(v.size())]; };
    const double x0 = m.x.front(), x1 = m.x.back(), y0 = m.y.front(), y1 = m.y.back();
    for (int k = 0; k < 40; ++k) {
      double cx = 0.0, cy = 0.0;
      switch (k % 5) {
        case 0:  // inside a cell
          cx = u.in(x0, x1), cy = u.in(y0, y1);
          break;
        case 1:  // on a line
          cx = line(m.x), cy = u.in(y0, y1);
          break;
        case 2:  // at a node
          cx = line(m.x), cy = line(m.y);
          break;
        case 3:  // next to a node
          cx = line(m.x) + u.sign() * 1e-8, cy = line(m.y) - u.sign() * 1e-11;
          break;
        default:  // outside, where the window reaches (half the grid's height) and beyond
          cx = u.in(x0, x1), cy = u.sign() > 0 ? y1 + u.in(0.0, y1 - y0) : y0 - u.in(0.0, y1 - y0);
          break;
      }
      const std::size_t cells = map.window_cells(cx, cy);
      if (cells > 0) ++windows;
      if (cells > 0 && (cy > y1 || cy < y0)) ++outside;
      ++points;
      const double d = difference(map(cx, cy), map.cell_by_cell(cx, cy)) / load;
      EXPECT_LT(d, 5e-12) << "grid " << grid << " (" << nx << " x " << ny << ") at (" << cx << ", "
                          << cy << "), " << cells << " cells by corner sums";
      worst = std::max(worst, d);
    }
  }
  // The centres inside the grid (four in five) have a window, and so do some outside it: the
  // sums were exercised there.
  EXPECT_GT(windows, points / 2);
  EXPECT_GT(outside, 10);
  std::cout << "[ worst    ] corner sums vs cell rules, of the load: " << worst << " (" << windows
            << " of " << points << " centres with a window, " << outside << " outside the grid)\n";
}

}  // namespace
}  // namespace frictionid::model::map_corner_sums_test
