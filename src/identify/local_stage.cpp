// Ceres adapter of the local stage; with joint_stage.cpp the only translation units that include
// ceres.h.
//
// All rows go to Ceres as one residual block in normal-equations form (normal_equations.hpp):
// each Jacobian evaluation runs the autodiff model over fixed chunks of rows on every thread,
// reduces each chunk to the Gram matrix of [J r], sums the chunks in order and hands Ceres the
// k+1 residuals [w; rho] with Jacobian [A; 0]. Levenberg-Marquardt sees the same cost, gradient,
// Gauss-Newton matrix and predicted decrease as with the m rows themselves (what
// DENSE_NORMAL_CHOLESKY would form), but never stores an m x k Jacobian: memory stays O(k^2),
// the work is one pass over the rows, and the bits do not depend on the thread count. Each pass
// runs a kernel per chunk of rows (chunk_kernels.hpp): where the build and the processor have
// AVX2, the closed-form models' rows of slip along x go four at a time, a row per vector lane.

// GCC's inliner runs out of budget inside the large Jet expressions of the models and leaves
// Eigen's 6-element vector operations as calls, which then cost more than the arithmetic.
#if defined(__GNUC__) && !defined(__clang__) && !defined(EIGEN_STRONG_INLINE)
#define EIGEN_STRONG_INLINE inline __attribute__((always_inline))
#endif

#include "identify/local_stage.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <optional>

#include "identify/chunk_kernels.hpp"
#include "identify/normal_equations.hpp"
#include "identify/row_chunks.hpp"
#include "identify/solver_progress.hpp"

namespace frictionid {
namespace {

// Sum of squared residuals over all rows in plain doubles; +inf if any is not finite.
double sum_of_squares(const LocalProblem& p, const ParamVector& x,
                      const PacketRowCache* cache = nullptr) {
  const FitSettings& s = *p.settings;
  const ModelEvaluator<double> model(s.model, s.law, x.data(), pass_table(p, x, false),
                                     p.quadrature, s.contact);
  const ChunkKernels<0>& kernels = chunk_kernels_for<0>();
  const PacketArgs<0> pp = kernels.packet_args(s, x.data());
  const std::size_t chunks = problem_chunks(p);
  std::vector<double> part(chunks, 0.0);
  std::vector<char> good(chunks, 1);
  for_each_chunk(chunks, p.threads, [&](std::size_t c) {
    if (!kernels.sum(p, model, pp, cache, chunk_begin(p, c), chunk_end(p, c), part[c])) good[c] = 0;
  });
  double total = 0.0;
  for (std::size_t c = 0; c < chunks; ++c) {
    if (!good[c]) return std::numeric_limits<double>::infinity();
    total += part[c];
  }
  return total;
}

// Autodiff passes with Jets as wide as the free parameters.
template <int N>
struct JetPasses {
  using Jet = ceres::Jet<double, N>;
  // One chunk's residual rows: N derivative columns, then the residual.
  using Block = Eigen::Matrix<double, Eigen::Dynamic, N + 1>;
  using Gram = Eigen::Matrix<double, N + 1, N + 1>;

  static ParamVector with_free(const LocalProblem& p, const ParamVector& base, const double* z) {
    ParamVector x = base;
    for (int j = 0; j < N; ++j) x[p.free[j]] = z[j];
    return x;
  }

  static std::array<Jet, kParamCount> seeded(const LocalProblem& p, const ParamVector& x) {
    std::array<Jet, kParamCount> pj;
    for (int i = 0; i < kParamCount; ++i) pj[i] = Jet(x[i]);
    for (int j = 0; j < N; ++j) pj[p.free[j]] = Jet(x[p.free[j]], j);
    return pj;
  }

  // Fills b with the chunk's rows; false if a residual or derivative is not finite.
  static bool fill(const LocalProblem& p, const ModelEvaluator<Jet>& model, const PacketArgs<N>& pp,
                   std::size_t c, Block& b, double& sum_sq) {
    const std::size_t i0 = chunk_begin(p, c), i1 = chunk_end(p, c);
    b.resize(static_cast<Eigen::Index>((i1 - i0) * p.rows.channels.size()), N + 1);
    return chunk_kernels_for<N>().fill(p, model, pp, i0, i1, b, sum_sq);
  }

