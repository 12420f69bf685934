// Subcommands as plain functions of plain option structs, so that only main.cpp pays for CLI11.
// Each returns the process exit code (exit_codes.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

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

struct GenerateOptions {
  std::string model = "exact";
  std::string pressure = "hertz";
  std::string params;
  std::size_t rows = 600;
  double noise = 0.0;      // relative standard deviation
  double noise_abs = 0.0;  // absolute standard deviation [channel units]
  bool sigma_columns = false;
  unsigned long long seed = 1;
  std::string output, truth;
  double eps_min = 1e-2, eps_max = 1e2;
  std::string loads = "2000,4000,6000";
  double R = 0.05, spin = 2.0;
  std::string slip_angles_deg = "0";
  bool forward_only = false;
};
int run_generate(const GenerateOptions& o);

struct FitOptions {
  std::string data;
  std::string model = "seed";
  std::string pressure = "hertz";
  std::string fix, bounds, initial, loss = "none", channels, columns;
  std::string noise_model = "auto";
  std::string intervals = "model";
  int bootstrap = 0;
  int starts = 4;
  unsigned long long seed = 1;
  long global_evaluations = 3000;
  std::size_t global_subsample = 400;
  bool no_global = false;
  std::string global_algorithm = "crs2";
  int threads = 0;  // 0: every hardware thread; results do not depend on it
  std::string report;
  bool no_wait = false;  // fail instead of waiting when another run holds the report's lock
  bool progress = false;
  std::vector<std::string> plot_x;  // report: channels also against these columns
  std::string color_by;             // report: colours of the collapse plots
};
int run_fit(const FitOptions& o);

struct CompareOptions {
  FitOptions fit;  // everything but --model, applied to every model where it applies
  std::string models = "seed,corrected,exact";
};
int run_compare(const CompareOptions& o);

struct BatchOptions {
  FitOptions fit;  // fit.data unused; fit.threads is used per fit only with --jobs 1
  std::vector<std::string> inputs;       // CSV files, globs, directories or manifests
  std::string group_by;                  // split each file by these columns: COL[,COL]
  std::string per_run_reports = "json";  // none, json or full
  bool force = false;                    // fit every run again, whatever the journal holds
  int jobs = 0;                          // runs fitted at once; 0: every hardware thread
  std::string shared;                    // P[,P]: parameters common to every run (joint fit)
  std::string trend_x = "mean_N";        // the covariate on summary.html's trend plots' x axis
  bool warm_start = false;  // runs after the first start from its fit (no global stage)
};
int run_batch(const BatchOptions& o);

struct SimulateOptions {
  std::string model = "exact";
  std::string pressure = "uniform";  // a flat rigid body on a plane
  std::string params;
  std::optional<double> inertia_ratio;  // I/(M_b R^2), required
  double v0 = 1.0, omega0 = 1.0, slip_angle_deg = 0.0;
  double mass = 1.0, R = 1.0;
  std::optional<double> N;  // default M_b g
  std::string output;
  double tol = 1e-10, stop_fraction = 1e-12;
  long max_steps = 200000;
};
int run_simulate(const SimulateOptions& o);

}  // namespace frictionid::cli
