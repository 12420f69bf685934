// Shared inputs of the contact-spot tests: a seeded uniform generator that does not depend on the
// standard library's distributions, and the pressure laws in two independent descriptions, the
// production PressureLaw and the oracle's RadialLaw (spot_reference.hpp).
#pragma once

#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/pressure_table.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "model/spot_reference.hpp"

namespace frictionid::testing::spot_cases {

// Uniform numbers from the raw 64-bit output of std::mt19937_64 (whose sequence the standard
// fixes), mapped by hand: the same cases on every standard library.
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : g_(seed) {}
  double u01() { return static_cast<double>(g_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double in(double a, double b) { return a + (b - a) * u01(); }
  double log_in(double a, double b) { return std::exp(in(std::log(a), std::log(b))); }
  double sign() { return u01() < 0.5 ? -1.0 : 1.0; }
  std::size_t index(std::size_t n) {
    return std::min(n - 1, static_cast<std::size_t>(u01() * static_cast<double>(n)));
  }

 private:
  std::mt19937_64 g_;
};

struct LawCase {
  std::string name;
  spot_ref::RadialLaw ref;
  model::PressureLaw<double> law;
};

// Piecewise linear with kinks at 0.3 and 0.8 and a step up at 0.55. Each run has two samples, so
// the production table's monotone cubic interpolates it as the same straight lines; the last
// value is not 0, so no rim factor is fitted.
inline LawCase kinked_step_table() {
  const std::vector<double> rho = {0.0, 0.3, 0.3, 0.55, 0.55, 0.8, 0.8, 1.0};
  const std::vector<double> sig = {1.0, 0.8, 0.8, 0.5, 1.2, 0.9, 0.9, 0.2};
  return {"table(kinks 0.3, 0.8; step 0.55)", spot_ref::piecewise_linear_law(rho, sig),
          model::PressureLaw<double>::tabulated(
              std::make_shared<const model::PressureTable>(rho, sig))};
}

inline std::vector<LawCase> law_cases() {
  using L = model::PressureLaw<double>;
  return {{"uniform", spot_ref::uniform_law(), L::uniform()},
          {"hertz", spot_ref::hertz_law(), L::hertz()},
          {"parabolic", spot_ref::parabolic_law(), L::parabolic()},
          {"power:0.3", spot_ref::power_law(0.3), L::power(0.3)},
          {"power:1.7", spot_ref::power_law(1.7), L::power(1.7)},
          {"annulus:0.4", spot_ref::annulus_law(0.4), L::annulus(0.4)},
          {"annulus:0.75", spot_ref::annulus_law(0.75), L::annulus(0.75)},
          kinked_step_table()};
}

}  // namespace frictionid::testing::spot_cases
