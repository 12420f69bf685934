// frictionid generate: a synthetic dataset from any model, with its truth.
#include <iostream>

#include "app/generation.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/terminal_observer.hpp"
#include "io/text.hpp"

namespace frictionid::cli {

int run_generate(const app::GenerateRequest& r) {
  app::GeneratedData g;
  if (!run_stoppable(r.progress, r.output,
                     [&](FitObserver& observer) { g = app::generate(r, &observer); }))
    return kExitInterrupted;
  app::write_generated(r, g);
  std::cerr << "frictionid: wrote " << g.data.rows() << " rows to " << text::for_terminal(r.output)
            << (r.truth.empty() ? "" : " and the truth to " + text::for_terminal(r.truth)) << "\n";
  return kExitOk;
}

}  // namespace frictionid::cli
