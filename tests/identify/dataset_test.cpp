#include <frictionid/dataset.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

namespace frictionid::dataset_test {
namespace {

Dataset numbered(std::size_t rows) {
  Dataset d;
  d.source = "d.csv";
  for (std::size_t i = 0; i < rows; ++i) {
    d.line.push_back(i + 2);
    d.v_x.push_back(static_cast<double>(i));
    d.v_y.push_back(0.0);
    d.omega.push_back(1.0);
    d.N.push_back(100.0);
    d.R.push_back(0.1);
    d.value[0].push_back(static_cast<double>(10 * i));
    d.present[0].push_back(1);
    d.sigma[0].push_back(1.0);
    for (int c = 1; c < kChannelCount; ++c) {
      d.value[c].push_back(0.0);
      d.present[c].push_back(0);
    }
  }
  return d;
}

TEST(DatasetSubsample, TakesEveryKthRowWithTheSmallestStrideThatFits) {
  const Dataset d = numbered(1000);
  const Dataset s = d.subsample(300);  // stride ceil(1000/300) = 4
  ASSERT_EQ(s.rows(), 250u);
  for (std::size_t j = 0; j < s.rows(); ++j) {
    EXPECT_EQ(s.v_x[j], static_cast<double>(4 * j));
    EXPECT_EQ(s.line[j], 4 * j + 2);
    EXPECT_EQ(s.value[0][j], 40.0 * static_cast<double>(j));
  }
  EXPECT_EQ(s.sigma[0].size(), s.rows());
  EXPECT_TRUE(s.sigma[1].empty());  // no sigma column stays no sigma column
  EXPECT_EQ(s.source, "d.csv");
}

TEST(DatasetSubsample, KeepsEveryRowWhenThereAreFewEnough) {
  const Dataset d = numbered(17);
  EXPECT_EQ(d.subsample(17).rows(), 17u);
  EXPECT_EQ(d.subsample(1000).rows(), 17u);
  EXPECT_EQ(d.subsample(1).rows(), 1u);
}

TEST(DatasetSubsample, RejectsZeroRowsInsteadOfDividingByZero) {
  EXPECT_THROW(numbered(5).subsample(0), std::invalid_argument);
}

}  // namespace
}  // namespace frictionid::dataset_test