  // One autodiff pass at x: reduce(c, b) turns chunk c's rows b into the chunk's result;
  // sum_sq[c] gets its sum of squared residuals. False if any chunk was not finite.
  template <typename Reduce>
  static bool pass(const LocalProblem& p, const ParamVector& x, std::vector<double>& sum_sq,
                   const Reduce& reduce) {
    const FitSettings& s = *p.settings;
    const auto pj = seeded(p, x);
    const ModelEvaluator<Jet> model(s.model, s.law, pj.data(), pass_table(p, x, true), p.quadrature,
                                    s.contact);
    const PacketArgs<N> pp = chunk_kernels_for<N>().packet_args(s, pj.data());
    const std::size_t chunks = problem_chunks(p);
    sum_sq.assign(chunks, 0.0);
    std::vector<char> good(chunks, 1);
    for_each_chunk(chunks, p.threads, [&](std::size_t c) {
      thread_local Block b;
      if (fill(p, model, pp, c, b, sum_sq[c]))
        reduce(c, b);
      else
        good[c] = 0;
    });
    return std::all_of(good.begin(), good.end(), [](char g) { return g != 0; });
  }

  // The Gram matrix of [J r] summed as the residuals come, with no m x (k+1) block in between.
  static bool normal_equations(const LocalProblem& p, const ParamVector& x, NormalEquations& ne) {
    const FitSettings& s = *p.settings;
    const auto pj = seeded(p, x);
    const ModelEvaluator<Jet> model(s.model, s.law, pj.data(), pass_table(p, x, true), p.quadrature,
                                    s.contact);
    const std::size_t chunks = problem_chunks(p);
    std::vector<Gram> gram(chunks);
    std::vector<char> good(chunks, 1);
    const ChunkKernels<N>& kernels = chunk_kernels_for<N>();
    const PacketArgs<N> pp = kernels.packet_args(s, pj.data());
    std::vector<double> sum_sq(chunks, 0.0);
    for_each_chunk(chunks, p.threads, [&](std::size_t c) {
      Gram g = Gram::Zero();
      if (!kernels.gram(p, model, pp, chunk_begin(p, c), chunk_end(p, c), g, sum_sq[c]))
        good[c] = 0;
      else
        gram[c] = g;
    });
    if (!std::all_of(good.begin(), good.end(), [](char ok) { return ok != 0; })) return false;
    // r^T r summed row by row and chunk by chunk, as the plain pass sums it (not the Gram
    // matrix's corner, whose packet lanes are summed apart): Ceres sees one cost whichever ran.
    Gram total = Gram::Zero();
    ne.rtr = 0.0;
    for (std::size_t c = 0; c < gram.size(); ++c) {
      total += gram[c];
      ne.rtr += sum_sq[c];
    }
    ne.jtj = total.template topLeftCorner<N, N>();
    ne.jtr = total.template topRightCorner<N, 1>();
    return true;
  }

  // TSQR: each chunk's Jacobian to its triangular factor, the factors stacked in chunk order.
  static std::optional<JacobianFactor> factor(const LocalProblem& p, const ParamVector& x) {
    std::vector<Eigen::MatrixXd> rc(problem_chunks(p));
    std::vector<double> sum_sq;
    const bool ok = pass(p, x, sum_sq, [&](std::size_t c, const Block& b) {
      rc[c] = triangular(b.template leftCols<N>());
    });
    if (!ok) return std::nullopt;
    JacobianFactor out;
    Eigen::MatrixXd r = Eigen::MatrixXd::Zero(N, N), stacked(2 * N, N);
    double total = 0.0;
    for (std::size_t c = 0; c < rc.size(); ++c) {
      stacked << r, rc[c];
      r = triangular(stacked);
      total += sum_sq[c];
    }
    out.r = r;
    out.cost = 0.5 * total;
    return out;
  }

