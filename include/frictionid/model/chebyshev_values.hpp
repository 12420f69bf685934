// T_0(x) .. T_n(x), the Chebyshev polynomials at one point, for the tables' series
// (spot_integral_table.hpp) and the weights of a table law's stretches
// (ellipse_law_integrator.hpp).
#pragma once

namespace frictionid::model {

// The recurrence, its last two terms kept in registers, up to h = ceil(n/2), then
// T_(h+j) = 2 T_h T_j - T_(h-j), independent of each other. The recurrence alone, through the
// array, was one chain of n dependent steps with a store and a load in each: a sixth of a table
// law's build. E: double or a dual number.
template <typename E>
void chebyshev_values(const E& x, int n, E* t) {
  t[0] = E(1.0);
  if (n < 1) return;
  t[1] = x;
  const int h = (n + 1) / 2;
  const E two_x = 2.0 * x;
  E before = t[0], last = x;
  for (int k = 2; k <= h; ++k) {
    const E next = two_x * last - before;
    t[k] = next;
    before = last;
    last = next;
  }
  const E twice = 2.0 * last;
  for (int j = 1; h + j <= n; ++j) t[h + j] = twice * t[j] - t[h - j];
}

}  // namespace frictionid::model
