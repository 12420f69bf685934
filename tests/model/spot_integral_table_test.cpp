// The tabulated spot integrals (spot_integral_table.hpp) against the ray integration of
// spot_integrals.hpp over the whole plane of the centre of rotation, the closed forms at the
// centre, the sliding limit far away, the symmetries the table relies on, and its build.
//
// The reference is SpotIntegrator at its fine angular rule: the default rule errs by up to 5e-9
// A0 within 1e-4 of a rectangle's corner. Far away (|c| > 50 max|r|) its rays, of length |c|,
// carry positions to only ~1e-16 |c|, so there the reference is a product quadrature about the
// spot's centre instead, where the integrand is smooth.
#include <frictionid/model/spot_integral_table.hpp>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/ellipse_law_integrator.hpp>
#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/map_strip_integrator.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

#include "model/spot_cases.hpp"

namespace frictionid::model::spot_integral_table_test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 1e-10;  // of A0, every channel

struct NamedLaw {
  std::string name;
  PressureLaw<double> law;
};

std::vector<NamedLaw> laws() {
  return {{"uniform", PressureLaw<double>::uniform()},
          {"hertz", PressureLaw<double>::hertz()},
          {"parabolic", PressureLaw<double>::parabolic()},
          {"annulus:0.5", PressureLaw<double>::annulus(0.5)}};
}

std::array<double, 12> channels(const SpotIntegrals& v) {
  std::array<double, 12> out{};
  for (std::size_t w = 0; w < 3; ++w) {
    out[w] = v.ex[w];
    out[3 + w] = v.ey[w];
    out[6 + w] = v.x_ey[w];
    out[9 + w] = v.y_ex[w];
  }
  return out;
}

using testing::spot_cases::Uniform;

double max_radius(SpotKind kind, double q) {
  return kind == SpotKind::Rect ? std::hypot(1.0, q) : std::max(1.0, q);
}

// Centres of rotation over the whole plane: the near field, within 1e-8..1e-1 of the rim or an
// edge (either side), next to the rectangle's corners, on the annulus' step, and far away up to
// |c| = 1e6.
std::vector<std::array<double, 2>> sample_centres(SpotKind kind, double q, int count,
                                                  std::uint64_t seed) {
  Uniform u(seed);
  std::vector<std::array<double, 2>> out = {{0.0, 0.0}};
  for (int i = 1; i < count; ++i) {
    const double near = std::pow(10.0, u.in(-8.0, -1.0));  // distance to a line
    double x = 0.0, y = 0.0;
    switch (i % 6) {
      case 0:
      case 1:  // near field
        x = u.in(-3.0, 3.0);
        y = q * u.in(-3.0, 3.0);
        break;
      case 2:  // next to the rim, an edge |x| = 1 or a step at 0.5
        if (kind == SpotKind::Ellipse) {
          const double t = u.in(-kPi, kPi), r = (i % 12 == 2 ? 0.5 : 1.0) + u.sign() * near;
          x = r * std::cos(t);
          y = q * r * std::sin(t);
        } else {
          x = u.sign() * ((i % 12 == 2 ? 0.5 : 1.0) + u.sign() * near);
          y = q * u.in(-1.2, 1.2);
        }
        break;
      case 3:  // next to the rim or an edge y = +-q
        if (kind == SpotKind::Ellipse) {
          const double t = u.in(-kPi, kPi), r = 1.0 + u.sign() * near;
          x = r * std::cos(t);
          y = q * r * std::sin(t);
        } else {
          x = u.in(-1.2, 1.2);
          y = u.sign() * q * (1.0 + u.sign() * near);
        }
        break;
      case 4: {  // next to a corner (the rectangle) or the rim's ends of the axes
        const double cx = (i % 12 == 4 ? 0.5 : 1.0), d = std::pow(10.0, u.in(-8.0, -1.0));
        x = u.sign() * (cx + d * u.in(-1.0, 1.0));
        y = u.sign() * q * (1.0 + near * u.in(-1.0, 1.0));
        break;
      }
      default: {  // far away
        const double r = max_radius(kind, q) * std::pow(10.0, u.in(0.0, 6.0)), t = u.in(-kPi, kPi);
        x = r * std::cos(t);
        y = r * std::sin(t);
        break;
      }
    }
    out.push_back({x, y});
  }
  return out;
}

// The reference far away: ∫∫ about the spot's centre, where the integrand is smooth, the radius
// (ellipse) or x (rectangle) by the fine tanh-sinh rule split at the law's breakpoints, the angle
// by the trapezoidal rule (periodic), y by Gauss–Legendre.
SpotIntegrals centred_quadrature(SpotKind kind, const PressureLaw<double>& law, double q, double cx,
                                 double cy) {
  std::array<double, 12> acc{};
  auto add = [&](double w, double x, double y) {
    const double dx = x - cx, dy = y - cy, inv = 1.0 / std::hypot(dx, dy);
    const double ex = -dy * inv * w, ey = dx * inv * w;
    const double v[12] = {ex,     x * ex,     y * ex,     ey,     x * ey,     y * ey,
                          x * ey, x * x * ey, x * y * ey, y * ex, x * y * ex, y * y * ex};
    for (std::size_t k = 0; k < 12; ++k) acc[k] += v[k];
  };
  const std::vector<QuadratureNode> across = make_gauss_legendre_rule(40);
  const int turns = 720;
  if (law.kind == PressureKind::Ring) {  // all load on the rim (line density q dtheta or dy)
    if (kind == SpotKind::Ellipse)
      for (int k = 0; k < turns; ++k) {
        const double t = 2.0 * kPi * (k + 0.5) / turns;
        add(q * 2.0 * kPi / turns, std::cos(t), q * std::sin(t));
      }
    else
      for (double side : {-1.0, 1.0})
        for (const QuadratureNode& g : across)
          add(2.0 * q * g.weight, side, q * (g.from_left - g.from_right));
  }
  std::vector<double> edges = {0.0};
  for (double b : law.breakpoints()) edges.push_back(b);
  edges.push_back(1.0);
  for (std::size_t s = 0; s + 1 < edges.size(); ++s) {
    const double a = edges[s], b = edges[s + 1], len = b - a;
    for (const QuadratureNode& n : fine_rule()) {
      const double rho = a + len * n.from_left, sigma = law(rho, (1.0 - b) + len * n.from_right);
      if (sigma == 0.0) continue;
      if (kind == SpotKind::Ellipse) {
        for (int k = 0; k < turns; ++k) {
          const double t = 2.0 * kPi * (k + 0.5) / turns;
          add(n.weight * len * sigma * q * rho * 2.0 * kPi / turns, rho * std::cos(t),
              q * rho * std::sin(t));
        }
      } else {
        for (double side : {-1.0, 1.0})
          for (const QuadratureNode& g : across)
            add(n.weight * len * sigma * 2.0 * q * g.weight, side * rho,
                q * (g.from_left - g.from_right));
      }
    }
  }
  return SpotIntegrals::from_channels(acc.data());
}

