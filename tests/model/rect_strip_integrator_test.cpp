// The strips of a rectangle (model/rect_strip_integrator.hpp) under a table law of many samples:
// the product rule against Gauss–Legendre between every two samples, which
// spot_integral_table_test.cpp checks against the rays and spot_model_table_test.cpp against the
// oracle.
#include <frictionid/model/rect_strip_integrator.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>

#include "model/spot_cases.hpp"

namespace frictionid::model::rect_strip_integrator_test {
namespace {

using testing::spot_cases::Uniform;

// Centres over the plane: inside, within 1e-13..1e-2 of an edge (either side) or of a sample's
// line x = +-rho_k, next to a corner, and far away.
std::vector<std::array<double, 2>> centres(double q, int samples, std::uint64_t seed) {
  Uniform u(seed);
  std::vector<std::array<double, 2>> out = {{0.0, 0.0}};
  for (int i = 1; i < 24; ++i) {
    const double near = u.sign() * std::pow(10.0, u.in(-13.0, -2.0));
    switch (i % 6) {
      case 0:
        out.push_back({u.in(-1.0, 1.0), u.in(-q, q)});
        break;
      case 1:
        out.push_back({u.sign() * (1.0 + near), u.in(-1.5 * q, 1.5 * q)});
        break;
      case 2:
        out.push_back({u.in(-1.5, 1.5), u.sign() * (q + near)});
        break;
      case 3: {
        const double line = static_cast<double>(u.index(static_cast<std::size_t>(samples))) /
                            static_cast<double>(samples - 1);
        out.push_back({u.sign() * line + near, u.in(-2.0 * q, 2.0 * q)});
        break;
      }
      case 4:
        out.push_back({u.sign() * (1.0 + near), u.sign() * (q + near)});
        break;
      default: {
        const double r = std::pow(10.0, u.in(0.3, 3.0)), t = u.in(-3.2, 3.2);
        out.push_back({r * std::cos(t), r * std::sin(t)});
        break;
      }
    }
  }
  return out;
}

// A table of 64 samples or more takes the product rule: (1 - x^2)^gamma times the strips at
// Chebyshev points of parts that ignore the samples, integrated against g(|x|) exactly. Against
// the cuts at every sample (by_samples): rim exponents 0, 1/2 and 3/2 (a fractional power at the
// rim), 80 to 1001 samples, aspects 0.3 to 2.5.
TEST(RectStripIntegrator, ATableOfManySamplesByTheProductRuleMatchesGaussLegendreBetweenThem) {
  namespace sc = testing::spot_cases;
  double worst = 0.0;
  for (double q : {0.3, 0.7, 2.5})
    for (const sc::SampledCase& k : sc::sampled_cases()) {
      const PressureLaw<double> law = sc::sampled_table(k.samples, k.gamma);
      const RectStripIntegrator product(law, q), cuts(law, q, true);
      const double A0 = spot_moments(ContactSpot::rect(q), law_moments(law), q).A0;
      worst =
          std::max(worst, sc::product_rule_difference(
                              product, cuts,
                              centres(q, k.samples, 0x5c7 + static_cast<std::uint64_t>(k.samples)),
                              A0, k, q));
    }
  std::cout << "[ worst    ] product rule vs Gauss–Legendre between samples, any channel / A0: "
            << worst << "\n";
}

}  // namespace
}  // namespace frictionid::model::rect_strip_integrator_test
