// The wheel form (include/frictionid/io/wheel_form.hpp, docs/physics.md §1.1): one worked
// example per sign, each written in ISO and in SAE axes; the same physical rows in both axes read
// to bit-identical native columns; the rolling direction per row; and every bad input an
// InputError at its file, line and column.
#include <frictionid/io/wheel_form.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include <frictionid/io/data_form.hpp>
#include <frictionid/io/input_error.hpp>
#include "support/scratch_dir.hpp"

namespace frictionid::wheel_form_test {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kDeg = kPi / 180.0;

class WheelForm : public ::testing::Test {
 protected:
  WheelForm() : dir_("wheel_form") {}

  Dataset read(const std::string& csv, Axes axes = Axes::Iso, DataForm* form = nullptr,
               const std::string& name = "w.csv") {
    const std::string path = dir_ / name;
    std::ofstream(path) << csv;
    DatasetReadOptions o;
    o.axes = axes;
    return load_wheel_csv(path, o, form);
  }

  // The InputError reading `csv` throws (or a failure).
  InputError error(const std::string& csv, Axes axes = Axes::Iso) {
    try {
      read(csv, axes);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "accepted:\n" << csv;
    return InputError("");
  }

  test::ScratchDir dir_;
};

const char* const kHeader = "V,alpha,slip_ratio,r_e,gamma,psi_dot,R,Fz,Fx,Fy,Mz,My,Mx\n";

// The slip angle is positive when the contact centre moves to the right of the wheel's heading,
// in both axis systems (ISO: V_y = -V sin alpha < 0; SAE J670: towards +y, which is right).
TEST_F(WheelForm, SlipAngleIsPositiveWhenTheContactMovesRightInBothAxes) {
  const Dataset iso = read(std::string(kHeader) + "10,0.1,0,0.3,0,0,0.05,4000,0,0,0,0,0\n");
  const Dataset sae =
      read(std::string(kHeader) + "10,0.1,0,0.3,0,0,0.05,-4000,0,0,0,0,0\n", Axes::Sae);
  EXPECT_EQ(iso.v_y[0], -10.0 * std::sin(0.1));  // ISO y is left: moving right is v_y < 0
  EXPECT_EQ(iso.v_x[0], 0.0);                    // no longitudinal slip
  EXPECT_EQ(sae.v_y[0], iso.v_y[0]);
}

// Positive slip ratio is driving: the wheel's circumference runs faster than the contact
// centre, so the contact slides backwards, v_x = V_x - Omega r_e = -V_x slip_ratio < 0.
TEST_F(WheelForm, PositiveSlipRatioIsDrivingAndSlidesTheContactBackwards) {
  const Dataset d = read(std::string(kHeader) + "10,0,0.1,0.3,0,0,0.05,4000,800,0,0,0,0\n");
  EXPECT_EQ(d.v_x[0], -1.0);
  // The road drives the tire forwards (Fx = 800 N); the resistance is against the sliding.
  EXPECT_EQ(d.value[static_cast<int>(Channel::T_x)][0], -800.0);
  EXPECT_EQ(d.tilt_sign[0], 1.0);
  const Dataset sae =
      read(std::string(kHeader) + "10,0,0.1,0.3,0,0,0.05,-4000,800,0,0,0,0\n", Axes::Sae);
  EXPECT_EQ(sae.v_x[0], d.v_x[0]);
  EXPECT_EQ(sae.value[0][0], d.value[0][0]);
}

// omega_w is the wheel's own spin, positive rolling forward: v_x = V_x - omega_w r_e.
TEST_F(WheelForm, WheelSpinGivesTheSlidingVelocity) {
  const Dataset d = read(
      "V,alpha,omega_w,r_e,gamma,R,Fz,Fx\n"
      "10,0,30,0.3,0,0.05,4000,-600\n");
  EXPECT_EQ(d.v_x[0], 10.0 - 30.0 * 0.3);  // braking: the contact slides forwards
  EXPECT_EQ(d.value[0][0], 600.0);
}

// The inclination gamma > 0 tilts the wheel's top towards +y in ISO (left) and, being the
// rotation about the shared x axis, towards the right in SAE: the same tilt is -gamma there.
// A wheel rolling forward with its top to the left spins the contact clockwise seen from above:
// omega = psi_dot - Omega sin(gamma) < 0.
TEST_F(WheelForm, InclinationTurnsOverBetweenTheAxes) {
  const Dataset iso = read(std::string(kHeader) + "10,0,0,0.3,0.05,0,0.05,4000,1,0,0,0,0\n");
  const double Omega = 10.0 / 0.3;
  EXPECT_EQ(iso.omega[0], -Omega * std::sin(0.05));
  EXPECT_LT(iso.omega[0], 0.0);
  const Dataset sae =
      read(std::string(kHeader) + "10,0,0,0.3,-0.05,0,0.05,-4000,1,0,0,0,0\n", Axes::Sae);
  EXPECT_EQ(sae.omega[0], iso.omega[0]);
}

// The yaw rate is about z: up in ISO, down in SAE; a left turn is +0.5 rad/s in ISO and -0.5 in
// SAE, and spins the contact counterclockwise (omega = +0.5).
TEST_F(WheelForm, YawRateTurnsOverBetweenTheAxes) {
  const Dataset iso = read(std::string(kHeader) + "10,0,0,0.3,0,0.5,0.05,4000,1,0,0,0,0\n");
  EXPECT_EQ(iso.omega[0], 0.5);
  const Dataset sae =
      read(std::string(kHeader) + "10,0,0,0.3,0,-0.5,0.05,-4000,1,0,0,0,0\n", Axes::Sae);
  EXPECT_EQ(sae.omega[0], 0.5);
}

// The road pushes the tire up: +Fz in ISO (z up), -Fz in SAE (z down); N is its size.
TEST_F(WheelForm, NormalForceIsUpInIsoAndDownInSae) {
  EXPECT_EQ(read(std::string(kHeader) + "10,0,0,0.3,0,0,0.05,4000,1,0,0,0,0\n").N[0], 4000.0);
  EXPECT_EQ(read(std::string(kHeader) + "10,0,0,0.3,0,0,0.05,-4000,1,0,0,0,0\n", Axes::Sae).N[0],
            4000.0);
}

// A contact sliding to the right (alpha > 0) is pushed left by the road: Fy > 0 in ISO, Fy < 0 in
// SAE; the resistance T_y = -Fy (ISO) points along the sliding, as the seed's T does.
TEST_F(WheelForm, LateralForceTurnsOverBetweenTheAxes) {
  const Dataset iso = read(std::string(kHeader) + "10,0.1,0,0.3,0,0,0.05,4000,0,500,0,0,0\n");
  const Dataset sae =
      read(std::string(kHeader) + "10,0.1,0,0.3,0,0,0.05,-4000,0,-500,0,0,0\n", Axes::Sae);
  const int Ty = static_cast<int>(Channel::T_y);
  EXPECT_EQ(iso.value[Ty][0], -500.0);
  EXPECT_GT(iso.value[Ty][0] * iso.v_y[0], 0.0) << "T_y has the sign of v_y";
  EXPECT_EQ(sae.value[Ty][0], iso.value[Ty][0]);
}

// The aligning moment is about z: a counterclockwise (ISO +) moment of the road on the tire is
// clockwise (negative) about SAE's downward z; M_z = -Mz(ISO) resists a counterclockwise spin.
TEST_F(WheelForm, AligningMomentTurnsOverBetweenTheAxes) {
  const Dataset iso = read(std::string(kHeader) + "10,0,0,0.3,0,0.5,0.05,4000,0,0,-20,0,0\n");
  const Dataset sae =
      read(std::string(kHeader) + "10,0,0,0.3,0,-0.5,0.05,-4000,0,0,20,0,0\n", Axes::Sae);
  const int Mz = static_cast<int>(Channel::M_z);
  EXPECT_EQ(iso.value[Mz][0], 20.0);
  EXPECT_GT(iso.value[Mz][0] * iso.omega[0], 0.0) << "the spin torque resists the spin";
  EXPECT_EQ(sae.value[Mz][0], iso.value[Mz][0]);
}

// Load ahead of the contact centre (the seed's h > 0, M_roll = int sigma x dS > 0) makes the
// road's moment about y negative in ISO (r x F = (x,0,0) x (0,0,N) = (0,-xN,0)) and positive
// about SAE's y, which points right: M_roll = -My(ISO) = My(SAE).
TEST_F(WheelForm, RollingResistanceMomentTurnsOverBetweenTheAxes) {
  const Dataset iso = read(std::string(kHeader) + "10,0,0,0.3,0,0,0.05,4000,0,0,0,-12,0\n");
  const Dataset sae =
      read(std::string(kHeader) + "10,0,0,0.3,0,0,0.05,-4000,0,0,0,12,0\n", Axes::Sae);
  const int Mr = static_cast<int>(Channel::M_roll);
  EXPECT_EQ(iso.value[Mr][0], 12.0);
  EXPECT_EQ(sae.value[Mr][0], 12.0);
}

// Load left of the centre (M_tilt = int sigma y dS > 0 in ISO) gives the road's moment about x
// (0,y,0) x (0,0,N) = (yN,0,0) > 0; x is shared by both axis systems, so Mx is the same number.
TEST_F(WheelForm, OverturningMomentIsTheSameInBothAxes) {
  const Dataset iso = read(std::string(kHeader) + "10,0,0,0.3,0,0,0.05,4000,0,0,0,0,7\n");
  const Dataset sae =
      read(std::string(kHeader) + "10,0,0,0.3,0,0,0.05,-4000,0,0,0,0,7\n", Axes::Sae);
  const int Mt = static_cast<int>(Channel::M_tilt);
  EXPECT_EQ(iso.value[Mt][0], 7.0);
  EXPECT_EQ(sae.value[Mt][0], 7.0);
}

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The same physical rows, with units, written in ISO and in SAE axes (y, z, the moments about
// them, the yaw rate and the inclination negated; a zero stays "0"): bit for bit the same
// native columns.
TEST_F(WheelForm, TheSameRowsInIsoAndSaeReadToBitIdenticalNativeColumns) {
  const std::string header =
      "V[km/h],alpha[deg],slip_ratio,omega_w[rpm],r_e[mm],gamma[deg],psi_dot[deg/s],R[mm],"
      "Fz[kN],Fx[N],Fy[kN],Mz[N*m],My[Nm],Mx[lbf*ft],run\n";
  const std::string iso_rows =
      "36,3.5,0.02,,305,1.5,2,48,4.2,310.5,-1.25,-35.5,-9.25,3.5,a\n"
      "54,-7,,520,298,-2,0,51,6,0,0.75,12.125,0,-1,b\n"
      "18,0,-0.05,,301,0,-4.5,50,2,-900,0,0,-3,0,c\n"
      "72,12.5,0.15,,310,4,1,47,3.3,2500,-2.5,60,-20,8.75,d\n";
  const std::string sae_rows =
      "36,3.5,0.02,,305,-1.5,-2,48,-4.2,310.5,1.25,35.5,9.25,3.5,a\n"
      "54,-7,,520,298,2,0,51,-6,0,-0.75,-12.125,0,-1,b\n"
      "18,0,-0.05,,301,0,4.5,50,-2,-900,0,0,3,0,c\n"
      "72,12.5,0.15,,310,-4,-1,47,-3.3,2500,2.5,-60,20,8.75,d\n";
  DataForm iso_form, sae_form;
  const Dataset iso = read(header + iso_rows, Axes::Iso, &iso_form, "iso.csv");
  const Dataset sae = read(header + sae_rows, Axes::Sae, &sae_form, "sae.csv");
  ASSERT_EQ(iso.rows(), 4u);
  ASSERT_EQ(sae.rows(), 4u);
  for (std::size_t i = 0; i < iso.rows(); ++i) {
    EXPECT_EQ(bits(iso.v_x[i]), bits(sae.v_x[i])) << i;
    EXPECT_EQ(bits(iso.v_y[i]), bits(sae.v_y[i])) << i;
    EXPECT_EQ(bits(iso.omega[i]), bits(sae.omega[i])) << i;
    EXPECT_EQ(bits(iso.N[i]), bits(sae.N[i])) << i;
    EXPECT_EQ(bits(iso.R[i]), bits(sae.R[i])) << i;
    EXPECT_EQ(bits(iso.tilt_sign[i]), bits(sae.tilt_sign[i])) << i;
    EXPECT_EQ(iso.line[i], sae.line[i]);
    for (int c = 0; c < kChannelCount; ++c) {
      EXPECT_EQ(iso.present[c][i], sae.present[c][i]) << i << " " << c;
      EXPECT_EQ(bits(iso.value[c][i]), bits(sae.value[c][i])) << i << " " << c;
    }
  }
  EXPECT_EQ(iso_form.axes, "iso");
  EXPECT_EQ(sae_form.axes, "sae");
  EXPECT_EQ(iso_form.units.size(), 13u);  // every wheel column of the header has a unit
  EXPECT_EQ(iso_form.units[0].column, "V[km/h]");
  EXPECT_EQ(iso_form.units[0].unit, "km/h");
}

// The pressure tilt follows the rolling direction: sgn(Omega) per row, 0 where the wheel stands.
TEST_F(WheelForm, TiltSignIsTheSignOfTheWheelSpin) {
  const Dataset d = read(
      "V,alpha,omega_w,r_e,gamma,R,Fz,Fx\n"
      "1,0,5,0.3,0,0.05,4000,1\n"
      "1,0,-5,0.3,0,0.05,4000,1\n"
      "0,0,0,0.3,0,0.05,4000,1\n");
  ASSERT_EQ(d.tilt_sign.size(), 3u);
  EXPECT_EQ(d.tilt_sign[0], 1.0);
  EXPECT_EQ(d.tilt_sign[1], -1.0);
  EXPECT_EQ(d.tilt_sign[2], 0.0);
}

TEST_F(WheelForm, EveryColumnButRIsKeptAsText) {
  const Dataset d = read(
      "tire,V[km/h],alpha,slip_ratio,r_e,gamma,R,Fz,Fy\n"
      "A7,36,0,0,0.3,0,0.05,4000,1\n");
  ASSERT_EQ(d.extra_names.size(), 8u);
  EXPECT_EQ(d.extra_names[0], "tire");
  EXPECT_EQ(d.extra_names[1], "V[km/h]");
  EXPECT_EQ(d.extra_values[0][0], "A7");
  EXPECT_EQ(d.extra_values[1][0], "36");
  EXPECT_EQ(d.extra_names.back(), "Fy");
}

TEST_F(WheelForm, ColumnMapRenamesWheelColumns) {
  const std::string path = dir_ / "renamed.csv";
  std::ofstream(path)
      << "speed[km/h],alpha,slip_ratio,r_e,gamma,R,load,Fy\n36,0,0,0.3,0,0.05,5,1\n";
  DatasetReadOptions o;
  o.columns.canonical_to_header = {{"V", "speed"}, {"Fz", "load"}};
  const Dataset d = load_wheel_csv(path, o);
  EXPECT_EQ(d.v_x[0], 0.0);
  EXPECT_EQ(d.N[0], 5.0);
}

TEST_F(WheelForm, ContactRadiusMayComeFromTheOptions) {
  const std::string path = dir_ / "noR.csv";
  std::ofstream(path) << "V,alpha,slip_ratio,r_e,gamma,Fz,Fy\n10,0,0,0.3,0,4000,1\n";
  DatasetReadOptions o;
  o.contact_radius = 0.04;
  EXPECT_EQ(load_wheel_csv(path, o).R[0], 0.04);
  EXPECT_THROW(load_wheel_csv(path, DatasetReadOptions{}), InputError);
}

// --- bad input: file:line:column and the reason -------------------------------------------

TEST_F(WheelForm, SlipRatioWithZeroSpeedIsRejectedAtItsField) {
  const InputError e = error(std::string(kHeader) + "10,0,0,0.3,0,0,0.05,4000,1,0,0,0,0\n" +
                             "0,0,0.1,0.3,0,0,0.05,4000,1,0,0,0,0\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.column(), 3u);
  EXPECT_NE(e.message().find("V = 0"), std::string::npos) << e.what();
}

TEST_F(WheelForm, NonPositiveRollingRadiusIsRejectedAtItsField) {
  for (const char* re : {"0", "-0.3"}) {
    const InputError e =
        error(std::string(kHeader) + "10,0,0.1," + re + ",0,0,0.05,4000,1,0,0,0,0\n");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.column(), 4u);
    EXPECT_NE(e.message().find("effective rolling radius"), std::string::npos) << e.what();
  }
}

TEST_F(WheelForm, SlipAngleOfNinetyDegreesOrMoreIsRejectedAtItsField) {
  for (const char* alpha : {"90", "-90", "120"}) {
    const InputError e = error("V,alpha[deg],slip_ratio,r_e,gamma,R,Fz,Fy\n10," +
                               std::string(alpha) + ",0,0.3,0,0.05,4000,1\n");
    EXPECT_EQ(e.line(), 2u) << alpha;
    EXPECT_EQ(e.column(), 2u) << alpha;
    EXPECT_NE(e.message().find("between -90 and 90 deg"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(read("V,alpha[deg],slip_ratio,r_e,gamma,R,Fz,Fy\n10,89.9,0,0.3,0,0.05,4000,1\n"));
}

TEST_F(WheelForm, NonPositiveNormalForceIsRejectedInIsoAxes) {
  for (const char* fz : {"0", "-4000"}) {
    const InputError e = error(std::string(kHeader) + "10,0,0,0.3,0,0,0.05," + fz + ",1,0,0,0,0\n");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.column(), 8u);
    EXPECT_NE(e.message().find("--axes sae"), std::string::npos) << e.what();
  }
}

TEST_F(WheelForm, NonNegativeNormalForceIsRejectedInSaeAxes) {
  for (const char* fz : {"0", "4000"}) {
    const InputError e =
        error(std::string(kHeader) + "10,0,0,0.3,0,0,0.05," + fz + ",1,0,0,0,0\n", Axes::Sae);
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.column(), 8u);
    EXPECT_NE(e.message().find("--axes iso"), std::string::npos) << e.what();
  }
}

TEST_F(WheelForm, AUnitOfTheWrongQuantityIsRejectedAtItsHeaderField) {
  const InputError e =
      error("V,alpha[kN],slip_ratio,r_e,gamma,R,Fz,Fy\n10,0,0,0.3,0,0.05,4000,1\n");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_EQ(e.column(), 2u);
  EXPECT_NE(e.message().find("rad, deg"), std::string::npos) << e.what();
}

TEST_F(WheelForm, AnUnknownUnitIsRejectedAtItsHeaderField) {
  const InputError e =
      error("V[knots],alpha,slip_ratio,r_e,gamma,R,Fz,Fy\n10,0,0,0.3,0,0.05,4000,1\n");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_EQ(e.column(), 1u);
  EXPECT_NE(e.message().find("m/s, km/h, mph"), std::string::npos) << e.what();
}

TEST_F(WheelForm, NegativeSpeedIsRejected) {
  const InputError e = error(std::string(kHeader) + "-1,0,0,0.3,0,0,0.05,4000,1,0,0,0,0\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.column(), 1u);
}

TEST_F(WheelForm, MissingColumnsAreNamedWithAHint) {
  const InputError e = error("V,Alpha,slip_ratio,r_e,gamma,R,Fy\n10,0,0,0.3,0,0.05,1\n");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_NE(e.message().find("alpha, Fz"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("did you mean 'alpha'"), std::string::npos) << e.what();
}

TEST_F(WheelForm, AnEmptyKinematicFieldIsRejected) {
  const InputError e = error(std::string(kHeader) + "10,0,0,0.3,,0,0.05,4000,1,0,0,0,0\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.column(), 5u);
}

TEST_F(WheelForm, NeitherSlipRatioNorWheelSpinIsRejected) {
  const InputError e =
      error("V,alpha,slip_ratio,omega_w,r_e,gamma,R,Fz,Fy\n10,0,,,0.3,0,0.05,4000,1\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.column(), 3u);
}

TEST_F(WheelForm, ANumberOutOfRangeAfterItsUnitIsRejected) {
  const InputError e =
      error("V,alpha,slip_ratio,r_e,gamma,R,Fz[kN],Fy\n10,0,0,0.3,0,0.05,1e306,1\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.column(), 7u);
  EXPECT_NE(e.message().find("out of range"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace frictionid::wheel_form_test
