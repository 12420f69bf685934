// Derivatives of the resultants along the kinematics (docs/physics.md §10.8): every variant and
// spot evaluated with velocities that are dual numbers (ceres::Jet<double, 1>) against
// fourth-order central differences of the same model in doubles, at slip angles all round, eps
// from 0.03 to 40, both spin signs, tilts along and across; and the same values along the dual
// path.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid::kinematic_autodiff_test {
namespace {

using Dual = ceres::Jet<double, 1>;

struct Case {
  std::string name;
  ModelKind kind;
  model::PressureLaw<double> law;
  model::ContactSpot spot;  // with its table, for a spot other than the circle
  std::shared_ptr<const model::RingIntegralTable> ring;
};

std::array<double, kParamCount> params(const Case& c) {
  auto p = default_parameters(c.law, c.spot, 0.7, 1.3, 0.15);
  p[kHy] = c.kind == ModelKind::Exact ? -0.1 : 0.0;
  return p;
}

model::Resultants<double> value(const Case& c, const std::array<double, kParamCount>& p,
                                const model::Kinematics& k) {
  return ModelEvaluator<double>(c.kind, c.law, p.data(), c.ring, nullptr, c.spot)(k);
}

model::Resultants<Dual> dual(const Case& c, const std::array<double, kParamCount>& p,
                             const model::Kinematics& k, const model::Kinematics& dk) {
  std::array<Dual, kParamCount> pd;
  for (int i = 0; i < kParamCount; ++i) pd[static_cast<std::size_t>(i)] = Dual(p[i]);
  return ModelEvaluator<Dual>(c.kind, c.law, pd.data(), c.ring, nullptr,
                              c.spot)(model::kinematics_along<Dual>(k, dk));
}

std::array<double, 3> forces(const model::Resultants<double>& r) {
  return {r.T_x, r.T_y, r.M_z};
}

void expect_derivatives_match_differences(const Case& c, int rows, unsigned seed) {
  const auto p = params(c);
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double N = 800.0, R = 0.05, F = p[kF] * std::max(1.0, p[kKappa]) * N;
  for (int i = 0; i < rows; ++i) {
    // eps log-uniform in [0.03, 40], the slip angle all round, either spin sign.
    const double eps = 0.03 * std::pow(40.0 / 0.03, unit(gen));
    const double alpha = 2.0 * M_PI * unit(gen), omega = (unit(gen) < 0.5 ? -1.0 : 1.0) * 3.0;
    const double v = eps * std::fabs(omega) * R;
    model::Kinematics k{v * std::cos(alpha), v * std::sin(alpha), omega, N, R};
    if (i % 5 == 4) k.tilt_sign = -1.0;
    model::Kinematics dk{std::cos(3.0 * alpha + 1.0), std::sin(2.0 * alpha), 2.0 * unit(gen) - 1.0,
                         N, R};
    dk.v_x *= 0.1;  // velocities of the row's own size
    dk.v_y *= 0.1;
    const model::Resultants<Dual> d = dual(c, p, k, dk);
    const auto at = [&](double t) {
      model::Kinematics kt = k;
      kt.v_x += t * dk.v_x;
      kt.v_y += t * dk.v_y;
      kt.omega += t * dk.omega;
      return forces(value(c, p, kt));
    };
    const double h = 1e-4;
    const auto p1 = at(h), m1 = at(-h), p2 = at(2 * h), m2 = at(-2 * h), v0 = at(0.0);
    const Dual got[3] = {d.T_x, d.T_y, d.M_z};
    const double scale[3] = {F, F, F * R};
    for (int j = 0; j < 3; ++j) {
      const double fd = (8.0 * (p1[j] - m1[j]) - (p2[j] - m2[j])) / (12.0 * h);
      EXPECT_NEAR(got[j].a, v0[j], 1e-13 * scale[j]) << c.name << " row " << i << " channel " << j;
      EXPECT_NEAR(got[j].v[0], fd, 2e-6 * scale[j] + 1e-6 * std::fabs(fd))
          << c.name << " row " << i << " channel " << j << " eps " << eps << " alpha " << alpha;
    }
  }
}

Case circle(ModelKind kind, const std::string& name, const model::PressureLaw<double>& law) {
  Case c{name, kind, law, {}, nullptr};
  if (kind == ModelKind::Exact) c.ring = std::make_shared<const model::RingIntegralTable>(law);
  return c;
}

Case spot(const std::string& name, const model::PressureLaw<double>& law,
          const model::ContactSpot& s) {
  return {name, ModelKind::Exact, law, spot_with_table(ModelKind::Exact, law, s.q, 1.0, s),
          nullptr};
}

TEST(KinematicAutodiff, ClosedFormsMatchCentralDifferences) {
  for (ModelKind kind : {ModelKind::Seed, ModelKind::Corrected})
    for (const auto& law :
         {model::PressureLaw<double>::hertz(), model::PressureLaw<double>::uniform()})
      expect_derivatives_match_differences(circle(kind, model_name(kind), law), 60, 11);
}

TEST(KinematicAutodiff, ExactCircleMatchesCentralDifferencesForEveryLawKind) {
  const auto step =
      model::PressureLaw<double>::tabulated(std::make_shared<const model::PressureTable>(
          std::vector<double>{0.0, 0.5, 0.5, 1.0}, std::vector<double>{2.0, 2.0, 1.0, 0.5}));
  const std::vector<std::pair<std::string, model::PressureLaw<double>>> laws = {
      {"hertz", model::PressureLaw<double>::hertz()},
      {"uniform", model::PressureLaw<double>::uniform()},
      {"power:1.7", model::PressureLaw<double>::power(1.7)},
      {"annulus:0.4", model::PressureLaw<double>::annulus(0.4)},
      {"ring", model::PressureLaw<double>::ring()},
      {"step table", step}};
  for (const auto& [name, law] : laws)
    expect_derivatives_match_differences(circle(ModelKind::Exact, "exact " + name, law), 60, 12);
}

TEST(KinematicAutodiff, ExactSpotsMatchCentralDifferencesThroughTheirTables) {
  auto map = std::make_shared<model::PressureMap>();
  map->x = {-1.0, -0.3, 0.4, 1.0};
  map->y = {-0.6, 0.1, 0.6};
  map->sigma0 = {0.2, 1.0, 0.9, 0.1, 0.5, 1.4, 1.2, 0.4, 0.0, 0.8, 0.7, 0.3};
  expect_derivatives_match_differences(
      spot("ellipse:0.6 hertz", model::PressureLaw<double>::hertz(),
           model::ContactSpot::ellipse(0.6)),
      60, 13);
  expect_derivatives_match_differences(
      spot("rect:0.7 parabolic", model::PressureLaw<double>::parabolic(),
           model::ContactSpot::rect(0.7)),
      60, 14);
  expect_derivatives_match_differences(spot("map 4 x 3", model::PressureLaw<double>::uniform(),
                                            model::ContactSpot::pressure_map(map)),
                                       60, 15);
}

TEST(KinematicAutodiff, AnExactModelWithoutItsTableRefusesDualKinematics) {
  const Case c{"no table", ModelKind::Exact, model::PressureLaw<double>::hertz(), {}, nullptr};
  const model::Kinematics k{0.1, 0.2, 1.0, 10.0, 0.1}, dk{1.0, 0.0, 0.0, 10.0, 0.1};
  EXPECT_THROW(dual(c, params(c), k, dk), std::logic_error);
}

}  // namespace
}  // namespace frictionid::kinematic_autodiff_test
