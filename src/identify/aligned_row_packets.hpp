// The autodiff pass of the closed-form models over four rows at a time, for rows of slip along x
// (v_y = 0: the common case of test-rig data). Each value is a 4-lane vector, one row per lane,
// and each derivative a vector of those: forward-mode autodiff as ceres::Jet does it, with the
// same operations in the same order (no fused multiply-add), so every lane holds the bits the
// Jet of its row would. Only the aligned branch of approximant_resultants (approximants.hpp) and
// the plain least-squares residual (residuals.hpp, no robust loss) are written here; every other
// row takes the scalar path. Included by local_stage.cpp only, which compiles it twice: for the
// baseline instruction set and for AVX2, chosen at run time.
#pragma once

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <immintrin.h>

#include <frictionid/model/approximants.hpp>

#include "identify/residuals.hpp"

// Every function that takes or returns Lanes by value is inlined: no call passes a 32-byte
// vector, so the ABI note GCC gives for them without AVX does not apply (-Wno-psabi, set for
// local_stage.cpp in src/CMakeLists.txt).
namespace frictionid::packets {

#define FRICTIONID_PACKET_INLINE inline __attribute__((always_inline))

constexpr int kLanes = 4;
typedef double Lanes __attribute__((vector_size(kLanes * sizeof(double))));

typedef std::int64_t Mask __attribute__((vector_size(kLanes * sizeof(std::int64_t))));

FRICTIONID_PACKET_INLINE Lanes broadcast(double x) {
  return Lanes{x, x, x, x};
}

// Four consecutive values of a column.
FRICTIONID_PACKET_INLINE Lanes load(const double* x) {
  Lanes r;
  std::memcpy(&r, x, sizeof r);
  return r;
}

// fabs of each lane: the sign bit cleared (-0 too).
FRICTIONID_PACKET_INLINE Lanes abs(Lanes x) {
  const std::int64_t magnitude = 0x7fffffffffffffff;
  return reinterpret_cast<Lanes>(reinterpret_cast<Mask>(x) & magnitude);
}

// Square roots of the four lanes in one instruction. The packet pass runs only where the
// processor has AVX2 (avx2_available) and inside functions compiled for it, where this inlines;
// elsewhere the scalar path is as fast (4-lane vectors on SSE2 are not). By pointer: a 32-byte
// vector by value changes the ABI.
__attribute__((target("avx2"))) inline void sqrt_avx2(const Lanes* x, Lanes* r) {
  *r = reinterpret_cast<Lanes>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(*x)));
}
FRICTIONID_PACKET_INLINE Lanes sqrt(Lanes x) {
  Lanes r;
  sqrt_avx2(&x, &r);
  return r;
}

// Whether this processor has AVX2 and the packets are allowed (allow_row_packets in
// local_stage.hpp; the tests compare the two paths).
inline std::atomic<bool>& row_packets_allowed() {
  static std::atomic<bool> allowed{true};
  return allowed;
}
inline bool avx2_available() {
  return __builtin_cpu_supports("avx2") && row_packets_allowed().load(std::memory_order_relaxed);
}

// A value and its N derivatives, each for four rows.
template <int N>
struct Dual {
  Lanes a;
  std::array<Lanes, N> v;
};

// A parameter as a plain number (the residual-only pass, N = 0).
template <int N>
Dual<N> broadcast(double x) {
  Dual<N> d;
  d.a = broadcast(x);
  for (int k = 0; k < N; ++k) d.v[k] = broadcast(0.0);
  return d;
}

// A parameter (or a product of parameters): the same value and derivatives in every lane.
template <int N, typename Jet>
Dual<N> broadcast(const Jet& j) {
  Dual<N> d;
  d.a = broadcast(j.a);
  for (int k = 0; k < N; ++k) d.v[k] = broadcast(j.v[k]);
  return d;
}

// ceres::Jet's f * g: (f.a g.a, f.a g.v + f.v g.a).
template <int N>
FRICTIONID_PACKET_INLINE Dual<N> mul(const Dual<N>& f, const Dual<N>& g) {
  Dual<N> r;
  r.a = f.a * g.a;
  for (int k = 0; k < N; ++k) r.v[k] = f.a * g.v[k] + f.v[k] * g.a;
  return r;
}

// f * s for a plain number s per lane.
template <int N>
FRICTIONID_PACKET_INLINE Dual<N> mul(const Dual<N>& f, Lanes s) {
  Dual<N> r;
  r.a = f.a * s;
  for (int k = 0; k < N; ++k) r.v[k] = f.v[k] * s;
  return r;
}

// c + f * s: what the models write T(c) + f * s (s = 1: T(c) + f).
template <int N>
FRICTIONID_PACKET_INLINE Dual<N> affine(Lanes c, const Dual<N>& f, Lanes s) {
  Dual<N> r;
  r.a = c + f.a * s;
  for (int k = 0; k < N; ++k) r.v[k] = f.v[k] * s;
  return r;
}

