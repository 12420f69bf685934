// The loops of the local stage's passes over one chunk of rows (local_stage.cpp), in two sets
// chosen once per process: row by row everywhere, or, where the compiler targets x86-64 (and the
// build is not FRICTIONID_PORTABLE) and the processor has AVX2, compiled for AVX2 with the
// closed-form models' rows of slip along x four at a time (aligned_row_packets.hpp). Both give
// the same residuals and costs to the bit. Included by local_stage.cpp only.
#pragma once

#include <ceres/jet.h>

#include <Eigen/Dense>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

#include "identify/local_stage.hpp"
#include "identify/residuals.hpp"
#include "identify/row_chunks.hpp"

// <immintrin.h> and every function compiled for AVX2 exist only here. FRICTIONID_PORTABLE is
// defined for local_stage.cpp, this header's one includer, by the CMake option of that name.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(FRICTIONID_PORTABLE)
#define FRICTIONID_ROW_PACKETS 1
#include "identify/aligned_row_packets.hpp"
#else
#define FRICTIONID_ROW_PACKETS 0
#endif

namespace frictionid {

inline std::size_t chunk_begin(const LocalProblem& p, std::size_t c) {
  return p.rows.begin + c * kChunkRows;
}
inline std::size_t chunk_end(const LocalProblem& p, std::size_t c) {
  return std::min(chunk_begin(p, c) + kChunkRows, p.rows.end);
}
inline std::size_t problem_chunks(const LocalProblem& p) {
  return chunk_count(p.rows.end - p.rows.begin);
}

// Whether the packet pass may run (allow_row_packets); the tests compare the two paths.
inline std::atomic<bool>& row_packets_allowed() {
  static std::atomic<bool> allowed{true};
  return allowed;
}

// The packet pass's parameters for one pass, or none (it does not apply, or is not built), and
// the packets of a problem's rows with their geometry formed once (RepeatedCost).
#if FRICTIONID_ROW_PACKETS
template <int N>
using PacketArgs = std::optional<packets::PacketParams<N>>;
struct PacketRowCache {
  std::vector<packets::PacketGeometry> geometry;  // in row order
  std::vector<std::int32_t> packet_at;  // per row from rows.begin: its packet's index, or -1
};
#else
template <int N>
struct PacketArgs {};
struct PacketRowCache {};
#endif

namespace chunk_kernels {

// Scalars of a pass: plain doubles for the residual-only pass (N = 0), Jets otherwise.
template <int N>
using Scalar = std::conditional_t<N == 0, double, ceres::Jet<double, N>>;
template <int N>
using Gram = Eigen::Matrix<double, N + 1, N + 1>;
template <int N>
using Block = Eigen::Matrix<double, Eigen::Dynamic, N + 1>;

// One row of each pass, as every kernel computes it where a row does not go in a packet.
// Inlined into the AVX2 kernels too: a call out of a loop with live 256-bit registers costs more
// than the row.
#define FRICTIONID_ROW_INLINE inline __attribute__((always_inline))

FRICTIONID_ROW_INLINE bool sum_row(const LocalProblem& p, const ModelEvaluator<double>& model,
                                   std::size_t i, double& sum) {
  const FitSettings& s = *p.settings;
  double buf[kChannelCount];
  if (!row_residuals(p.rows, model, s.loss, s.loss_scale, i, buf)) return false;
  for (std::size_t j = 0; j < p.rows.channels.size(); ++j) sum += buf[j] * buf[j];
  return true;
}

template <int N>
FRICTIONID_ROW_INLINE bool gram_row(const LocalProblem& p, const ModelEvaluator<Scalar<N>>& model,
                                    std::size_t i, Gram<N>& g, double& sum) {
  const FitSettings& s = *p.settings;
  Scalar<N> buf[kChannelCount];
  if (!row_residuals(p.rows, model, s.loss, s.loss_scale, i, buf)) return false;
  Eigen::Matrix<double, N + 1, 1> v;
  for (std::size_t j = 0; j < p.rows.channels.size(); ++j) {
    v.template head<N>() = buf[j].v;
    v[N] = buf[j].a;
    g.noalias() += v * v.transpose();
    sum += buf[j].a * buf[j].a;
  }
  return true;
}

template <int N>
FRICTIONID_ROW_INLINE bool fill_row(const LocalProblem& p, const ModelEvaluator<Scalar<N>>& model,
                                    std::size_t i, Block<N>& b, Eigen::Index& row, double& sum) {
  const FitSettings& s = *p.settings;
  Scalar<N> buf[kChannelCount];
  if (!row_residuals(p.rows, model, s.loss, s.loss_scale, i, buf)) return false;
  for (std::size_t j = 0; j < p.rows.channels.size(); ++j, ++row) {
    b.template leftCols<N>().row(row) = buf[j].v.transpose();
    b(row, N) = buf[j].a;
    sum += buf[j].a * buf[j].a;
  }
  return true;
}

// The row-by-row kernels. sum: the squared residuals of rows [i0, i1) summed row by row; gram:
// their [J r] Gram matrix added to g; fill: their [J r] rows into b (a row per residual,
// channels in order). Each also gives the sum of squares; false if a residual or derivative is
// not finite.
inline bool sum_rows(const LocalProblem& p, const ModelEvaluator<double>& model,
                     const PacketArgs<0>&, const PacketRowCache*, std::size_t i0, std::size_t i1,
                     double& sum_sq) {
  double sum = 0.0;  // a local: sum_sq may share a cache line with another thread's
  for (std::size_t i = i0; i < i1; ++i)
    if (!sum_row(p, model, i, sum)) return false;
  sum_sq = sum;
  return true;
}

template <int N>
bool gram_rows(const LocalProblem& p, const ModelEvaluator<Scalar<N>>& model, const PacketArgs<N>&,
               std::size_t i0, std::size_t i1, Gram<N>& g, double& sum_sq) {
  double sum = 0.0;
  for (std::size_t i = i0; i < i1; ++i)
    if (!gram_row<N>(p, model, i, g, sum)) return false;
  sum_sq = sum;
  return true;
}

template <int N>
bool fill_rows(const LocalProblem& p, const ModelEvaluator<Scalar<N>>& model, const PacketArgs<N>&,
               std::size_t i0, std::size_t i1, Block<N>& b, double& sum_sq) {
  Eigen::Index row = 0;
  double sum = 0.0;
  for (std::size_t i = i0; i < i1; ++i)
    if (!fill_row<N>(p, model, i, b, row, sum)) return false;
  sum_sq = sum;
  return true;
}

template <int N>
PacketArgs<N> no_packets(const FitSettings&, const Scalar<N>*) {
  return {};
}

inline std::unique_ptr<PacketRowCache> no_cache(const LocalProblem&) {
  return nullptr;
}

#if FRICTIONID_ROW_PACKETS
// The kernels with the packet pass: the same loops, with four rows at a time where the next four
// go in a packet (packet_ahead) and the pass's parameters are given.

// Whether the packet pass applies: a closed-form model without a robust loss.
inline bool packets_apply(const FitSettings& s) {
  return s.model != ModelKind::Exact && s.loss == LossKind::None &&
         row_packets_allowed().load(std::memory_order_relaxed);
}

// The packet pass's parameters where it applies. params: in ParamVector order.
template <int N>
PacketArgs<N> packet_args(const FitSettings& s, const Scalar<N>* params) {
  if (!packets_apply(s)) return std::nullopt;
  const bool seed = s.model == ModelKind::Seed;
  const model::ApproximantParams<Scalar<N>> ap{
      params[kF], params[kKappa], params[kH], params[kA], seed ? params[kB] : params[kBTilde],
      params[kM], params[kP0]};
  return packets::packet_params<N>(
      seed ? model::ApproximantForm::Seed : model::ApproximantForm::Corrected, ap,
      model::approximant_shape(model::law_moments(s.law)));
}

// Whether rows i .. i+3 of [i, end) all go in a packet. Inlined into the AVX2 kernels: a call to
// it, compiled for plain SSE2, from a loop with live 256-bit registers cost some processors (seen
// on AMD Zen 3) more than the packet's arithmetic.
FRICTIONID_PACKET_INLINE bool packet_ahead(const Dataset& d, std::size_t i, std::size_t end) {
  return i + packets::kLanes <= end && packets::packet_row(d, i) && packets::packet_row(d, i + 1) &&
         packets::packet_row(d, i + 2) && packets::packet_row(d, i + 3);
}

// sum_rows; a packet's geometry from `cache` where given.
__attribute__((target("avx2"))) inline bool sum_rows_avx2(
    const LocalProblem& p, const ModelEvaluator<double>& model, const PacketArgs<0>& pp,
    const PacketRowCache* cache, std::size_t i0, std::size_t i1, double& sum_sq) {
  const std::size_t nc = p.rows.channels.size();
  double sum = 0.0;
  for (std::size_t i = i0; i < i1;) {
    if (pp &&
        (cache ? cache->packet_at[i - p.rows.begin] >= 0 : packet_ahead(*p.rows.data, i, i1))) {
      packets::Dual<0> res[kChannelCount];
      const bool finite =
          cache ? packets::packet_residuals(
                      cache->geometry[static_cast<std::size_t>(cache->packet_at[i - p.rows.begin])],
                      p.rows, *pp, res)
                : packets::packet_residuals(p.rows, *pp, i, res);
      if (!finite) return false;
      // Row by row, as the scalar pass adds them.
      for (int l = 0; l < packets::kLanes; ++l)
        for (std::size_t j = 0; j < nc; ++j) sum += res[j].a[l] * res[j].a[l];
      i += packets::kLanes;
    } else {
      if (!sum_row(p, model, i, sum)) return false;
      ++i;
    }
  }
  sum_sq = sum;
  return true;
}

// gram_rows. The packets' outer products go to a lower triangle of lanes, summed into g at the
// end: J^T J and J^T r differ from the row-by-row sums in rounding, the sum of squares not.
template <int N>
__attribute__((target("avx2"))) bool gram_rows_avx2(const LocalProblem& p,
                                                    const ModelEvaluator<Scalar<N>>& model,
                                                    const PacketArgs<N>& pp, std::size_t i0,
                                                    std::size_t i1, Gram<N>& g, double& sum_sq) {
  using packets::Lanes;
  constexpr int kLower = (N + 1) * (N + 2) / 2;
  Lanes lower[kLower];
  for (auto& x : lower) x = packets::broadcast(0.0);
  double sum = 0.0;
  for (std::size_t i = i0; i < i1;) {
    if (pp && packet_ahead(*p.rows.data, i, i1)) {
      if (!packets::packet_rows(p.rows, *pp, i, lower, sum)) return false;
      i += packets::kLanes;
    } else {
      if (!gram_row<N>(p, model, i, g, sum)) return false;
      ++i;
    }
  }
  int k = 0;
  for (int x = 0; x <= N; ++x)
    for (int y = 0; y <= x; ++y, ++k) {
      const double t = (lower[k][0] + lower[k][1]) + (lower[k][2] + lower[k][3]);
      g(x, y) += t;
      if (x != y) g(y, x) += t;
    }
  sum_sq = sum;
  return true;
}

template <int N>
__attribute__((target("avx2"))) bool fill_rows_avx2(const LocalProblem& p,
                                                    const ModelEvaluator<Scalar<N>>& model,
                                                    const PacketArgs<N>& pp, std::size_t i0,
                                                    std::size_t i1, Block<N>& b, double& sum_sq) {
  const std::size_t nc = p.rows.channels.size();
  Eigen::Index row = 0;
  double sum = 0.0;
  for (std::size_t i = i0; i < i1;) {
    if (pp && packet_ahead(*p.rows.data, i, i1)) {
      packets::Dual<N> res[kChannelCount];
      if (!packets::packet_residuals(p.rows, *pp, i, res)) return false;
      for (int l = 0; l < packets::kLanes; ++l)
        for (std::size_t j = 0; j < nc; ++j, ++row) {
          for (int k = 0; k < N; ++k) b(row, k) = res[j].v[k][l];
          b(row, N) = res[j].a[l];
          sum += res[j].a[l] * res[j].a[l];
        }
      i += packets::kLanes;
    } else {
      if (!fill_row<N>(p, model, i, b, row, sum)) return false;
      ++i;
    }
  }
  sum_sq = sum;
  return true;
}

// The packets the passes over p's rows take (packet_ahead within each chunk), with their
// geometry; none where the packet pass does not apply.
__attribute__((target("avx2"))) inline std::unique_ptr<PacketRowCache> cache_packets_avx2(
    const LocalProblem& p) {
  if (!packets_apply(*p.settings)) return nullptr;
  auto cache = std::make_unique<PacketRowCache>();
  cache->packet_at.assign(p.rows.end - p.rows.begin, -1);
  for (std::size_t c = 0; c < problem_chunks(p); ++c) {
    const std::size_t i1 = chunk_end(p, c);
    for (std::size_t i = chunk_begin(p, c); i < i1;) {
      if (packet_ahead(*p.rows.data, i, i1)) {
        cache->packet_at[i - p.rows.begin] = static_cast<std::int32_t>(cache->geometry.size());
        cache->geometry.emplace_back();
        packets::packet_geometry(p.rows, i, cache->geometry.back());
        i += packets::kLanes;
      } else {
        ++i;
      }
    }
  }
  return cache;
}
#endif

// Whether the AVX2 kernels run: built in, and this processor has AVX2 (asked once).
inline bool avx2_kernels() {
#if FRICTIONID_ROW_PACKETS
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return false;
#endif
}

}  // namespace chunk_kernels

// The kernels of the residual-only pass (N = 0) and of the autodiff passes with N free
// parameters, chosen once.
template <int N>
struct ChunkKernels {
  // The packet pass's parameters at a pass's parameter values (none: row by row).
  PacketArgs<N> (*packet_args)(const FitSettings&, const chunk_kernels::Scalar<N>*);
  // N = 0 only.
  bool (*sum)(const LocalProblem&, const ModelEvaluator<double>&, const PacketArgs<0>&,
              const PacketRowCache*, std::size_t, std::size_t, double&);
  std::unique_ptr<PacketRowCache> (*cache)(const LocalProblem&);
  // N > 0 only.
  bool (*gram)(const LocalProblem&, const ModelEvaluator<chunk_kernels::Scalar<N>>&,
               const PacketArgs<N>&, std::size_t, std::size_t, chunk_kernels::Gram<N>&, double&);
  bool (*fill)(const LocalProblem&, const ModelEvaluator<chunk_kernels::Scalar<N>>&,
               const PacketArgs<N>&, std::size_t, std::size_t, chunk_kernels::Block<N>&, double&);
};

template <int N>
const ChunkKernels<N>& chunk_kernels_for() {
  using namespace chunk_kernels;
  static const ChunkKernels<N> kernels = [] {
    ChunkKernels<N> k{no_packets<N>, nullptr, no_cache, nullptr, nullptr};
    if constexpr (N == 0) k.sum = sum_rows;
    if constexpr (N > 0) {
      k.gram = gram_rows<N>;
      k.fill = fill_rows<N>;
    }
#if FRICTIONID_ROW_PACKETS
    if (avx2_kernels()) {
      k.packet_args = packet_args<N>;
      if constexpr (N == 0) {
        k.sum = sum_rows_avx2;
        k.cache = cache_packets_avx2;
      }
      if constexpr (N > 0) {
        k.gram = gram_rows_avx2<N>;
        k.fill = fill_rows_avx2<N>;
      }
    }
#endif
    return k;
  }();
  return kernels;
}

}  // namespace frictionid
