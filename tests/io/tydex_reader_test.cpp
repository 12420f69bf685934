// TYDEX files read as the wheel form (include/frictionid/io/tydex_reader.hpp): the hand-written
// file of tests/data/wheel (the published TYDEX 1.3 layout), the channel mapping and its signs,
// factors and units, constants, kept channels, and each malformed file an InputError at its line.
#include <frictionid/io/tydex_reader.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <frictionid/io/data_form.hpp>
#include <frictionid/io/input_error.hpp>
#include "support/scratch_dir.hpp"

namespace frictionid::tydex_reader_test {
namespace {

constexpr double kDeg = 3.141592653589793 / 180.0;

std::string data_file(const std::string& name) {
  return std::string(FRICTIONID_TEST_DATA_DIR) + "/wheel/" + name;
}

DatasetReadOptions with_radius(double R) {
  DatasetReadOptions o;
  o.contact_radius = R;
  return o;
}

std::string column(const Dataset& d, const std::string& name, std::size_t row) {
  const auto it = std::find(d.extra_names.begin(), d.extra_names.end(), name);
  if (it == d.extra_names.end()) return "<no column " + name + ">";
  return d.extra_values[static_cast<std::size_t>(it - d.extra_names.begin())][row];
}

// A TYDEX file around `channels` and `data` (the MEASURCHANNELS and MEASURDATA lines).
std::string tydex(const std::string& channels, const std::string& data,
                  const std::string& constants = "") {
  return "**HEADER\nRELEASE   Release of TYDEX-Format                 1.3\n**CONSTANTS\n" +
         constants + "**MEASURCHANNELS\n" + channels + "**MEASURDATA\n" + data + "**END\n";
}

const char* const kChannels =
    "TRAJVELW  Trajectory velocity           m/s       1         0         0\n"
    "SLIPANGL  Slip angle                    rad       1         0         0\n"
    "LONGSLIP  Longitudinal slip             -         1         0         0\n"
    "WHROTSPD  Wheel rotational speed        rad/s     1         0         0\n"
    "INCLANGL  Inclination angle             rad       1         0         0\n"
    "FZW       Vertical force W              N         1         0         0\n"
    "FYW       Lateral force W               N         1         0         0\n";

class Tydex : public ::testing::Test {
 protected:
  Tydex() : dir_("tydex") {}
  Dataset read(const std::string& content, const DatasetReadOptions& o = with_radius(0.05),
               DataForm* form = nullptr) {
    const std::string path = dir_ / "t.tdx";
    std::ofstream(path) << content;
    return load_tydex(path, o, form);
  }
  InputError error(const std::string& content, const DatasetReadOptions& o = with_radius(0.05)) {
    try {
      read(content, o);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "accepted:\n" << content;
    return InputError("");
  }
  test::ScratchDir dir_;
};

TEST_F(Tydex, TheHandWrittenFileReadsAsTheWheelForm) {
  DataForm form;
  const Dataset d = load_tydex(data_file("rig_iso.tdx"), with_radius(0.05), &form);
  ASSERT_EQ(d.rows(), 4u);
  EXPECT_EQ(d.line[0], 28u);  // the first line after **MEASURDATA
  // Row 1: 36 km/h, SLIPANGL -3.5 deg (the wheel form's alpha = +3.5 deg: moving right).
  const double V = 36.0 * (1000.0 / 3600.0);
  EXPECT_NEAR(d.v_y[0], -V * std::sin(3.5 * kDeg), 1e-15);
  EXPECT_NEAR(d.v_x[0], -V * std::cos(3.5 * kDeg) * 0.02, 1e-15);  // LONGSLIP 2 %
  EXPECT_EQ(d.N[0], 4200.0);
  EXPECT_EQ(d.R[0], 0.05);
  EXPECT_EQ(d.value[static_cast<int>(Channel::T_x)][0], -310.5);  // FXW 621 with factor 0.5
  EXPECT_EQ(d.value[static_cast<int>(Channel::T_y)][0], 1250.0);
  EXPECT_EQ(d.value[static_cast<int>(Channel::M_z)][0], 35.5);
  EXPECT_EQ(d.value[static_cast<int>(Channel::M_roll)][0], 9.25);
  EXPECT_FALSE(d.has_channel(Channel::M_tilt));
  // INCLANGL -1.5 deg is the wheel form's +1.5 deg: omega = -Omega sin(1.5 deg) < 0.
  const double Omega = 318.757866456 * 2.0 * 3.141592653589793 / 60.0;
  EXPECT_NEAR(d.omega[0], -Omega * std::sin(1.5 * kDeg), 1e-12);
  EXPECT_EQ(d.tilt_sign[0], 1.0);
  EXPECT_EQ(form.form, "wheel");
  EXPECT_EQ(form.format, "tydex");
  EXPECT_EQ(form.axes, "iso");
  EXPECT_EQ(form.units.front().column, "TRAJVELW");
  EXPECT_EQ(form.units.front().unit, "km/h");
}

TEST_F(Tydex, ChannelsAndConstantsAreKeptUnderTheirNames) {
  const Dataset d = load_tydex(data_file("rig_iso.tdx"), with_radius(0.05));
  EXPECT_EQ(column(d, "INFLPRES", 2), "242");
  EXPECT_EQ(column(d, "RUNTIME", 1), "2.5");
  EXPECT_EQ(column(d, "SLIPANGL", 0), "-3.5");  // as written
  EXPECT_EQ(column(d, "FXW", 0), "310.5");      // the physical value: factor 0.5 applied
  EXPECT_EQ(column(d, "NOMPRES", 3), "240");    // a constant, in every row
  EXPECT_EQ(column(d, "TESTNO", 0), "17");
}

TEST_F(Tydex, NotAvailMeansTheChannelIsNotMeasuredInThatRow) {
  const Dataset d = read(tydex(kChannels,
                               "10 0.01 0 33.3 0 4000 NOTAVAIL\n10 0.02 0 33.3 0 4000 90\n"
                               "10 0 0 33.3 0 4000 0\n"));
  EXPECT_EQ(d.present[static_cast<int>(Channel::T_y)][0], 0);
  EXPECT_EQ(d.present[static_cast<int>(Channel::T_y)][1], 1);
}

TEST_F(Tydex, AConstantGivesAWheelColumnInEveryRow) {
  const std::string channels =
      "TRAJVELW  Trajectory velocity           m/s       1         0         0\n"
      "SLIPANGL  Slip angle                    deg       1         0         0\n"
      "LONGSLIP  Longitudinal slip             -         1         0         0\n"
      "FZW       Vertical force W              N         1         0         0\n"
      "FYW       Lateral force W               N         1         0         0\n";
  const std::string constants =
      "INCLANGL  Inclination angle             deg       -2\n"
      "RLOADED   Loaded radius                 mm        300\n";
  DatasetReadOptions o = with_radius(0.05);
  o.columns.canonical_to_header = {{"r_e", "RLOADED"}};  // r_e has no TYDEX name of its own
  const Dataset d = read(tydex(channels, "10 1 0 4000 5\n", constants), o);
  // Omega = V_x / r_e = 10 / 0.3; gamma = +2 deg (INCLANGL -2 deg): omega = -Omega sin 2 deg.
  EXPECT_NEAR(d.omega[0], -(10.0 * std::cos(kDeg) / 0.3) * std::sin(2.0 * kDeg), 1e-14);
}

TEST_F(Tydex, NonZeroOffsetsAreRejectedAtTheirLine) {
  const std::string channels = std::string(kChannels) +
                               "MZW       Aligning torque W             Nm        1         3.5"
                               "       0\n";
  const InputError e = error(tydex(channels, "10 0 0 33.3 0 4000 1 2\n"));
  EXPECT_EQ(e.line(), 12u);
  EXPECT_EQ(e.column(), 51u);
  EXPECT_NE(e.message().find("offsets"), std::string::npos) << e.what();
}

TEST_F(Tydex, AChannelLineOffTheLayoutIsRejected) {
  const InputError e = error(tydex("FZW N 1\n", "4000\n"));
  EXPECT_EQ(e.line(), 5u);
  EXPECT_NE(e.message().find("columns 1-10"), std::string::npos) << e.what();
}

TEST_F(Tydex, ADataRowWithTooFewValuesIsRejected) {
  const InputError e = error(tydex(kChannels, "10 0 0 33.3 0 4000\n"));
  EXPECT_EQ(e.line(), 13u);
  EXPECT_EQ(e.column(), 7u);
}

TEST_F(Tydex, AMalformedNumberIsRejectedAtItsLineAndField) {
  const InputError e = error(tydex(kChannels, "10 0 0 33.3 0 4000 1\n10 0 0 33.3 abc 4000 1\n"));
  EXPECT_EQ(e.line(), 14u);
  EXPECT_EQ(e.column(), 5u);
}

TEST_F(Tydex, TheWheelFormsChecksApplyToItsRows) {
  const InputError e = error(tydex(kChannels, "10 0 0 33.3 0 -4000 1\n"));  // FZW < 0 in W axes
  EXPECT_EQ(e.line(), 13u);
  EXPECT_EQ(e.column(), 6u);
}

TEST_F(Tydex, AFileThatDoesNotBeginWithHeaderIsRejected) {
  const InputError e = error("**MEASURCHANNELS\n");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_NE(e.message().find("**HEADER"), std::string::npos) << e.what();
}

TEST_F(Tydex, AFileWithoutMeasurDataIsRejected) {
  const InputError e = error("**HEADER\n**MEASURCHANNELS\n" + std::string(kChannels) + "**END\n");
  EXPECT_NE(e.message().find("MEASURDATA"), std::string::npos) << e.what();
}

TEST_F(Tydex, SaeAxesDoNotApplyToTydex) {
  DatasetReadOptions o = with_radius(0.05);
  o.axes = Axes::Sae;
  const InputError e = error(tydex(kChannels, "10 0 0 33.3 0 4000 1\n"), o);
  EXPECT_NE(e.message().find("W axes"), std::string::npos) << e.what();
}

TEST_F(Tydex, ExtensionIsRecognisedInAnyCase) {
  EXPECT_TRUE(has_tydex_extension("a/b.tdx"));
  EXPECT_TRUE(has_tydex_extension("B.TDX"));
  EXPECT_FALSE(has_tydex_extension("b.csv"));
}

}  // namespace
}  // namespace frictionid::tydex_reader_test
