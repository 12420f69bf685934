// A number with its derivatives along the two coordinates of the plane (forward-mode
// differentiation), for the corner sums of map_corner_sums.hpp along the centre of rotation. A
// map's table reads its near cells by those sums; instantiated with the fit's and the
// simulations' dual numbers (ceres Jets of several sizes), each size compiled the sums' eighteen
// primitives again, a third of a fit's local stage to compile under the sanitizers. With this
// one type they are compiled once, and the chain rule carries the two slopes into any dual
// number (SpotIntegralTable::add_near).
#pragma once

#include <cmath>

namespace frictionid::model {

struct PlaneDual {
  double v = 0.0, dx = 0.0, dy = 0.0;  // the value and its derivatives along x and y
  PlaneDual() = default;
  PlaneDual(double value) : v(value) {}  // implicit: a constant
  PlaneDual(double value, double along_x, double along_y) : v(value), dx(along_x), dy(along_y) {}
};

inline PlaneDual operator+(const PlaneDual& a, const PlaneDual& b) {
  return {a.v + b.v, a.dx + b.dx, a.dy + b.dy};
}
inline PlaneDual operator-(const PlaneDual& a, const PlaneDual& b) {
  return {a.v - b.v, a.dx - b.dx, a.dy - b.dy};
}
inline PlaneDual operator-(const PlaneDual& a) {
  return {-a.v, -a.dx, -a.dy};
}
inline PlaneDual operator*(const PlaneDual& a, const PlaneDual& b) {
  return {a.v * b.v, a.dx * b.v + a.v * b.dx, a.dy * b.v + a.v * b.dy};
}
inline PlaneDual operator/(const PlaneDual& a, const PlaneDual& b) {
  const double inverse = 1.0 / b.v, q = a.v * inverse;
  return {q, (a.dx - q * b.dx) * inverse, (a.dy - q * b.dy) * inverse};
}
inline PlaneDual& operator+=(PlaneDual& a, const PlaneDual& b) {
  return a = a + b;
}
inline bool operator>=(const PlaneDual& a, double b) {
  return a.v >= b;
}
inline bool operator>(const PlaneDual& a, double b) {
  return a.v > b;
}

// At 0 (the centre on a grid node, where the distance r to it has a cone) the slope taken is 0,
// where a ceres Jet's would be infinite.
inline PlaneDual sqrt(const PlaneDual& a) {
  const double r = std::sqrt(a.v), half = r > 0.0 ? 0.5 / r : 0.0;
  return {r, a.dx * half, a.dy * half};
}
inline PlaneDual log(const PlaneDual& a) {
  return {std::log(a.v), a.dx / a.v, a.dy / a.v};
}

}  // namespace frictionid::model