// inv_sqrt of scalar_ops.hpp: 1/sqrt(x), derivative -x^(-3/2)/2.
template <int N>
FRICTIONID_PACKET_INLINE Dual<N> inv_sqrt(const Dual<N>& x) {
  Dual<N> r;
  r.a = 1.0 / sqrt(x.a);
  const Lanes d = -0.5 * r.a * r.a * r.a;
  for (int k = 0; k < N; ++k) r.v[k] = x.v[k] * d;
  return r;
}

// The parameters of one pass, broadcast.
template <int N>
struct PacketParams {
  Dual<N> f, h, a, b, m, p0, fkh, spin;
  double rho_roll = 0.0;
  bool seed = true;
};

template <int N, typename Jet>
PacketParams<N> packet_params(model::ApproximantForm form, const model::ApproximantParams<Jet>& p,
                              const model::ApproximantShape<double>& shape) {
  const model::ApproximantProducts<Jet> pp = model::approximant_products(p, shape);
  PacketParams<N> out;
  out.f = broadcast<N>(p.f);
  out.h = broadcast<N>(p.h);
  out.a = broadcast<N>(p.a);
  out.b = broadcast<N>(p.b);
  out.m = broadcast<N>(p.m);
  out.p0 = broadcast<N>(p.p0);
  out.fkh = broadcast<N>(pp.fkh);
  out.spin = broadcast<N>(pp.spin);
  out.rho_roll = shape.rho_roll;
  out.seed = form == model::ApproximantForm::Seed;
  return out;
}

// Whether row i goes in a packet: slip along x and not at rest (slip_geometry's aligned case).
inline bool packet_row(const Dataset& d, std::size_t i) {
  return d.v_y[i] == 0.0 && !(d.v_x[i] == 0.0 && d.omega[i] == 0.0);
}

// What a packet's residuals need of its four rows (all packet_row), apart from the parameters:
// the slip geometry and, per fitted channel in channel order, the measured value, the weight
// and which lanes measure it. The fit's passes form it for every packet they evaluate; the global
// stage, thousands of evaluations on the same few hundred rows, forms it once (RepeatedCost).
// alignas: outside AVX2 code GCC aligns a 32-byte vector to 16 bytes only, so a heap copy made
// there would not be where the AVX2 code's aligned loads expect it.
struct alignas(32) PacketGeometry {
  Lanes ca_n, s_n, s_nr, nr, y_t0, y_t1, y_p0, y_p1, ph, pc, g_e, g_f, g_g;
  Lanes value[kChannelCount], w[kChannelCount];
  Mask measured[kChannelCount];
};

FRICTIONID_PACKET_INLINE void packet_geometry(const ResidualRows& rows, std::size_t i,
                                              PacketGeometry& g) {
  const Dataset& d = *rows.data;
  // The slip geometry of the four rows as slip_geometry gives it for v_y = 0, lane by lane:
  // u = |omega| R, v = |v_x|, eps = v/u (inf for u = 0), 1/eps = u/v (inf for v = 0).
  const Lanes zero = broadcast(0.0), one = broadcast(1.0), inf = broadcast(HUGE_VAL);
  const Lanes vx = load(&d.v_x[i]), om = load(&d.omega[i]), nn = load(&d.N[i]), rr = load(&d.R[i]);
  const Lanes u = abs(om) * rr, v = abs(vx);
  const Lanes eps = u > zero ? v / u : inf, inv_eps = v > zero ? u / v : inf;
  const Lanes s = om > zero ? one : (om < zero ? -one : zero);
  const Lanes ca = vx < zero ? -one : one;
  const Mask small = eps <= one;
  const Lanes ee = eps * eps, q = small ? zero : inv_eps, inv2 = q * q;
  const Lanes f_t = small ? eps : one;
  g.ca_n = f_t * ca * nn;
  g.s_n = s * nn;
  g.s_nr = s * nn * rr;
  g.nr = nn * rr;
  // y_t = small ? e2 + a : 1 + a inv2; y_p's first factor small ? 1 + b e2 : inv2 + b.
  g.y_t0 = small ? ee : one;
  g.y_t1 = small ? one : inv2;
  g.y_p0 = small ? one : inv2;
  g.y_p1 = small ? ee : one;
  g.ph = small ? eps : q;  // the seed's p_hat factor
  g.pc = small ? one : q;  // the corrected form's
  // g = g_g / sqrt(g_e + m g_f)
  g.g_e = small ? one : inv2;
  g.g_f = small ? ee : one;
  g.g_g = small ? one : q;
  const std::size_t nc = rows.channels.size();
  for (std::size_t j = 0; j < nc; ++j) {
    const int ci = static_cast<int>(rows.channels[j]);
    const std::uint8_t* pr = &d.present[ci][i];
    const Mask m{pr[0] ? -1 : 0, pr[1] ? -1 : 0, pr[2] ? -1 : 0, pr[3] ? -1 : 0};
    g.measured[j] = m;
    // w = 1/sigma (inverse_sigma of residuals.hpp); unmeasured lanes are masked out below.
    const double* sc = rows.sigma_column(rows.channels[j]);
    g.w[j] = sc ? one / load(sc + i) : broadcast(1.0 / rows.scale[ci]);
    g.value[j] = m ? load(&d.value[ci][i]) : zero;
  }
}