struct Reference {
  ContactSpot spot;
  PressureLaw<double> law;
  double q;
  SpotIntegrator rays;
  Reference(const ContactSpot& s, const PressureLaw<double>& l, double aspect,
            const std::vector<QuadratureNode>* angular = &fine_rule())
      // The rule along the rays (closed_rays false), not the closed forms the table takes.
      : spot(s),
        law(l),
        q(aspect),
        rays(s, l, aspect, SpotRules{&radial_rule(), angular, false, false}) {}
  SpotIntegrals operator()(double cx, double cy) const {
    const SpotKind kind = spot.kind == SpotKind::Rect ? SpotKind::Rect : SpotKind::Ellipse;
    if (std::hypot(cx, cy) > 50.0 * max_radius(kind, q))
      return centred_quadrature(kind, law, q, cx, cy);
    return rays(cx, cy);
  }
};

// Tables are built once per spot, aspect and law and shared by the tests.
const SpotIntegralTable& table_for(const ContactSpot& spot, const NamedLaw& law) {
  static std::map<std::string, std::unique_ptr<SpotIntegralTable>> tables;
  const std::string key =
      std::to_string(static_cast<int>(spot.kind)) + " " + std::to_string(spot.q) + " " + law.name;
  auto& slot = tables[key];
  if (!slot) slot = std::make_unique<SpotIntegralTable>(spot, law.law, spot.q);
  return *slot;
}

double area(const ContactSpot& spot, const PressureLaw<double>& law, double q) {
  return spot_moments(spot, law_moments(law), q).A0;
}

// The worst difference table - reference over the points, relative to A0, with where it is.
struct Worst {
  double error = 0.0, cx = 0.0, cy = 0.0;
  int channel = -1;
};

Worst compare(const SpotIntegralTable& table, const Reference& reference,
              const std::vector<std::array<double, 2>>& centres, double A0) {
  Worst worst;
  for (const auto& c : centres) {
    const auto got = channels(table(c[0], c[1])), want = channels(reference(c[0], c[1]));
    for (std::size_t k = 0; k < 12; ++k) {
      const double e = std::fabs(got[k] - want[k]) / A0;
      if (!(e <= worst.error)) worst = {e, c[0], c[1], static_cast<int>(k)};
    }
  }
  return worst;
}

void expect_agreement(SpotKind kind) {
  int points = 0;
  for (double q : {0.4, 1.0, 2.5})
    for (const auto& l : laws()) {
      const ContactSpot spot =
          kind == SpotKind::Rect ? ContactSpot::rect(q) : ContactSpot::ellipse(q);
      const SpotIntegralTable& table = table_for(spot, l);
      const auto centres = sample_centres(kind, q, 170, 11);
      const Worst w = compare(table, Reference(spot, l.law, q), centres, area(spot, l.law, q));
      EXPECT_LT(w.error, kTolerance) << l.name << " q " << q << ": channel " << w.channel << " at ("
                                     << w.cx << ", " << w.cy << ")";
      points += static_cast<int>(centres.size());
    }
  EXPECT_GE(points, 2000);
}

TEST(SpotIntegralTable, EllipsesMatchTheIntegratorWithin1e10OfTheLoadOverThePlane) {
  expect_agreement(SpotKind::Ellipse);
}

TEST(SpotIntegralTable, RectanglesMatchTheIntegratorWithin1e10OfTheLoadOverThePlane) {
  expect_agreement(SpotKind::Rect);
}

TEST(SpotIntegralTable, OtherLawsMatchTheIntegratorToo) {
  struct Case {
    ContactSpot spot;
    NamedLaw law;
    const std::vector<QuadratureNode>* angular;
  };
  // The ring's rim integral needs a finer angular rule than fine_rule() off q = 1.
  static const std::vector<QuadratureNode> rim = make_tanh_sinh_rule(1.0 / 64.0, 1e-30);
  // A table with kinks and a step: the rectangle's points by strips, the ellipse's by layers of
  // the uniform ellipse (ellipse_law_integrator.hpp); the reference integrates the law itself.
  const testing::spot_cases::LawCase table = testing::spot_cases::kinked_step_table();
  const std::vector<Case> cases = {
      {ContactSpot::ellipse(0.7), {"power:1.7", PressureLaw<double>::power(1.7)}, &fine_rule()},
      {ContactSpot::rect(0.7), {"power:1.7", PressureLaw<double>::power(1.7)}, &fine_rule()},
      {ContactSpot::ellipse(1.6), {"power:2.5", PressureLaw<double>::power(2.5)}, &fine_rule()},
      {ContactSpot::ellipse(0.7), {"ring", PressureLaw<double>::ring()}, &rim},
      {ContactSpot::rect(0.7), {"ring", PressureLaw<double>::ring()}, &rim},
      {ContactSpot::circle(), {"hertz", PressureLaw<double>::hertz()}, &fine_rule()},
      {ContactSpot::rect(0.7), {table.name, table.law}, &fine_rule()},
      {ContactSpot::ellipse(0.7), {table.name, table.law}, &fine_rule()}};
  for (const Case& c : cases) {
    const SpotIntegralTable& table = table_for(c.spot, c.law);
    const SpotKind kind = c.spot.kind == SpotKind::Rect ? SpotKind::Rect : SpotKind::Ellipse;
    const auto centres = sample_centres(kind, c.spot.q, 90, 23);
    const Reference reference(c.spot, c.law.law, c.spot.q, c.angular);
    const Worst w = compare(table, reference, centres, area(c.spot, c.law.law, c.spot.q));
    EXPECT_LT(w.error, kTolerance)
        << c.law.name << " on kind " << static_cast<int>(c.spot.kind) << ": channel " << w.channel
        << " at (" << w.cx << ", " << w.cy << ")";
  }
}

