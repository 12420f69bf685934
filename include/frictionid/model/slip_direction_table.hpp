// The friction of a spot that does not slide along x (v_x = 0, the towed wheel of
// docs/physics.md §10) tabulated over the slip direction theta of (v_y, omega R): the resultants
// are homogeneous of degree 0 in (v_y, omega R), so for a fixed N and R they are functions of
// theta alone. n samples over a full turn, cubic Hermite interpolation with 4th-order
// finite-difference slopes: O(h^4) where the resultants are smooth in theta; near eps = 1 (the
// instantaneous centre on the rim, (eps - 1)^2 ln|eps - 1| in the integrals, §7.3) less. A row
// with v_x != 0, another N or R goes to the model itself.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <frictionid/model/kinematics.hpp>
#include <frictionid/model/shimmy_wheel.hpp>

namespace frictionid::model {

template <typename Friction>
class SlipDirectionTable {
 public:
  SlipDirectionTable(const Friction& friction, double N, double R, int n)
      : friction_(friction), N_(N), R_(R), n_(n), h_(2.0 * M_PI / n) {
    for (int i = 0; i < n; ++i) {
      const double th = h_ * i;
      const Resultants<double> r = friction(Kinematics{0.0, std::cos(th), std::sin(th) / R, N, R});
      values_.push_back({r.T_x, r.T_y, r.M_z});
      if (i == 0) first_ = r;
    }
    slopes_.resize(values_.size());
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        slopes_[at(i)][c] =
            (-value(i + 2, c) + 8.0 * value(i + 1, c) - 8.0 * value(i - 1, c) + value(i - 2, c)) /
            (12.0 * h_);
  }

  Resultants<double> operator()(const Kinematics& k) const {
    if (!tabulated(k)) return friction_(k);
    const Cell c = cell(k);
    const double s = c.s, s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2,
                 h11 = s3 - s2;
    Resultants<double> r = first_;
    double out[3];
    for (int j = 0; j < 3; ++j)
      out[j] = h00 * value(c.i, j) + h10 * h_ * slopes_[at(c.i)][j] + h01 * value(c.i + 1, j) +
               h11 * h_ * slopes_[at(c.i + 1)][j];
    r.T_x = out[0];
    r.T_y = out[1];
    r.M_z = out[2];
    return r;
  }

  // The derivative of (T_x, T_y, M_z) along dk: the interpolant's own, through
  // d theta = (v_y d(omega R) - omega R d v_y)/(v_y^2 + (omega R)^2); the model's elsewhere.
  ContactForces slip_slope(const Kinematics& k, const Kinematics& dk) const {
    if (!tabulated(k) || dk.v_x != 0.0) return friction_.slip_slope(k, dk);
    const Cell c = cell(k);
    const double w = k.omega * R_,
                 dth = (k.v_y * dk.omega * R_ - w * dk.v_y) / (k.v_y * k.v_y + w * w);
    const double s = c.s, s2 = s * s;
    // d/ds of the Hermite basis, then d s/d theta = 1/h.
    const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s,
                 d11 = 3 * s2 - 2 * s;
    double out[3];
    for (int j = 0; j < 3; ++j)
      out[j] = (d00 * value(c.i, j) + d01 * value(c.i + 1, j)) / h_ + d10 * slopes_[at(c.i)][j] +
               d11 * slopes_[at(c.i + 1)][j];
    return {out[0] * dth, out[1] * dth, out[2] * dth};
  }

 private:
  // Rows of this table's N and R with v_x = 0, not at rest (where the friction is undetermined).
  bool tabulated(const Kinematics& k) const {
    return k.v_x == 0.0 && k.N == N_ && k.R == R_ && k.tilt_sign == 1.0 &&
           !(k.v_y == 0.0 && k.omega == 0.0);
  }

  struct Cell {
    int i;     // the sample below theta
    double s;  // where theta lies between it and the next, in [0, 1)
  };
  Cell cell(const Kinematics& k) const {
    double th = std::atan2(k.omega * R_, k.v_y);
    if (th < 0.0) th += 2.0 * M_PI;
    const double x = th / h_;
    int i = static_cast<int>(std::floor(x));
    const double s = x - i;
    if (i >= n_) i -= n_;
    return {i, s};
  }

  std::size_t at(int i) const { return static_cast<std::size_t>(((i % n_) + n_) % n_); }
  double value(int i, int c) const { return values_[at(i)][c]; }

  const Friction& friction_;
  double N_, R_;
  int n_;
  double h_;
  std::vector<std::array<double, 3>> values_;
  std::vector<std::array<double, 3>> slopes_;
  Resultants<double> first_{};
};

}  // namespace frictionid::model
