#include "identify/spot_cache.hpp"

#include <atomic>
#include <cmath>
#include <mutex>
#include <vector>

#include <frictionid/fit_error.hpp>
#include <frictionid/model/spot_integrals.hpp>

#include "identify/row_chunks.hpp"

namespace frictionid {

std::shared_ptr<const model::SpotIntegralCache> spot_cache_for_rows(
    const Dataset& data, const FitSettings& s, int threads, const std::function<bool()>& stop) {
  if (s.model != ModelKind::Exact || s.contact.kind == model::SpotKind::Circle) return nullptr;
  const bool power = s.law.kind == model::PressureKind::Power;
  if (!s.params[kQ].fixed && s.contact.has_aspect()) return nullptr;
  if (power && !s.params[kN].fixed) return nullptr;
  const double q = s.contact.has_aspect() ? s.params[kQ].initial : 1.0;
  const double n = power ? s.params[kN].initial : s.law.n;
  model::PressureLaw<double> law = s.law;
  if (power) law.n = n;
  const model::SpotIntegrator integrate(s.contact, law, q);

  const std::size_t rows = data.rows();
  std::vector<model::SpotIntegrals> values(rows);
  std::vector<std::uint8_t> spinning(rows, 0);
  std::atomic<bool> stopped{false};
  for_each_chunk(chunk_count(rows), threads, [&](std::size_t c) {
    if (stopped.load(std::memory_order_relaxed) || (stop && stop())) {
      stopped = true;
      return;
    }
    const std::size_t end = std::min(rows, (c + 1) * kChunkRows);
    for (std::size_t i = c * kChunkRows; i < end; ++i) {
      if (data.omega[i] == 0.0 || !std::isfinite(data.omega[i])) continue;
      const auto [cx, cy] =
          model::rotation_centre(data.v_x[i], data.v_y[i], data.omega[i], data.R[i]);
      if (!std::isfinite(cx) || !std::isfinite(cy)) continue;
      values[i] = integrate(cx, cy);
      spinning[i] = 1;
    }
  });
  if (stopped) throw FitError("interrupted");
  auto cache = std::make_shared<model::SpotIntegralCache>(q, n);
  cache->reserve(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    if (!spinning[i]) continue;
    const auto [cx, cy] =
        model::rotation_centre(data.v_x[i], data.v_y[i], data.omega[i], data.R[i]);
    cache->insert(cx, cy, values[i]);
  }
  return cache;
}

}  // namespace frictionid