// An elongated ellipse's table takes confocal coordinates outside its rim, where the reference
// polar ones stretched its cells 1/q times along the rim: its points grew as 1/q (144,000 at
// q = 0.02, 240,000 at 0.01). Now few at any aspect, and as exact.
TEST(SpotIntegralTable, ElongatedEllipsesStayExactInFewPoints) {
  static const std::vector<QuadratureNode> rim = make_tanh_sinh_rule(1.0 / 128.0, 1e-30);
  const std::vector<NamedLaw> cases = {{"hertz", PressureLaw<double>::hertz()},
                                       {"uniform", PressureLaw<double>::uniform()},
                                       {"ring", PressureLaw<double>::ring()}};
  for (double q : {0.2, 0.02, 0.005})
    for (const NamedLaw& l : cases) {
      const ContactSpot spot = ContactSpot::ellipse(q);
      const SpotIntegralTable& table = table_for(spot, l);
      const auto centres = sample_centres(SpotKind::Ellipse, q, 120, 31);
      const Reference reference(spot, l.law, q,
                                l.law.kind == PressureKind::Ring ? &rim : &fine_rule());
      const Worst w = compare(table, reference, centres, area(spot, l.law, q));
      EXPECT_LT(w.error, kTolerance) << l.name << " q " << q << ": channel " << w.channel << " at ("
                                     << w.cx << ", " << w.cy << ")";
      EXPECT_LT(table.stats().points, 30000u) << l.name << " q " << q;
    }
}

// A table law's points come from layers of the uniform ellipse read along c/s. Below aspect 0.3
// that table reaches beyond the rim in polar coordinates (uniform_for_layers), where the table
// law's own table and the rows integrated one by one take confocal ones: both against the rays.
TEST(SpotIntegralTable, ATableLawOnAnElongatedEllipseMatchesTheIntegrator) {
  const testing::spot_cases::LawCase table = testing::spot_cases::kinked_step_table();
  for (double q : {0.2, 0.08}) {
    const ContactSpot spot = ContactSpot::ellipse(q);
    const SpotIntegralTable& t = table_for(spot, {table.name, table.law});
    const auto centres = sample_centres(SpotKind::Ellipse, q, 90, 37);
    const Worst w = compare(t, Reference(spot, table.law, q), centres, area(spot, table.law, q));
    EXPECT_LT(w.error, kTolerance)
        << "q " << q << ": channel " << w.channel << " at (" << w.cx << ", " << w.cy << ")";
  }
}

// A table of 9 to 63 samples on an ellipse has every kink a boundary of the table's cells, the
// strongest graded, the others plain (make_roots). It holds its points, the layers of the
// uniform ellipse (which ellipse_law_integrator_test.cpp holds to the rays), over the plane:
// next to the rim and to a sample's ellipse (rho_e = 0.5) on both sides, at aspects either side
// of 1.
TEST(SpotIntegralTable, ATableLawOfFewSamplesOnAnEllipseHoldsItsLayers) {
  const PressureLaw<double> law = testing::spot_cases::sampled_table(25, 0.5);
  for (double q : {0.7, 2.0}) {
    const ContactSpot spot = ContactSpot::ellipse(q);
    const SpotIntegralTable& t = table_for(spot, {"sampled 25", law});
    const EllipseLawIntegrator<SpotIntegralTable> layers(
        SpotIntegralTable::uniform_for_layers(q, {}, spot_threads(0)), law, q);
    const double A0 = area(spot, law, q);
    double worst = 0.0, wx = 0.0, wy = 0.0;
    for (const auto& c : sample_centres(SpotKind::Ellipse, q, 300, 53)) {
      const auto got = channels(t(c[0], c[1])), want = channels(layers(c[0], c[1]));
      for (std::size_t k = 0; k < 12; ++k)
        if (std::fabs(got[k] - want[k]) / A0 > worst) {
          worst = std::fabs(got[k] - want[k]) / A0;
          wx = c[0];
          wy = c[1];
        }
    }
    EXPECT_LT(worst, kTolerance) << "q " << q << " at (" << wx << ", " << wy << ")";
  }
}

// The layers' uniform ellipse (polar beyond the rim down to aspect 0.05, its points read from a
// tighter confocal table below 0.3) is as exact as the confocal one, and its rays read it at c/s
// beyond the rim too, by the slices of the polar patch.
TEST(SpotIntegralTable, TheLayersUniformEllipseIsExactAndItsRaysReadIt) {
  for (double q : {0.2, 0.1, 0.03}) {
    const auto uniform = SpotIntegralTable::uniform_for_layers(q, {}, spot_threads(0));
    const ContactSpot spot = ContactSpot::ellipse(q);
    const PressureLaw<double> law = PressureLaw<double>::uniform();
    const double A0 = area(spot, law, q);
    const Worst w = compare(*uniform, Reference(spot, law, q),
                            sample_centres(SpotKind::Ellipse, q, 120, 43), A0);
    EXPECT_LT(w.error, kTolerance)
        << "q " << q << ": channel " << w.channel << " at (" << w.cx << ", " << w.cy << ")";
    Uniform u(47);
    double worst = 0.0;
    for (int i = 0; i < 40; ++i) {
      const double cx = u.in(-2.0, 2.0), cy = q * u.in(-2.0, 2.0);
      const SpotIntegralTable::Ray ray = uniform->ray(cx, cy);
      for (int k = 0; k < 30; ++k) {
        const double s = std::pow(10.0, u.in(-3.0, 0.3));
        const auto got = ray(s);
        const auto want = uniform->channels_at(cx / s, cy / s);
        for (std::size_t j = 0; j < 12; ++j)
          worst = std::max(worst, std::fabs(got[j] - want[j]) / A0);
      }
    }
    EXPECT_LT(worst, 1e-14) << "q " << q;
  }
}

