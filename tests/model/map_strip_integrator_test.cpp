// The integration of a pressure map (map_strip_integrator.hpp), with the corner sums over a window
// around the centre of rotation and cell by cell, against the independent two-dimensional oracle
// (spot_reference.hpp): the twelve integrals recombined into T_x, T_y and M_z by docs/physics.md
// (9.5) with random kappa, h and h_y, on random grids with zero samples, for centres of rotation
// inside cells, on and next to grid lines and nodes, on the map's edges and corners, just outside
// it and far away.
#include <frictionid/model/map_strip_integrator.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/spot_integrals.hpp>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace frictionid::model::map_strip_integrator_test {
namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;

// A random grid: 3..8 lines each way over about [-1.3, 1.3] x [-1.2, 1.2], samples in
// [0.05, 1.5] with about one in five zero; every other grid has nonzero edge samples (sigma0
// jumps at the map's rim).
sr::Grid random_grid(sc::Uniform& u, bool zero_rim) {
  auto lines = [&u](std::size_t n, double lo, double hi) {
    std::vector<double> out = {lo};
    std::vector<double> w(n - 1);
    double sum = 0.0;
    for (double& x : w) sum += (x = u.in(0.3, 1.0));
    for (std::size_t k = 0; k + 2 < n; ++k) out.push_back(out.back() + (hi - lo) * w[k] / sum);
    out.push_back(hi);
    return out;
  };
  sr::Grid g;
  g.x = lines(3 + u.index(6), -u.in(0.5, 1.3), u.in(0.5, 1.3));
  g.y = lines(3 + u.index(6), -u.in(0.3, 1.2), u.in(0.3, 1.2));
  for (std::size_t j = 0; j < g.y.size(); ++j)
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      const bool rim = i == 0 || j == 0 || i + 1 == g.x.size() || j + 1 == g.y.size();
      g.sigma0.push_back((zero_rim && rim) || u.u01() < 0.2 ? 0.0 : u.in(0.05, 1.5));
    }
  g.sigma0[(g.y.size() / 2) * g.x.size() + g.x.size() / 2] = 1.0;
  return g;
}

PressureMap production_map(const sr::Grid& g) {
  PressureMap m;
  m.x = g.x;
  m.y = g.y;
  m.sigma0 = g.sigma0;
  return m;
}

// Centres of rotation: inside cells, on and within 1e-10..1e-3 of grid lines and nodes, on the
// outer edges and corners, just outside and far away.
std::vector<std::array<double, 2>> centres(sc::Uniform& u, const sr::Grid& g) {
  const double x0 = g.x.front(), x1 = g.x.back(), y0 = g.y.front(), y1 = g.y.back();
  std::vector<std::array<double, 2>> out;
  auto line = [&u](const std::vector<double>& v) { return v[u.index(v.size())]; };
  auto near = [&u] { return u.sign() * std::pow(10.0, u.in(-10.0, -3.0)); };
  for (int k = 0; k < 16; ++k) {
    switch (k % 8) {
      case 0:
        out.push_back({u.in(x0, x1), u.in(y0, y1)});
        break;
      case 1:
        out.push_back({u.in(x0, x1), line(g.y)});
        break;
      case 2:
        out.push_back({line(g.x) + near(), u.in(y0, y1)});
        break;
      case 3:
        out.push_back({line(g.x), line(g.y)});
        break;
      case 4:
        out.push_back({line(g.x) + near(), line(g.y) + near()});
        break;
      case 5:
        out.push_back({u.sign() > 0 ? x1 : x0, u.sign() > 0 ? y1 : y0});
        break;
      case 6:
        out.push_back({u.in(x0 - 0.5, x1 + 0.5), u.sign() > 0 ? y1 + u.in(0.0, 0.3) : y0 - 0.01});
        break;
      default: {
        const double r = std::pow(10.0, u.in(0.5, 6.0)), t = u.in(-sc::kPi, sc::kPi);
        out.push_back({r * std::cos(t), r * std::sin(t)});
        break;
      }
    }
  }
  return out;
}

