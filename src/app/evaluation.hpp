// What a model predicts: at one point, for every row of a kinematics CSV, or for columns held in
// memory (`frictionid eval`, `frictionid.evaluate()`).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/fit_observer.hpp>

#include "app/model_setup.hpp"
#include "app/requests.hpp"

namespace frictionid::app {

// {T_x, T_y, M_z, M_roll, N} at r's point (vx and omega required, vy default 0), and M_tilt
// after M_roll when the model shows it (shows_tilt: a spot other than the circle, or h_y != 0).
nlohmann::ordered_json evaluate_point(const EvalRequest& r);

// Every row of r.input (dataset columns; channels optional) written to r.output: the row as read,
// the file's other columns, then the predictions T_x,T_y,M_z,M_roll,N (suffixed _model where the
// input already has such a column), with M_tilt after M_roll when the model shows it. The rows
// run on up to r.threads threads, the file is the same on any number. Returns the rows written.
// The observer (may be null) hears a spot's table build and the model's rows and may cancel them
// (FitError("interrupted"); nothing is written then).
std::size_t evaluate_file(const EvalRequest& r, FitObserver* observer = nullptr);

// Kinematics columns of one length: v_x, v_y, omega finite; N and R finite and > 0.
struct KinematicsColumns {
  const double* v_x;
  const double* v_y;
  const double* omega;
  const double* N;
  const double* R;
  std::size_t rows;
};

struct ResultantColumns {
  std::vector<double> T_x, T_y, M_z, M_roll, M_tilt, N;
};

// Throws InputError naming the column and the index of the first bad value. The rows run on up
// to `threads` threads (0: every hardware thread); the values do not depend on how many. The
// observer as evaluate_file's.
ResultantColumns evaluate_columns(const ModelSetup& s, const KinematicsColumns& k, int threads = 0,
                                  FitObserver* observer = nullptr);

}  // namespace frictionid::app
