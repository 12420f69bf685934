// frictionid generate: a synthetic dataset from any model, with its truth.
#include <cstdio>
#include <iostream>

#include <frictionid/fit_error.hpp>

#include "app/generation.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/signals.hpp"
#include "cli/terminal_observer.hpp"
#include "io/text.hpp"

namespace frictionid::cli {

int run_generate(const app::GenerateRequest& r) {
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  app::GeneratedData g;
  try {
    TerminalObserver observer(interrupted, show_progress(r.progress));
    g = app::generate(r, &observer);
  } catch (const FitError&) {
    if (!interrupted->load()) throw;
    std::fprintf(stderr, "frictionid: interrupted; %s not written\n",
                 text::for_terminal(r.output).c_str());
    return kExitInterrupted;
  }
  app::write_generated(r, g);
  std::cerr << "frictionid: wrote " << g.data.rows() << " rows to " << text::for_terminal(r.output)
            << (r.truth.empty() ? "" : " and the truth to " + text::for_terminal(r.truth)) << "\n";
  return kExitOk;
}

}  // namespace frictionid::cli
