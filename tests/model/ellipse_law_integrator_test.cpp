// The integrals of an ellipse under a pressure law, built from the uniform ellipse's table layer
// by layer (ellipse_law_integrator.hpp, docs/physics.md (9.8)), against the ray integration of
// spot_integrals.hpp at its fine rules, which integrates the law itself over the spot (every
// breakpoint of these laws cuts its rays and their angles).
#include <frictionid/model/ellipse_law_integrator.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

#include "model/spot_cases.hpp"

namespace frictionid::model::ellipse_law_integrator_test {
namespace {

using testing::spot_cases::Uniform;
constexpr double kPi = 3.14159265358979323846;

struct NamedLaw {
  std::string name;
  PressureLaw<double> law;
};

// Every kind of law the layers serve: closed forms with a fractional and a whole rim exponent,
// a step only, and tables with kinks and a step, and with an edge exponent (1 - rho^2)^0.7.
std::vector<NamedLaw> laws() {
  std::vector<double> rho, sig;
  for (int i = 0; i <= 6; ++i) {  // few samples: each one cuts every ray of the reference
    const double r = i / 6.0;
    rho.push_back(r);
    sig.push_back(std::pow(1.0 - r * r, 0.7) * (1.0 + 0.4 * r * r));
  }
  return {{"hertz", PressureLaw<double>::hertz()},
          {"parabolic", PressureLaw<double>::parabolic()},
          {"power:0.3", PressureLaw<double>::power(0.3)},
          {"power:2.5", PressureLaw<double>::power(2.5)},
          {"annulus:0.4", PressureLaw<double>::annulus(0.4)},
          {"table with kinks and a step", testing::spot_cases::kinked_step_table().law},
          {"table with an edge exponent",
           PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(rho, sig))}};
}

// Centres over the plane: the spot's centre, inside, within 1e-13..1e-1 of the rim (either
// side), near the ends of the long axis, and far away.
std::vector<std::array<double, 2>> centres(double q, std::uint64_t seed) {
  Uniform u(seed);
  std::vector<std::array<double, 2>> out = {{0.0, 0.0}};
  for (int i = 1; i < 20; ++i) {
    const double t = u.in(-kPi, kPi);
    double r = 0.0;
    switch (i % 4) {
      case 0:
        r = u.in(0.0, 1.0);
        break;
      case 1:
        r = 1.0 + u.sign() * std::pow(10.0, u.in(-13.0, -1.0));
        break;
      case 2:
        r = u.in(1.0, 3.0);
        break;
      default:
        r = std::pow(10.0, u.in(0.5, 3.0));
        break;
    }
    out.push_back({r * std::cos(t), q * r * std::sin(t)});
  }
  return out;
}

TEST(EllipseLawIntegrator, EveryLawMatchesTheRaysOnEllipsesOfAspect0_1To4) {
  double worst = 0.0;
  for (double q : {0.1, 0.7, 4.0}) {
    const ContactSpot spot = ContactSpot::ellipse(q);
    const auto uniform = std::make_shared<const SpotIntegralTable>(
        spot, PressureLaw<double>::uniform(), q, std::function<bool()>{}, 0);
    for (const NamedLaw& l : laws()) {
      const EllipseLawIntegrator<SpotIntegralTable> layers(uniform, l.law, q);
      const SpotIntegrator rays(spot, l.law, q,
                                SpotRules{&radial_rule(), &fine_rule(), false, false});
      const double A0 = spot_moments(spot, law_moments(l.law), q).A0;
      for (const auto& c : centres(q, 0x1a7e5 + static_cast<std::uint64_t>(10 * q))) {
        const auto got = layers(c[0], c[1]).channels(), want = rays(c[0], c[1]).channels();
        for (std::size_t k = 0; k < 12; ++k) {
          const double e = std::fabs(got[k] - want[k]) / A0;
          worst = std::max(worst, e);
          EXPECT_LT(e, 1e-10) << l.name << ", q " << q << ", channel " << k << " at (" << c[0]
                              << ", " << c[1] << ")";
        }
      }
    }
  }
  std::cout << "[ worst    ] layers vs rays, any channel / A0: " << worst << "\n";
}

// A table of many samples takes the product rule: the smooth factor at Chebyshev points of
// parts that ignore the samples, integrated against the law's piecewise slope exactly. Against
// Gauss–Legendre between every two samples (by_samples), which the test above checks against
// the rays: rim exponents 0, 1/2 (a fractional rim piece of its own) and 3/2 (a fractional power
// at the rim's end of a part), 80 to 1001 samples, aspects 0.1 to 4, the same centres.
TEST(EllipseLawIntegrator, ATableOfManySamplesByTheProductRuleMatchesGaussLegendreBetweenThem) {
  namespace sc = testing::spot_cases;
  double worst = 0.0;
  for (double q : {0.1, 0.7, 4.0}) {
    const auto uniform = std::make_shared<const SpotIntegralTable>(
        ContactSpot::ellipse(q), PressureLaw<double>::uniform(), q, std::function<bool()>{}, 0);
    for (const sc::SampledCase& k : sc::sampled_cases()) {
      const PressureLaw<double> law = sc::sampled_table(k.samples, k.gamma);
      const EllipseLawIntegrator<SpotIntegralTable> product(uniform, law, q),
          cuts(uniform, law, q, true);
      const double A0 = spot_moments(ContactSpot::ellipse(q), law_moments(law), q).A0;
      worst = std::max(
          worst,
          sc::product_rule_difference(
              product, cuts, centres(q, 0x9a11 + static_cast<std::uint64_t>(k.samples)), A0, k, q));
    }
  }
  std::cout << "[ worst    ] product rule vs Gauss–Legendre between samples, any channel / A0: "
            << worst << "\n";
}

// A table of two samples, 1 at the centre and 0 at the rim: its one piece makes the stretches'
// parts span whole pieces of the uniform table (12 points on each erred by 5e-10 A0).
PressureLaw<double> two_samples() {
  return PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(
      std::vector<double>{0.0, 1.0}, std::vector<double>{1.0, 0.0}));
}