// Read with dual numbers (a fit's derivatives along c), the confocal patch's coordinates carry
// the derivatives of the interpolant: against central differences of the table itself.
TEST(SpotIntegralTable, ConfocalCoordinatesCarryTheDerivativesAlongTheCentre) {
  const double q = 0.05;
  const SpotIntegralTable& table =
      table_for(ContactSpot::ellipse(q), {"hertz", PressureLaw<double>::hertz()});
  using J = ceres::Jet<double, 2>;
  const double A0 = area(ContactSpot::ellipse(q), PressureLaw<double>::hertz(), q);
  // Outside the rim, off the axes and near them, next to the rim and 2 spot radii away.
  for (const auto& c : std::vector<std::array<double, 2>>{
           {0.6, 0.05}, {-0.3, -0.07}, {1.02, 0.004}, {0.05, 0.0521}, {1.5, 1.1}}) {
    const auto d = table.channels_at(J(c[0], 0), J(c[1], 1));
    const double h = 1e-6;
    for (int dir = 0; dir < 2; ++dir) {
      const double dx = dir == 0 ? h : 0.0, dy = dir == 1 ? h : 0.0;
      const auto plus = table.channels_at(c[0] + dx, c[1] + dy);
      const auto minus = table.channels_at(c[0] - dx, c[1] - dy);
      for (std::size_t k = 0; k < 12; ++k) {
        const double fd = (plus[k] - minus[k]) / (2.0 * h);
        EXPECT_NEAR(d[k].v[dir], fd, 1e-6 * A0 + 1e-6 * std::fabs(fd))
            << "channel " << k << " along " << dir << " at (" << c[0] << ", " << c[1] << ")";
      }
    }
  }
}

// An annulus on an ellipse reads the uniform ellipse's table at c and c/B: held to its own load
// (1 - B^2) A0 however thin the annulus and however elongated the ellipse, the step's ellipse
// included.
TEST(SpotIntegralTable, AnAnnulusFromTheUniformEllipseHoldsForAnyInnerRadiusAndAspect) {
  struct Case {
    double q, B;
  };
  for (const Case& c : {Case{0.15, 0.95}, Case{0.7, 0.75}, Case{3.5, 0.3}}) {
    const ContactSpot spot = ContactSpot::ellipse(c.q);
    const NamedLaw law{"annulus:" + std::to_string(c.B), PressureLaw<double>::annulus(c.B)};
    const SpotIntegralTable& table = table_for(spot, law);
    auto centres = sample_centres(SpotKind::Ellipse, c.q, 90, 29);
    Uniform u(37);
    for (int i = 0; i < 30; ++i) {  // within 1e-8..1e-1 of the step, either side
      const double t = u.in(-kPi, kPi);
      const double r = c.B * (1.0 + u.sign() * std::pow(10.0, u.in(-8.0, -1.0)));
      centres.push_back({r * std::cos(t), c.q * r * std::sin(t)});
    }
    const Reference reference(spot, law.law, c.q);
    const Worst w = compare(table, reference, centres, area(spot, law.law, c.q));
    EXPECT_LT(w.error, kTolerance) << law.name << " q " << c.q << ": channel " << w.channel
                                   << " at (" << w.cx << ", " << w.cy << ")";
  }
}

// A ray's readings (the layers' way of reading the uniform ellipse) are the table's own values
// at c/s, from every quadrant, the centre, the polar patch and the far one, to rounding.
TEST(SpotIntegralTable, ItsRayReadsTheTableAtCOverS) {
  for (double q : {0.4, 2.5}) {
    const ContactSpot spot = ContactSpot::ellipse(q);
    const NamedLaw law{"uniform", PressureLaw<double>::uniform()};
    const SpotIntegralTable& table = table_for(spot, law);
    const double A0 = area(spot, law.law, q);
    Uniform u(41);
    double worst = 0.0;
    for (int i = 0; i < 40; ++i) {
      const double cx = i == 0 ? 0.0 : u.in(-2.0, 2.0), cy = i == 0 ? 0.0 : q * u.in(-2.0, 2.0);
      const SpotIntegralTable::Ray ray = table.ray(cx, cy);
      for (int k = 0; k < 30; ++k) {
        const double s = std::pow(10.0, u.in(-3.0, 0.3));
        const auto got = ray(s);
        const auto want = table.channels_at(cx / s, cy / s);
        for (std::size_t j = 0; j < 12; ++j)
          worst = std::max(worst, std::fabs(got[j] - want[j]) / A0);
      }
    }
    EXPECT_LT(worst, 1e-14) << "q " << q;
  }
}

