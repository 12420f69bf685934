#include "identify/normal_equations.hpp"

#include <algorithm>
#include <cmath>

namespace frictionid {

SquareRootForm square_root_form(const NormalEquations& ne) {
  const Eigen::Index k = ne.jtj.rows();
  SquareRootForm out;
  out.a = Eigen::MatrixXd::Zero(k, k);
  out.w = Eigen::VectorXd::Zero(k);
  // Equilibrate: S = D^-1 J^T J D^-1 has a unit diagonal whatever the parameters' units.
  Eigen::VectorXd d(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const double v = ne.jtj(i, i);
    d[i] = v > 0.0 ? std::sqrt(v) : 1.0;
  }
  const Eigen::VectorXd dinv = d.cwiseInverse();
  const Eigen::MatrixXd s = dinv.asDiagonal() * ne.jtj * dinv.asDiagonal();
  const Eigen::VectorXd g = dinv.asDiagonal() * ne.jtr;  // D^-1 J^T r

  Eigen::LLT<Eigen::MatrixXd> llt(s);
  bool factored = llt.info() == Eigen::Success;
  if (factored) {
    // S = L L^T: A = L^T D, w = L^-1 D^-1 J^T r.
    const Eigen::MatrixXd lt = llt.matrixU();
    const double dmin = lt.diagonal().cwiseAbs().minCoeff();
    const double dmax = lt.diagonal().cwiseAbs().maxCoeff();
    factored = dmin > 1e-8 * dmax;  // nearly singular: take the eigen path's clean null space
    if (factored) {
      out.a = lt * d.asDiagonal();
      out.w = llt.matrixL().solve(g);
    }
  }
  if (!factored) {
    // S = V diag(lambda) V^T: A = diag(sqrt(lambda)) V^T D, w_i = v_i^T g / sqrt(lambda_i).
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(s);
    const Eigen::VectorXd lambda = eig.eigenvalues();
    const Eigen::MatrixXd& v = eig.eigenvectors();
    const double lmax = std::max(lambda.maxCoeff(), 0.0);
    for (Eigen::Index i = 0; i < k; ++i) {
      if (!(lambda[i] > 1e-14 * lmax)) continue;  // no curvature along v_i
      const double sl = std::sqrt(lambda[i]);
      out.a.row(i) = sl * (v.col(i).transpose() * d.asDiagonal());
      out.w[i] = v.col(i).dot(g) / sl;
    }
  }
  out.rho = std::sqrt(std::max(ne.rtr - out.w.squaredNorm(), 0.0));
  return out;
}

}  // namespace frictionid
