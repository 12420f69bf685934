// The far field of a pressure map in blocks of grid cells (map_block_rules.hpp), through
// MapStripIntegrator: against every cell by its own rule on random grids of 16 to 70 lines each
// way (spacing jittered, one sample in five zero, some with a zero rim), for centres of rotation
// inside, on grid lines, next to the edges, outside and far away; and against the independent
// two-dimensional oracle (spot_reference.hpp) on a 24 x 24 grid, where the blocks take part.
#include <frictionid/model/map_block_rules.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/map_strip_integrator.hpp>
#include <frictionid/model/spot_integrals.hpp>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace frictionid::model::map_block_rules_test {
namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;

// n lines over [lo, hi], each inner one jittered by up to a third of the mean spacing.
std::vector<double> jittered_lines(sc::Uniform& u, std::size_t n, double lo, double hi) {
  std::vector<double> out;
  const double h = (hi - lo) / static_cast<double>(n - 1);
  for (std::size_t k = 0; k < n; ++k) {
    const bool inner = k > 0 && k + 1 < n;
    out.push_back(lo + h * (static_cast<double>(k) + (inner ? u.in(-1.0, 1.0) / 3.0 : 0.0)));
  }
  return out;
}

PressureMap random_map(sc::Uniform& u, std::size_t nx, std::size_t ny, bool zero_rim) {
  PressureMap m;
  m.x = jittered_lines(u, nx, -u.in(0.6, 1.3), u.in(0.6, 1.3));
  m.y = jittered_lines(u, ny, -u.in(0.4, 1.1), u.in(0.4, 1.1));
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const bool rim = i == 0 || j == 0 || i + 1 == nx || j + 1 == ny;
      m.sigma0.push_back((zero_rim && rim) || u.u01() < 0.2 ? 0.0 : u.in(0.05, 1.5));
    }
  return m;
}

std::vector<std::array<double, 2>> centres(sc::Uniform& u, const PressureMap& m) {
  const double x0 = m.x.front(), x1 = m.x.back(), y0 = m.y.front(), y1 = m.y.back();
  std::vector<std::array<double, 2>> out;
  for (int k = 0; k < 24; ++k) {
    switch (k % 6) {
      case 0:
        out.push_back({u.in(x0, x1), u.in(y0, y1)});
        break;
      case 1:
        out.push_back({m.x[u.index(m.nx())], u.in(y0, y1)});
        break;
      case 2:
        out.push_back({m.x[u.index(m.nx())] + 1e-9, m.y[u.index(m.ny())]});
        break;
      case 3:
        out.push_back({u.in(x0, x1), (u.sign() > 0 ? y1 : y0) + u.in(-0.05, 0.05)});
        break;
      case 4:
        out.push_back({u.in(2.0 * x0, 2.0 * x1), u.in(2.0 * y0, 2.0 * y1)});
        break;
      default: {
        const double r = std::pow(10.0, u.in(0.5, 5.0)), t = u.in(-sc::kPi, sc::kPi);
        out.push_back({r * std::cos(t), r * std::sin(t)});
        break;
      }
    }
  }
  return out;
}

TEST(MapBlockRules, AgreeWithTheCellsOwnRulesTo2e13OfTheLoadOnRandomGrids) {
  sc::Uniform u(2027);
  double worst = 0.0;
  int differing = 0;
  for (int grid = 0; grid < 8; ++grid) {
    const PressureMap m = random_map(u, 16 + u.index(55), 16 + u.index(55), grid % 2 == 0);
    const MapStripIntegrator strips(m);
    const double a0 = map_moments(m).A0;
    for (const auto& c : centres(u, m)) {
      const auto got = strips(c[0], c[1]).channels();
      const auto want = strips.without_blocks(c[0], c[1]).channels();
      for (std::size_t ch = 0; ch < got.size(); ++ch) {
        const double err = std::fabs(got[ch] - want[ch]) / a0;
        EXPECT_LT(err, 2e-13) << "grid " << grid << " channel " << ch << " at (" << c[0] << ", "
                              << c[1] << ")";
        worst = std::max(worst, err);
        differing += got[ch] != want[ch] ? 1 : 0;
      }
    }
  }
  EXPECT_GT(differing, 1000);  // the blocks did take part
  std::cout << "[ worst    ] blocks vs each cell's rule, of the load: " << worst << "\n";
}

TEST(MapBlockRules, KeepTheIntegralsWithinTheOraclesTolerance) {
  sc::Uniform u(77);
  const PressureMap m = random_map(u, 24, 24, false);
  sr::Spot spot;
  spot.shape = sr::Shape::Map;
  spot.grid.x = m.x;
  spot.grid.y = m.y;
  spot.grid.sigma0 = m.sigma0;
  const MapStripIntegrator strips(m);
  const SpotMoments<double> mom = map_moments(m);
  double worst = 0.0;
  for (const auto& c : std::vector<std::array<double, 2>>{
           {0.0, 0.0}, {0.31, -0.22}, {m.x[3], m.y[20]}, {m.x.back(), 0.1}, {2.5, 1.0}}) {
    sr::Params p = sc::random_params(u, 1.0);
    p.f = 1.0;
    sr::Motion motion;
    motion.omega = 1.0;
    motion.v_x = c[1];  // c = (-v_y, v_x)/(omega R)
    motion.v_y = -c[0];
    const sr::Result want = sr::spot_reference(spot, p, motion, 1e-12);
    const SpotIntegrals v = strips(c[0], c[1]);
    const SpotIntegrals cells = strips.without_blocks(c[0], c[1]);
    EXPECT_NE(v.ex[0], cells.ex[0]) << "no block at (" << c[0] << ", " << c[1] << ")";
    // T_x, T_y, M_z of docs/physics.md (9.5) with f = N = R = omega = 1.
    const double k = 1.0 / (mom.A0 + p.h * mom.Ax + p.h_y * mom.Ay);
    auto mix = [&p](const std::array<double, 3>& w) { return w[0] + p.h * w[1] + p.h_y * w[2]; };
    const double tx = k * mix(v.ex), ty = k * p.kappa * mix(v.ey);
    const double mz = k * (p.kappa * mix(v.x_ey) - mix(v.y_ex));
    const double err =
        std::max({std::fabs(tx - want.T_x), std::fabs(ty - want.T_y), std::fabs(mz - want.M_z)});
    EXPECT_LT(err, 1e-12) << "at (" << c[0] << ", " << c[1] << ")";
    worst = std::max(worst, err);
  }
  std::cout << "[ worst    ] blocks vs oracle, of f N (R): " << worst << "\n";
}

// A fit makes an integrator at every pass and reads its rows from a cache: the blocks (0.07 s on
// a 64 x 64 map) are set up only when a point asks, once, and copies share them.
TEST(MapBlockRules, AreSetUpOnlyWhenAPointAsksForThem) {
  sc::Uniform u(5);
  const PressureMap m = random_map(u, 64, 64, false);
  const MapStripIntegrator strips(m);
  EXPECT_FALSE(strips.blocks_set_up());
  const MapStripIntegrator copy = strips;
  const SpotIntegrals first = copy(0.1, 0.2);
  EXPECT_TRUE(strips.blocks_set_up());
  EXPECT_EQ(strips(0.1, 0.2).channels(), first.channels());
}

}  // namespace
}  // namespace frictionid::model::map_block_rules_test
