// frictionid eval: the resultants a model predicts, at one point (JSON on stdout) or for every
// row of a file.
#include <iostream>

#include "app/evaluation.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/terminal_observer.hpp"
#include "io/text.hpp"

namespace frictionid::cli {

int run_eval(const app::EvalRequest& r) {
  if (!r.input.empty()) {
    std::size_t rows = 0;
    if (!run_stoppable(r.progress, r.output,
                       [&](FitObserver& observer) { rows = app::evaluate_file(r, &observer); }))
      return kExitInterrupted;
    std::cerr << "frictionid: wrote " << rows << " rows to " << text::for_terminal(r.output)
              << "\n";
    return kExitOk;
  }
  std::cout << app::evaluate_point(r).dump(2) << "\n";
  return kExitOk;
}

}  // namespace frictionid::cli
