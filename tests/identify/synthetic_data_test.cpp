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

TEST(SyntheticData, TheRowsDoNotDependOnTheThreads) {
  // A rectangle with a lateral tilt: every row integrated by itself, M_tilt among the channels.
  const auto law = model::PressureLaw<double>::parabolic();
  std::array<double, kParamCount> p = default_parameters(law, 0.9, 1.1, 0.05);
  p[kHy] = 0.04;
  p[kQ] = 0.7;
  SyntheticDesign design;
  design.rows = 120;
  design.slip_angles = {0.0, 0.2, -0.3};
  const NoiseSpec noise{0.01, 1e-3, true};
  const model::ContactSpot spot = model::ContactSpot::rect(0.7);
  const Dataset one = generate_dataset(ModelKind::Exact, law, p, design, noise, 5, spot, 1);
  for (int threads : {2, 3, 0}) {
    const Dataset d = generate_dataset(ModelKind::Exact, law, p, design, noise, 5, spot, threads);
    for (int c = 0; c < kChannelCount; ++c) {
      EXPECT_EQ(d.value[c], one.value[c]) << "channel " << c << ", threads " << threads;
      EXPECT_EQ(d.sigma[c], one.sigma[c]) << "channel " << c << ", threads " << threads;
    }
  }
  EXPECT_EQ(one.value[kChannelCount - 1].size(), design.rows);  // M_tilt was generated
}

TEST(SyntheticData, NoiseFollowsRowOrderAcrossTheBlocksOfPredictions) {
  // 70,000 rows run through the model in blocks of 65,536: each value is still the model's
  // plus its sigma times the next deviates of one stream, in row order, channel by channel.
  const auto law = model::PressureLaw<double>::hertz();
  const auto p = default_parameters(law, 0.9, 1.1, 0.05);
  SyntheticDesign design;
  design.rows = 70000;
  const NoiseSpec noise{0.01, 0.0, false};
  const Dataset clean = generate_dataset(ModelKind::Seed, law, p, design, NoiseSpec{}, 9, {}, 2);
  const Dataset noisy = generate_dataset(ModelKind::Seed, law, p, design, noise, 9, {}, 2);
  const ModelEvaluator<double> model(ModelKind::Seed, law, p.data());
  NormalStream normal(9);
  for (std::size_t i = 0; i < design.rows; ++i) {
    const auto r = model({clean.v_x[i], clean.v_y[i], clean.omega[i], clean.N[i], clean.R[i]});
    const double want[] = {r.T_x, r.T_y, r.M_z, r.M_roll};
    for (int c = 0; c < 4; ++c) {
      const double z = normal.next();
      ASSERT_EQ(clean.value[c][i], want[c]) << "row " << i << ", channel " << c;
      ASSERT_EQ(noisy.value[c][i], want[c] + std::fabs(0.01 * want[c]) * z)
          << "row " << i << ", channel " << c;
    }
  }
}

}  // namespace
}  // namespace frictionid::synthetic_data_test