// A ray's sums of layers, w s^(2+d) U(c/s) over many s (Ray::add, each reading's Chebyshev
// weights gathered per piece and summed against its coefficients once), are those of the
// table's own values at c/s: from every quadrant and the centre, in the polar, far and confocal
// patches, with readings in random order, so that consecutive ones change piece, root cell and
// patch.
TEST(SpotIntegralTable, ItsRaySumsLayersAsTheTableValuesAtCOverSDo) {
  for (double q : {0.4, 2.5, 0.1}) {
    const ContactSpot spot = ContactSpot::ellipse(q);
    const NamedLaw law{"uniform", PressureLaw<double>::uniform()};
    const SpotIntegralTable& table = table_for(spot, law);
    const double A0 = area(spot, law.law, q);
    Uniform u(53);
    double worst = 0.0;
    for (int i = 0; i < 40; ++i) {
      const double cx = i == 0 ? 0.0 : u.in(-2.0, 2.0), cy = i == 0 ? 0.0 : q * u.in(-2.0, 2.0);
      const SpotIntegralTable::Ray ray = table.ray(cx, cy);
      double want[12] = {}, scale = 0.0;
      for (int k = 0; k < 60; ++k) {
        const double s = std::pow(10.0, u.in(-3.0, 0.3)), w = u.in(-1.0, 1.0);
        ray.add(s, w);
        const auto v = table.channels_at(cx / s, cy / s);
        for (std::size_t j = 0; j < 12; ++j)
          want[j] += w * std::pow(s, 2 + SpotIntegrals::kChannelDegree[j]) * v[j];
        scale += std::fabs(w) * s * s;
      }
      double got[12] = {};
      ray.add_to(got);
      for (std::size_t j = 0; j < 12; ++j)
        worst = std::max(worst, std::fabs(got[j] - want[j]) / (A0 * scale));
    }
    EXPECT_LT(worst, 1e-14) << "q " << q;
  }
}

TEST(SpotIntegralTable, EachIntegralIsEvenOrOddInEachCoordinateOfTheCentre) {
  // Reflecting x turns e_y and the weight x; reflecting y turns e_x and the weight y. Channels:
  // ex[0..2], ey[0..2], x_ey[0..2], y_ex[0..2].
  const bool odd_x[12] = {false, true, false, true,  false, true,
                          false, true, false, false, true,  false};
  const bool odd_y[12] = {true,  true,  false, false, false, true,
                          false, false, true,  false, false, true};
  Uniform u(5);
  for (const ContactSpot& spot : {ContactSpot::ellipse(0.4), ContactSpot::rect(2.5)})
    for (const auto& l : {laws()[0], laws()[3]}) {
      const SpotIntegrator integrate(spot, l.law, spot.q);
      const SpotIntegralTable& table = table_for(spot, l);
      const double A0 = area(spot, l.law, spot.q);
      for (int i = 0; i < 6; ++i) {
        const double x = u.in(0.05, 2.0), y = spot.q * u.in(0.05, 2.0);
        const auto base = channels(integrate(x, y));
        const auto fx = channels(integrate(-x, y)), fy = channels(integrate(x, -y));
        const auto tx = channels(table(-x, y)), ty = channels(table(x, -y));
        for (std::size_t k = 0; k < 12; ++k) {
          EXPECT_NEAR(fx[k], odd_x[k] ? -base[k] : base[k], 1e-13 * A0) << l.name << " ch " << k;
          EXPECT_NEAR(fy[k], odd_y[k] ? -base[k] : base[k], 1e-13 * A0) << l.name << " ch " << k;
          EXPECT_NEAR(tx[k], fx[k], kTolerance * A0) << l.name << " ch " << k;
          EXPECT_NEAR(ty[k], fy[k], kTolerance * A0) << l.name << " ch " << k;
        }
      }
    }
}

TEST(SpotIntegralTable, AtTheSpotsCentreTheTableTakesTheClosedForms) {
  // Pure spin about the centre of a uniform disk: ∫ x^2/r dA = pi/3; of the square [-1, 1]^2:
  // (1/2) ∫ r dA = (2/3)(sqrt 2 + asinh 1). ey[1] = x_ey[0] = that, ex[2] = y_ex[0] = minus it,
  // every other channel vanishes by symmetry.
  const double disk = kPi / 3.0, square = 2.0 / 3.0 * (std::sqrt(2.0) + std::asinh(1.0));
  for (const auto& [spot, value] :
       {std::pair{ContactSpot::ellipse(1.0), disk}, std::pair{ContactSpot::rect(1.0), square}}) {
    const SpotIntegralTable& table = table_for(spot, {"uniform", PressureLaw<double>::uniform()});
    const auto v = channels(table(0.0, 0.0));
    for (std::size_t k = 0; k < 12; ++k) {
      const double want = (k == 4 || k == 6) ? value : (k == 2 || k == 9) ? -value : 0.0;
      EXPECT_NEAR(v[k], want, 1e-11) << "channel " << k;
    }
  }
}

TEST(SpotIntegralTable, OnTheRimEdgesAndCornersTheTableMatchesTheIntegrator) {
  for (const auto& l : {laws()[0], laws()[1]})
    for (double q : {0.4, 2.5}) {
      for (const ContactSpot& spot : {ContactSpot::ellipse(q), ContactSpot::rect(q)}) {
        const SpotIntegralTable& table = table_for(spot, l);
        const Reference reference(spot, l.law, q);
        std::vector<std::array<double, 2>> centres;
        if (spot.kind == SpotKind::Ellipse) {
          for (double t : {0.0, 0.3, 1.0, kPi / 2, 2.0, kPi, -0.7})
            for (double r : {0.5, 1.0}) centres.push_back({r * std::cos(t), q * r * std::sin(t)});
        } else {
          for (double x : {0.0, 0.3, 0.5, 0.9, 1.0})
            for (double y : {0.0, 0.4 * q, q}) {
              centres.push_back({x, y});
              centres.push_back({-x, -y});
            }
          centres.push_back({1.0, 1.5 * q});
          centres.push_back({1.5, q});
        }
        const Worst w = compare(table, reference, centres, area(spot, l.law, q));
        EXPECT_LT(w.error, kTolerance)
            << l.name << " q " << q << " kind " << static_cast<int>(spot.kind) << ": channel "
            << w.channel << " at (" << w.cx << ", " << w.cy << ")";
      }
    }
}

