// The one interface between identification and physics: a model variant maps a parameter vector
// and one row of kinematics to predicted channels. Every variant reads the same parameter layout;
// parameters a variant does not use are simply never read (and held fixed by the fitter).
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <frictionid/model/approximants.hpp>
#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/exact_model.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/spot_coefficients.hpp>
#include <frictionid/model/spot_model.hpp>
#include <frictionid/parameters.hpp>

namespace frictionid {

// Values the pressure law implies for every parameter (f = 1, kappa = 1, h = 0 unless given):
// a user's --param overrides them; coefficients follow the given kappa.
inline std::array<double, kParamCount> default_parameters(const model::PressureLaw<double>& law,
                                                          double f = 1.0, double kappa = 1.0,
                                                          double h = 0.0) {
  const auto c = model::coefficients(model::law_moments(law), kappa);
  std::array<double, kParamCount> p{};
  p[kF] = f;
  p[kKappa] = kappa;
  p[kH] = h;
  p[kA] = c.a;
  p[kB] = c.b;
  p[kM] = c.m;
  p[kN] = law.kind == model::PressureKind::Power ? law.n : 0.5;
  p[kP0] = c.p0;
  p[kBTilde] = c.b_tilde;
  p[kHy] = 0.0;
  p[kQ] = 1.0;
  return p;
}

// The same for any contact spot: the coefficients by the spot's own slope matching
// (spot_coefficients.hpp) and q from the spot.
inline std::array<double, kParamCount> default_parameters(const model::PressureLaw<double>& law,
                                                          const model::ContactSpot& spot,
                                                          double f = 1.0, double kappa = 1.0,
                                                          double h = 0.0) {
  if (spot.kind == model::SpotKind::Circle) return default_parameters(law, f, kappa, h);
  std::array<double, kParamCount> p = default_parameters(law, f, kappa, h);
  const model::PressureLaw<double>& shape =
      spot.kind == model::SpotKind::Map ? model::PressureLaw<double>::uniform() : law;
  const auto c = model::spot_coefficients(spot, shape, spot.q, kappa);
  p[kA] = c.a;
  p[kB] = c.b;
  p[kM] = c.m;
  p[kP0] = c.p0;
  p[kBTilde] = c.b_tilde;
  p[kQ] = spot.q;
  return p;
}

// Rows from which a tabulated exact model beats the radial quadrature when the table serves one
// pass over the rows only (building one costs as much as ~4000 quadrature points).
inline constexpr std::size_t kRingTableMinRows = 4000;

// A table of law's ring integrals at exponent n (power law; ignored otherwise) for the exact
// variant, with n-slopes if asked; nullptr for the other variants and the ring law (its
// integrals are closed-form kernel values, as cheap as a table). `stop`, when given, may end the
// build early (model::RingTableBuildStopped).
inline std::shared_ptr<const model::RingIntegralTable> ring_table_for(
    ModelKind kind, const model::PressureLaw<double>& law, double n, bool n_slope,
    std::function<bool()> stop = {}, const model::ContactSpot& spot = {}) {
  if (kind != ModelKind::Exact || law.kind == model::PressureKind::Ring ||
      spot.kind != model::SpotKind::Circle)
    return nullptr;
  model::PressureLaw<double> at = law;
  if (at.kind == model::PressureKind::Power) at.n = n;
  return std::make_shared<const model::RingIntegralTable>(at, n_slope, std::move(stop));
}

// The same for one pass over `rows` rows: nullptr where the radial quadrature is cheaper.
inline std::shared_ptr<const model::RingIntegralTable> ring_table_for_rows(
    ModelKind kind, const model::PressureLaw<double>& law, double n, bool n_slope, std::size_t rows,
    const model::ContactSpot& spot = {}) {
  return rows >= kRingTableMinRows ? ring_table_for(kind, law, n, n_slope, {}, spot) : nullptr;
}

// A tabulated spot (spot_integral_table.hpp) against integrating every row. A table's points come
// from the same rays, strips or layers as the rows (an annulus on an ellipse's row costs two: the
// uniform ellipse at c and at c/B); they crowd where the integrals are hardest, next to the rim,
// the edges and a map's grid lines, and cost 0.7-1.7 times a row of a test design. A reading
// costs ~0.3 us (a map's 0.9-1.7 us). The points a table needs range from ~2,400 (ellipse:0.6,
// Hertz) to ~49,000 (a table law of 41 samples on ellipse:0.1) and 68,000 (a rough random
// 20 x 20 map), and a map's build time grows with the square of its cells. So a build is
// attempted with a budget of as many points as the rows would cost (spot_table_budget) and
// abandoned before it would exceed it (model::SpotTableOverBudget): the rows are then integrated,
// and the attempt has cost about what they do. Either way one pass costs at most ~2-3 times the
// cheaper of the two (experiments/README.md, "Contact spots"). Below kSpotTableMinRows rows no
// table is attempted.
inline constexpr std::size_t kSpotTableMinRows = 2000;

inline std::size_t spot_table_budget(const model::ContactSpot& spot,
                                     const model::PressureLaw<double>& law, std::size_t rows) {
  const std::size_t points_per_row =
      spot.kind == model::SpotKind::Ellipse && law.kind == model::PressureKind::Annulus ? 2 : 1;
  const std::size_t most = model::SpotIntegralTable::kMaxPoints;
  if (rows < kSpotTableMinRows) return 0;
  return rows > most / points_per_row ? most : rows * points_per_row;
}

// A table's build, asked before every point, reports its progress every this many points (a fit's
// progress line, shimmy's).
inline constexpr long kTablePointsStep = 4096;

// The spot with its integrals tabulated for the exact variant at aspect q and exponent n (power
// law; ignored otherwise): an ellipse, a rectangle or a map, not the circle (the ring model).
// `threads` as SpotIntegralTable's; `stop` may end the build early
// (model::SpotTableBuildStopped), and a build that would compute more than `max_points` points
// throws model::SpotTableOverBudget.
inline model::ContactSpot spot_with_table(
    ModelKind kind, const model::PressureLaw<double>& law, double q, double n,
    const model::ContactSpot& spot, const std::function<bool()>& stop = {}, int threads = 0,
    std::size_t max_points = model::SpotIntegralTable::kMaxPoints) {
  if (kind != ModelKind::Exact || spot.kind == model::SpotKind::Circle) return spot;
  model::PressureLaw<double> at = law;
  if (at.kind == model::PressureKind::Power) at.n = n;
  if (spot.table && spot.table->matches(spot, q, at)) return spot;
  model::ContactSpot out = spot;
  out.table =
      std::make_shared<const model::SpotIntegralTable>(spot, at, q, stop, threads, max_points);
  return out;
}

// The spot with its table, or as given, integrated point by point, where the table would need
// more than `max_points` points: by default model::SpotIntegralTable::kMaxPoints (a map of
// thousands of cells), for work whose points are not known in advance (simulate, shimmy).
// `stop` and `threads` as spot_with_table's (`stop` is asked before every point: a progress count
// may ride on it).
inline model::ContactSpot spot_with_table_if_bounded(
    ModelKind kind, const model::PressureLaw<double>& law, double q, double n,
    const model::ContactSpot& spot, std::size_t max_points = model::SpotIntegralTable::kMaxPoints,
    const std::function<bool()>& stop = {}, int threads = 0) {
  try {
    return spot_with_table(kind, law, q, n, spot, stop, threads, max_points);
  } catch (const model::SpotTableOverBudget&) {
    return spot;
  }
}

// The same for one pass over `rows` rows: the spot as given where integrating them is cheaper
// (spot_table_budget). The table is built on `threads` threads (0: every hardware thread).
inline model::ContactSpot spot_for_rows(ModelKind kind, const model::PressureLaw<double>& law,
                                        double q, double n, std::size_t rows,
                                        const model::ContactSpot& spot, int threads = 0) {
  const std::size_t budget = spot_table_budget(spot, law, rows);
  return budget == 0 ? spot
                     : spot_with_table_if_bounded(kind, law, q, n, spot, budget, {}, threads);
}

// Evaluates one variant for a fixed parameter vector; construct once, call per row.
template <typename T>
class ModelEvaluator {
 public:
  // table: the law's ring integrals tabulated (exact variant only; see ring_table_for). With a
  // free exponent n and autodiff T it must carry the n-slopes.
  // rule: the radial quadrature without a table (default the exact model's own).
  // spot: the contact spot; anything but the circle needs the exact variant.
  ModelEvaluator(ModelKind kind, const model::PressureLaw<double>& law, const T* params,
                 std::shared_ptr<const model::RingIntegralTable> table = nullptr,
                 const std::vector<model::QuadratureNode>* rule = nullptr,
                 const model::ContactSpot& spot = {})
      : kind_(kind) {
    if (spot.kind != model::SpotKind::Circle) {
      if (kind_ != ModelKind::Exact)
        throw std::invalid_argument(std::string("the ") + model_name(kind_) +
                                    " approximant knows the circular spot only: a non-circular "
                                    "contact needs the exact model");
      spot_ = std::make_unique<model::SpotModel<T>>(
          model::SpotParams<T>{params[kF], params[kKappa], params[kH], params[kHy], params[kQ]},
          promote(law, params), spot);
    } else if (kind_ == ModelKind::Exact) {
      exact_ = std::make_unique<model::ExactModel<T>>(exact_params(params), promote(law, params),
                                                      std::move(table), rule);
    } else {
      shape_ = model::approximant_shape(model::law_moments(law));
      approx_ = {params[kF],
                 params[kKappa],
                 params[kH],
                 params[kA],
                 kind == ModelKind::Seed ? params[kB] : params[kBTilde],
                 params[kM],
                 params[kP0]};
      products_ = model::approximant_products(approx_, shape_);
      turned_ = approx_;
      turned_.h = -approx_.h;
      turned_products_ = model::approximant_products(turned_, shape_);
    }
  }

