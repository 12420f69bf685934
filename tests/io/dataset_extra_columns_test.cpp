#include <frictionid/io/dataset_csv.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace frictionid::dataset_extra_columns_test {
namespace {

namespace fs = std::filesystem;

std::string write_csv(const std::string& name, const std::string& content) {
  const fs::path p =
      fs::temp_directory_path() / ("extra_columns_" + name + std::to_string(::getpid()) + ".csv");
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}

TEST(DatasetExtraColumns, OtherColumnsAreKeptAsTextInFileOrder) {
  const std::string path = write_csv("kept",
                                     "run,v_x,omega,N,R,slip_angle,T_x,camber\n"
                                     "A1,0.1,2,100,0.05,1.5,30, -0.25\n"
                                     "\"B,2\",0.2,2,100,0.05,3,40,0\n");
  const Dataset d = load_dataset_csv(path);
  fs::remove(path);
  EXPECT_EQ(d.extra_names, (std::vector<std::string>{"run", "slip_angle", "camber"}));
  ASSERT_EQ(d.extra_values.size(), 3u);
  EXPECT_EQ(d.extra_values[0], (std::vector<std::string>{"A1", "B,2"}));
  EXPECT_EQ(d.extra_values[1], (std::vector<std::string>{"1.5", "3"}));
  EXPECT_EQ(d.extra_values[2], (std::vector<std::string>{"-0.25", "0"}));
  EXPECT_EQ(d.v_x, (std::vector<double>{0.1, 0.2}));  // the canonical columns are unaffected
}

TEST(DatasetExtraColumns, AFileWithOnlyCanonicalColumnsHasNone) {
  const std::string path = write_csv("none", "v_x,omega,N,R,T_x\n0.1,2,100,0.05,30\n");
  const Dataset d = load_dataset_csv(path);
  fs::remove(path);
  EXPECT_TRUE(d.extra_names.empty());
  EXPECT_TRUE(d.extra_values.empty());
}

TEST(DatasetExtraColumns, AColumnShadowedByARenameIsKeptAsExtra) {
  const std::string path = write_csv("renamed", "v_x,omega,spin,N,R,T_x\n0.1,7,2,100,0.05,30\n");
  const Dataset d = load_dataset_csv(path, ColumnMap{{{"omega", "spin"}}});
  fs::remove(path);
  EXPECT_EQ(d.omega, (std::vector<double>{2.0}));
  EXPECT_EQ(d.extra_names, (std::vector<std::string>{"omega"}));
  EXPECT_EQ(d.extra_values[0], (std::vector<std::string>{"7"}));
}

}  // namespace
}  // namespace frictionid::dataset_extra_columns_test