TEST(SpotIntegralTable, FarAwayTheTableTakesTheSlidingLimit) {
  // e = (sin gamma, -cos gamma) everywhere as |c| -> inf: ex[0] = A0 sin, ey[0] = -A0 cos,
  // x_ey[1] = -Axx cos, y_ex[2] = Ayy sin, the rest 0 (the spot is symmetric).
  for (const ContactSpot& spot : {ContactSpot::ellipse(0.4), ContactSpot::rect(2.5)}) {
    const PressureLaw<double> law = PressureLaw<double>::hertz();
    const SpotIntegralTable& table = table_for(spot, {"hertz", law});
    const SpotMoments<double> m = spot_moments(spot, law_moments(law), spot.q);
    for (double gamma : {0.0, 0.4, 2.0, -1.0, -2.9})
      for (double r : {1e14, 1e300}) {
        const auto v = channels(table(r * std::cos(gamma), r * std::sin(gamma)));
        const double s = std::sin(gamma), c = std::cos(gamma);
        const double want[12] = {s * m.A0, 0,          0, -c * m.A0, 0, 0,
                                 0,        -c * m.Axx, 0, 0,         0, s * m.Ayy};
        for (std::size_t k = 0; k < 12; ++k)
          EXPECT_NEAR(v[k], want[k], kTolerance * m.A0) << "gamma " << gamma << " |c| " << r;
      }
  }
}

TEST(SpotIntegralTable, TheBuildGivesTheSameBitsOnOneOrTwoThreadsOrAFitsPool) {
  const ContactSpot spot = ContactSpot::rect(0.7);
  const PressureLaw<double> law = PressureLaw<double>::parabolic();
  const SpotIntegralTable one(spot, law, 0.7, {}, 1), two(spot, law, 0.7, {}, 2);
  std::atomic<int> calls{0};
  const SpotParallelFor pool = [&calls](std::size_t count,
                                        const std::function<void(std::size_t)>& work) {
    ++calls;
    spot_threads(2)(count, work);
  };
  const SpotIntegralTable pooled(spot, law, 0.7, {}, pool);
  EXPECT_GT(calls.load(), 0);
  EXPECT_EQ(one.stats().points, two.stats().points);
  for (const auto& c : sample_centres(SpotKind::Rect, 0.7, 200, 3)) {
    const auto a = channels(one(c[0], c[1])), b = channels(two(c[0], c[1])),
               p = channels(pooled(c[0], c[1]));
    for (std::size_t k = 0; k < 12; ++k) {
      EXPECT_EQ(a[k], b[k]);
      EXPECT_EQ(a[k], p[k]);
    }
  }
}

TEST(SpotIntegralTable, AStopRequestEndsTheBuild) {
  std::atomic<int> asked{0};
  const auto stop = [&asked] { return ++asked > 100; };
  EXPECT_THROW(
      SpotIntegralTable(ContactSpot::ellipse(0.5), PressureLaw<double>::hertz(), 0.5, stop, 2),
      SpotTableBuildStopped);
  EXPECT_LT(asked.load(), 1000);
}

// A build computes at most max_points points, and says so before computing a round that would
// take it beyond: one point short of what a table needs and it throws, having computed none of
// that round; with exactly as many it is the same table as without a limit. Its caller then
// integrates the rows instead (model_variant.hpp).
TEST(SpotIntegralTable, ABuildThrowsBeforeItWouldExceedItsBudgetAndWithinItIsTheSameTable) {
  std::atomic<std::size_t> asked{0};
  const auto count = [&asked] {
    ++asked;
    return false;
  };
  for (const NamedLaw& l : {NamedLaw{"hertz", PressureLaw<double>::hertz()},
                            NamedLaw{"annulus:0.5", PressureLaw<double>::annulus(0.5)}}) {
    SCOPED_TRACE(l.name);
    const ContactSpot spot = ContactSpot::ellipse(0.6);
    const SpotIntegralTable full(spot, l.law, 0.6, {}, 2);
    const std::size_t points = full.stats().points;
    asked = 0;
    EXPECT_THROW(SpotIntegralTable(spot, l.law, 0.6, count, 2, points - 1), SpotTableOverBudget);
    EXPECT_LT(asked.load(), points - 1);  // the round that would overrun was not computed
    const SpotIntegralTable exact(spot, l.law, 0.6, {}, 2, points);
    EXPECT_EQ(exact.stats().points, points);
    for (const auto& c : sample_centres(SpotKind::Ellipse, 0.6, 100, 5)) {
      const auto a = channels(full(c[0], c[1])), b = channels(exact(c[0], c[1]));
      for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(a[k], b[k]);
    }
  }
}

// The same on a map, where a first round beyond the budget is seen from the root cells alone,
// before the near cells are set up and any point is queued: a budget of one point computes none.
TEST(SpotIntegralTable, AMapsBuildThrowsBeforeItWouldExceedItsBudgetFirstRoundIncluded) {
  auto map = std::make_shared<PressureMap>();
  map->x = {-1.0, 0.2, 1.0};
  map->y = {-0.5, 0.5};
  map->sigma0 = {1.0, 0.5, 0.8, 1.2, 0.0, 0.7};
  const ContactSpot spot = ContactSpot::pressure_map(map);
  const PressureLaw<double> law = PressureLaw<double>::uniform();
  std::atomic<std::size_t> asked{0};
  const auto count = [&asked] {
    ++asked;
    return false;
  };
  const SpotIntegralTable full(spot, law, 1.0, {}, 2);
  const std::size_t points = full.stats().points;
  for (std::size_t budget : {std::size_t{1}, std::size_t{100}}) {
    asked = 0;
    EXPECT_THROW(SpotIntegralTable(spot, law, 1.0, count, 2, budget), SpotTableOverBudget);
    EXPECT_EQ(asked.load(), 0u) << budget;
  }
  asked = 0;
  EXPECT_THROW(SpotIntegralTable(spot, law, 1.0, count, 2, points - 1), SpotTableOverBudget);
  EXPECT_LT(asked.load(), points - 1);
  const SpotIntegralTable exact(spot, law, 1.0, {}, 2, points);
  EXPECT_EQ(exact.stats().points, points);
  for (const auto& c : std::vector<std::array<double, 2>>{{0.1, 0.2}, {-0.7, 0.45}, {3.0, -2.0}}) {
    const auto a = channels(full(c[0], c[1])), b = channels(exact(c[0], c[1]));
    for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(a[k], b[k]);
  }
}

