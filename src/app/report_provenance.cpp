// The provenance of a report, from a request (app/report_provenance.hpp).
#include "app/report_provenance.hpp"

#include <exception>
#include <utility>

#include "app/fit_request.hpp"
#include "app/request_json.hpp"
#include "identify/thread_budget.hpp"

namespace frictionid::app {

Provenance report_provenance(const FitRequest& r, const std::vector<std::string>& inputs) {
  Provenance p;
  p.command_line = r.command_line;
  p.options = fit_request_json(r);
  std::vector<std::string> files = inputs;
  for (const auto& path : request_input_files(r)) files.push_back(path);  // a pressure map
  for (const auto& path : files) {
    try {
      p.inputs.push_back(input_file(path));
    } catch (const std::exception&) {
      // A FIFO or a process substitution was read once and has no bytes left to hash; the
      // report still names it (sha256 empty: not fingerprinted).
      p.inputs.push_back(InputFile{path, 0, ""});
    }
  }
  return p;
}

std::future<Provenance> report_provenance_async(const FitRequest& r,
                                                std::vector<std::string> inputs) {
  ThreadBudget* const budget = current_thread_budget();
  if (budget && budget->acquire(1) == 1)
    return std::async(std::launch::async, [&r, budget, inputs = std::move(inputs)] {
      struct Release {
        ThreadBudget* budget;
        ~Release() { budget->release(1); }
      } release{budget};
      return report_provenance(r, inputs);
    });
  std::promise<Provenance> now;
  now.set_value(report_provenance(r, inputs));
  return now.get_future();
}

}  // namespace frictionid::app
