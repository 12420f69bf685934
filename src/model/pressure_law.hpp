// Static contact pressure shapes sigma0(rho) (physics.md §1) and their moments
// m_k = ∫_0^1 sigma0(rho) rho^k drho. The exponent n of power:N is of the scalar type T so that
// it can be identified with autodiff; the other laws are fixed shapes.
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "model/pressure_table.hpp"
#include "model/tanh_sinh_rule.hpp"

namespace frictionid::model {

enum class PressureKind { Uniform, Hertz, Parabolic, Power, Table };

template <typename T>
struct PressureLaw {
  PressureKind kind = PressureKind::Hertz;
  T n = T(0.5);  // exponent of (1 - rho^2)^n; meaningful for Power only
  std::shared_ptr<const PressureTable> table;

  static PressureLaw uniform() { return {PressureKind::Uniform, T(0), nullptr}; }
  static PressureLaw hertz() { return {PressureKind::Hertz, T(0.5), nullptr}; }
  static PressureLaw parabolic() { return {PressureKind::Parabolic, T(1), nullptr}; }
  static PressureLaw power(const T& exponent) { return {PressureKind::Power, exponent, nullptr}; }
  static PressureLaw tabulated(std::shared_ptr<const PressureTable> t) {
    return {PressureKind::Table, T(0), std::move(t)};
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
    }
    return T(0);
  }
};

// Moments m_0..m_5 of a law. Closed forms where they exist; the even moments of power:N come
// from m_0 (m_2 = m_0/(2n+3), m_4 = 3 m_0/((2n+3)(2n+5))) with m_0 by quadrature, which keeps
// the code path generic in T (no digamma needed for derivatives with respect to n).
template <typename T>
struct LawMoments {
  T m[6];
  const T& operator[](int k) const { return m[k]; }
};

template <typename T>
T integrate_law(const PressureLaw<T>& law, int power_of_rho) {
  T sum = T(0);
  if (law.kind == PressureKind::Table) {
    // Piecewise: the interpolant is only C^1 at the samples, so integrate segment by segment.
    const auto& x = law.table->nodes();
    std::vector<double> edges;
    if (x.front() > 0.0) edges.push_back(0.0);
    edges.insert(edges.end(), x.begin(), x.end());
    if (edges.back() < 1.0) edges.push_back(1.0);
    for (std::size_t s = 0; s + 1 < edges.size(); ++s) {
      const double a = edges[s], b = edges[s + 1], len = b - a;
      for (const auto& q : fine_rule()) {
        const double rho = a + len * q.from_left;
        const double omr = (1.0 - b) + len * q.from_right;
        sum += T(q.weight * len * std::pow(rho, power_of_rho)) * law(rho, omr);
      }
    }
    return sum;
  }
  for (const auto& q : fine_rule()) {
    sum += T(q.weight * std::pow(q.from_left, power_of_rho)) * law(q.from_left, q.from_right);
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
    case PressureKind::Table:
      for (int k = 0; k < 6; ++k) r.m[k] = integrate_law(law, k);
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
  }
  return "?";
}

}  // namespace frictionid::model
