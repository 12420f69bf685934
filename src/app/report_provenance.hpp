// The provenance a front end hands to the report writers (include/frictionid/io/provenance.hpp):
// the request's command line, its resolved options and the input files' fingerprints.
#pragma once

#include <future>
#include <string>
#include <vector>

#include <frictionid/io/provenance.hpp>

#include "app/requests.hpp"

namespace frictionid::app {

// r.command_line, fit_request_json(r) as the resolved options, and each of `inputs` and the
// request's own files (a pressure map, request_input_files) with its size and SHA-256, read now (a
// file that cannot be read again, such as a FIFO, is named with an empty sha256).
Provenance report_provenance(const FitRequest& r, const std::vector<std::string>& inputs);

// The same on a thread of its own where the calling thread's budget (identify/thread_budget.hpp)
// has one to spare, holding it until done, so that hashing the inputs (9 ms for the 12.8 MB of
// 1e5 rows) overlaps with what the caller does next: a fit's global stage runs on one thread.
// Without a spare thread it is read now. r must outlive the future.
std::future<Provenance> report_provenance_async(const FitRequest& r,
                                                std::vector<std::string> inputs);

}  // namespace frictionid::app
