// Static contact pressure shapes sigma0(rho) (docs/physics.md §1) and their moments
// m_k = ∫_0^1 sigma0(rho) rho^k drho. The exponent n of power:N is of the scalar type T so that
// it can be identified with autodiff; the other laws are fixed shapes.
//
// Contacts that carry no load at the centre: annulus:B is uniform on B <= rho <= 1 (a thrust
// collar, a clutch ring), ring puts all load on the rim rho = 1 (the annulus as B -> 1: a delta,
// sigma0 = delta(rho - 1), so m_k = 1 for every k and no radial integral is needed).
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model/scalar_ops.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

namespace frictionid::model {

enum class PressureKind { Uniform, Hertz, Parabolic, Power, Table, Annulus, Ring };

template <typename T>
struct PressureLaw {
  PressureKind kind = PressureKind::Hertz;
  // The shape parameter: exponent of (1 - rho^2)^n for Power, the inner radius B for Annulus
  // (one field, so that every copy of a law keeps its shape).
  T n = T(0.5);
  std::shared_ptr<const PressureTable> table;

  static PressureLaw uniform() { return {PressureKind::Uniform, T(0), nullptr}; }
  static PressureLaw hertz() { return {PressureKind::Hertz, T(0.5), nullptr}; }
  static PressureLaw parabolic() { return {PressureKind::Parabolic, T(1), nullptr}; }
  static PressureLaw power(const T& exponent) { return {PressureKind::Power, exponent, nullptr}; }
  static PressureLaw tabulated(std::shared_ptr<const PressureTable> t) {
    return {PressureKind::Table, T(0), std::move(t)};
  }
  static PressureLaw annulus(double inner) { return {PressureKind::Annulus, T(inner), nullptr}; }
  static PressureLaw ring() { return {PressureKind::Ring, T(0), nullptr}; }

  // The annulus' inner radius B (0 for every other law).
  double inner_radius() const { return kind == PressureKind::Annulus ? value_of(n) : 0.0; }

  // Sorted distinct rho in (0, 1) where sigma0 or one of its derivatives jumps: a radial
  // quadrature must not run across them (docs/physics.md §2 numerics).
  std::vector<double> breakpoints() const {
    if (kind == PressureKind::Table) return table->breakpoints();
    if (kind == PressureKind::Annulus && inner_radius() > 0.0) return {inner_radius()};
    return {};
  }
  // The subset where sigma0 itself jumps.
  std::vector<double> steps() const {
    if (kind == PressureKind::Table) return table->steps();
    return breakpoints();
  }

