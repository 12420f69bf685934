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

// The few generic steps that the packet pass of src/identify instantiates with vectors of
// doubles (one row per lane) are forced inline: inside its functions compiled for AVX2 they
// then use 256-bit registers, where an out-of-line copy would be compiled for the baseline
// instruction set and pass its vectors through memory.
#if defined(__GNUC__)
#define FRICTIONID_MODEL_INLINE inline __attribute__((always_inline))
#else
#define FRICTIONID_MODEL_INLINE inline
#endif

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

// cond ? a : b as a D: a plain number, a vector of them (cond a lane mask, a or b may be a plain
// number, broadcast) or a dual number (a plain a or b promoted, with no derivative).
template <typename D, typename C, typename A, typename B>
FRICTIONID_MODEL_INLINE D select(const C& cond, const A& a, const B& b) {
  if constexpr (is_dual_number<D>::value) {
    return cond ? D(a) : D(b);
  } else {
    return cond ? a : b;
  }
}

// c + f s for a plain number (or a vector of them) c and s: the models' "T(c) + f * s", which
// for a dual number costs one product per derivative and no addition of zeros.
template <typename T, typename D>
FRICTIONID_MODEL_INLINE T affine(const D& c, const T& f, const D& s) {
  if constexpr (is_dual_number<T>::value && !is_dual_number<D>::value) {
    T r = f * s;
    r.a = c + r.a;
    return r;
  } else {
    return c + f * s;
  }
}

// |x| for a double, or for each lane of a vector of doubles (GCC/Clang vector extension): the
// sign cleared, -0 included (x + 0 is +0 for either zero).
template <typename D>
FRICTIONID_MODEL_INLINE D magnitude(const D& x) {
  if constexpr (std::is_floating_point_v<D>) {
    return std::fabs(x);
  } else {
    return x < 0.0 ? -x : x + 0.0;
  }
}

// 1/sqrt of every element. A plain loop over doubles: the compiler turns it into packed square
// roots and divisions, two (or more) per instruction.
template <typename E, std::size_t N>
std::array<E, N> inv_sqrt_each(const std::array<E, N>& y) {
  std::array<E, N> r;
  for (std::size_t i = 0; i < N; ++i) {
    if constexpr (std::is_same_v<E, double>) {
      r[i] = 1.0 / std::sqrt(y[i]);
    } else {
      r[i] = inv_sqrt(y[i]);
    }
  }
  return r;
}

}  // namespace frictionid::model
