// Units in column headers (include/frictionid/io/units.hpp): the factors are the definitions,
// headers split into name and unit, a unit of another quantity or an unknown one is an error
// that names the column and lists the units of its quantity, and the native reader converts.
#include <frictionid/io/units.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include "support/scratch_dir.hpp"

namespace frictionid::units_test {
namespace {

constexpr double kPi = 3.141592653589793;

double factor(Quantity q, const char* unit) {
  const auto f = unit_factor(q, unit);
  EXPECT_TRUE(f.has_value()) << unit;
  return f.value_or(std::nan(""));
}

TEST(Units, SpeedFactorsAreTheDefinitions) {
  EXPECT_EQ(factor(Quantity::Speed, "m/s"), 1.0);
  EXPECT_EQ(factor(Quantity::Speed, "km/h"), 1000.0 / 3600.0);
  EXPECT_EQ(factor(Quantity::Speed, "mph"), 0.44704);  // 1609.344 m / 3600 s, exactly
  EXPECT_NEAR(36.0 * factor(Quantity::Speed, "km/h"), 10.0, 1e-15);
}

TEST(Units, AngleAndAngularRateFactorsAreTheDefinitions) {
  EXPECT_EQ(factor(Quantity::Angle, "rad"), 1.0);
  EXPECT_EQ(factor(Quantity::Angle, "deg"), kPi / 180.0);
  EXPECT_DOUBLE_EQ(180.0 * factor(Quantity::Angle, "deg"), kPi);
  EXPECT_EQ(factor(Quantity::AngularRate, "rad/s"), 1.0);
  EXPECT_EQ(factor(Quantity::AngularRate, "deg/s"), kPi / 180.0);
  EXPECT_EQ(factor(Quantity::AngularRate, "rpm"), 2.0 * kPi / 60.0);
  EXPECT_DOUBLE_EQ(60.0 * factor(Quantity::AngularRate, "rpm"), 2.0 * kPi);
}

TEST(Units, LengthForceAndMomentFactorsAreTheDefinitions) {
  EXPECT_EQ(factor(Quantity::Length, "m"), 1.0);
  EXPECT_EQ(factor(Quantity::Length, "cm"), 0.01);
  EXPECT_EQ(factor(Quantity::Length, "mm"), 0.001);
  EXPECT_EQ(factor(Quantity::Length, "in"), 0.0254);
  EXPECT_EQ(factor(Quantity::Force, "N"), 1.0);
  EXPECT_EQ(factor(Quantity::Force, "kN"), 1000.0);
  EXPECT_EQ(factor(Quantity::Force, "lbf"), 4.4482216152605);
  for (const char* u : {"N*m", "Nm", "N\xC2\xB7m"}) EXPECT_EQ(factor(Quantity::Moment, u), 1.0);
  for (const char* u : {"kN*m", "kNm"}) EXPECT_EQ(factor(Quantity::Moment, u), 1000.0);
  // lbf ft = 4.4482216152605 N * 0.3048 m = 1.3558179483314004 N m.
  EXPECT_NEAR(factor(Quantity::Moment, "lbf*ft"), 1.3558179483314004, 2e-16);
}

TEST(Units, DimensionlessTakesPercent) {
  EXPECT_EQ(factor(Quantity::Dimensionless, "-"), 1.0);
  EXPECT_EQ(factor(Quantity::Dimensionless, "%"), 0.01);
}

TEST(Units, AUnitOfAnotherQuantityIsNotFound) {
  EXPECT_FALSE(unit_factor(Quantity::Angle, "kN").has_value());
  EXPECT_FALSE(unit_factor(Quantity::Speed, "rpm").has_value());
  EXPECT_EQ(quantity_of_unit("kN"), Quantity::Force);
  EXPECT_FALSE(quantity_of_unit("furlong").has_value());
}

TEST(Units, HeadersSplitIntoNameAndUnit) {
  const HeaderName a = split_header_name("V[km/h]");
  EXPECT_EQ(a.name, "V");
  EXPECT_EQ(a.unit, "km/h");
  EXPECT_TRUE(a.has_unit);
  const HeaderName b = split_header_name(" alpha [ deg ] ");
  EXPECT_EQ(b.name, "alpha");
  EXPECT_EQ(b.unit, "deg");
  for (const char* plain : {"V", "V[km/h", "a[b]c", "x]"}) {
    const HeaderName h = split_header_name(plain);
    EXPECT_FALSE(h.has_unit) << plain;
    EXPECT_EQ(h.name, plain);
  }
  const HeaderName empty = split_header_name("V[]");
  EXPECT_TRUE(empty.has_unit);
  EXPECT_EQ(empty.unit, "");
}

TEST(Units, AMisplacedUnitNamesTheColumnAndListsItsQuantitysUnits) {
  try {
    column_unit_factor(Quantity::Angle, "alpha[kN]", split_header_name("alpha[kN]"), "f.csv", 1, 3);
    FAIL() << "alpha[kN] accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.line(), 1u);
    EXPECT_EQ(e.column(), 3u);
    EXPECT_NE(what.find("f.csv:1:3"), std::string::npos) << what;
    EXPECT_NE(what.find("'alpha[kN]'"), std::string::npos) << what;
    EXPECT_NE(what.find("the unit of a force"), std::string::npos) << what;
    EXPECT_NE(what.find("rad, deg"), std::string::npos) << what;
  }
}

TEST(Units, AnUnknownUnitIsAnError) {
  try {
    column_unit_factor(Quantity::Speed, "V[knots]", split_header_name("V[knots]"), "f.csv", 1, 1);
    FAIL() << "knots accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("does not know"), std::string::npos) << what;
    EXPECT_NE(what.find("m/s, km/h, mph"), std::string::npos) << what;
  }
  EXPECT_THROW(column_unit_factor(Quantity::Speed, "V[]", split_header_name("V[]"), "f", 1, 1),
               InputError);
}

TEST(Units, NoUnitIsSI) {
  EXPECT_EQ(column_unit_factor(Quantity::Force, "Fz", split_header_name("Fz"), "f", 1, 1), 1.0);
}

TEST(Units, TheNativeReaderConvertsColumnsWithUnits) {
  test::ScratchDir dir("units_native");
  const std::string path = dir / "u.csv";
  std::ofstream(path) << "v_x[km/h],omega[rpm],N[kN],R[mm],T_x[kN],M_z[kN*m],note[kPa]\n"
                         "36,60,4,50,2.5,0.1,240\n";
  const Dataset d = load_dataset_csv(path);
  EXPECT_NEAR(d.v_x[0], 10.0, 1e-15);
  EXPECT_DOUBLE_EQ(d.omega[0], 2.0 * kPi);
  EXPECT_EQ(d.N[0], 4000.0);
  EXPECT_EQ(d.R[0], 0.05);
  EXPECT_EQ(d.value[0][0], 2500.0);
  EXPECT_EQ(d.value[2][0], 100.0);
  // A column the reader does not know keeps its header and text: no unit is applied to it.
  ASSERT_EQ(d.extra_names.size(), 1u);
  EXPECT_EQ(d.extra_names[0], "note[kPa]");
  EXPECT_EQ(d.extra_values[0][0], "240");
}

TEST(Units, TheNativeReaderRejectsAWrongUnitAtItsColumn) {
  test::ScratchDir dir("units_native_bad");
  const std::string path = dir / "u.csv";
  std::ofstream(path) << "v_x,omega[deg],N[kN],R,T_x\n1,2,3,0.05,1\n";
  try {
    load_dataset_csv(path);
    FAIL() << "omega[deg] accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1u);
    EXPECT_EQ(e.column(), 2u);
    EXPECT_NE(std::string(e.what()).find("rad/s, deg/s, rpm"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace frictionid::units_test
