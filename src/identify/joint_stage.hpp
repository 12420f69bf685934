// The local stage of a joint fit (docs/physics.md §8.13): one Ceres problem with a parameter
// block of shared parameters and one block of own parameters per run. Each run is one residual
// block in normal-equations form (normal_equations.hpp) over both blocks, so the Jacobian is
// block-sparse with the Schur structure: the solver eliminates the runs' blocks and solves a
// dense system the size of the shared block.
#pragma once

#include <string>
#include <vector>

#include <frictionid/fit_observer.hpp>

#include "identify/local_stage.hpp"

namespace frictionid {

struct JointProblem {
  std::vector<int> shared;         // parameter indices common to every run
  std::vector<LocalProblem> runs;  // free = shared, then the run's own free parameters
  std::vector<ParamVector> start;  // per run; its shared entries are the common start
  int threads = 1;                 // runs evaluated in parallel; bits do not depend on it
};

struct JointOutcome {
  std::vector<ParamVector> x;  // per run, shared entries equal across runs
  double cost = 0.0;           // +inf if Ceres failed
  int iterations = 0;
  std::string termination;
  bool converged = false;
  std::string linear_solver;
};

JointOutcome joint_local_fit(const JointProblem& p, FitObserver* observer);

}  // namespace frictionid
