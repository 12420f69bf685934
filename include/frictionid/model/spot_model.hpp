// The exact model on any contact spot (docs/physics.md §9): the pressure
// sigma = c sigma0 (1 + h x/R + h_y y/R), c fixed by ∫sigma dS = N, and the anisotropic Coulomb
// law integrated about the instantaneous centre of rotation (spot_integrals.hpp). The circle
// keeps the ring-reduced model (exact_model.hpp), which this reproduces at q = 1.
//
// f, kappa, h and h_y enter only through sums of precomputed integrals, so they are of any
// scalar type. The integrals depend on the aspect q and on a power law's exponent n; when those
// are dual numbers with derivative parts (a fit that frees q or n) their slopes come from central
// differences of the integrals (relative accuracy ~1e-9, ample for a Jacobian). Derivatives
// along the kinematics (velocities that are dual numbers of T) differentiate the spot's table.
#pragma once

#include <cmath>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/exact_model.hpp>
#include <frictionid/model/kinematics.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/scalar_ops.hpp>
#include <frictionid/model/spot_integral_cache.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/spot_point_integrator.hpp>

namespace frictionid::model {

template <typename T>
struct SpotParams {
  T f;      // friction coefficient along x
  T kappa;  // anisotropy: kappa f along y
  T h;      // pressure tilt along x (per R)
  T h_y;    // pressure tilt along y (per R)
  T q;      // aspect of an ellipse or a rectangle (ignored for the circle and a map)
};

namespace detail {

template <typename T>
bool has_derivative(const T& x) {
  if constexpr (is_dual_number<T>::value) {
    for (int i = 0; i < x.v.size(); ++i)
      if (x.v[i] != 0.0) return true;
  } else {
    (void)x;
  }
  return false;
}

// One integral with its slopes in q and n, as a scalar of type T.
template <typename T>
T with_slopes(double value, double dq, double dn, const T& q, double q0, const T& n, double n0) {
  if constexpr (is_dual_number<T>::value) {
    T r = T(value);
    if (dq != 0.0) r += (q - T(q0)) * dq;
    if (dn != 0.0) r += (n - T(n0)) * dn;
    return r;
  } else {
    (void)dq;
    (void)dn;
    (void)q;
    (void)q0;
    (void)n;
    (void)n0;
    return T(value);
  }
}

}  // namespace detail

// The 12 spot integrals of spot_integrals.hpp as scalars of type T.
template <typename T>
struct SpotIntegralsT {
  T ex[3], ey[3], x_ey[3], y_ex[3];
};

template <typename T>
class SpotModel {
 public:
  SpotModel(const SpotParams<T>& params, PressureLaw<T> law, ContactSpot spot, SpotRules rules = {})
      : p_(params), law_(std::move(law)), spot_(std::move(spot)), rules_(rules) {
    if (spot_.kind == SpotKind::Map && !spot_.map)
      throw std::invalid_argument("a map spot needs its pressure map");
    q_ = spot_.has_aspect() ? p_.q : T(1);
    if (spot_.has_aspect() && !(value_of(q_) > 0.0))
      throw std::invalid_argument("the spot's aspect q must be > 0");
    if (spot_.kind == SpotKind::Circle) {
      circle_ = std::make_unique<ExactModel<T>>(
          FrictionParams<T>{p_.f, p_.kappa, p_.h, p_.h_y, true}, law_);
      return;
    }
    const PressureLaw<double> law_d = value_law(law_);
    integrator_ = std::make_unique<SpotPointIntegrator>(spot_, law_d, value_of(q_), rules_);
    if (detail::has_derivative(q_) && spot_.has_aspect()) {
      const double q0 = value_of(q_), dq = 1e-5 * q0;
      q_minus_ = std::make_unique<SpotPointIntegrator>(spot_, law_d, q0 - dq, rules_);
      q_plus_ = std::make_unique<SpotPointIntegrator>(spot_, law_d, q0 + dq, rules_);
      q_step_ = dq;
    }
    if (law_.kind == PressureKind::Power && detail::has_derivative(law_.n) &&
        spot_.kind != SpotKind::Map) {
      const double n0 = value_of(law_.n), dn = 1e-5 * std::fmax(1.0, n0);
      PressureLaw<double> lo = law_d, hi = law_d;
      lo.n = n0 >= dn ? n0 - dn : n0;
      hi.n = n0 + dn;
      n_minus_ = std::make_unique<SpotPointIntegrator>(spot_, lo, value_of(q_), rules_);
      n_plus_ = std::make_unique<SpotPointIntegrator>(spot_, hi, value_of(q_), rules_);
      n_step_ = hi.n - lo.n;
    }
    moments_ = spot_moments(spot_, law_moments(law_), q_);
    const auto& c = spot_.cache;
    if (c && !q_plus_ && !n_plus_ && c->q() == value_of(q_) &&
        (law_.kind != PressureKind::Power || c->n() == value_of(law_.n)))
      cache_ = c.get();
    const auto& t = spot_.table;
    if (t && !q_plus_ && !n_plus_ && t->matches(spot_, value_of(q_), law_d)) table_ = t.get();
  }

  // k's velocities are doubles, or dual numbers of T itself; those need the spot's table
  // (ContactSpot::table), whose interpolant they differentiate.
  template <typename K = double>
  Resultants<T> operator()(const KinematicsT<K>& k) const {
    static_assert(std::is_same_v<K, double> || std::is_same_v<K, T>,
                  "kinematics are plain numbers or the parameters' own scalar type");
    if (circle_) return (*circle_)(k);
    if (k.tilt_sign < 0.0) return resultants(k, -p_.h, -p_.h_y);
    return resultants(k, p_.h, p_.h_y);
  }

