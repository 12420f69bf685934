#include "identify/global_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <random>
#include <stdexcept>

namespace frictionid {
namespace {

struct Archive {
  const GlobalSearchProblem* problem;
  const std::function<bool()>* stop;
  std::vector<std::vector<double>> points;
  std::vector<double> values;
  nlopt::opt* opt = nullptr;
  std::size_t budget = 0;  // NLopt's maxeval lets CRS2 finish a few trial points past it
};

double nlopt_objective(unsigned n, const double* x, double* grad, void* data) {
  (void)grad;  // derivative-free algorithms only
  auto* a = static_cast<Archive*>(data);
  if (*a->stop && (*a->stop)() && a->opt) a->opt->force_stop();
  double f = a->problem->objective(x);
  if (!std::isfinite(f)) f = std::numeric_limits<double>::max();
  a->points.emplace_back(x, x + n);
  a->values.push_back(f);
  if (a->opt && a->values.size() >= a->budget) a->opt->force_stop();
  return f;
}

nlopt::algorithm algorithm_of(const std::string& name) {
  if (name == "crs2") return nlopt::GN_CRS2_LM;
  if (name == "isres") return nlopt::GN_ISRES;
  if (name == "direct") return nlopt::GN_DIRECT_L;
  if (name == "esch") return nlopt::GN_ESCH;
  throw std::invalid_argument("unknown global algorithm '" + name + "'");
}

}  // namespace

std::string global_algorithm_label(const std::string& a) {
  if (a == "crs2") return "NLopt GN_CRS2_LM";
  if (a == "isres") return "NLopt GN_ISRES";
  if (a == "direct") return "NLopt GN_DIRECT_L";
  if (a == "esch") return "NLopt GN_ESCH";
  if (a == "random") return "uniform random sampling";
  return a;
}

std::vector<std::string> global_algorithms() {
  return {"crs2", "isres", "direct", "esch", "random"};
}

GlobalSearchOutcome global_search(const GlobalSearchProblem& problem, const std::string& algorithm,
                                  long max_evaluations, unsigned long long seed, int starts,
                                  const std::function<bool()>& stop) {
  const unsigned dim = static_cast<unsigned>(problem.lower.size());
  Archive archive{&problem, &stop,   {},
                  {},       nullptr, static_cast<std::size_t>(std::max(max_evaluations, 1L))};
  GlobalSearchOutcome out;
  out.algorithm = algorithm;
  if (algorithm == "random") {
    // Plain seeded uniform sampling: a baseline for the algorithm experiment.
    std::mt19937_64 rng(seed);
    std::vector<double> x(dim);
    for (long e = 0; e < max_evaluations; ++e) {
      if (stop && stop()) break;
      for (unsigned i = 0; i < dim; ++i) {
        const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
        x[i] = problem.lower[i] + u * (problem.upper[i] - problem.lower[i]);
      }
      nlopt_objective(dim, x.data(), nullptr, &archive);
    }
  } else {
    nlopt::srand(seed);
    nlopt::opt opt(algorithm_of(algorithm), dim);
    archive.opt = &opt;
    opt.set_lower_bounds(problem.lower);
    opt.set_upper_bounds(problem.upper);
    opt.set_min_objective(nlopt_objective, &archive);
    opt.set_maxeval(static_cast<int>(max_evaluations));
    std::vector<double> x(dim);
    for (unsigned i = 0; i < dim; ++i) x[i] = 0.5 * (problem.lower[i] + problem.upper[i]);
    double f = 0.0;
    try {
      opt.optimize(x, f);
    } catch (const nlopt::forced_stop&) {
    } catch (const nlopt::roundoff_limited&) {
      // The archive still holds everything evaluated; the local stage takes over from there.
    } catch (const std::exception& e) {
      // NLopt gave up (bad input to it, out of memory, ...): keep what it evaluated and say so.
      out.failure = std::string("NLopt: ") + e.what();
    }
  }
  out.evaluations = static_cast<long>(archive.values.size());

  // Best distinct points: sorted by value (ties by index, for determinism), greedily keeping
  // points at least 10% of the box apart (in every-coordinate max norm) from those kept.
  std::vector<std::size_t> order(archive.values.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return archive.values[a] < archive.values[b];
  });
  for (std::size_t idx : order) {
    if (static_cast<int>(out.starts.size()) >= starts) break;
    const auto& p = archive.points[idx];
    bool distinct = true;
    for (const auto& q : out.starts) {
      double d = 0.0;
      for (unsigned i = 0; i < dim; ++i)
        d = std::max(d, std::fabs(p[i] - q[i]) / (problem.upper[i] - problem.lower[i]));
      if (d < 0.1) {
        distinct = false;
        break;
      }
    }
    if (distinct) {
      out.starts.push_back(p);
      out.start_values.push_back(archive.values[idx]);
    }
  }
  return out;
}

}  // namespace frictionid
