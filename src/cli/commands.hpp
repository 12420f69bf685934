// Subcommands as plain functions of plain option structs, so that only main.cpp pays for CLI11.
// Each returns the process exit code (exit_codes.hpp).
#pragma once

#include <optional>
#include <string>

namespace frictionid::cli {

struct CoefficientsOptions {
  std::string pressure = "hertz";
  double kappa = 1.0;
  double alpha = 0.0;  // slip direction [rad] for m(alpha)
  std::string format = "json";
};
int run_coefficients(const CoefficientsOptions& o);

struct EvalOptions {
  std::string model = "exact";
  std::string pressure = "hertz";
  std::string params;  // "f=..,kappa=..,h=..,a=..": unspecified ones follow the pressure law
  std::optional<double> vx, vy, omega;
  double N = 1.0, R = 1.0;
  std::string input, output, columns;
};
int run_eval(const EvalOptions& o);

}  // namespace frictionid::cli