  // The meat of the HC3 sandwich: sum over residuals of J_i^T J_i r_i^2 / (1 - h_ii)^2 with the
  // leverage h_ii = J_i B J_i^T, B = (J^T J)^-1 (the bread). Chunks are summed in order.
  // With `spread`, also per parameter l the sums of q_il = (J_i B)_l^2 / (1 - h_ii) and of
  // q_il^2 (columns 0 and 1): (B M B)_ll = sum_i q_il u_i with u_i = r_i^2/(1 - h_ii).
  static bool meat(const LocalProblem& p, const ParamVector& x, const Eigen::MatrixXd& bread,
                   Eigen::MatrixXd& out, Eigen::MatrixXd* spread) {
    // Dynamic sizes: one pass per fit, and GCC's bounds analysis trips over 1 x 1 fixed ones.
    std::vector<Eigen::MatrixXd> part(problem_chunks(p), Eigen::MatrixXd::Zero(N, N));
    std::vector<Eigen::MatrixXd> part_q(spread ? problem_chunks(p) : 0,
                                        Eigen::MatrixXd::Zero(N, 2));
    std::vector<double> sum_sq;
    const bool ok = pass(p, x, sum_sq, [&](std::size_t c, const Block& rows) {
      const Eigen::MatrixXd j = rows.template leftCols<N>();
      const Eigen::MatrixXd jb = j * bread;
      const Eigen::VectorXd h = jb.cwiseProduct(j).rowwise().sum();
      Eigen::VectorXd w(j.rows());
      for (Eigen::Index i = 0; i < j.rows(); ++i) {
        const double one_minus_h = 1.0 - std::min(h[i], 1.0 - 1e-12);
        const double r = rows(i, N) / one_minus_h;
        w[i] = r * r;
        if (spread)
          for (Eigen::Index l = 0; l < N; ++l) {
            const double q = jb(i, l) * jb(i, l) / one_minus_h;
            part_q[c](l, 0) += q;
            part_q[c](l, 1) += q * q;
          }
      }
      part[c] = j.transpose() * w.asDiagonal() * j;
    });
    if (!ok) return false;
    out = Eigen::MatrixXd::Zero(N, N);
    for (const auto& m : part) out += m;
    if (spread) {
      *spread = Eigen::MatrixXd::Zero(N, 2);
      for (const auto& m : part_q) *spread += m;
    }
    return true;
  }

  // The k x k upper triangular factor R of m = Q R (zero rows below m's rank when m is short).
  static Eigen::MatrixXd triangular(const Eigen::MatrixXd& m) {
    Eigen::MatrixXd r = Eigen::MatrixXd::Zero(N, N);
    if (m.rows() == 0) return r;
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(m);
    const Eigen::Index top = std::min<Eigen::Index>(N, m.rows());
    r.topRows(top) = qr.matrixQR().topRows(top).template triangularView<Eigen::Upper>();
    return r;
  }
};

// The local stage's passes over the rows at Ceres' current point, run before Ceres asks for them
// (an EvaluationCallback, as in the joint stage); the cost function below only hands them over.
class LocalEvaluations : public ceres::EvaluationCallback {
 public:
  // The N + 1 residuals [w; rho] and, when asked and prepared, the Jacobian [A; 0]. False when
  // the pass failed (a non-finite model or derivative) or nothing was prepared.
  virtual bool fill(double* residuals, double* jacobian) const = 0;
};

// The whole problem as one residual block of N + 1 residuals (see the top of this file).
//
// Ceres evaluates the cost alone at each trial point (a new evaluation point) and, when it
// accepts the step, asks for the Jacobian at that same point (not a new one). Near a minimum
// nearly every step is accepted, so the trial cost comes from the autodiff pass, whose normal
// equations are kept for the request that follows: one pass per accepted step instead of two.
// After a rejected step (no request followed) the next trial costs a plain-double pass again,
// which is half as dear. Both passes compute the residuals with the same operations, so the cost
// Ceres sees does not depend on which ran.
template <int N>
class NormalEquationsEvaluations final : public LocalEvaluations {
 public:
  // z: the free parameters, the memory Ceres updates before each PrepareForEvaluation.
  NormalEquationsEvaluations(const LocalProblem& p, const ParamVector& base, const double* z)
      : p_(p), base_(base), z_(z) {}