  // sigma0 at rho; one_minus_rho = 1 - rho to full relative precision (rim behaviour).
  T operator()(double rho, double one_minus_rho) const {
    using std::exp;
    using std::log;
    const double rim = one_minus_rho * (1.0 + rho);  // 1 - rho^2 without cancellation
    switch (kind) {
      case PressureKind::Uniform:
        return T(1);
      case PressureKind::Hertz:
        return T(std::sqrt(rim));
      case PressureKind::Parabolic:
        return T(rim);
      case PressureKind::Power:
        if (rim > 0.0) return T(exp(n * log(rim)));
        return n == 0.0 ? T(1) : T(0);  // (1 - rho^2)^0 = 1 on the rim too
      case PressureKind::Table:
        return T((*table)(rho, one_minus_rho));
      case PressureKind::Annulus:
        return T(rho >= inner_radius() ? 1.0 : 0.0);
      case PressureKind::Ring:
        return T(0);  // no density: every integral of the ring law is taken on rho = 1 itself
    }
    return T(0);
  }
};

// Moments m_0..m_5 of a law. Closed forms where they exist; the even moments of power:N come
// from m_0 (m_2 = m_0/(2n+3), m_4 = 3 m_0/((2n+3)(2n+5))) with m_0 by quadrature, which keeps
// the code path generic in T (no digamma needed for derivatives with respect to n).
// d sigma0/d rho of a law with a density (not the ring law), at 0 < rho < 1; one_minus_rho as
// for the law itself. Steps are not in it (law_jumps).
template <typename T>
double law_slope(const PressureLaw<T>& law, double rho, double one_minus_rho) {
  const double rim = one_minus_rho * (1.0 + rho);
  const double n = value_of(law.n);
  switch (law.kind) {
    case PressureKind::Hertz:
      return -rho / std::sqrt(rim);
    case PressureKind::Parabolic:
      return -2.0 * rho;
    case PressureKind::Power:
      return n == 0.0 ? 0.0 : -2.0 * n * rho * std::exp((n - 1.0) * std::log(rim));
    case PressureKind::Table:
      return law.table->slope(rho, one_minus_rho);
    default:
      return 0.0;
  }
}

// The exponent gamma of sigma0 ~ (1 - rho^2)^gamma at the rim (0: sigma0 stays positive there);
// its slope then grows like (1 - rho^2)^(gamma - 1).
template <typename T>
double law_rim_exponent(const PressureLaw<T>& law) {
  switch (law.kind) {
    case PressureKind::Hertz:
      return 0.5;
    case PressureKind::Parabolic:
      return 1.0;
    case PressureKind::Power:
      return value_of(law.n);
    case PressureKind::Table:
      return law.table->gamma();
    default:
      return 0.0;
  }
}

// Where sigma0 jumps inside the spot, and its value just inside minus just outside.
template <typename T>
std::vector<PressureTable::Jump> law_jumps(const PressureLaw<T>& law) {
  if (law.kind == PressureKind::Table) return law.table->jumps();
  if (law.kind == PressureKind::Annulus && law.inner_radius() > 0.0)
    return {{law.inner_radius(), -1.0}};
  return {};
}

template <typename T>
struct LawMoments {
  T m[6];
  const T& operator[](int k) const { return m[k]; }
};

template <typename T>
T integrate_law(const PressureLaw<T>& law, int power_of_rho) {
  // Piecewise between the law's breakpoints (a table's interpolant is only C^1 at its samples,
  // an annulus jumps at B). Inner pieces are polynomials: Gauss–Legendre integrates them
  // exactly; the rim piece (sigma0 may go like (1 - rho^2)^n there) gets the fine rule.
  std::vector<double> edges = {0.0};
  for (double b : law.breakpoints()) edges.push_back(b);
  edges.push_back(1.0);
  T sum = T(0);
  for (std::size_t s = 0; s + 1 < edges.size(); ++s) {
    const double a = edges[s], b = edges[s + 1], len = b - a;
    for (const auto& q : b < 1.0 ? smooth_piece_rule() : fine_rule()) {
      const double rho = a + len * q.from_left;
      const double omr = (1.0 - b) + len * q.from_right;
      sum += T(q.weight * len * std::pow(rho, power_of_rho)) * law(rho, omr);
    }
  }
  return sum;
}

template <typename T>
LawMoments<T> law_moments(const PressureLaw<T>& law) {
  LawMoments<T> r;
  switch (law.kind) {
    case PressureKind::Uniform:
      for (int k = 0; k < 6; ++k) r.m[k] = T(1.0 / (k + 1));
      return r;
    case PressureKind::Hertz:
      r.m[0] = T(M_PI / 4);
      r.m[1] = T(1.0 / 3);
      r.m[2] = T(M_PI / 16);
      r.m[3] = T(2.0 / 15);
      r.m[4] = T(M_PI / 32);
      r.m[5] = T(8.0 / 105);
      return r;
    case PressureKind::Parabolic:
      for (int k = 0; k < 6; ++k) r.m[k] = T(2.0 / ((k + 1) * (k + 3)));
      return r;
    case PressureKind::Power: {
      const T& n = law.n;
      r.m[0] = integrate_law(law, 0);
      r.m[1] = T(1) / (T(2) * (n + T(1)));
      r.m[2] = r.m[0] / (T(2) * n + T(3));
      r.m[3] = r.m[1] / (n + T(2));
      r.m[4] = T(3) * r.m[2] / (T(2) * n + T(5));
      r.m[5] = T(2) * r.m[3] / (n + T(3));
      return r;
    }
    case PressureKind::Table: {
      // A table's values are data, not parameters: its moments are plain numbers, kept on it.
      const auto& m = law.table->moments([&law] {
        std::array<double, 6> out;
        for (int k = 0; k < 6; ++k) out[k] = value_of(integrate_law(law, k));
        return out;
      });
      for (int k = 0; k < 6; ++k) r.m[k] = T(m[k]);
      return r;
    }
    case PressureKind::Annulus: {
      // (1 - B^(k+1))/(k+1), without cancellation for B near 1.
      const double B = law.inner_radius();
      for (int k = 0; k < 6; ++k)
        r.m[k] = T(B > 0.0 ? -std::expm1((k + 1) * std::log(B)) / (k + 1) : 1.0 / (k + 1));
      return r;
    }
    case PressureKind::Ring:
      for (int k = 0; k < 6; ++k) r.m[k] = T(1);
      return r;
  }
  return r;
}

inline std::string pressure_name(PressureKind kind) {
  switch (kind) {
    case PressureKind::Uniform:
      return "uniform";
    case PressureKind::Hertz:
      return "hertz";
    case PressureKind::Parabolic:
      return "parabolic";
    case PressureKind::Power:
      return "power";
    case PressureKind::Table:
      return "table";
    case PressureKind::Annulus:
      return "annulus";
    case PressureKind::Ring:
      return "ring";
  }
  return "?";
}

}  // namespace frictionid::model
