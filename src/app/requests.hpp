// What a user asks of frictionid, as typed values: the command line parses argv into these
// requests (src/cli), the Python package builds them from keyword arguments (src/python). Each is
// validated once, by the app layer, with the same messages whichever front end built it
// (docs/design.md §1).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <frictionid/io/dataset_csv.hpp>

namespace frictionid::app {

// Parameter name -> value ("f", "kappa", "h", "a", ...).
using ParameterValues = std::map<std::string, double>;
// Parameter name -> (lower, upper).
using ParameterBounds = std::map<std::string, std::pair<double, double>>;

// A model with its pressure law, contact spot and parameter values: unspecified coefficients
// follow the law (and the spot).
struct ModelRequest {
  std::string model = "exact";
  std::string pressure = "hertz";
  ParameterValues params;
  // The contact spot: circle, ellipse:Q, rect:Q (0 < Q <= 4) or map:FILE (the map is the
  // pressure: no --pressure with it).
  std::string contact = "circle";
  bool pressure_given = false;  // --pressure was given (an error with map:FILE)
};

struct CoefficientsRequest {
  std::string pressure = "hertz";
  double kappa = 1.0;
  double alpha = 0.0;  // slip direction [rad] for m(alpha)
  std::string contact = "circle";
  bool pressure_given = false;
};

struct EvalRequest {
  ModelRequest model;
  std::optional<double> vx, vy, omega;  // one point, or
  double N = 1.0, R = 1.0;
  std::string input, output;  // every row of a kinematics CSV, predictions appended
  ColumnMap columns;
  int threads = 0;  // for the rows (0: every hardware thread); the output does not depend on it
  bool progress = false;  // progress line on stderr (the command line sets it on a tty)
};

struct GenerateRequest {
  ModelRequest model;
  std::size_t rows = 600;
  double noise = 0.0;      // relative standard deviation
  double noise_abs = 0.0;  // absolute standard deviation [channel units]
  bool sigma_columns = false;
  unsigned long long seed = 1;
  std::string output, truth;  // files the command line writes
  double eps_min = 1e-2, eps_max = 1e2;
  std::vector<double> loads = {2000.0, 4000.0, 6000.0};
  double R = 0.05, spin = 2.0;
  std::vector<double> slip_angles_deg = {0.0};
  bool forward_only = false;
  int threads = 0;        // for the rows (0: every hardware thread); the data do not depend on it
  bool progress = false;  // progress line on stderr (the command line sets it on a tty)
};

struct FitRequest {
  std::string data;  // the dataset CSV (fit, compare); batch plans its own
  std::string model = "seed";
  std::string pressure = "hertz";
  bool pressure_given = false;        // --pressure was given (an error with map:FILE)
  std::string contact = "circle";     // circle, ellipse:Q, rect:Q or map:FILE
  ParameterValues fix;                // held at these values
  std::vector<std::string> free;      // fitted although held by default (h_y, q)
  ParameterBounds bounds;             // replace the default bounds
  ParameterValues start;              // where the local fit starts (with no_global)
  std::string loss = "none";          // none, huber:S, cauchy:S or soft_l1:S
  std::vector<std::string> channels;  // empty: every measured channel
  ColumnMap columns;                  // renames of the dataset's columns
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
  // The report (command line; Python writes one on request).
  std::string report;
  bool no_wait = false;  // fail instead of waiting when another run holds the report's lock
  bool progress = false;
  std::vector<std::string> plot_x;  // report: channels also against these columns
  std::string color_by;             // report: colours of the collapse plots
  // The command as typed (text::command_line), printed in the reports' provenance; empty from
  // Python. Compare and batch carry theirs here too.
  std::string command_line;
  // How the data file is read (io/data_form.hpp): its form (auto, native or wheel), the wheel
  // form's axes (iso or sae) and the contact radius of a wheel-form file without an R column.
  std::string input_form = "auto";
  std::string axes = "iso";
  std::optional<double> contact_radius;
  // batch: columns of the data (e.g. a tire id, the pressure) whose value in each run goes to
  // summary.csv beside the covariates.
  std::vector<std::string> keep;
};

struct CompareRequest {
  FitRequest fit;  // everything but the model and the spot, applied to every model where it applies
  std::vector<std::string> models = {"seed", "corrected", "exact"};
  // Every model is fitted on each of these spots, models first ("exact" on "circle" and
  // "ellipse:0.7"); a spot that a model does not support is an error, as for fit.
  std::vector<std::string> contacts = {"circle"};
};

struct BatchRequest {
  FitRequest fit;  // fit.data unused; fit.threads is used per fit only with jobs = 1
  std::vector<std::string> inputs;       // CSV files, globs, directories or manifests
  std::vector<std::string> group_by;     // split each file by these columns
  std::string per_run_reports = "json";  // none, json or full
  bool force = false;                    // fit every run again, whatever the journal holds
  int jobs = 0;                          // runs fitted at once; 0: every hardware thread
  std::vector<std::string> shared;       // parameters common to every run (joint fit)
  std::string trend_x = "mean_N";        // the covariate on summary.html's trend plots' x axis
  bool warm_start = false;  // runs after the first start from its fit (no global stage)
};

struct SimulateRequest {
  ModelRequest model{"exact", "uniform", {}};  // a flat rigid body on a plane
  std::optional<double> inertia_ratio;         // I/(M_b R^2), required
  double v0 = 1.0, omega0 = 1.0, slip_angle_deg = 0.0;
  double mass = 1.0, R = 1.0;
  std::optional<double> N;  // default M_b g
  std::string output;       // trajectory CSV (command line)
  double tol = 1e-10, stop_fraction = 1e-12;
  long max_steps = 200000;
  bool trajectory = false;  // record every accepted step (implied by output)
};

// frictionid shimmy: a towed wheel or nose gear under a model's friction (docs/physics.md §10).
struct ShimmyRequest {
  ModelRequest model{"exact", "hertz", {}};
  std::string from_report;  // report.json of a fit: its model, law, spot and parameters
  double N = 1000.0, R = 0.05;
  double speed = 10.0, caster = 0.1;
  double yaw_inertia = 1.0, yaw_stiffness = 1e4, yaw_damping = 0.0;
  double lateral_mass = 10.0, lateral_stiffness = 1e5, lateral_damping = 0.0;
  std::string lateral = "elastic";       // or "rigid": y = 0 throughout
  std::string contact_law = "friction";  // or "nonholonomic": Keldysh's no-slip u_y = 0
  std::string integrator = "switching";  // or "explicit": Dormand–Prince only (§10.8)
  double psi0 = 0.0, y0 = 0.0;
  double duration = 2.0;
  std::string output;        // trajectory CSV (command line)
  double output_step = 0.0;  // > 0: rows at k output_step from dense output
  bool trajectory = false;   // keep the rows in the outcome (Python)
  double tol = 1e-10;        // the integrator's relative and (per state scale) absolute tolerance
  double stick_threshold = 1e-5;  // |s| below this fraction of its scale: the cohesion test
  double cycle_tol = 1e-3;        // relative amplitude change per cycle of a limit cycle
  std::string speed_sweep;        // A:B:N
  std::string sweep_param;        // yaw-damping:A:B:N or caster:A:B:N
  std::string sweep_dir = ".";    // where shimmy.csv and shimmy.html go
  double onset_tol = 0.0;         // onset speeds to this [m/s]; 0: 1e-3 of the sweep's range
  bool progress = false;          // progress line on stderr (the command line sets it on a tty)
  int table_directions = 0;       // > 0: the friction tabulated over the slip direction
};

}  // namespace frictionid::app