// A table's build takes a table law's slopes by the ray's stretches through the uniform table's
// pieces, whose weights it finds once per reference radius (slopes_by_stretches), where the
// readings of the other path integrate the same interpolant of U: the two agree to rounding.
// Rim exponents 0 (kinks and a step), 0.44 and 0.7 (fractional: the rim piece by readings) and
// 1, 2, 6 to 41 samples (and 201 on the elongated ellipse, where a build takes those by
// stretches too), aspects 0.1 to 4 on the polar tables that a build reads; the centres
// above, centres whose reference radius is a sample, the rim or 1e-9, and each centre a second
// time, from the stretches' weights found the first.
TEST(EllipseLawIntegrator, ATableLawByStretchesMatchesItsReadings) {
  namespace sc = testing::spot_cases;
  std::vector<NamedLaw> tables = {{"kinks and a step", sc::kinked_step_table().law},
                                  {"41 samples, edge exponent 0.44", sc::sampled_table(41, 0.5)},
                                  {"11 samples, edge exponent 1", sc::sampled_table(11, 1.0)},
                                  {"2 samples: stretches span whole pieces", two_samples()}};
  tables.push_back(laws().back());  // 7 samples, edge exponent 0.7
  double worst = 0.0;
  for (double q : {0.1, 0.3, 0.7, 4.0}) {
    const auto uniform = SpotIntegralTable::uniform_for_layers(q, {}, spot_threads(0));
    std::vector<NamedLaw> here = tables;  // many samples by stretches on an elongated ellipse
    if (q < 0.2) here.push_back({"201 samples, edge exponent 0.44", sc::sampled_table(201, 0.5)});
    for (const NamedLaw& l : here) {
      const EllipseLawIntegrator<SpotIntegralTable> readings(uniform, l.law, q),
          stretches(uniform, l.law, q, false, true);
      ASSERT_TRUE(stretches.takes_stretches()) << l.name;
      const double A0 = spot_moments(ContactSpot::ellipse(q), law_moments(l.law), q).A0;
      std::vector<std::array<double, 2>> at = centres(q, 0x57e7c + static_cast<std::uint64_t>(q));
      Uniform u(0x5a3);
      for (double P : {0.3, 0.55, 0.8, 0.975, 1.0, 1.0 - 1e-12, 1.0 + 1e-12, 1e-9, 0.65, 1.35}) {
        const double t = u.in(-kPi, kPi);
        at.push_back({P * std::cos(t), q * P * std::sin(t)});
      }
      for (int pass = 0; pass < 2; ++pass)
        for (const auto& c : at) {
          const auto got = stretches(c[0], c[1]).channels();
          const auto want = readings(c[0], c[1]).channels();
          for (std::size_t k = 0; k < 12; ++k) {
            const double e = std::fabs(got[k] - want[k]) / A0;
            worst = std::max(worst, e);
            EXPECT_LT(e, 1e-12) << l.name << ", q " << q << ", pass " << pass << ", channel " << k
                                << " at (" << c[0] << ", " << c[1] << ")";
          }
        }
      EXPECT_GT(stretches.stretches_found(), 0u) << l.name;
    }
  }
  std::cout << "[ worst    ] stretches vs readings, any channel / A0: " << worst << "\n";
}

