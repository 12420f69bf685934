// One local problem: the rows, channels and whitening to fit, the free parameters and how the
// model is evaluated. In a header of its own, because the statistics, intervals, warnings and
// searches that read a problem need none of the local stage's solver.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <frictionid/fit_settings.hpp>
#include <frictionid/model/ring_integral_table.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>
#include "identify/residuals.hpp"

namespace frictionid {

using ParamVector = std::array<double, kParamCount>;

// Rows, channels and whitening of one problem, the free parameters and how to evaluate them.
struct LocalProblem {
  ResidualRows rows;  // all rows of the problem
  const FitSettings* settings = nullptr;
  std::vector<int> used;  // parameter indices the model reads, in report order
  std::vector<int> free;  // those Ceres moves; the rest come from the start
  int threads = 1;
  // Exact model with a fixed pressure law: its ring integrals tabulated once for the whole fit.
  // Without one, a free exponent n gets a table per pass when the rows make it worth it.
  std::shared_ptr<const model::RingIntegralTable> exact_table;
  // The exact model's radial rule where no table is used (nullptr: its accurate default).
  const std::vector<model::QuadratureNode>* quadrature = nullptr;
};

// Whether the pressure exponent n is among the free parameters (a power law's shape is fitted).
bool exponent_free(const LocalProblem& p);

// The ring-integral table a pass at x uses (nullptr: radial quadrature or a closed form).
std::shared_ptr<const model::RingIntegralTable> pass_table(const LocalProblem& p,
                                                           const ParamVector& x, bool n_slopes);

}  // namespace frictionid
