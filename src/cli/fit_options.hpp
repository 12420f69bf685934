// Turns the fit options shared by `fit` and `compare` into FitSettings, and the Ctrl-C flag.
#pragma once

#include <atomic>
#include <string>

#include <frictionid/fit_settings.hpp>
#include "cli/commands.hpp"

namespace frictionid::cli {

// Throws InputError on bad values. lenient: --fix/--bounds/--param names that the model does
// not use are ignored (compare applies one option set to several models) instead of rejected.
FitSettings fit_settings_from_options(const FitOptions& o, const std::string& model,
                                      bool lenient = false);

// Whether fits show a progress line: --progress, or stderr is a terminal.
bool show_progress(const FitOptions& o);

// SIGINT, SIGTERM and SIGHUP set the returned flag (io/interruption.hpp): fits stop at their next
// evaluation, and the report stage keeps the earlier report.
const std::atomic<bool>* install_interrupt_handler();

}  // namespace frictionid::cli
