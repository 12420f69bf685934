// Uncertainty from the whitened Jacobian at the optimum, and the t quantile for intervals.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace frictionid {

// Covariance (J^T J)^-1 of the free parameters by SVD of the column-equilibrated Jacobian (what
// Ceres' DENSE_SVD covariance does), plus which parameters it determines: a parameter with a
// component > 1e-2 along a singular direction (relative singular value < rel_tol) is reported
// as not determined instead of receiving a pseudo-inverse's meaningless variance.
struct JacobianCovariance {
  Eigen::MatrixXd covariance;    // k x k; rows/cols of undetermined parameters are 0
  std::vector<bool> determined;  // per column of J
  std::vector<std::vector<int>> null_directions;  // columns taking part in each null direction
  double condition = 0.0;                         // of the equilibrated Jacobian
};
JacobianCovariance covariance_from_jacobian(const Eigen::MatrixXd& jacobian, double rel_tol = 1e-9);

// Quantile of Student's t distribution with dof degrees of freedom (dof > 0), p in (0, 1).
double student_t_quantile(double p, double dof);

// Regularized incomplete beta I_x(a, b).
double regularized_incomplete_beta(double x, double a, double b);

}  // namespace frictionid
