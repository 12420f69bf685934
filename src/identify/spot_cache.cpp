#include "identify/spot_cache.hpp"

#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <vector>

#include <frictionid/fit_error.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_point_integrator.hpp>
#include <frictionid/model_variant.hpp>

#include "identify/observer_progress.hpp"
#include "identify/row_chunks.hpp"

namespace frictionid {

std::shared_ptr<const model::SpotIntegralCache> spot_cache_for_rows(const Dataset& data,
                                                                    const FitSettings& s,
                                                                    int threads,
                                                                    FitObserver* observer) {
  if (s.model != ModelKind::Exact || s.contact.kind == model::SpotKind::Circle) return nullptr;
  const bool power = s.law.kind == model::PressureKind::Power;
  if (power && !s.params[kN].fixed) return nullptr;
  const double q = s.contact.has_aspect() ? s.params[kQ].initial : 1.0;
  const double n = power ? s.params[kN].initial : s.law.n;
  model::PressureLaw<double> law = s.law;
  if (power) law.n = n;
  const std::size_t rows = data.rows();
  std::size_t spinning_rows = 0;
  for (std::size_t i = 0; i < rows; ++i)
    if (data.omega[i] != 0.0 && std::isfinite(data.omega[i])) ++spinning_rows;
  // Many rows: tabulate the plane of the centre of rotation once and read every row from it
  // (~0.3-0.5 us) instead of integrating each (6-300 us), where the table needs fewer points
  // than the rows (model_variant.hpp, spot_table_budget). The table stays within 3e-11 of the
  // load of the integrals.
  const auto stop = [observer] { return observer != nullptr && observer->cancelled(); };
  std::unique_ptr<const model::SpotIntegralTable> table;
  if (const std::size_t budget = spot_table_budget(s.contact, law, spinning_rows)) {
    const std::function<bool()> count_and_stop =
        table_progress_check(observer, static_cast<long>(budget));
    try {
      table = std::make_unique<const model::SpotIntegralTable>(
          s.contact, law, q, count_and_stop,
          [threads](std::size_t count, const std::function<void(std::size_t)>& work) {
            for_each_chunk(count, threads, work);
          },
          budget);
    } catch (const model::SpotTableBuildStopped&) {
      throw FitError("interrupted");
    } catch (const model::SpotTableOverBudget&) {
      table.reset();  // integrating the rows costs less
    }
  }
  const model::SpotPointIntegrator integrate(s.contact, law, q);

  std::vector<model::SpotIntegrals> values(rows);
  std::vector<std::uint8_t> spinning(rows, 0);
  std::atomic<bool> stopped{false};
  RowsProgress progress(observer, FitStage::ContactRows, static_cast<long>(rows));
  for_each_chunk(chunk_count(rows), threads, [&](std::size_t c) {
    if (stopped.load(std::memory_order_relaxed) || stop()) {
      stopped = true;
      return;
    }
    const std::size_t end = std::min(rows, (c + 1) * kChunkRows);
    progress.at();
    for (std::size_t i = c * kChunkRows; i < end; ++i) {
      if (data.omega[i] == 0.0 || !std::isfinite(data.omega[i])) continue;
      const auto [cx, cy] =
          model::rotation_centre(data.v_x[i], data.v_y[i], data.omega[i], data.R[i]);
      if (!std::isfinite(cx) || !std::isfinite(cy)) continue;
      values[i] = table ? (*table)(cx, cy) : integrate(cx, cy);
      spinning[i] = 1;
    }
    progress.done(end - c * kChunkRows);
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
