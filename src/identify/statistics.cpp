#include "identify/statistics.hpp"

#include <cmath>
#include <limits>

namespace frictionid {

JacobianCovariance covariance_from_jacobian(const Eigen::MatrixXd& J, double rel_tol) {
  const Eigen::Index k = J.cols();
  JacobianCovariance out;
  out.covariance = Eigen::MatrixXd::Zero(k, k);
  out.determined.assign(static_cast<std::size_t>(k), false);
  if (k == 0) return out;
  // Equilibrate columns so that the rank test does not depend on the parameters' units.
  Eigen::VectorXd norms = J.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < k; ++j)
    if (!(norms[j] > 0.0)) norms[j] = 1.0;
  // A tall Jacobian is reduced to its k x k triangular factor first: same singular values and
  // right singular vectors, at O(m k^2) instead of a one-sided Jacobi sweep over m rows.
  Eigen::MatrixXd Js = J * norms.cwiseInverse().asDiagonal();
  if (Js.rows() > Js.cols()) {
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(Js);
    Js = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixV();
  const double smax = s.size() > 0 ? s[0] : 0.0;
  out.condition = s.size() > 0 && s[s.size() - 1] > 0 ? smax / s[s.size() - 1]
                                                      : std::numeric_limits<double>::infinity();
  std::vector<bool> in_null(static_cast<std::size_t>(k), false);
  Eigen::MatrixXd inv = Eigen::MatrixXd::Zero(k, k);
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s[i] > rel_tol * smax && s[i] > 0.0) {
      inv += V.col(i) * V.col(i).transpose() / (s[i] * s[i]);
      continue;
    }
    std::vector<int> members;
    for (Eigen::Index j = 0; j < k; ++j) {
      if (V(j, i) * V(j, i) > 1e-2) {
        in_null[static_cast<std::size_t>(j)] = true;
        members.push_back(static_cast<int>(j));
      }
    }
    out.null_directions.push_back(members);
  }
  // Undo the equilibration: cov = D^-1 (Js^T Js)^-1 D^-1.
  const Eigen::MatrixXd cov =
      norms.cwiseInverse().asDiagonal() * inv * norms.cwiseInverse().asDiagonal();
  for (Eigen::Index j = 0; j < k; ++j)
    out.determined[static_cast<std::size_t>(j)] = !in_null[static_cast<std::size_t>(j)];
  for (Eigen::Index i = 0; i < k; ++i)
    for (Eigen::Index j = 0; j < k; ++j)
      if (out.determined[static_cast<std::size_t>(i)] &&
          out.determined[static_cast<std::size_t>(j)])
        out.covariance(i, j) = cov(i, j);
  return out;
}

namespace {
// Continued fraction of the incomplete beta function (modified Lentz).
double beta_continued_fraction(double x, double a, double b) {
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 500; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1.0) < 1e-16) break;
  }
  return h;
}
}  // namespace

double regularized_incomplete_beta(double x, double a, double b) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double ln_front =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  const double front = std::exp(ln_front);
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_continued_fraction(x, a, b) / a;
  return 1.0 - front * beta_continued_fraction(1.0 - x, b, a) / b;
}

double student_t_quantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0) || !(dof > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (p == 0.5) return 0.0;
  const bool upper = p > 0.5;
  const double tail = upper ? 1.0 - p : p;  // P(T > t) for the positive quantile
  // P(T > t) = I_{dof/(dof+t^2)}(dof/2, 1/2)/2, decreasing in t: bisection in t.
  double lo = 0.0, hi = 1.0;
  while (0.5 * regularized_incomplete_beta(dof / (dof + hi * hi), 0.5 * dof, 0.5) > tail &&
         hi < 1e12)
    hi *= 2.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (0.5 * regularized_incomplete_beta(dof / (dof + mid * mid), 0.5 * dof, 0.5) > tail)
      lo = mid;
    else
      hi = mid;
    if (hi - lo <= 1e-15 * hi) break;
  }
  const double t = 0.5 * (lo + hi);
  return upper ? t : -t;
}

}  // namespace frictionid
