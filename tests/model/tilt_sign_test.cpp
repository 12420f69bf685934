// A row whose pressure tilt is turned (Kinematics::tilt_sign = -1, the wheel rolling backwards in
// the wheel form; docs/physics.md §9.2) is the same row with h and h_y negated, for every model
// variant and spot; the tilt's own couples change sign with it.
#include <gtest/gtest.h>

#include <frictionid/model_variant.hpp>

namespace frictionid::tilt_sign_test {
namespace {

void expect_turned_equals_negated(ModelKind kind, const model::ContactSpot& spot) {
  const auto law = model::PressureLaw<double>::hertz();
  auto p = default_parameters(law, spot, 0.8, 1.3, 0.2);
  p[kHy] = kind == ModelKind::Exact ? 0.1 : 0.0;
  auto negated = p;
  negated[kH] = -p[kH];
  negated[kHy] = -p[kHy];
  const ModelEvaluator<double> turned_model(kind, law, p.data(), nullptr, nullptr, spot);
  const ModelEvaluator<double> negated_model(kind, law, negated.data(), nullptr, nullptr, spot);
  for (const auto& [vx, vy, w] :
       {std::tuple{0.3, 0.2, 1.1}, std::tuple{-0.5, 0.0, 0.7}, std::tuple{0.02, -0.4, -2.0}}) {
    model::Kinematics k{vx, vy, w, 2.0, 0.5, -1.0};
    const auto a = turned_model(k);
    k.tilt_sign = 1.0;
    const auto b = negated_model(k);
    EXPECT_EQ(a.T_x, b.T_x);
    EXPECT_EQ(a.T_y, b.T_y);
    EXPECT_EQ(a.M_z, b.M_z);
    EXPECT_EQ(a.M_roll, b.M_roll);
    EXPECT_EQ(a.M_tilt, b.M_tilt);
    const auto plain = turned_model(k);  // the same row with its tilt as given
    EXPECT_NEAR(plain.M_roll, -a.M_roll, 1e-15);
  }
}

TEST(TiltSign, ATurnedRowIsTheRowWithNegatedTiltsForTheSeedApproximant) {
  expect_turned_equals_negated(ModelKind::Seed, {});
}

TEST(TiltSign, ATurnedRowIsTheRowWithNegatedTiltsForTheCorrectedApproximant) {
  expect_turned_equals_negated(ModelKind::Corrected, {});
}

TEST(TiltSign, ATurnedRowIsTheRowWithNegatedTiltsForTheExactModelOnTheCircle) {
  expect_turned_equals_negated(ModelKind::Exact, {});
}

TEST(TiltSign, ATurnedRowIsTheRowWithNegatedTiltsForTheExactModelOnAnEllipse) {
  expect_turned_equals_negated(ModelKind::Exact, model::ContactSpot::ellipse(0.7));
}

}  // namespace
}  // namespace frictionid::tilt_sign_test
