// Ring kernels (docs/physics.md §2): angular integrals over one ring of the contact spot, functions
// of k = eps/rho only. With Delta = sqrt(1 + k^2 - 2k sin(theta)):
//   P = ∫ (k - sin)/Delta,   Q = ∫ cos^2/Delta,   S = ∫ sin (sin - k)/Delta,
//   U = ∫ sin cos^2/Delta,   V = ∫ sin^2 (k - sin)/Delta,   X = P - V = ∫ cos^2 (k - sin)/Delta.
// Closed forms use the associate elliptic integrals B, D (elliptic.hpp) and are rearranged so
// that nothing cancels as k -> 0, k -> inf or k -> 1; for k > 1 the moment map
// mu_n(k) = mu_n(1/k)/k turns every kernel into functions of q = 1/k <= 1.
#pragma once

#include <frictionid/model/elliptic.hpp>

namespace frictionid::model {

template <typename T>
struct RingKernels {
  T P, Q, S, U, V, X;
};

// Kernels for k <= 1, given k, m = k^2 and m1 = 1 - m (to full relative precision).
template <typename T>
RingKernels<T> ring_kernels_inside(const T& k, const T& m, const T& m1) {
  const EllipticParts<T> e = elliptic_parts(m, m1);
  RingKernels<T> r;
  r.P = T(4) * k * e.B;
  r.Q = T(4.0 / 3.0) * (e.B + e.E);
  r.S = T(4.0 / 3.0) * (T(2) * e.E - e.B);
  if (m < 0.5) {
    // Small k: D and B are both near pi/4; their difference enters only through (B - D)/m.
    r.U = T(4.0 / 15.0) * k * (e.b_minus_d_over_m + T(3) * e.D + e.B - T(2) * m * e.D);
    r.V = T(4.0 / 15.0) * k * (e.b_minus_d_over_m + T(6) * e.B - T(2) * e.D + T(3) * m * e.D);
  } else {
    // Near k = 1: D diverges logarithmically but only m1*D appears.
    const T m1d = m1 * e.D;
    r.U = T(4.0 / 15.0) / k * ((T(1) + m) * e.B - (T(1) - T(2) * m) * m1d);
    r.V = T(4.0 / 15.0) / k * ((T(1) + T(6) * m) * e.B - (T(1) + T(3) * m) * m1d);
  }
  r.X = r.P - r.V;
  return r;
}

// Kernels for k >= 1, given q = 1/k, m = q^2 and m1 = 1 - m.
template <typename T>
RingKernels<T> ring_kernels_outside(const T& q, const T& m, const T& m1) {
  const EllipticParts<T> e = elliptic_parts(m, m1);
  RingKernels<T> r;
  r.P = T(4) * e.E;
  r.Q = q * T(4.0 / 3.0) * (e.B + e.E);
  if (m < 0.5) {
    r.S = T(4.0 / 3.0) * q * m * (e.b_minus_d_over_m + e.D);  // O(k^-3), docs/physics.md §2
    r.U = T(4.0 / 15.0) * m * (e.b_minus_d_over_m + T(3) * e.D + e.B - T(2) * m * e.D);
  } else {
    const T m1d = m1 * e.D;
    r.S = T(4.0 / 3.0) * q * (e.B - m1d);
    r.U = T(4.0 / 15.0) * ((T(1) + m) * e.B - (T(1) - T(2) * m) * m1d);
  }
  r.V = T(4.0 / 15.0) * ((T(6) + m) * e.B + m1 * (T(9) + T(2) * m) * e.D);
  r.X = r.P - r.V;
  return r;
}

// Convenience entry for any k >= 0 (m1 computed here; callers near k = 1 should use the two
// functions above with an accurate m1).
template <typename T>
RingKernels<T> ring_kernels(const T& k) {
  if (k <= 1.0) {
    const T m = k * k;
    return ring_kernels_inside(k, m, (T(1) - k) * (T(1) + k));
  }
  const T q = T(1) / k;
  const T m = q * q;
  return ring_kernels_outside(q, m, (T(1) - q) * (T(1) + q));
}

}  // namespace frictionid::model
