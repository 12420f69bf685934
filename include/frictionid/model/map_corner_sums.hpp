// Corner sums for the twelve spot integrals (spot_integrals.hpp) of a bilinear pressure map
// (docs/physics.md §9.3). With a = x - c_x, e = y - c_y and r = sqrt(a^2 + e^2), the integrands
// are sigma0 {1, x, y, x y, y^2} (-e/r) and sigma0 {1, x, y, x^2, x y} (a/r); in a cell sigma0
// is bilinear, so each is a sum of a^k e^l / r with k, l <= 4. For each (k, l), Phi_kl(a, e) with
// d^2 Phi_kl / da de = a^k e^l / r is a polynomial in a, e and r plus polynomials times
// ln(a + r) and ln(e + r) (scripts/derive-map-corner-primitives derives and checks them, and
// prints the code below). The integral over a cell is Phi at its corners (x1, y1) and (x0, y0)
// minus Phi at (x0, y1) and (x1, y0), exact wherever c lies: inside the cell, on its edge or at
// a corner (where the logarithms' factors vanish and they are taken as 0). The cells around a
// grid node share its Phi: with their sigma0 about the node summed with those signs
// (MapCornerNode), a node costs one square root, two logarithms and ~150 flops.
//
// A cell of side h at distance D contributes ~h^2 D^(k+l-1) through terms of size D^(k+l+1),
// and sigma0's coefficients about c grow as (D/h)^2 too: the sums lose ~(D/h)^4 of the
// precision, so MapStripIntegrator takes them over a window of cells around c only.
#pragma once

#include <cmath>

namespace frictionid::model {

struct MapCornerNode {
  double x, y;                       // the node, units of R
  double alpha, beta, gamma, delta;  // sigma0 about it, alpha + beta dx + gamma dy + delta dx dy,
                                     // summed over its cells with their corners' signs
};

// The moments X_ij = ∫ sigma0 a^i e^j e/r and Y_ij = ∫ sigma0 a^i e^j a/r over the cells whose
// nodes are added, about one centre c. E is double, or PlaneDual (plane_dual.hpp), whose parts
// carry the derivatives along c (a pressure map's table adds the cells next to c this way,
// spot_integral_table.hpp).
template <typename E>
class BasicMapCornerMoments {
 public:
  BasicMapCornerMoments(const E& cx, const E& cy) : cx_(cx), cy_(cy) {}

  void add(const MapCornerNode& n) {
    const E a = n.x - cx_, e = n.y - cy_;
    E g[18];
    primitives(a, e, g);
    // sigma0 about c: A + B a + C e + D a e.
    const E A = n.alpha - n.beta * a - n.gamma * e + n.delta * a * e;
    const E B = n.beta - n.delta * e, C = n.gamma - n.delta * a;
    const double D = n.delta;
    x00_ += A * g[k01] + B * g[k11] + C * g[k02] + D * g[k12];
    x10_ += A * g[k11] + B * g[k21] + C * g[k12] + D * g[k22];
    x01_ += A * g[k02] + B * g[k12] + C * g[k03] + D * g[k13];
    x11_ += A * g[k12] + B * g[k22] + C * g[k13] + D * g[k23];
    x02_ += A * g[k03] + B * g[k13] + C * g[k04] + D * g[k14];
    y00_ += A * g[k10] + B * g[k20] + C * g[k11] + D * g[k21];
    y10_ += A * g[k20] + B * g[k30] + C * g[k21] + D * g[k31];
    y01_ += A * g[k11] + B * g[k21] + C * g[k12] + D * g[k22];
    y20_ += A * g[k30] + B * g[k40] + C * g[k31] + D * g[k41];
    y11_ += A * g[k21] + B * g[k31] + C * g[k22] + D * g[k32];
  }

  // Adds the twelve channels (SpotIntegrals::channels' order) to acc: x = a + c_x, y = e + c_y,
  // e_x = -e/r, e_y = a/r.
  void add_channels(E* acc) const {
    const E cx = cx_, cy = cy_;
    const E ex = -x00_, ex_x = -(x10_ + cx * x00_), ex_y = -(x01_ + cy * x00_);
    const E ex_xy = -(x11_ + cy * x10_ + cx * x01_ + cx * cy * x00_);
    const E ex_yy = -(x02_ + 2.0 * cy * x01_ + cy * cy * x00_);
    const E ey = y00_, ey_x = y10_ + cx * y00_, ey_y = y01_ + cy * y00_;
    const E ey_xx = y20_ + 2.0 * cx * y10_ + cx * cx * y00_;
    const E ey_xy = y11_ + cy * y10_ + cx * y01_ + cx * cy * y00_;
    const E v[12] = {ex, ex_x, ex_y, ey, ey_x, ey_y, ey_x, ey_xx, ey_xy, ex_y, ex_xy, ex_yy};
    for (int k = 0; k < 12; ++k) acc[k] += v[k];
  }

 private:
  // The indices of Phi_kl in primitives()' output.
  // clang-format off
  enum : int { k01, k02, k03, k04, k10, k11, k12, k13, k14, k20, k21, k22, k23, k30, k31, k32,
               k40, k41 };
  // clang-format on