  void PrepareForEvaluation(bool evaluate_jacobians, bool new_evaluation_point) override {
    const ParamVector x = JetPasses<N>::with_free(p_, base_, z_);
    ready_ = Ready::Nothing;
    if (!evaluate_jacobians) {
      // The previous trial was rejected if its normal equations are still unclaimed.
      const bool last_accepted = !kept_;
      kept_ = false;
      if (last_accepted && !expect_final() && JetPasses<N>::normal_equations(p_, x, kept_ne_)) {
        kept_ = true;
        sum_sq_ = kept_ne_.rtr;
        ready_ = Ready::Cost;
        return;
      }
      // Also where only a derivative was not finite: the cost alone decides a trial, as before.
      sum_sq_ = sum_of_squares(p_, x);
      if (std::isfinite(sum_sq_)) ready_ = Ready::Cost;
      return;
    }
    const bool reuse = kept_ && !new_evaluation_point;
    kept_ = false;
    NormalEquations fresh;
    if (!reuse && !JetPasses<N>::normal_equations(p_, x, fresh)) return;
    at_ne_ = reuse ? kept_ne_ : fresh;
    std::copy(z_, z_ + N, at_z_.begin());
    have_at_ = true;
    form_ = square_root_form(at_ne_);
    ready_ = Ready::Jacobian;
  }

  bool fill(double* residuals, double* jacobian) const override {
    if (ready_ == Ready::Nothing || (jacobian != nullptr && ready_ != Ready::Jacobian))
      return false;
    if (ready_ == Ready::Cost) {
      for (int j = 0; j < N; ++j) residuals[j] = 0.0;
      residuals[N] = std::sqrt(sum_sq_);
      return true;
    }
    for (int i = 0; i < N; ++i) residuals[i] = form_.w[i];
    residuals[N] = form_.rho;
    if (jacobian == nullptr) return true;
    for (int i = 0; i < N; ++i)  // row-major (N + 1) x N
      for (int j = 0; j < N; ++j) jacobian[i * N + j] = form_.a(i, j);
    for (int j = 0; j < N; ++j) jacobian[N * N + j] = 0.0;
    return true;
  }

 private:
  // Whether the trial point looks like the last of the fit: where the Gauss-Newton model at the
  // last Jacobian predicts a cost change within the function tolerance, Ceres will likely stop on
  // it and never ask for its Jacobian, so the plain pass is enough. A wrong guess costs one pass,
  // never a bit of the result.
  bool expect_final() const {
    if (!have_at_) return false;
    Eigen::Matrix<double, N, 1> d;
    for (int j = 0; j < N; ++j) d[j] = z_[j] - at_z_[j];
    const double predicted = at_ne_.jtr.dot(d) + 0.5 * d.dot(at_ne_.jtj * d);
    return std::fabs(predicted) <= p_.settings->function_tolerance * 0.5 * at_ne_.rtr;
  }

  enum class Ready { Nothing, Cost, Jacobian };

  const LocalProblem& p_;
  ParamVector base_;
  const double* z_;
  Ready ready_ = Ready::Nothing;
  double sum_sq_ = 0.0;
  SquareRootForm form_;
  // The normal equations of the last trial point, until Ceres asks for them or moves on.
  bool kept_ = false;
  NormalEquations kept_ne_;
  // The point of the last Jacobian and its normal equations: the model of the next trial.
  bool have_at_ = false;
  std::array<double, N> at_z_{};
  NormalEquations at_ne_;
};

// The residual block: what the evaluations prepared at this point.
template <int N>
class PreparedCost final : public ceres::CostFunction {
 public:
  explicit PreparedCost(const LocalEvaluations& e) : e_(e) {
    set_num_residuals(N + 1);
    mutable_parameter_block_sizes()->push_back(N);
  }

  bool Evaluate(double const* const* /*parameters*/, double* residuals,
                double** jacobians) const override {
    return e_.fill(residuals, jacobians != nullptr ? jacobians[0] : nullptr);
  }