// The residuals of a packet, a Dual per fitted channel of `rows` in channel order (lane l: the
// packet's row l). False if a residual or derivative is not finite.
template <int N>
FRICTIONID_PACKET_INLINE bool packet_residuals(const PacketGeometry& g, const ResidualRows& rows,
                                               const PacketParams<N>& p,
                                               Dual<N> (&res)[kChannelCount]) {
  const Lanes zero = broadcast(0.0);
  const Dual<N> y_t = affine(g.y_t0, p.a, g.y_t1);
  const Dual<N> c_p = affine(g.y_p0, p.b, g.y_p1);
  const Dual<N> y_p = p.seed ? mul(c_p, y_t) : c_p;
  const Dual<N> p_hat = p.seed ? mul(inv_sqrt(y_p), g.ph) : mul(p.p0, mul(inv_sqrt(y_p), g.pc));
  const Dual<N> t = mul(inv_sqrt(y_t), g.ca_n);
  // small: inv_sqrt(1 + m e2) as it is; large: q inv_sqrt(inv2 + m), the factor 1 exact.
  const Dual<N> g_aligned = mul(inv_sqrt(affine(g.g_e, p.m, g.g_f)), g.g_g);
  Dual<N> out[kChannelCount];
  out[static_cast<int>(Channel::T_x)] = mul(p.f, t);
  out[static_cast<int>(Channel::T_y)] = mul(p.fkh, mul(p_hat, g.s_n));
  out[static_cast<int>(Channel::M_z)] = mul(p.spin, mul(g_aligned, g.s_nr));
  out[static_cast<int>(Channel::M_roll)] = mul(p.h, g.nr * p.rho_roll);

  // Residuals (model - measured) w; 0 where the channel is not measured.
  const std::size_t nc = rows.channels.size();
  for (std::size_t j = 0; j < nc; ++j) {
    const int ci = static_cast<int>(rows.channels[j]);
    const Mask m = g.measured[j];
    // (pred - value) w where measured, exactly 0 where not, whatever the model gives there.
    Dual<N>& r = res[j];
    r.a = m ? (out[ci].a - g.value[j]) * g.w[j] : zero;
    for (int k = 0; k < N; ++k) r.v[k] = m ? out[ci].v[k] * g.w[j] : zero;
  }
  // Finite everywhere, or the pass fails (Ceres then rejects the step).
  for (std::size_t j = 0; j < nc; ++j) {
    Lanes all = res[j].a * 0.0;
    for (int k = 0; k < N; ++k) all += res[j].v[k] * 0.0;
    for (int l = 0; l < kLanes; ++l)
      if (!(all[l] == 0.0)) return false;
  }
  return true;
}

// The residuals of rows i .. i+3 (all packet_row), as above.
template <int N>
FRICTIONID_PACKET_INLINE bool packet_residuals(const ResidualRows& rows, const PacketParams<N>& p,
                                               std::size_t i, Dual<N> (&res)[kChannelCount]) {
  PacketGeometry g;
  packet_geometry(rows, i, g);
  return packet_residuals(g, rows, p, res);
}

// Rows i .. i+3 (all packet_row): adds each residual's [J r] outer product to the lower triangle
// `gram` ((N+1)(N+2)/2 entries, row by row, a lane per data row) and the squared residuals to
// sum_sq in row order, as the scalar pass would. False if a residual or derivative is not finite.
template <int N>
FRICTIONID_PACKET_INLINE bool packet_rows(const ResidualRows& rows, const PacketParams<N>& p,
                                          std::size_t i, Lanes* gram, double& sum_sq) {
  Dual<N> res[kChannelCount];
  if (!packet_residuals(rows, p, i, res)) return false;
  const std::size_t nc = rows.channels.size();
  for (int l = 0; l < kLanes; ++l)
    for (std::size_t j = 0; j < nc; ++j) sum_sq += res[j].a[l] * res[j].a[l];
  // Lower triangle of [J r]^T [J r], column r last.
  for (std::size_t j = 0; j < nc; ++j) {
    const Dual<N>& r = res[j];
    Lanes col[N + 1];
    for (int k = 0; k < N; ++k) col[k] = r.v[k];
    col[N] = r.a;
    Lanes* g = gram;
    for (int x = 0; x <= N; ++x)
      for (int y = 0; y <= x; ++y) *g++ += col[x] * col[y];
  }
  return true;
}

}  // namespace frictionid::packets