  // ln(u + r) with u + r computed without cancellation (u < 0: (r^2 - u^2)/(r - u)); 0 where it
  // is -infinity, where its factor in every Phi vanishes (the other coordinate is 0).
  static E log_plus(const E& u, const E& v2, const E& r) {
    using std::log;
    if (u >= 0.0) return r > 0.0 ? E(log(u + r)) : E(0.0);
    return v2 > 0.0 ? E(log(v2 / (r - u))) : E(0.0);
  }

  // Phi_kl(a, e), in the order of the enum (scripts/derive-map-corner-primitives).
  static void primitives(const E& a, const E& e, E* phi) {
    using std::sqrt;
    const E a2 = a * a, a3 = a2 * a, a4 = a2 * a2, a5 = a4 * a, a6 = a3 * a3;
    const E e2 = e * e, e3 = e2 * e, e4 = e2 * e2, e5 = e4 * e, e6 = e3 * e3;
    const E r = sqrt(a2 + e2), r3 = r * r * r, r5 = r3 * r * r;
    const E La = log_plus(a, e2, r), Le = log_plus(e, a2, r);
    const E t0 = a * r;
    const E t1 = La * e3;
    const E t2 = Le * a3;
    const E t3 = e * t0;
    const E t4 = La * e4;
    const E t5 = a * r3;
    const E t6 = -2.0 * t5;
    const E t7 = e2 * t0;
    const E t8 = La * e5;
    const E t9 = Le * a5;
    const E t10 = e * r3;
    const E t11 = a * t10;
    const E t12 = 5.0 * e3 * t0;
    const E t13 = e3 * r;
    const E t14 = Le * a4;
    const E t15 = 5.0 * e2 * r3;
    const E t16 = e3 * r3;
    const E t17 = 3.0 * Le * a6 - 3.0 * e * r5 + 3.0 * e5 * r;
    const E t18 = a * r5;
    const E t19 = 3.0 * La * e6 + 3.0 * e4 * t0;
    phi[0] = (1.0 / 2.0) * La * e2 + (1.0 / 2.0) * t0;                 // (0, 1)
    phi[1] = (1.0 / 3.0) * t1 - 1.0 / 6.0 * t2 + (1.0 / 6.0) * t3;     // (0, 2)
    phi[2] = (1.0 / 4.0) * t4 + (1.0 / 12.0) * t6 + (1.0 / 4.0) * t7;  // (0, 3)
    phi[3] =
        -3.0 / 40.0 * t11 + (1.0 / 40.0) * t12 + (1.0 / 5.0) * t8 + (3.0 / 40.0) * t9;  // (0, 4)
    phi[4] = (1.0 / 2.0) * (Le * a2 + e * r);                                           // (1, 0)
    phi[5] = (1.0 / 3.0) * r3;                                                          // (1, 1)
    phi[6] = (1.0 / 8.0) * t10 + (1.0 / 8.0) * t13 - 1.0 / 8.0 * t14;                   // (1, 2)
    phi[7] = -2.0 / 15.0 * r5 + (1.0 / 15.0) * t15;                                     // (1, 3)
    phi[8] = (1.0 / 6.0) * t16 + (1.0 / 48.0) * t17;                                    // (1, 4)
    phi[9] = -1.0 / 6.0 * t1 + (1.0 / 3.0) * t2 + (1.0 / 6.0) * t3;                     // (2, 0)
    phi[10] = -1.0 / 8.0 * t4 - 1.0 / 8.0 * t6 - 1.0 / 8.0 * t7;                        // (2, 1)
    phi[11] = (1.0 / 10.0) * a * e * r3 - 1.0 / 10.0 * t8 - 1.0 / 10.0 * t9;            // (2, 2)
    phi[12] = (5.0 / 18.0) * a * e2 * r3 - 1.0 / 9.0 * t18 - 1.0 / 36.0 * t19;          // (2, 3)
    phi[13] = (1.0 / 12.0) * t10 - 1.0 / 4.0 * t13 + (1.0 / 4.0) * t14;                 // (3, 0)
    phi[14] = (1.0 / 5.0) * r5 - 1.0 / 15.0 * t15;                                      // (3, 1)
    phi[15] = -1.0 / 9.0 * t16 - 1.0 / 36.0 * t17;                                      // (3, 2)
    phi[16] =
        (1.0 / 20.0) * t11 - 1.0 / 40.0 * t12 + (3.0 / 40.0) * t8 + (1.0 / 5.0) * t9;  // (4, 0)
    phi[17] = -7.0 / 24.0 * e2 * t5 + (1.0 / 6.0) * t18 + (1.0 / 48.0) * t19;          // (4, 1)
  }

  E cx_, cy_;
  E x00_ = E(0.0), x10_ = E(0.0), x01_ = E(0.0), x11_ = E(0.0), x02_ = E(0.0);
  E y00_ = E(0.0), y10_ = E(0.0), y01_ = E(0.0), y20_ = E(0.0), y11_ = E(0.0);
};

using MapCornerMoments = BasicMapCornerMoments<double>;

}  // namespace frictionid::model
