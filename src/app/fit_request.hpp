// A FitRequest turned into the identification layer's FitSettings, with every check a fit makes
// before it reads data (docs/design.md §3.5), and the fit of a loaded dataset.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>
#include "app/requests.hpp"

namespace frictionid::app {

// The global stage seeds NLopt, which keeps only 32 bits of a seed: larger seeds are rejected
// instead of aliasing another seed.
inline constexpr unsigned long long kMaxFitSeed = 4'294'967'295ULL;

// Throws InputError on bad values, naming the option (e.g. "--fix"). lenient: fixed, bounded or
// started parameters that the model does not use are ignored (compare applies one request to
// several models) instead of rejected.
// The spot (r.contact) is checked as for eval (app::checked_contact); h_y is held at 0 on the
// circle and fitted on any other spot, q held at the spot's Q, unless --fix or --free (r.free)
// say otherwise; a fixed or starting tilt must keep the pressure >= 0 on the spot.
FitSettings fit_settings(const FitRequest& r, const std::string& model, bool lenient = false);

// The settings for fitting `data`: fit_settings, and h_y fitted on the circle too when the data
// measure M_tilt and the fit takes that channel (unless --fix holds it). What a fit runs with;
// fit_settings alone checks a request before its data are read.
FitSettings fit_settings(const FitRequest& r, const std::string& model, const Dataset& data,
                         bool lenient = false);

// The request's files besides its data whose bytes a report fingerprints: a pressure map.
std::vector<std::string> request_input_files(const FitRequest& r);

// Fits `data` with `s`; a dataset the fit rejects (std::invalid_argument) becomes an InputError
// naming the data's source, as for a file the reader rejects. FitError passes through.
FitResult fit_dataset(const FitSettings& s, const Dataset& data, FitObserver* observer);

// Per channel, row by row, the sigma the final fit divided each residual by (a sigma column, the
// estimated noise model's sigma, or the channel's fixed scale; NaN where the row does not
// measure the channel); empty for channels not fitted.
using RowSigmas = std::array<std::vector<double>, kChannelCount>;

// fit_dataset that also hands back the row sigmas (Python's whitened residuals).
FitResult fit_dataset(const FitSettings& s, const Dataset& data, FitObserver* observer,
                      RowSigmas& sigma);

}  // namespace frictionid::app
