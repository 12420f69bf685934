#include <frictionid/synthetic_data.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace frictionid::synthetic_data_test {
namespace {

TEST(SyntheticData, SameSeedGivesTheSameRowsAndAnotherSeedDifferentNoise) {
  const auto law = model::PressureLaw<double>::hertz();
  const auto p = default_parameters(law, 0.9, 1.1, 0.05);
  const NoiseSpec noise{0.01, 0.0, false};
  const Dataset a = generate_dataset(ModelKind::Exact, law, p, SyntheticDesign{}, noise, 42);
  const Dataset b = generate_dataset(ModelKind::Exact, law, p, SyntheticDesign{}, noise, 42);
  const Dataset c = generate_dataset(ModelKind::Exact, law, p, SyntheticDesign{}, noise, 43);
  EXPECT_EQ(a.value[0], b.value[0]);
  EXPECT_EQ(a.v_x, c.v_x);
  EXPECT_NE(a.value[0], c.value[0]);
}

TEST(SyntheticData, RelativeNoiseHasTheRequestedSpread) {
  const auto law = model::PressureLaw<double>::hertz();
  const auto p = default_parameters(law, 0.9, 1.1, 0.05);
  SyntheticDesign design;
  design.rows = 4000;
  const Dataset clean = generate_dataset(ModelKind::Seed, law, p, design, NoiseSpec{}, 1);
  const Dataset noisy =
      generate_dataset(ModelKind::Seed, law, p, design, NoiseSpec{0.02, 0, false}, 1);
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < clean.rows(); ++i) {
    const double z = (noisy.value[0][i] - clean.value[0][i]) / (0.02 * clean.value[0][i]);
    sum += z;
    sum2 += z * z;
  }
  const double n = static_cast<double>(clean.rows());
  EXPECT_NEAR(sum / n, 0.0, 4.0 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n), 1.0, 0.05);
}

TEST(SyntheticData, DesignSpansTheRequestedEpsRangeWithBothSpinSignsAndBackwardSlip) {
  const auto law = model::PressureLaw<double>::hertz();
  const auto p = default_parameters(law);
  SyntheticDesign design;
  const Dataset d = generate_dataset(ModelKind::Seed, law, p, design, NoiseSpec{}, 1);
  double lo = 1e300, hi = 0;
  int neg_omega = 0, neg_v = 0;
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const double eps = std::hypot(d.v_x[i], d.v_y[i]) / (std::fabs(d.omega[i]) * d.R[i]);
    lo = std::min(lo, eps);
    hi = std::max(hi, eps);
    neg_omega += d.omega[i] < 0;
    neg_v += d.v_x[i] < 0;
  }
  EXPECT_GE(lo, design.eps_min * (1 - 1e-12));
  EXPECT_LE(hi, design.eps_max * (1 + 1e-12));
  EXPECT_LT(lo, 2 * design.eps_min);
  EXPECT_GT(hi, design.eps_max / 2);
  EXPECT_GT(neg_omega, 0);
  EXPECT_GT(neg_v, 0);
}

}  // namespace
}  // namespace frictionid::synthetic_data_test
