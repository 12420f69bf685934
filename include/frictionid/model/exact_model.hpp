// The exact (ring-reduced) model: resultants of the anisotropic Coulomb law integrated over a
// circular spot with tilted pressure sigma = sigma0 (1 + h rho cos theta), any slip direction
// (docs/physics.md §2, general alpha). Construct once per parameter set, evaluate per row.
#pragma once

#include <cmath>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include <frictionid/model/closed_forms.hpp>
#include <frictionid/model/kinematics.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/ring_integral_table.hpp>
#include <frictionid/model/ring_integrals.hpp>
#include <frictionid/model/scalar_ops.hpp>

namespace frictionid::model {

template <typename T>
struct FrictionParams {
  T f;      // friction coefficient along x
  T kappa;  // anisotropy: coefficient kappa f along y
  T h;      // rolling tilt of the pressure (per contact radius)
  // The tilt across the rolling direction, sigma0 (1 + h x/R + h_y y/R) (docs/physics.md §9.2),
  // read only when tilt_y is set: without it every expression is the one of the tilt along x,
  // bit for bit.
  T h_y = T(0);
  bool tilt_y = false;
};

// Combines radial integrals into resultants; shared by the ring quadrature and the fast paths.
template <typename T, typename I, typename K>
Resultants<T> combine_ring_integrals(const FrictionParams<T>& p, const SlipGeometryT<K>& g,
                                     const I& P, const I& Q, const I& S, const I& U, const I& V,
                                     const I& X, const T& force_scale, const T& torque_scale) {
  const K ca = g.cos_alpha, sa = g.sin_alpha;
  const double s = g.spin_sign;
  const T d11 = T(ca * ca) + p.kappa * (sa * sa);
  const T d22 = T(sa * sa) + p.kappa * (ca * ca);
  const T d12 = (p.kappa - T(1)) * (sa * ca);
  Resultants<T> r;
  if (p.tilt_y) {
    // The formulas see the tilt vector through its projections on the slip, h.e_par = h cos a
    // + h_y sin a, and across it, -h.e_perp = h sin a - h_y cos a (linear in the tilt).
    const T h_par = p.h * ca + p.h_y * sa, h_across = p.h * sa - p.h_y * ca;
    const T base = P + h_across * s * S;
    const T tilt = h_par * s * Q;
    const T t_par = force_scale * (d11 * base + d12 * tilt);
    const T t_perp = force_scale * (d12 * base + d22 * tilt);
    r.T_x = t_par * ca - t_perp * sa;
    r.T_y = t_par * sa + t_perp * ca;
    r.M_z = torque_scale *
            (s * (d22 * Q + d11 * S) + h_par * d12 * (X - U) - h_across * (d22 * U - d11 * V));
    return r;
  }
  const T base = P + p.h * (s * sa) * S;  // sliding + tilt-along-slip part
  const T tilt = p.h * (s * ca) * Q;      // tilt across the slip
  const T t_par = force_scale * (d11 * base + d12 * tilt);
  const T t_perp = force_scale * (d12 * base + d22 * tilt);
  r.T_x = t_par * ca - t_perp * sa;
  r.T_y = t_par * sa + t_perp * ca;
  r.M_z = torque_scale *
          (s * (d22 * Q + d11 * S) + p.h * ca * d12 * (X - U) - p.h * sa * (d22 * U - d11 * V));
  return r;
}

template <typename T>
class ExactModel {
 public:
  // With a table (ring_integral_table.hpp) of the same law the ring integrals come from it
  // instead of the radial quadrature: ~50 ns instead of ~4 us per point, and more accurate.
  // Without a table the integrals come from `rule` (default radial_rule(), ~1e-10).
  ExactModel(const FrictionParams<T>& params, PressureLaw<T> law,
             std::shared_ptr<const RingIntegralTable> table = nullptr,
             const std::vector<QuadratureNode>* rule = nullptr)
      : p_(params),
        law_(std::move(law)),
        moments_(law_moments(law_)),
        table_(std::move(table)),
        rule_(rule ? rule : &radial_rule()) {
    turned_ = p_;
    turned_.h = -p_.h;
    turned_.h_y = -p_.h_y;
    if (table_ && (table_->law().kind != law_.kind ||
                   ((law_.kind == PressureKind::Power || law_.kind == PressureKind::Annulus) &&
                    table_->law().n != value_of(law_.n)) ||
                   (law_.kind == PressureKind::Table && table_->law().table != law_.table)))
      throw std::invalid_argument("ring integral table built for another pressure law");
  }

  const LawMoments<T>& moments() const { return moments_; }

