// Turns the fit options shared by `fit` and `compare` into FitSettings, and the Ctrl-C flag.
#pragma once

#include <atomic>
#include <string>

#include "cli/commands.hpp"
#include "identify/fit_settings.hpp"

namespace frictionid::cli {

// Throws InputError on bad values. lenient: --fix/--bounds/--param names that the model does
// not use are ignored (compare applies one option set to several models) instead of rejected.
FitSettings fit_settings_from_options(const FitOptions& o, const std::string& model,
                                      bool lenient = false);

// SIGINT/SIGTERM set the returned flag; fits stop at their next evaluation.
const std::atomic<bool>* install_interrupt_handler();

}  // namespace frictionid::cli