 private:
  const LocalEvaluations& e_;
};

template <int N>
std::unique_ptr<LocalEvaluations> make_evaluations_n(const LocalProblem& p, const ParamVector& base,
                                                     const double* z) {
  return std::make_unique<NormalEquationsEvaluations<N>>(p, base, z);
}
template <int N>
ceres::CostFunction* make_cost_n(const LocalEvaluations& e) {
  return new PreparedCost<N>(e);
}
template <int N>
bool normal_equations_n(const LocalProblem& p, const ParamVector& x, NormalEquations& out) {
  return JetPasses<N>::normal_equations(p, x, out);
}
template <int N>
std::optional<JacobianFactor> factor_n(const LocalProblem& p, const ParamVector& x) {
  return JetPasses<N>::factor(p, x);
}
template <int N>
bool meat_n(const LocalProblem& p, const ParamVector& x, const Eigen::MatrixXd& bread,
            Eigen::MatrixXd& out, Eigen::MatrixXd* spread) {
  return JetPasses<N>::meat(p, x, bread, out, spread);
}

// Jet width is a compile-time constant: dispatch on the number of free parameters.
void check_width(std::size_t k) {
  if (k < 1 || k > kParamCount) throw std::logic_error("free parameter count out of range");
}
std::unique_ptr<LocalEvaluations> make_evaluations(const LocalProblem& p, const ParamVector& base,
                                                   const double* z) {
  using Maker =
      std::unique_ptr<LocalEvaluations> (*)(const LocalProblem&, const ParamVector&, const double*);
  static constexpr Maker makers[kParamCount] = {
      make_evaluations_n<1>, make_evaluations_n<2>, make_evaluations_n<3>,
      make_evaluations_n<4>, make_evaluations_n<5>, make_evaluations_n<6>,
      make_evaluations_n<7>, make_evaluations_n<8>, make_evaluations_n<9>};
  check_width(p.free.size());
  return makers[p.free.size() - 1](p, base, z);
}

std::unique_ptr<ceres::CostFunction> make_cost_function(const LocalProblem& p,
                                                        const LocalEvaluations& e) {
  using Maker = ceres::CostFunction* (*)(const LocalEvaluations&);
  static constexpr Maker makers[kParamCount] = {make_cost_n<1>, make_cost_n<2>, make_cost_n<3>,
                                                make_cost_n<4>, make_cost_n<5>, make_cost_n<6>,
                                                make_cost_n<7>, make_cost_n<8>, make_cost_n<9>};
  check_width(p.free.size());
  return std::unique_ptr<ceres::CostFunction>(makers[p.free.size() - 1](e));
}

}  // namespace

bool exponent_free(const LocalProblem& p) {
  return p.settings->law.kind == model::PressureKind::Power &&
         std::find(p.free.begin(), p.free.end(), kN) != p.free.end();
}

std::shared_ptr<const model::RingIntegralTable> pass_table(const LocalProblem& p,
                                                           const ParamVector& x, bool n_slopes) {
  const FitSettings& s = *p.settings;
  if (s.model != ModelKind::Exact) return nullptr;
  if (p.exact_table) return p.exact_table;
  if (!exponent_free(p)) return nullptr;
  return ring_table_for_rows(s.model, s.law, x[kN], n_slopes, p.rows.end - p.rows.begin);
}

void allow_row_packets(bool allow) {
  row_packets_allowed().store(allow, std::memory_order_relaxed);
}

bool row_packets_available() {
  return chunk_kernels::avx2_kernels();
}

double problem_cost(const LocalProblem& p, const ParamVector& x) {
  return 0.5 * sum_of_squares(p, x);
}

RepeatedCost::RepeatedCost(const LocalProblem& p)
    : p_(p), cache_(chunk_kernels_for<0>().cache(p)) {}

RepeatedCost::~RepeatedCost() = default;

double RepeatedCost::operator()(const ParamVector& x) const {
  return 0.5 * sum_of_squares(p_, x, cache_.get());
}

bool normal_equations(const LocalProblem& p, const ParamVector& x, NormalEquations& out) {
  using Pass = bool (*)(const LocalProblem&, const ParamVector&, NormalEquations&);
  static constexpr Pass passes[kParamCount] = {
      normal_equations_n<1>, normal_equations_n<2>, normal_equations_n<3>,
      normal_equations_n<4>, normal_equations_n<5>, normal_equations_n<6>,
      normal_equations_n<7>, normal_equations_n<8>, normal_equations_n<9>};
  check_width(p.free.size());
  return passes[p.free.size() - 1](p, x, out);
}

std::optional<JacobianFactor> jacobian_factor(const LocalProblem& p, const ParamVector& x) {
  using Factor = std::optional<JacobianFactor> (*)(const LocalProblem&, const ParamVector&);
  static constexpr Factor factors[kParamCount] = {factor_n<1>, factor_n<2>, factor_n<3>,
                                                  factor_n<4>, factor_n<5>, factor_n<6>,
                                                  factor_n<7>, factor_n<8>, factor_n<9>};
  check_width(p.free.size());
  return factors[p.free.size() - 1](p, x);
}

std::optional<Eigen::MatrixXd> sandwich_meat(const LocalProblem& p, const ParamVector& x,
                                             const Eigen::MatrixXd& bread,
                                             Eigen::MatrixXd* spread) {
  using Meat = bool (*)(const LocalProblem&, const ParamVector&, const Eigen::MatrixXd&,
                        Eigen::MatrixXd&, Eigen::MatrixXd*);
  static constexpr Meat meats[kParamCount] = {meat_n<1>, meat_n<2>, meat_n<3>, meat_n<4>, meat_n<5>,
                                              meat_n<6>, meat_n<7>, meat_n<8>, meat_n<9>};
  check_width(p.free.size());
  Eigen::MatrixXd out;
  if (!meats[p.free.size() - 1](p, x, bread, out, spread)) return std::nullopt;
  return out;
}

LocalOutcome local_fit(const LocalProblem& p, const ParamVector& start, FitObserver* observer,
                       int start_index, int starts) {
  const FitSettings& s = *p.settings;
  LocalOutcome out;
  out.x = start;
  if (p.free.empty()) {
    out.cost = problem_cost(p, out.x);
    if (!std::isfinite(out.cost)) out.cost = std::numeric_limits<double>::infinity();
    out.termination = ceres::TerminationTypeToString(ceres::CONVERGENCE);
    out.converged = true;
    return out;
  }
  std::vector<double> z;
  for (int i : p.free) z.push_back(out.x[i]);
  const std::unique_ptr<LocalEvaluations> evaluations = make_evaluations(p, start, z.data());
  ceres::Problem::Options po;
  po.evaluation_callback = evaluations.get();
  ceres::Problem problem(po);
  problem.AddResidualBlock(make_cost_function(p, *evaluations).release(), nullptr, z.data());
  for (std::size_t j = 0; j < p.free.size(); ++j) {
    problem.SetParameterLowerBound(z.data(), static_cast<int>(j), s.params[p.free[j]].lower);
    problem.SetParameterUpperBound(z.data(), static_cast<int>(j), s.params[p.free[j]].upper);
  }
  // One thread: rows are spread over threads inside the block (row_chunks.hpp).
  ceres::Solver::Options o = solver_options(s);
  // The block is (k+1) x k: a dense QR of it costs nothing next to one pass over the rows.
  o.linear_solver_type = ceres::DENSE_QR;
  SolverProgress cb(observer, start_index, starts, s.max_iterations);
  o.callbacks.push_back(&cb);
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);
  for (std::size_t j = 0; j < p.free.size(); ++j) out.x[p.free[j]] = z[j];
  out.full_report = summary.FullReport();
  out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  out.termination = ceres::TerminationTypeToString(summary.termination_type);
  out.converged = summary.termination_type == ceres::CONVERGENCE ||
                  summary.termination_type == ceres::USER_SUCCESS;
  out.cost = summary.final_cost;
  // FAILURE: an evaluation or the linear solver failed; the point it stopped at is no result.
  if (!std::isfinite(out.cost) || summary.termination_type == ceres::FAILURE)
    out.cost = std::numeric_limits<double>::infinity();
  return out;
}

}  // namespace frictionid
