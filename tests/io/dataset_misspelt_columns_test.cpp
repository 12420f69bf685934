// A column whose name is one slip away from a column the file lacks is an error with "did you
// mean", not an extra column: read as extra, `vy` would leave the lateral slip at 0 and the fit
// would say nothing (issue case: f 0.820 and kappa 1.069 instead of 0.9 and 1.15, "No warnings").
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include "support/scratch_dir.hpp"

namespace frictionid::dataset_misspelt_columns_test {
namespace {

std::string message_for(const test::ScratchDir& d, const std::string& header) {
  const std::string path = d / "data.csv";
  std::ofstream(path) << header << "\n"
                      << "0.1,0.2,1,100,0.05,10,0.5\n";
  try {
    (void)load_dataset_csv(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DatasetMisspeltColumns, ANameOneSlipFromAnAbsentColumnIsAnErrorWithDidYouMean) {
  const test::ScratchDir d("misspelt_columns");
  struct Case {
    const char* header;
    const char* column;  // "1:C" of the misspelt field
    const char* meant;
  };
  for (const Case& c :
       {Case{"v_x,vy,omega,N,R,T_x,M_z", ":1:2:", "did you mean 'v_y'"},
        Case{"v_x,v_y,omega,N,R,Tx,M_z", ":1:6:", "did you mean 'T_x'"},
        Case{"v_x,v_y,omega,N,R,T_x,m_z", ":1:7:", "did you mean 'M_z'"},
        Case{"v_x,v_y,omega,N,R,T_x,sigma_Tx", ":1:7:", "did you mean 'sigma_T_x'"}}) {
    const std::string m = message_for(d, c.header);
    EXPECT_NE(m.find(c.column), std::string::npos) << c.header << ": " << m;
    EXPECT_NE(m.find(c.meant), std::string::npos) << c.header << ": " << m;
  }
}

TEST(DatasetMisspeltColumns, UnrelatedExtraColumnsAndNamesOfPresentColumnsAreKept) {
  const test::ScratchDir d("misspelt_columns_ok");
  for (const char* header : {"v_x,v_y,omega,N,R,T_x,slip_angle", "v_x,v_y,omega,N,R,T_x,R2",
                             "v_x,v_y,omega,N,R,T_x,vy", "v_x,v_y,omega,N,R,T_x,tire_id"}) {
    EXPECT_EQ(message_for(d, header), "") << header;
  }
}

}  // namespace
}  // namespace frictionid::dataset_misspelt_columns_test