// T_x, T_y, M_z of (9.5) with f = N = R = 1 and omega = sign.
std::array<double, 3> resultants(const SpotIntegrals& v, const SpotMoments<double>& m,
                                 const sr::Params& p, double sign) {
  const double c = 1.0 / (m.A0 + p.h * m.Ax + p.h_y * m.Ay);
  auto mix = [&p](const std::array<double, 3>& w) { return w[0] + p.h * w[1] + p.h_y * w[2]; };
  return {sign * c * mix(v.ex), sign * c * p.kappa * mix(v.ey),
          sign * c * (p.kappa * mix(v.x_ey) - mix(v.y_ex))};
}

TEST(MapStripIntegrator, MatchesTheTwoDimensionalOracleOnRandomGridsTo1e12OfTheLoad) {
  sc::Uniform u(41);
  double worst = 0.0;
  int compared = 0;
  for (int grid = 0; grid < 10; ++grid) {
    sr::Spot spot;
    spot.shape = sr::Shape::Map;
    spot.grid = random_grid(u, grid % 2 == 0);
    const PressureMap map = production_map(spot.grid);
    const MapStripIntegrator strips(map);
    const SpotMoments<double> m = map_moments(map);
    const double extent = std::max({-map.x.front(), map.x.back(), -map.y.front(), map.y.back()});
    for (const auto& c : centres(u, spot.grid)) {
      sr::Params p = sc::random_params(u, 1.0);
      p.f = 1.0;
      p.h /= extent;
      p.h_y /= extent;
      const double sign = u.sign();
      sr::Motion motion;
      motion.omega = sign;
      motion.v_x = c[1] * sign;  // c = (-v_y, v_x)/(omega R)
      motion.v_y = -c[0] * sign;
      const sr::Result want = sr::spot_reference(spot, p, motion, 1e-12);
      // With the corner sums over a window around c, and every cell by its own rule.
      for (const SpotIntegrals& v : {strips(c[0], c[1]), strips.cell_by_cell(c[0], c[1])}) {
        const auto got = resultants(v, m, p, sign);
        const double err = std::max({std::fabs(got[0] - want.T_x), std::fabs(got[1] - want.T_y),
                                     std::fabs(got[2] - want.M_z)});
        EXPECT_LT(err, 1e-12) << "grid " << grid << " centre (" << c[0] << ", " << c[1] << ")";
        worst = std::max(worst, err);
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 160);
  std::cout << "[ worst    ] map strips vs oracle, of f N (R): " << worst << "\n";
}

TEST(MapStripIntegrator, AUniformMapIsTheUniformRectangle) {
  // docs/physics.md §9.4: a uniform map on [-1, 1] x [-q, q] is the rectangle with the uniform
  // law; the reference is the ray integration at its fine rules.
  const double q = 0.7;
  PressureMap map;
  map.x = std::vector<double>{-1.0, 0.2, 1.0};
  map.y = std::vector<double>{-q, 0.1, q};
  map.sigma0.assign(9, 2.0);
  const MapStripIntegrator strips(map);
  const SpotIntegrator rays(ContactSpot::rect(q), PressureLaw<double>::uniform(), q,
                            SpotRules{&fine_rule(), &fine_rule()});
  for (const auto& c : std::vector<std::array<double, 2>>{
           {0.0, 0.0}, {0.2, 0.1}, {1.0, q}, {-0.3, 0.9}, {3.0, -2.0}, {40.0, 10.0}}) {
    const SpotIntegrals a = strips(c[0], c[1]), r = rays(c[0], c[1]);
    for (std::size_t w = 0; w < 3; ++w) {
      EXPECT_NEAR(a.ex[w], 2.0 * r.ex[w], 1e-12) << "at (" << c[0] << ", " << c[1] << ")";
      EXPECT_NEAR(a.ey[w], 2.0 * r.ey[w], 1e-12) << "at (" << c[0] << ", " << c[1] << ")";
      EXPECT_NEAR(a.x_ey[w], 2.0 * r.x_ey[w], 1e-12) << "at (" << c[0] << ", " << c[1] << ")";
      EXPECT_NEAR(a.y_ex[w], 2.0 * r.y_ex[w], 1e-12) << "at (" << c[0] << ", " << c[1] << ")";
    }
  }
}

}  // namespace
}  // namespace frictionid::model::map_strip_integrator_test
