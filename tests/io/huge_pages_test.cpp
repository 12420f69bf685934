#include "io/huge_pages.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace frictionid::io_detail::huge_pages_test {
namespace {

// The advice is only a hint: a buffer keeps its contents and stays writable.
TEST(HugePages, AdviceKeepsTheContents) {
  std::vector<double> column(3'000'000);
  std::iota(column.begin(), column.end(), 0.0);
  advise_huge_pages(column.data(), column.size() * sizeof(double));
  for (std::size_t i = 0; i < column.size(); i += 4099) ASSERT_EQ(column[i], double(i));
  column.resize(column.capacity() + 1, -1.0);
  EXPECT_EQ(column.back(), -1.0);
}

TEST(HugePages, SmallAndEmptyBuffersAreAccepted) {
  std::vector<char> small(1000, 'x');
  advise_huge_pages(small.data(), small.size());
  advise_huge_pages(small.data() + 1, 0);
  advise_huge_pages(nullptr, 0);
  EXPECT_EQ(small, std::vector<char>(1000, 'x'));
}

}  // namespace
}  // namespace frictionid::io_detail::huge_pages_test