  // k's velocities are doubles, or dual numbers of T itself for derivatives along the
  // kinematics (docs/physics.md §10.8): those come from the table, so a model built without one
  // cannot give them.
  template <typename K = double>
  Resultants<T> operator()(const KinematicsT<K>& k) const {
    static_assert(std::is_same_v<K, double> || std::is_same_v<K, T>,
                  "kinematics are plain numbers or the parameters' own scalar type");
    // A row whose tilt is turned (docs/physics.md §9.2) sees -h and -h_y.
    const FrictionParams<T>& p = k.tilt_sign < 0.0 ? turned_ : p_;
    const SlipGeometryT<K> g = slip_geometry(k);
    // c = N/(2 pi R^2 m1) is the pressure scale; forces come in f c R^2, torques in f c R^3.
    const T force_scale = p_.f * k.N / (T(2 * M_PI) * moments_[1]);
    const T torque_scale = force_scale * k.R;
    Resultants<T> r;
    if (g.at_rest) {
      r.T_x = r.T_y = r.M_z = T(0);  // pure rolling: no slip anywhere, no friction to report
    } else if constexpr (!std::is_same_v<K, double>) {
      if (!table_)
        throw std::logic_error(
            "derivatives along the kinematics need the ring-integral table of the exact model");
      const RingIntegrals<T> in = table_integrals(g.eps);
      r = combine_ring_integrals(p, g, in.P, in.Q, in.S, in.U, in.V, in.X, force_scale,
                                 torque_scale);
    } else if (use_hertz_fast_path(k, g)) {
      const AlignedIntegrals a = hertz_aligned_integrals(g.eps);
      r = combine_ring_integrals(p, g, a.P, a.Q, a.J - a.Q, 0.0, 0.0, 0.0, force_scale,
                                 torque_scale);
    } else if (use_uniform_fast_path(k, g)) {
      const AlignedIntegrals a = uniform_aligned_integrals(g.eps);
      r = combine_ring_integrals(p, g, a.P, 0.0, a.J, 0.0, 0.0, 0.0, force_scale, torque_scale);
    } else {
      const RingIntegrals<T> in =
          table_ ? table_integrals(g.eps) : ring_integrals(law_, moments_, g.eps, *rule_);
      r = combine_ring_integrals(p, g, in.P, in.Q, in.S, in.U, in.V, in.X, force_scale,
                                 torque_scale);
    }
    r.M_roll = p.h * k.N * k.R * moments_[3] / (T(2) * moments_[1]);
    if (p.tilt_y) r.M_tilt = p.h_y * k.N * k.R * moments_[3] / (T(2) * moments_[1]);
    r.N = T(k.N);
    return r;
  }

 private:
  // The aligned fast paths leave out the integrals U, V, X, which a tilt across the rolling
  // direction needs even for aligned slip.
  bool aligned_spin(const Kinematics& k, const SlipGeometry& g) const {
    return k.v_y == 0.0 && g.spin_sign != 0.0 && !p_.tilt_y;
  }
  bool use_hertz_fast_path(const Kinematics& k, const SlipGeometry& g) const {
    return law_.kind == PressureKind::Hertz && aligned_spin(k, g) &&
           g.eps <= kHertzClosedFormMaxEps;
  }
  // Uniform has no closed-form p, so the fast path holds only where p is not needed: isotropic,
  // untilted, and for plain doubles (derivatives in kappa or h would need I_Q).
  bool use_uniform_fast_path(const Kinematics& k, const SlipGeometry& g) const {
    if constexpr (std::is_same_v<T, double>) {
      return law_.kind == PressureKind::Uniform && aligned_spin(k, g) && p_.kappa == 1.0 &&
             p_.h == 0.0;
    }
    return false;
  }

  // eps is a double, or a dual number of T (then the table's interpolant is differentiated).
  template <typename E>
  RingIntegrals<T> table_integrals(const E& eps) const {
    if (!(eps < HUGE_VAL)) return sliding_ring_integrals(moments_);
    E v[6], s[6];
    if (law_.kind == PressureKind::Power && table_->has_n_slope()) {
      table_->evaluate(eps, v, s);
      // First order in n about the table's exponent: the value is the table's, the derivative
      // part (zero for a double) follows n.
      const T dn = law_.n - T(table_->law().n);
      return {T(v[0]) + dn * s[0], T(v[1]) + dn * s[1], T(v[2]) + dn * s[2],
              T(v[3]) + dn * s[3], T(v[4]) + dn * s[4], T(v[5]) + dn * s[5]};
    }
    table_->evaluate(eps, v);
    return {T(v[0]), T(v[1]), T(v[2]), T(v[3]), T(v[4]), T(v[5])};
  }

  FrictionParams<T> p_, turned_;  // turned_: h and h_y negated
  PressureLaw<T> law_;
  LawMoments<T> moments_;
  std::shared_ptr<const RingIntegralTable> table_;
  const std::vector<QuadratureNode>* rule_;
};

// Ring quadrature only, no fast paths: the reference the fast paths are tested against.
template <typename T>
Resultants<T> exact_resultants_by_quadrature(const FrictionParams<T>& p, const PressureLaw<T>& law,
                                             const Kinematics& k) {
  const LawMoments<T> mo = law_moments(law);
  const SlipGeometry g = slip_geometry(k);
  const T force_scale = p.f * k.N / (T(2 * M_PI) * mo[1]);
  Resultants<T> r{T(0), T(0), T(0), T(0), T(0)};
  if (!g.at_rest) {
    const RingIntegrals<T> in = ring_integrals(law, mo, g.eps);
    r = combine_ring_integrals(p, g, in.P, in.Q, in.S, in.U, in.V, in.X, force_scale,
                               force_scale * k.R);
  }
  r.M_roll = p.h * k.N * k.R * mo[3] / (T(2) * mo[1]);
  r.N = T(k.N);
  return r;
}

}  // namespace frictionid::model
