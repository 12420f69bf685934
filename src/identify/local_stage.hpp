// The local stage: Ceres' Levenberg-Marquardt from one start, with autodiff Jacobians over all
// rows, and the whitened Jacobian at the optimum for the statistics.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_settings.hpp>
#include "identify/local_problem.hpp"
#include "identify/normal_equations.hpp"

namespace frictionid {

struct LocalOutcome {
  ParamVector x{};
  double cost = 0.0;  // 1/2 sum of squared (robustified) residuals; +inf if Ceres failed
  int iterations = 0;
  std::string termination;  // Ceres' termination type, e.g. CONVERGENCE
  bool converged = false;
  std::string full_report;  // Ceres' FullReport, for diagnostics
};

// Ceres from `start`, reporting each iteration to the observer (may be null), which can stop it.
LocalOutcome local_fit(const LocalProblem& p, const ParamVector& start, FitObserver* observer,
                       int start_index, int starts);

// 1/2 sum of squared (robustified) residuals at x, or +inf where the model is not finite.
double problem_cost(const LocalProblem& p, const ParamVector& x);

// problem_cost at many x on the same rows, as the global stage asks for it: what the packet pass
// needs of the rows (aligned_row_packets.hpp) is formed once, not at every x. The same bits as
// problem_cost. p, its rows and its dataset must outlive it and stay as they are.
struct PacketRowCache;
class RepeatedCost {
 public:
  explicit RepeatedCost(const LocalProblem& p);
  ~RepeatedCost();
  RepeatedCost(const RepeatedCost&) = delete;
  RepeatedCost& operator=(const RepeatedCost&) = delete;
  double operator()(const ParamVector& x) const;

 private:
  const LocalProblem& p_;
  std::unique_ptr<PacketRowCache> cache_;
};

// Whether the passes of the closed-form models may take rows of slip along x four at a time
// where the processor has AVX2 (chunk_kernels.hpp); on unless turned off. Off: every row one at
// a time, the same costs to the bit. Process-wide; for tests and comparisons.
void allow_row_packets(bool allow);

// Whether this build and this processor have the packet pass at all: x86-64 with AVX2, and not
// a FRICTIONID_PORTABLE build.
bool row_packets_available();

// J^T J, J^T r and r^T r over all rows at x (J with respect to the free parameters): one
// autodiff pass, the work of one Jacobian evaluation of the local stage. False where the model
// is not finite.
bool normal_equations(const LocalProblem& p, const ParamVector& x, NormalEquations& out);

// The whitened Jacobian at x with respect to the free parameters, reduced to its k x k
// triangular factor R (J = Q R: same singular values and covariance), and the cost there.
struct JacobianFactor {
  Eigen::MatrixXd r;
  double cost = 0.0;
};
std::optional<JacobianFactor> jacobian_factor(const LocalProblem& p, const ParamVector& x);

// The meat of the HC3 sandwich covariance B M B at x: M = sum over residuals of
// J_i^T J_i r_i^2 / (1 - h_ii)^2, h_ii = J_i B J_i^T, for the bread B = (J^T J)^-1 of the free
// parameters. nullopt where the model is not finite. With `spread` (k x 2), per free parameter l
// the sums over residuals of q_il = (J_i B)_l^2/(1 - h_ii) and of q_il^2: (B M B)_ll is
// sum_i q_il u_i with u_i = r_i^2/(1 - h_ii), which a correct noise model makes ~chi^2_1, so
// these give the HC3 variance's expectation and sampling spread under that model (§8.11).
std::optional<Eigen::MatrixXd> sandwich_meat(const LocalProblem& p, const ParamVector& x,
                                             const Eigen::MatrixXd& bread,
                                             Eigen::MatrixXd* spread = nullptr);

}  // namespace frictionid
