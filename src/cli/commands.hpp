// The subcommands: each runs one app request (src/app/requests.hpp) and prints what the command
// line prints. Plain functions, so that only main.cpp pays for CLI11. Each returns the process
// exit code (exit_codes.hpp).
#pragma once

#include "app/requests.hpp"

namespace frictionid::cli {

int run_coefficients(const app::CoefficientsRequest& r, const std::string& format);
int run_eval(const app::EvalRequest& r);
int run_generate(const app::GenerateRequest& r);
int run_fit(const app::FitRequest& r);
int run_compare(const app::CompareRequest& r);
int run_batch(const app::BatchRequest& r);
int run_simulate(const app::SimulateRequest& r);
int run_shimmy(const app::ShimmyRequest& r);

}  // namespace frictionid::cli