  // The integrals for the centre of rotation at (cx, cy) (units of R), with q- and n-slopes.
  SpotIntegralsT<T> integrals(double cx, double cy) const {
    const SpotIntegrals* cached = cache_ ? cache_->find(cx, cy) : nullptr;
    const SpotIntegrals v = cached ? *cached : table_ ? (*table_)(cx, cy) : (*integrator_)(cx, cy);
    SpotIntegrals dq, dn;
    if (q_plus_) dq = ((*q_plus_)(cx, cy) - (*q_minus_)(cx, cy)) * (1.0 / (2.0 * q_step_));
    if (n_plus_) dn = ((*n_plus_)(cx, cy) - (*n_minus_)(cx, cy)) * (1.0 / n_step_);
    const double q0 = value_of(q_), n0 = value_of(law_.n);
    SpotIntegralsT<T> out;
    for (int w = 0; w < 3; ++w) {
      out.ex[w] = detail::with_slopes(v.ex[w], dq.ex[w], dn.ex[w], q_, q0, law_.n, n0);
      out.ey[w] = detail::with_slopes(v.ey[w], dq.ey[w], dn.ey[w], q_, q0, law_.n, n0);
      out.x_ey[w] = detail::with_slopes(v.x_ey[w], dq.x_ey[w], dn.x_ey[w], q_, q0, law_.n, n0);
      out.y_ex[w] = detail::with_slopes(v.y_ex[w], dq.y_ex[w], dn.y_ex[w], q_, q0, law_.n, n0);
    }
    return out;
  }

 private:
  template <typename K>
  Resultants<T> resultants(const KinematicsT<K>& k, const T& h, const T& h_y) const {
    using std::hypot;
    const SpotMoments<T>& A = moments_;
    // c R^2 = N/(A0 + h Ax + h_y Ay): the pressure scale that carries the load N.
    const T load_area = A.A0 + h * A.Ax + h_y * A.Ay;
    const T scale = T(k.N) / load_area;  // c R^2
    Resultants<T> r;
    r.N = T(k.N);
    r.M_roll = scale * k.R * (A.Ax + h * A.Axx + h_y * A.Axy);
    r.M_tilt = scale * k.R * (A.Ay + h * A.Axy + h_y * A.Ayy);
    const bool at_rest = k.v_x == 0.0 && k.v_y == 0.0 && k.omega == 0.0;
    if (at_rest) {
      r.T_x = r.T_y = r.M_z = T(0);
      return r;
    }
    if (k.omega == 0.0) {
      // Pure sliding: the slip direction is v/|v| everywhere (docs/physics.md (9.7)).
      const K v = hypot(k.v_x, k.v_y), ux = k.v_x / v, uy = k.v_y / v;
      r.T_x = p_.f * k.N * ux;
      r.T_y = p_.f * p_.kappa * k.N * uy;
      r.M_z = p_.f * (p_.kappa * uy * r.M_roll - ux * r.M_tilt);
      return r;
    }
    const auto [cx, cy] = rotation_centre(k.v_x, k.v_y, k.omega, k.R);
    const SpotIntegralsT<T> I = integrals(cx, cy);
    const double s = k.omega > 0.0 ? 1.0 : -1.0;
    const T force = p_.f * scale * s, torque = force * k.R;
    r.T_x = force * (I.ex[0] + h * I.ex[1] + h_y * I.ex[2]);
    r.T_y = force * p_.kappa * (I.ey[0] + h * I.ey[1] + h_y * I.ey[2]);
    r.M_z = torque * (p_.kappa * (I.x_ey[0] + h * I.x_ey[1] + h_y * I.x_ey[2]) -
                      (I.y_ex[0] + h * I.y_ex[1] + h_y * I.y_ex[2]));
    return r;
  }

  // A centre that is a dual number: the table's interpolant differentiated (doubles take the
  // public integrals() above).
  template <typename K>
  SpotIntegralsT<T> integrals(const K& cx, const K& cy) const {
    if (!table_)
      throw std::logic_error("derivatives along the kinematics need the spot's integral table");
    const std::array<K, 12> v = table_->template channels_at<K>(cx, cy);
    return integrals_from_channels<SpotIntegralsT<T>>(v.data());
  }

  static PressureLaw<double> value_law(const PressureLaw<T>& law) {
    PressureLaw<double> d;
    d.kind = law.kind;
    d.n = value_of(law.n);
    d.table = law.table;
    return d;
  }

  SpotParams<T> p_;
  PressureLaw<T> law_;
  ContactSpot spot_;
  SpotRules rules_;
  T q_;
  SpotMoments<T> moments_{};
  std::unique_ptr<ExactModel<T>> circle_;
  std::unique_ptr<SpotPointIntegrator> integrator_, q_minus_, q_plus_, n_minus_, n_plus_;
  const SpotIntegralCache* cache_ = nullptr;  // the fit's rows, when q and n are the cache's
  const SpotIntegralTable* table_ = nullptr;  // the plane, when q and the law are the table's
  double q_step_ = 0.0, n_step_ = 0.0;
};

// One evaluation, for tests and one-off use.
template <typename T>
Resultants<T> spot_resultants(const SpotParams<T>& p, const PressureLaw<T>& law,
                              const ContactSpot& spot, const Kinematics& k, SpotRules rules = {}) {
  return SpotModel<T>(p, law, spot, rules)(k);
}

}  // namespace frictionid::model
