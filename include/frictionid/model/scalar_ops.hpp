// Elementary functions the models need, for plain doubles and for dual numbers alike. A dual
// number (an autodiff Jet: value member `a`, derivative vector `v`) gets a direct derivative
// formula where the generic expression would cost several divisions: 1/sqrt(x) through
// sqrt() and operator/ takes three, here one.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace frictionid::model {

template <typename T, typename = void>
struct is_dual_number : std::false_type {};
template <typename T>
struct is_dual_number<T, std::void_t<decltype(std::declval<T>().a), decltype(std::declval<T>().v)>>
    : std::true_type {};

// The value part of a scalar (the number itself for a double).
template <typename T>
double value_of(const T& x) {
  if constexpr (is_dual_number<T>::value) {
    return x.a;
  } else {
    return static_cast<double>(x);
  }
}

// 1/sqrt(x), x > 0.
template <typename T>
T inv_sqrt(const T& x) {
  if constexpr (is_dual_number<T>::value) {
    T r = x;
    r.a = 1.0 / std::sqrt(x.a);
    r.v = x.v * (-0.5 * r.a * r.a * r.a);  // d x^(-1/2) = -x^(-3/2)/2 dx
    return r;
  } else {
    using std::sqrt;
    return T(1) / sqrt(x);
  }
}

// 1/sqrt of every element. A plain loop over doubles: the compiler turns it into packed square
// roots and divisions, two (or more) per instruction.
template <std::size_t N>
std::array<double, N> inv_sqrt_each(const std::array<double, N>& y) {
  std::array<double, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = 1.0 / std::sqrt(y[i]);
  return r;
}

}  // namespace frictionid::model
