// A dataset in any form (include/frictionid/io/dataset_reader.hpp): which form auto reads and
// why, what --input-form and the column map do, and the same rows written in the native form, in
// the wheel form (ISO axes, with units), in the wheel form (SAE axes) and as TYDEX reading to the
// same native dataset.
#include <frictionid/io/dataset_reader.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <frictionid/io/input_error.hpp>
#include "support/scratch_dir.hpp"

namespace frictionid::dataset_reader_test {
namespace {

constexpr double kPi = 3.141592653589793;

// The rows of tests/data/wheel/rig_iso.tdx: V [km/h], alpha [deg], slip_ratio, r_e [mm],
// gamma [deg], Fz, Fx, Fy [N], Mz, My [N m], in ISO axes (the wheel form's signs); R = 50 mm.
struct Row {
  double V, alpha, slip, re, gamma, Fz, Fx, Fy, Mz, My;
};
const std::vector<Row> kRows = {
    {36, 3.5, 0.02, 305, 1.5, 4200, 310.5, -1250, -35.5, -9.25},
    {54, -7, -0.01, 298, -2, 6000, -150, 750, 12.125, -4},
    {18, 0.5, -0.05, 301, 0, 2000, -900, -10, 0.5, -3},
    {72, 12.5, 0.15, 310, 4, 3300, 2500, -2500, 60, -20},
};

std::string g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

class DatasetReader : public ::testing::Test {
 protected:
  DatasetReader() : dir_("dataset_reader") {}
  std::string write(const std::string& name, const std::string& content) {
    const std::string path = dir_ / name;
    std::ofstream(path) << content;
    return path;
  }
  test::ScratchDir dir_;
};

// physics.md (1.9) by hand, in SI: the native rows of kRows.
std::string native_csv() {
  std::string out = "v_x,v_y,omega,N,R,T_x,T_y,M_z,M_roll\n";
  for (const Row& r : kRows) {
    const double V = r.V * 1000.0 / 3600.0, a = r.alpha * kPi / 180.0;
    const double g = r.gamma * kPi / 180.0, re = r.re / 1000.0;
    const double Vx = V * std::cos(a), Vy = -V * std::sin(a);
    const double Omega = Vx * (1.0 + r.slip) / re;
    out += g17(-Vx * r.slip) + "," + g17(Vy) + "," + g17(-Omega * std::sin(g)) + "," + g17(r.Fz) +
           ",0.05," + g17(-r.Fx) + "," + g17(-r.Fy) + "," + g17(-r.Mz) + "," + g17(-r.My) + "\n";
  }
  return out;
}

std::string wheel_csv(bool sae) {
  const double s = sae ? -1.0 : 1.0;
  std::string out =
      "V[km/h],alpha[deg],slip_ratio,r_e[mm],gamma[deg],R[mm],Fz[kN],Fx,Fy,Mz[N*m],My[N*m]\n";
  for (const Row& r : kRows)
    out += g17(r.V) + "," + g17(r.alpha) + "," + g17(r.slip) + "," + g17(r.re) + "," +
           g17(s * r.gamma) + ",50," + g17(s * r.Fz / 1000.0) + "," + g17(r.Fx) + "," +
           g17(s * r.Fy) + "," + g17(s * r.Mz) + "," + g17(s * r.My) + "\n";
  return out;
}

void expect_same(const Dataset& a, const Dataset& b, double rel, const std::string& what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  const auto near = [&](double x, double y, const char* name, std::size_t i) {
    EXPECT_LE(std::abs(x - y), rel * std::max({std::abs(x), std::abs(y), 1e-300}))
        << what << " " << name << " row " << i << ": " << g17(x) << " vs " << g17(y);
  };
  for (std::size_t i = 0; i < a.rows(); ++i) {
    near(a.v_x[i], b.v_x[i], "v_x", i);
    near(a.v_y[i], b.v_y[i], "v_y", i);
    near(a.omega[i], b.omega[i], "omega", i);
    near(a.N[i], b.N[i], "N", i);
    near(a.R[i], b.R[i], "R", i);
    EXPECT_EQ(a.tilt_sign_at(i), b.tilt_sign_at(i)) << what << " row " << i;
    for (int c = 0; c < kChannelCount; ++c) {
      EXPECT_EQ(a.present[c][i], b.present[c][i]) << what << " channel " << c << " row " << i;
      if (a.present[c][i]) near(a.value[c][i], b.value[c][i], channel_name(kAllChannels[c]), i);
    }
  }
}

TEST_F(DatasetReader, TheSameRowsInFourFormsReadToTheSameNativeDataset) {
  const LoadedDataset native = read_dataset(write("native.csv", native_csv()));
  const LoadedDataset iso = read_dataset(write("iso.csv", wheel_csv(false)));
  DatasetReadOptions sae_options;
  sae_options.axes = Axes::Sae;
  const LoadedDataset sae = read_dataset(write("sae.csv", wheel_csv(true)), sae_options);
  DatasetReadOptions tdx_options;
  tdx_options.contact_radius = 0.05;
  const LoadedDataset tdx =
      read_dataset(std::string(FRICTIONID_TEST_DATA_DIR) + "/wheel/rig_iso.tdx", tdx_options);
  EXPECT_EQ(native.form.form, "native");
  EXPECT_EQ(iso.form.form, "wheel");
  EXPECT_EQ(sae.form.axes, "sae");
  EXPECT_EQ(tdx.form.format, "tydex");
  // Units are converted by one multiplication each (km/h, deg, mm): a few ulps.
  expect_same(native.data, iso.data, 1e-14, "wheel form in ISO axes");
  expect_same(native.data, sae.data, 1e-14, "wheel form in SAE axes");
  // The TYDEX file gives the wheel's speed in rpm to 12 digits.
  expect_same(native.data, tdx.data, 1e-11, "TYDEX");
}

TEST_F(DatasetReader, AutoReadsTheWheelFormWhenTheHeaderHasVAndAlphaAndNoVx) {
  const LoadedDataset d = read_dataset(write("w.csv", wheel_csv(false)));
  EXPECT_EQ(d.form.form, "wheel");
  EXPECT_EQ(d.form.reason, "auto: the header has V and alpha and no v_x");
  EXPECT_EQ(d.form.units.size(), 8u);
}

TEST_F(DatasetReader, AutoReadsTheNativeFormWhenTheHeaderHasVx) {
  const LoadedDataset d = read_dataset(write("n.csv", native_csv()));
  EXPECT_EQ(d.form.form, "native");
  EXPECT_EQ(d.form.reason, "auto: the header has v_x");
  EXPECT_TRUE(d.data.tilt_sign.empty());  // the native form's tilt stays along +x
}

TEST_F(DatasetReader, InputFormOverridesTheHeader) {
  DatasetReadOptions o;
  o.form = InputForm::Native;
  EXPECT_THROW(read_dataset(write("w.csv", wheel_csv(false)), o), InputError);  // no v_x
  o.form = InputForm::Wheel;
  const LoadedDataset d = read_dataset(write("w2.csv", wheel_csv(false)), o);
  EXPECT_EQ(d.form.reason, "--input-form wheel");
}

TEST_F(DatasetReader, TydexIsRecognisedByItsNameOrItsFirstLine) {
  DatasetReadOptions o;
  o.contact_radius = 0.05;
  std::ifstream in(std::string(FRICTIONID_TEST_DATA_DIR) + "/wheel/rig_iso.tdx");
  const std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(read_dataset(write("rig.tdx", content), o).form.reason,
            "auto: a TYDEX file (its name ends in .tdx)");
  EXPECT_EQ(read_dataset(write("rig.dat", content), o).form.reason,
            "auto: a TYDEX file (it begins with **HEADER)");
  o.form = InputForm::Native;
  EXPECT_THROW(read_dataset(write("rig2.tdx", content), o), InputError);
}

TEST_F(DatasetReader, WheelFormOptionsForANativeFileAreAnError) {
  const std::string path = write("n.csv", native_csv());
  DatasetReadOptions o;
  o.axes = Axes::Sae;
  EXPECT_THROW(read_dataset(path, o), InputError);
  o.axes = Axes::Iso;
  o.contact_radius = 0.05;
  EXPECT_THROW(read_dataset(path, o), InputError);
  EXPECT_THROW(inspect_dataset_form(path, o), InputError);
}

TEST_F(DatasetReader, AColumnMapNameOfNeitherFormIsAnError) {
  DatasetReadOptions o;
  o.columns.canonical_to_header = {{"speed", "V"}};
  EXPECT_THROW(read_dataset(write("n.csv", native_csv()), o), InputError);
}

TEST_F(DatasetReader, AColumnMapAppliesToTheFormItNames) {
  std::string csv = wheel_csv(false);
  csv.replace(0, 7, "U[km/h]");  // V renamed
  DatasetReadOptions o;
  o.columns.canonical_to_header = {{"V", "U"}, {"v_x", "vx"}};
  const LoadedDataset d = read_dataset(write("u.csv", csv), o);
  EXPECT_EQ(d.form.form, "wheel");
  EXPECT_EQ(d.data.rows(), kRows.size());
}

TEST_F(DatasetReader, InspectTellsTheFormWithoutTheRows) {
  DatasetReadOptions o;
  o.axes = Axes::Sae;
  const DataForm f = inspect_dataset_form(write("s.csv", wheel_csv(true)), o);
  EXPECT_EQ(f.form, "wheel");
  EXPECT_EQ(f.axes, "sae");
  EXPECT_EQ(f.units.size(), 8u);
  EXPECT_NE(data_form_text(f).find("SAE J670 axes"), std::string::npos) << data_form_text(f);
  const auto j = data_form_json(f);
  EXPECT_EQ(j.at("units").at("Fz[kN]"), "kN");
}

}  // namespace
}  // namespace frictionid::dataset_reader_test
