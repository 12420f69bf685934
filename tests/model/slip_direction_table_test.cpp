// The friction tabulated over the slip direction at v_x = 0 (model/slip_direction_table.hpp):
// between its samples it follows the exact model to the accuracy of a 4th-order interpolation,
// rows it does not cover go to the model itself, and its derivative along the kinematics is its
// interpolant's own.
#include <frictionid/model/slip_direction_table.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include <frictionid/model/exact_model.hpp>
#include <frictionid/model/pressure_law.hpp>

namespace slip_direction_table_test {
namespace {

using namespace frictionid::model;

struct Exact {
  ExactModel<double> model;
  Resultants<double> operator()(const Kinematics& k) const { return model(k); }
  // Never asked for the rows the table covers; a marker for the others.
  ContactForces slip_slope(const Kinematics&, const Kinematics&) const {
    return {-1.0, -1.0, -1.0};
  }
};

TEST(SlipDirectionTable, FollowsTheModelBetweenItsSamples) {
  const Exact fr{ExactModel<double>({0.8, 1.3, 0.2}, PressureLaw<double>::hertz())};
  const double N = 1000.0, R = 0.05;
  const SlipDirectionTable<Exact> coarse(fr, N, R, 1024), fine(fr, N, R, 4096);
  double worst_coarse = 0.0, worst_fine = 0.0;
  for (int i = 0; i < 997; ++i) {
    const double th = 2.0 * M_PI * (i + 0.37) / 997.0;
    const double speed = 0.3 + 0.01 * i;  // the resultants do not depend on |s|
    const Kinematics k{0.0, speed * std::cos(th), speed * std::sin(th) / R, N, R};
    const Resultants<double> m = fr(k), a = coarse(k), b = fine(k);
    const double scale = 0.8 * N;
    for (const auto& [x, y, z] :
         {std::array<double, 3>{m.T_x, a.T_x, b.T_x}, std::array<double, 3>{m.T_y, a.T_y, b.T_y},
          std::array<double, 3>{m.M_z / R, a.M_z / R, b.M_z / R}}) {
      worst_coarse = std::max(worst_coarse, std::fabs(y - x) / scale);
      worst_fine = std::max(worst_fine, std::fabs(z - x) / scale);
    }
  }
  EXPECT_LT(worst_fine, 1e-6);
  EXPECT_LT(worst_fine, worst_coarse);  // converges with the number of samples
}

TEST(SlipDirectionTable, RowsItDoesNotCoverGoToTheModel) {
  const Exact fr{ExactModel<double>({0.8, 1.0, 0.0}, PressureLaw<double>::uniform())};
  const SlipDirectionTable<Exact> table(fr, 1000.0, 0.05, 256);
  for (const Kinematics& k :
       {Kinematics{0.1, 0.2, 3.0, 1000.0, 0.05}, Kinematics{0.0, 0.2, 3.0, 900.0, 0.05},
        Kinematics{0.0, 0.2, 3.0, 1000.0, 0.06}}) {
    const Resultants<double> a = fr(k), b = table(k);
    EXPECT_EQ(a.T_x, b.T_x);
    EXPECT_EQ(a.T_y, b.T_y);
    EXPECT_EQ(a.M_z, b.M_z);
  }
}

}  // namespace

namespace {

TEST(SlipDirectionTable, ItsSlopeIsTheDerivativeOfItsInterpolant) {
  const Exact fr{ExactModel<double>({0.8, 1.3, 0.2}, PressureLaw<double>::hertz())};
  const double N = 1000.0, R = 0.05;
  const SlipDirectionTable<Exact> table(fr, N, R, 64);  // coarse: the cubic pieces show
  for (int i = 0; i < 199; ++i) {
    const double th = 2.0 * M_PI * (i + 0.29) / 199.0, speed = 0.5 + 0.02 * i;
    const Kinematics k{0.0, speed * std::cos(th), speed * std::sin(th) / R, N, R};
    // Any direction of (v_y, omega); only its part across the slip turns theta.
    const Kinematics dk{0.0, std::cos(3.0 * th), std::sin(5.0 * th) / R, N, R};
    const ContactForces d = table.slip_slope(k, dk);
    const double h = 1e-6;
    const auto at = [&](double t) {
      const Resultants<double> r =
          table(Kinematics{0.0, k.v_y + t * dk.v_y, k.omega + t * dk.omega, N, R});
      return std::array<double, 3>{r.T_x, r.T_y, r.M_z};
    };
    const auto p = at(h), m = at(-h);
    const double got[3] = {d.T_x, d.T_y, d.M_z}, scale[3] = {N, N, N * R};
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(got[j], (p[j] - m[j]) / (2.0 * h), 1e-6 * scale[j] / speed) << th << " " << j;
  }
  // A row the table does not cover (v_x != 0) asks the model.
  const ContactForces other =
      table.slip_slope(Kinematics{0.1, 0.2, 3.0, N, R}, Kinematics{0.0, 1.0, 0.0, N, R});
  EXPECT_EQ(other.T_y, -1.0);
}

}  // namespace
}  // namespace slip_direction_table_test