// The weights found once serve every later point that shares them, bit for bit: the same
// centres in the opposite order through a second integrator give the same channels.
TEST(EllipseLawIntegrator, AStretchsWeightsDoNotDependOnWhichPointFoundThemFirst) {
  const double q = 0.3;
  const auto uniform = SpotIntegralTable::uniform_for_layers(q, {}, spot_threads(0));
  const PressureLaw<double> law = testing::spot_cases::sampled_table(41, 0.5);
  const EllipseLawIntegrator<SpotIntegralTable> forward(uniform, law, q, false, true),
      backward(uniform, law, q, false, true);
  std::vector<std::array<double, 2>> at;
  for (double P : {0.2, 0.5, 0.9}) {  // each radius at several angles: the stretches repeat
    for (int i = 0; i < 7; ++i) {
      const double t = 0.2 * i;
      at.push_back({P * std::cos(t), q * P * std::sin(t)});
    }
  }
  std::vector<std::array<double, 12>> first;
  std::size_t one_ray = 0;  // the stretches of the first point
  for (const auto& c : at) {
    first.push_back(forward(c[0], c[1]).channels());
    if (one_ray == 0) one_ray = forward.stretches_found();
  }
  for (std::size_t i = at.size(); i-- > 0;) {
    const auto again = backward(at[i][0], at[i][1]).channels();
    for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(again[k], first[i][k]) << i << ", " << k;
  }
  EXPECT_LT(forward.stretches_found(), at.size() * one_ray);  // the points shared some
  EXPECT_GT(forward.angle_rows_found(), 0u);
}

// A build's integrator sums each piece of the uniform table at a ray's angle once and keeps the
// sums for later rays at that angle; a table of 201 samples (the product rule's readings, no
// stretches) gives the channels of an integrator that sums every piece at every reading, to
// rounding, and the same bits when its centres come in the opposite order.
TEST(EllipseLawIntegrator, APiecesSumsAtAnAngleServeLaterRaysAtItAsTheReadingsWould) {
  for (double q : {0.3, 0.7, 4.0}) {
    const auto uniform = SpotIntegralTable::uniform_for_layers(q, {}, spot_threads(0));
    const PressureLaw<double> law = testing::spot_cases::sampled_table(201, 0.5);
    const EllipseLawIntegrator<SpotIntegralTable> each(uniform, law, q),
        forward(uniform, law, q, false, true), backward(uniform, law, q, false, true);
    ASSERT_TRUE(forward.uses_product_rule());
    ASSERT_FALSE(forward.takes_stretches());
    const double A0 = spot_moments(ContactSpot::ellipse(q), law_moments(law), q).A0;
    std::vector<std::array<double, 2>> at;
    for (double P : {0.05, 0.4, 0.93, 1.0, 1.2, 3.0})  // each angle at several radii
      for (double t : {0.0, 0.3, 1.2, 1.5707963267948966, 2.5})
        at.push_back({P * std::cos(t), q * P * std::sin(t)});
    std::vector<std::array<double, 12>> first;
    for (const auto& c : at) {
      first.push_back(forward(c[0], c[1]).channels());
      const auto want = each(c[0], c[1]).channels();
      for (std::size_t k = 0; k < 12; ++k)
        EXPECT_LT(std::fabs(first.back()[k] - want[k]), 1e-14 * A0)
            << "q " << q << ", channel " << k << " at (" << c[0] << ", " << c[1] << ")";
    }
    for (std::size_t i = at.size(); i-- > 0;) {
      const auto again = backward(at[i][0], at[i][1]).channels();
      for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(again[k], first[i][k]) << i << ", " << k;
    }
    EXPECT_GT(forward.angle_rows_found(), 0u);
  }
}

}  // namespace
}  // namespace frictionid::model::ellipse_law_integrator_test
