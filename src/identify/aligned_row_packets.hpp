// The autodiff pass of the closed-form models over four rows at a time, for rows of slip along x
// (v_y = 0: the common case of test-rig data). Each value is a 4-lane vector, one row per lane,
// and each derivative a vector of those: forward-mode autodiff as ceres::Jet does it, with the
// same operations in the same order (no fused multiply-add), so every lane holds the bits the
// Jet of its row would. The physics is not written here: the model's own templates
// (axis_slip in kinematics.hpp; eps_factors, axis_row and axis_resultants in approximants.hpp)
// are instantiated with vectors for the plain numbers and Dual below for the dual numbers. This
// file adds the vector arithmetic and the plain least-squares residual (residuals.hpp, no
// robust loss); every other row takes the scalar path. Compiled only where the compiler targets
// x86-64 (chunk_kernels.hpp), inside functions compiled for AVX2 and chosen at run time.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <immintrin.h>

#include <frictionid/model/approximants.hpp>

#include "identify/residuals.hpp"

// Every function that takes or returns Lanes by value is inlined: no call passes a 32-byte
// vector, so the ABI note GCC gives for them without AVX does not apply (-Wno-psabi, set for
// local_stage.cpp, which includes this through chunk_kernels.hpp, in src/CMakeLists.txt).
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

// Square roots of the four lanes in one instruction. The packet pass runs only where the
// processor has AVX2 (chunk_kernels.hpp) and inside functions compiled for it, where this inlines;
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
FRICTIONID_PACKET_INLINE Dual<N> operator*(const Dual<N>& f, const Dual<N>& g) {
  Dual<N> r;
  r.a = f.a * g.a;
  for (int k = 0; k < N; ++k) r.v[k] = f.a * g.v[k] + f.v[k] * g.a;
  return r;
}

// f * s for a plain number s per lane.
template <int N>
FRICTIONID_PACKET_INLINE Dual<N> operator*(const Dual<N>& f, const Lanes& s) {
  Dual<N> r;
  r.a = f.a * s;
  for (int k = 0; k < N; ++k) r.v[k] = f.v[k] * s;
  return r;
}

// inv_sqrt of scalar_ops.hpp: 1/sqrt(x), derivative -x^(-3/2)/2. Found by argument-dependent
// lookup from the model's templates, and preferred there to the generic one as more specialised.
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
  model::ApproximantForm form = model::ApproximantForm::Seed;
  model::ApproximantParams<Dual<N>> p;
  model::ApproximantProducts<Dual<N>> pp;
  double rho_roll = 0.0;
};

template <int N, typename Jet>
PacketParams<N> packet_params(model::ApproximantForm form, const model::ApproximantParams<Jet>& p,
                              const model::ApproximantShape<double>& shape) {
  const model::ApproximantProducts<Jet> pp = model::approximant_products(p, shape);
  PacketParams<N> out;
  out.form = form;
  out.p = {broadcast<N>(p.f), broadcast<N>(p.kappa), broadcast<N>(p.h), broadcast<N>(p.a),
           broadcast<N>(p.b), broadcast<N>(p.m),     broadcast<N>(p.p0)};
  out.pp = {broadcast<N>(pp.fkh), broadcast<N>(pp.spin)};
  out.rho_roll = shape.rho_roll;
  return out;
}

// Whether row i goes in a packet: slip along x and not at rest (slip_geometry's aligned case).
// A row whose tilt is turned (tilt_sign -1) takes the scalar path.
inline bool packet_row(const Dataset& d, std::size_t i) {
  return d.v_y[i] == 0.0 && !(d.v_x[i] == 0.0 && d.omega[i] == 0.0) && d.tilt_sign_at(i) > 0.0;
}

// What a packet's residuals need of its four rows (all packet_row), apart from the parameters:
// the slip geometry and, per fitted channel in channel order, the measured value, the weight
// and which lanes measure it. The fit's passes form it for every packet they evaluate; the global
// stage, thousands of evaluations on the same few hundred rows, forms it once (RepeatedCost).
// alignas: outside AVX2 code GCC aligns a 32-byte vector to 16 bytes only, so a heap copy made
// there would not be where the AVX2 code's aligned loads expect it.
struct alignas(32) PacketGeometry {
  model::EpsFactors<Lanes> eps;
  model::AxisRow<Lanes> row;
  Lanes value[kChannelCount], w[kChannelCount];
  Mask measured[kChannelCount];
};

FRICTIONID_PACKET_INLINE void packet_geometry(const ResidualRows& rows, std::size_t i,
                                              PacketGeometry& g) {
  const Dataset& d = *rows.data;
  const Lanes vx = load(&d.v_x[i]), om = load(&d.omega[i]), nn = load(&d.N[i]), rr = load(&d.R[i]);
  const model::AxisSlip<Lanes> slip = model::axis_slip(vx, om, rr);
  g.eps = model::eps_factors(slip.eps, slip.inv_eps);
  g.row = model::axis_row(g.eps, slip.cos_alpha, slip.spin_sign, nn, rr);
  const Lanes zero = broadcast(0.0), one = broadcast(1.0);
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
  const model::AxisResultants<Dual<N>> a = model::axis_resultants(p.form, p.p, p.pp, g.eps, g.row);
  Dual<N> out[kChannelCount];
  out[static_cast<int>(Channel::T_x)] = a.T_x;
  out[static_cast<int>(Channel::T_y)] = a.T_y;
  out[static_cast<int>(Channel::M_z)] = a.M_z;
  out[static_cast<int>(Channel::M_roll)] = model::rolling_moment(p.p.h, g.row.nr, p.rho_roll);

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