TEST(SpotIntegralTable, ItServesOnlyItsSpotAspectAndLaw) {
  const SpotIntegralTable table(ContactSpot::ellipse(0.8), PressureLaw<double>::annulus(0.5), 0.8);
  EXPECT_TRUE(table.matches(ContactSpot::ellipse(0.8), 0.8, PressureLaw<double>::annulus(0.5)));
  EXPECT_FALSE(
      table.matches(ContactSpot::ellipse(0.8), 0.8000001, PressureLaw<double>::annulus(0.5)));
  EXPECT_FALSE(table.matches(ContactSpot::ellipse(0.8), 0.8, PressureLaw<double>::annulus(0.6)));
  EXPECT_FALSE(table.matches(ContactSpot::rect(0.8), 0.8, PressureLaw<double>::annulus(0.5)));
  EXPECT_FALSE(table.matches(ContactSpot::ellipse(0.8), 0.8, PressureLaw<double>::uniform()));
  const SpotIntegralTable circle(ContactSpot::circle(), PressureLaw<double>::hertz(), 1.0);
  EXPECT_TRUE(circle.matches(ContactSpot::circle(), 0.3, PressureLaw<double>::hertz()));
  EXPECT_TRUE(circle.matches(ContactSpot::ellipse(1.0), 1.0, PressureLaw<double>::hertz()));
}

// A random map: 4 lines each way, samples in [0.1, 1.5] with some zeros, nonzero on the rim
// (sigma0 jumps at the map's edges).
std::shared_ptr<PressureMap> random_map(Uniform& u) {
  auto m = std::make_shared<PressureMap>();
  auto lines = [&u](std::size_t n, double lo, double hi) {
    std::vector<double> out;
    for (std::size_t k = 0; k < n; ++k)
      out.push_back(lo +
                    (hi - lo) *
                        (static_cast<double>(k) + (k == 0 || k + 1 == n ? 0.0 : u.in(-0.3, 0.3))) /
                        static_cast<double>(n - 1));
    return out;
  };
  m->x = lines(4, -u.in(0.6, 1.2), u.in(0.6, 1.2));
  m->y = lines(4, -u.in(0.4, 1.0), u.in(0.4, 1.0));
  for (std::size_t k = 0; k < m->x.size() * m->y.size(); ++k)
    m->sigma0.push_back(u.u01() < 0.15 ? 0.0 : u.in(0.1, 1.5));
  return m;
}

// Centres over the whole plane for a map: inside, on and within 1e-9..1e-2 of grid lines and
// nodes (the map's corners among them), and far away up to |c| = 1e6.
std::vector<std::array<double, 2>> map_centres(const PressureMap& m, Uniform& u, int count) {
  std::vector<std::array<double, 2>> out;
  const double x0 = m.x.front(), x1 = m.x.back(), y0 = m.y.front(), y1 = m.y.back();
  auto near = [&u] { return u.sign() * std::pow(10.0, u.in(-9.0, -2.0)); };
  for (int i = 0; i < count; ++i) {
    const double gx = m.x[u.index(m.nx())], gy = m.y[u.index(m.ny())];
    switch (i % 6) {
      case 0:
        out.push_back({u.in(x0 - 1.0, x1 + 1.0), u.in(y0 - 1.0, y1 + 1.0)});
        break;
      case 1:
        out.push_back({gx + near(), u.in(y0 - 0.3, y1 + 0.3)});
        break;
      case 2:
        out.push_back({u.in(x0 - 0.3, x1 + 0.3), gy + near()});
        break;
      case 3:
        out.push_back({gx + near(), gy + near()});
        break;
      case 4:
        out.push_back({gx, gy});
        break;
      default: {
        const double r = std::pow(10.0, u.in(0.3, 6.0)), t = u.in(-kPi, kPi);
        out.push_back({r * std::cos(t), r * std::sin(t)});
        break;
      }
    }
  }
  return out;
}

TEST(SpotIntegralTable, MapsMatchTheStripIntegrationOverThePlane) {
  // A map has no symmetry: the table covers the whole plane. Its points come from
  // MapStripIntegrator (itself checked against the 2-D oracle), which is the reference here.
  Uniform u(31);
  for (int k = 0; k < 2; ++k) {
    const auto map = random_map(u);
    const ContactSpot spot = ContactSpot::pressure_map(map);
    const SpotIntegralTable table(spot, PressureLaw<double>::uniform(), 1.0, {}, 2);
    const MapStripIntegrator strips(*map);
    const double A0 = map_moments(*map).A0;
    Worst worst;
    for (const auto& c : map_centres(*map, u, 600)) {
      const auto got = channels(table(c[0], c[1])), want = channels(strips(c[0], c[1]));
      for (std::size_t j = 0; j < 12; ++j) {
        const double e = std::fabs(got[j] - want[j]) / A0;
        if (!(e <= worst.error)) worst = {e, c[0], c[1], static_cast<int>(j)};
      }
    }
    EXPECT_LT(worst.error, kTolerance) << "map " << k << ": channel " << worst.channel << " at ("
                                       << worst.cx << ", " << worst.cy << ")";
    EXPECT_LT(table.stats().estimate, kTolerance);
    // Far away: the sliding limit with the map's own moments (no symmetry: Ax, Ay, Axy too).
    const SpotMoments<double> m = map_moments(*map);
    for (double gamma : {0.3, 2.5, -1.2}) {
      const auto v = channels(table(1e300 * std::cos(gamma), 1e300 * std::sin(gamma)));
      const double s = std::sin(gamma), c = std::cos(gamma);
      const double want[12] = {s * m.A0,  s * m.Ax,   s * m.Ay,   -c * m.A0, -c * m.Ax, -c * m.Ay,
                               -c * m.Ax, -c * m.Axx, -c * m.Axy, s * m.Ay,  s * m.Axy, s * m.Ayy};
      for (std::size_t j = 0; j < 12; ++j) EXPECT_NEAR(v[j], want[j], kTolerance * A0) << j;
    }
  }
}