  // k's velocities are doubles, or dual numbers of T itself for derivatives along the
  // kinematics (the exact variant then needs its table: ring_table_for, spot_with_table).
  template <typename K = double>
  model::Resultants<T> operator()(const model::KinematicsT<K>& k) const {
    // A row whose tilt is turned (docs/physics.md §9.2) sees -h.
    const bool turned = k.tilt_sign < 0.0;
    switch (kind_) {
      case ModelKind::Seed:
        return model::approximant_resultants(model::ApproximantForm::Seed,
                                             turned ? turned_ : approx_,
                                             turned ? turned_products_ : products_, shape_, k);
      case ModelKind::Corrected:
        return model::approximant_resultants(model::ApproximantForm::Corrected,
                                             turned ? turned_ : approx_,
                                             turned ? turned_products_ : products_, shape_, k);
      case ModelKind::Exact:
        return spot_ ? (*spot_)(k) : (*exact_)(k);
    }
    throw std::logic_error("unknown model kind");
  }

 private:
  static model::PressureLaw<T> promote(const model::PressureLaw<double>& law, const T* params) {
    model::PressureLaw<T> out;
    out.kind = law.kind;
    out.table = law.table;
    out.n = law.kind == model::PressureKind::Power ? params[kN] : T(law.n);
    return out;
  }
  // The tilt across the rolling direction is read only when it is in play (a value or a
  // derivative), so that a circle without it takes exactly the path it always took.
  static model::FrictionParams<T> exact_params(const T* p) {
    const bool tilt_y = model::value_of(p[kHy]) != 0.0 || model::detail::has_derivative(p[kHy]);
    return {p[kF], p[kKappa], p[kH], p[kHy], tilt_y};
  }

  ModelKind kind_;
  std::unique_ptr<model::ExactModel<T>> exact_;  // the exact variant on the circle
  std::unique_ptr<model::SpotModel<T>> spot_;    // the exact variant on any other spot
  model::ApproximantShape<double> shape_{};
  model::ApproximantParams<T> approx_{};
  model::ApproximantProducts<T> products_{};
  model::ApproximantParams<T> turned_{};  // h negated, for rows whose tilt is turned
  model::ApproximantProducts<T> turned_products_{};
};

}  // namespace frictionid
