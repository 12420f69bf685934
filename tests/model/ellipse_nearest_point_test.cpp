// nearest_rim_point (model/ellipse_nearest_point.hpp) against a brute-force search along the rim.
#include <frictionid/model/ellipse_nearest_point.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "model/spot_cases.hpp"

namespace ellipse_nearest_point_test {
namespace {

namespace fm = frictionid::model;
namespace sc = frictionid::testing::spot_cases;

// The smallest distance from (x, y) to (cos t, q sin t): the best of 20,000 samples of t, then
// golden-section search about it.
double brute_force_distance(double q, double x, double y) {
  auto distance = [&](double t) { return std::hypot(std::cos(t) - x, q * std::sin(t) - y); };
  constexpr int kSamples = 20000;
  double best = 0.0, d_best = HUGE_VAL;
  for (int k = 0; k < kSamples; ++k) {
    const double t = 2.0 * sc::kPi * k / kSamples;
    if (distance(t) < d_best) {
      d_best = distance(t);
      best = t;
    }
  }
  double a = best - 2.0 * sc::kPi / kSamples, b = best + 2.0 * sc::kPi / kSamples;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (distance(c) < distance(d))
      b = d;
    else
      a = c;
  }
  return std::min(d_best, distance(0.5 * (a + b)));
}

// Inside, outside, on both axes and at the centre, for ellipses of aspect 0.05 to 4: the
// distance agrees with the search, and the point returned lies on the rim that far away.
TEST(NearestRimPoint, MatchesABruteForceSearchAlongTheRim) {
  sc::Uniform u(0x9e1);
  double worst = 0.0;
  for (double q : {0.05, 0.3, 1.0, 2.5, 4.0})
    for (int i = 0; i < 40; ++i) {
      double x = u.in(-2.0, 2.0), y = q * u.in(-2.0, 2.0);
      if (i % 8 == 1) y = 0.0;  // on the x axis
      if (i % 8 == 2) x = 0.0;  // on the y axis
      if (i % 8 == 3) x = y = 0.0;
      if (i % 8 == 4) {  // next to the rim
        const double t = u.in(-sc::kPi, sc::kPi), r = 1.0 + u.sign() * 1e-6;
        x = r * std::cos(t);
        y = q * r * std::sin(t);
      }
      const fm::RimPoint p = fm::nearest_rim_point(q, x, y);
      const double want = brute_force_distance(q, x, y);
      const double e = std::fabs(p.distance - want);
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-12) << "q " << q << " at (" << x << ", " << y << ")";
      EXPECT_NEAR(p.x * p.x + (p.y / q) * (p.y / q), 1.0, 1e-14) << "q " << q;
      EXPECT_NEAR(std::hypot(p.x - x, p.y - y), p.distance, 1e-14) << "q " << q;
    }
  std::printf("[ worst    ] nearest rim point vs brute force: %.3g\n", worst);
}

// Off the long axis by next to nothing, from inside (where the nearest point leaves the axis)
// and outside: the root's variable kept only ~1e-16/offset of its relative precision there, and
// below an offset of 2^-53 the rim point went to infinity (a table law's points on ellipse:2,
// read at cos(pi/2) = 6e-17, were 1e-7 off, and its table grew past its budget).
TEST(NearestRimPoint, NextToTheLongAxisItStaysExact) {
  for (double q : {0.3, 2.5})
    for (double along : {0.2, 0.6, 1.5})
      for (double off : {1e-20, 6e-17, 1e-13, 1e-8, 1e-4}) {
        const double x = q < 1.0 ? along : off, y = q < 1.0 ? off : q * along;
        const fm::RimPoint p = fm::nearest_rim_point(q, x, y);
        EXPECT_NEAR(p.distance, brute_force_distance(q, x, y), 1e-12)
            << "q " << q << " at (" << x << ", " << y << ")";
        EXPECT_NEAR(p.x * p.x + (p.y / q) * (p.y / q), 1.0, 1e-14) << "q " << q;
      }
}

}  // namespace
}  // namespace ellipse_nearest_point_test
