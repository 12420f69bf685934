// A tall least-squares problem (m residuals r, Jacobian J, m >> k) seen through its normal
// equations, and a (k+1)-row problem with exactly the same cost, gradient and Gauss-Newton
// matrix: the form in which the local stage hands all rows to Ceres at once.
#pragma once

#include <Eigen/Dense>

namespace frictionid {

struct NormalEquations {
  Eigen::MatrixXd jtj;  // J^T J, k x k
  Eigen::VectorXd jtr;  // J^T r
  double rtr = 0.0;     // r^T r
};

// A (k x k), w (k) and rho with
//   A^T A = J^T J,   A^T w = J^T r,   |w|^2 + rho^2 = r^T r,
// so that the stacked residuals c = [w; rho] with Jacobian [A; 0] give the same cost, gradient,
// J^T J and predicted cost change |r + J d|^2 = |c + [A; 0] d|^2 for every step d. A comes from
// a Cholesky factor of the column-equilibrated J^T J, or, when that is singular, from its
// eigen-decomposition (directions with no curvature get a zero row and no share of J^T r).
struct SquareRootForm {
  Eigen::MatrixXd a;
  Eigen::VectorXd w;
  double rho = 0.0;
};
SquareRootForm square_root_form(const NormalEquations& ne);

}  // namespace frictionid