// A map's table holds each cell's integrals less those of its near cells, which a reading adds
// by their corner sums: read with dual numbers, that sum carries its derivatives along c with
// the interpolant's. Against central differences of the table itself, inside grid cells,
// outside the grid next to its edges and corners, and beyond the box. The value equals the
// plain reading's to rounding (1.9e-15 of the load here): the two sum the corner terms in
// different arithmetic, and the sums over up to 5 x 5 cells cancel more than over 3 x 3.
TEST(SpotIntegralTable, AMapsTableCarriesTheDerivativesAlongTheCentre) {
  Uniform u(37);
  const auto map = random_map(u);
  const SpotIntegralTable table(ContactSpot::pressure_map(map), PressureLaw<double>::uniform(), 1.0,
                                {}, 2);
  const double A0 = map_moments(*map).A0;
  using J = ceres::Jet<double, 2>;
  const double x0 = map->x.front(), x1 = map->x.back(), y0 = map->y.front(), y1 = map->y.back();
  std::vector<std::array<double, 2>> centres;
  // Inside: the middle of every grid cell and a random point in each, 1e-3 from its edges.
  for (std::size_t j = 0; j + 1 < map->ny(); ++j)
    for (std::size_t i = 0; i + 1 < map->nx(); ++i) {
      const double a = map->x[i], b = map->x[i + 1], c = map->y[j], d = map->y[j + 1];
      centres.push_back({0.5 * (a + b), 0.5 * (c + d)});
      centres.push_back({u.in(a + 1e-3, b - 1e-3), u.in(c + 1e-3, d - 1e-3)});
    }
  // Outside: next to an edge, next to a corner, and 3 map widths away.
  centres.push_back({x1 + 0.01, 0.5 * (map->y[1] + map->y[2])});
  centres.push_back({0.3 * x0 + 0.7 * x1, y0 - 0.02});
  centres.push_back({x0 - 0.05, y1 + 0.04});
  centres.push_back({3.0 * (x1 - x0), -2.0 * (y1 - y0)});
  const double h = 1e-6;
  double worst = 0.0;  // the dual reading's value against the plain one, of the load
  for (const auto& c : centres) {
    const auto d = table.channels_at(J(c[0], 0), J(c[1], 1));
    for (int dir = 0; dir < 2; ++dir) {
      const double dx = dir == 0 ? h : 0.0, dy = dir == 1 ? h : 0.0;
      const auto plus = table.channels_at(c[0] + dx, c[1] + dy);
      const auto minus = table.channels_at(c[0] - dx, c[1] - dy);
      const auto at = table.channels_at(c[0], c[1]);
      for (std::size_t k = 0; k < 12; ++k) {
        const double fd = (plus[k] - minus[k]) / (2.0 * h);
        EXPECT_NEAR(d[k].a, at[k], 1e-14 * A0) << "channel " << k;
        worst = std::max(worst, std::fabs(d[k].a - at[k]) / A0);
        EXPECT_NEAR(d[k].v[dir], fd, 1e-6 * A0 + 1e-6 * std::fabs(fd))
            << "channel " << k << " along " << dir << " at (" << c[0] << ", " << c[1] << ")";
      }
    }
  }
  std::cout << "[ worst    ] a dual reading's value vs the plain reading, of the load: " << worst
            << "\n";
}

TEST(SpotIntegralTable, AMapsTableServesThatMapObjectOnly) {
  auto map = std::make_shared<PressureMap>();
  map->x = {-1.0, 1.0};
  map->y = {-0.5, 0.5};
  map->sigma0 = {1.0, 0.5, 0.8, 1.2};
  const auto copy = std::make_shared<PressureMap>(*map);
  const SpotIntegralTable table(ContactSpot::pressure_map(map), PressureLaw<double>::uniform(),
                                1.0);
  EXPECT_EQ(table.kind(), SpotKind::Map);
  EXPECT_TRUE(table.matches(ContactSpot::pressure_map(map), 1.0, PressureLaw<double>::uniform()));
  EXPECT_TRUE(table.matches(ContactSpot::pressure_map(map), 0.5, PressureLaw<double>::hertz()));
  EXPECT_FALSE(table.matches(ContactSpot::pressure_map(copy), 1.0, PressureLaw<double>::uniform()));
  EXPECT_FALSE(table.matches(ContactSpot::rect(1.0), 1.0, PressureLaw<double>::uniform()));
  const SpotIntegralTable rect(ContactSpot::rect(1.0), PressureLaw<double>::uniform(), 1.0);
  EXPECT_FALSE(rect.matches(ContactSpot::pressure_map(map), 1.0, PressureLaw<double>::uniform()));
  auto empty = std::make_shared<PressureMap>(*map);
  std::fill(empty->sigma0.begin(), empty->sigma0.end(), 0.0);
  EXPECT_THROW(
      SpotIntegralTable(ContactSpot::pressure_map(empty), PressureLaw<double>::uniform(), 1.0),
      std::invalid_argument);
}

TEST(RectStripIntegrator, MatchesTheRayIntegrationNearAndFar) {
  // The closed-form y-integral against the rays at their fine angular rule, including points
  // within 1e-8 of the edges and corners, to 2e-12 of A0.
  for (double q : {0.4, 2.5})
    for (const auto& l : laws()) {
      const ContactSpot spot = ContactSpot::rect(q);
      const RectStripIntegrator strips(l.law, q);
      const Reference reference(spot, l.law, q);
      const double A0 = area(spot, l.law, q);
      for (const auto& c : sample_centres(SpotKind::Rect, q, 60, 17)) {
        const auto got = channels(strips(c[0], c[1])), want = channels(reference(c[0], c[1]));
        for (std::size_t k = 0; k < 12; ++k)
          ASSERT_NEAR(got[k], want[k], 2e-12 * A0)
              << l.name << " q " << q << " channel " << k << " at (" << c[0] << ", " << c[1] << ")";
      }
    }
}

}  // namespace
}  // namespace frictionid::model::spot_integral_table_test
