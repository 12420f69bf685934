// The problem a fit solves, set up once from the data and the settings: which channels are
// fitted, how each is whitened, which parameters the model reads and which the solver moves.
#pragma once

#include <string>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>

#include "identify/local_problem.hpp"

namespace frictionid {

// Fills res.channels and res.channel_summaries (with a warning for a requested channel that no
// row measures) and returns the problem over all rows. Throws std::invalid_argument when no
// requested channel is measured.
LocalProblem make_fit_problem(const Dataset& data, const FitSettings& s, FitResult& res);

// The same problem over another dataset (e.g. a subsample), keeping its whitening scales.
LocalProblem problem_on(const LocalProblem& p, const Dataset& rows);

// The starting point: initial values clamped into their bounds, fixed values as given.
ParamVector initial_parameters(const FitSettings& s);

// Where the model or the whitened residual first stops being finite at x, in words ("line 12 of
// data.csv, channel T_x: the model gives inf"), or an empty string when every row is finite.
std::string first_nonfinite_row(const LocalProblem& p, const ParamVector& x);

}  // namespace frictionid
