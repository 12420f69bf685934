// Coverage study of the per-channel noise models (experiments/README.md, "Identification
// study"). For every cell (noise condition x model x with/without sigma columns x noise-model
// setting) it generates replicated datasets with known per-channel noise, fits each with the
// library's Fitter (default settings apart from the noise model and one thread per fit), and
// writes one CSV line per fit and parameter: estimate, model-based standard error and ci95, HC3
// sandwich standard error and its interval. The interval cells (fewer replicates: each fit
// refits hundreds of times) also ask for the profile interval and the wild bootstrap
// (--intervals profile --bootstrap B) and add those intervals and the bootstrap standard error.
// summarize.py turns the lines into tables and a plot.
//
//   coverage_study [--replicates N] [--replicates-exact N] [--baseline-replicates N]
//                  [--interval-replicates N] [--bootstrap-resamples B]
//                  [--cells all|default|intervals] [--conditions relative,absolute,...]
//                  [--rows R] [--jobs J] [--output FILE]
//
// Deterministic: replicate i of a (noise, model) pair uses the same noise draw in every cell
// (with and without sigma columns, default and constant noise model, interval cells), whatever
// --jobs is.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <frictionid/fitter.hpp>
#include <frictionid/synthetic_data.hpp>
#include "identify/noise_model.hpp"
#include "identify/statistics.hpp"

namespace {

using namespace frictionid;

// Per channel (T_x, T_y, M_z, M_roll): relative sigma r_c, and absolute sigma as a fraction of
// the channel's RMS over the noise-free rows. Each condition differs between channels.
struct NoiseCondition {
  const char* name;
  std::array<double, kChannelCount> rel;      // sigma_rel per channel
  std::array<double, kChannelCount> abs_rms;  // sigma_abs / RMS(channel) per channel
  bool additive = false;  // sigma = s_abs + s_rel |y| instead of the two in quadrature
};

// The additive condition: a floor plus a proportional part whose balance differs strongly
// between channels (floor-dominated T_y and M_roll, proportional T_x).
const NoiseCondition kConditions[] = {
    {"relative", {0.01, 0.03, 0.02, 0.005}, {0.0, 0.0, 0.0, 0.0}},
    {"absolute", {0.0, 0.0, 0.0, 0.0}, {0.01, 0.03, 0.02, 0.005}},
    {"affine", {0.01, 0.02, 0.015, 0.005}, {0.005, 0.01, 0.01, 0.002}},
    {"additive", {0.02, 0.002, 0.01, 0.001}, {0.001, 0.02, 0.005, 0.01}, true},
};
constexpr int kConditionCount = static_cast<int>(std::size(kConditions));

struct Cell {
  int condition = 0;
  ModelKind model = ModelKind::Seed;
  bool columns = false;
  NoiseModelKind noise_model = NoiseModelKind::Auto;
  int replicates = 0;
  // Interval cells: profile intervals and a wild bootstrap of `bootstrap` resamples as well.
  bool profile = false;
  int bootstrap = 0;
};

struct Task {
  int cell = 0;
  int replicate = 0;
};

std::uint64_t noise_seed(int condition, ModelKind model, int replicate) {
  return 20261123ULL + 1000003ULL * static_cast<std::uint64_t>(condition) +
         100000007ULL * static_cast<std::uint64_t>(static_cast<int>(model)) +
         static_cast<std::uint64_t>(replicate);
}

// The dataset of replicate `replicate`: the default design's noise-free rows plus Gaussian noise
// with sigma_i^2 = s_abs^2 + (s_rel y_i)^2 (additive: sigma_i = s_abs + s_rel |y_i|) per channel;
// sigma columns hold the true sigma.
Dataset make_data(const Dataset& clean, const std::array<double, kChannelCount>& s_abs,
                  const NoiseCondition& cond, bool columns, std::uint64_t seed) {
  Dataset d = clean;
  NormalStream normal(seed);
  for (int c = 0; c < kChannelCount; ++c)
    if (columns) d.sigma[c].assign(d.rows(), 0.0);
  for (std::size_t i = 0; i < d.rows(); ++i)
    for (int c = 0; c < kChannelCount; ++c) {
      const double y = clean.value[c][i];
      const double sd = cond.additive ? s_abs[c] + cond.rel[c] * std::fabs(y)
                                      : std::hypot(s_abs[c], cond.rel[c] * y);
      d.value[c][i] = y + sd * normal.next();
      if (columns) d.sigma[c][i] = sd > 0.0 ? sd : 1e-300;
    }
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  int replicates = 500, replicates_exact = 500, baseline = 300, jobs = 2;
  int interval_replicates = 400, bootstrap_resamples = 199;
  std::string which = "all";  // all, default (model-based and HC3 cells) or intervals
  std::string conditions;     // comma-separated noise conditions of the default cells; empty: all
  std::size_t rows = 600;
  std::string output = "coverage_fits.csv";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--replicates")
      replicates = std::stoi(next());
    else if (a == "--replicates-exact")
      replicates_exact = std::stoi(next());
    else if (a == "--baseline-replicates")
      baseline = std::stoi(next());
    else if (a == "--interval-replicates")
      interval_replicates = std::stoi(next());
    else if (a == "--bootstrap-resamples")
      bootstrap_resamples = std::stoi(next());
    else if (a == "--cells")
      which = next();
    else if (a == "--conditions")
      conditions = next();
    else if (a == "--rows")
      rows = std::stoul(next());
    else if (a == "--jobs")
      jobs = std::max(1, std::stoi(next()));
    else if (a == "--output")
      output = next();
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  if (which != "all" && which != "default" && which != "intervals") {
    std::cerr << "--cells must be all, default or intervals, not " << which << "\n";
    return 2;
  }

  const auto law = model::PressureLaw<double>::hertz();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  const ModelKind models[] = {ModelKind::Seed, ModelKind::Corrected, ModelKind::Exact};

  // Noise-free rows and absolute sigmas per model (the channel RMS depends on the model a little).
  SyntheticDesign design;
  design.rows = rows;
  std::array<Dataset, 3> clean;
  std::array<std::array<std::array<double, kChannelCount>, kConditionCount>, 3>
      s_abs{};  // [model][cond]
  for (int m = 0; m < 3; ++m) {
    clean[m] = generate_dataset(models[m], law, truth, design, NoiseSpec{}, 1);
    for (int k = 0; k < kConditionCount; ++k)
      for (int c = 0; c < kChannelCount; ++c) {
        double ss = 0.0;
        for (double y : clean[m].value[c]) ss += y * y;
        s_abs[m][k][c] = kConditions[k].abs_rms[c] * std::sqrt(ss / static_cast<double>(rows));
      }
  }

  std::vector<Cell> cells;
  for (int k = 0; k < kConditionCount && which != "intervals"; ++k)
    if (conditions.empty() || conditions.find(kConditions[k].name) != std::string::npos)
      for (int m = 0; m < 3; ++m)
        for (bool columns : {false, true}) {
          const int n = models[m] == ModelKind::Exact ? replicates_exact : replicates;
          cells.push_back({k, models[m], columns, NoiseModelKind::Auto, n});
          // The constant-noise baseline (precision comparison) without sigma columns only.
          if (baseline > 0 && !columns)
            cells.push_back(
                {k, models[m], columns, NoiseModelKind::Constant, std::min(n, baseline)});
        }
  // Interval cells: the profile and the wild bootstrap on the same fits, default noise model, no
  // sigma columns; relative and affine noise (the heteroscedastic conditions), every model.
  if (which != "default" && interval_replicates > 0)
    for (int k : {0, 2})
      for (int m = 0; m < 3; ++m)
        cells.push_back({k, models[m], false, NoiseModelKind::Auto, interval_replicates, true,
                         bootstrap_resamples});
  std::vector<Task> tasks;
  for (int c = 0; c < static_cast<int>(cells.size()); ++c)
    for (int r = 1; r <= cells[c].replicates; ++r) tasks.push_back({c, r});
  // Slowest first (interval cells, then exact fits) so the workers finish together.
  auto weight = [&](const Task& t) {
    return 2 * cells[t.cell].profile + (cells[t.cell].model == ModelKind::Exact);
  };
  std::stable_sort(tasks.begin(), tasks.end(),
                   [&](const Task& x, const Task& y) { return weight(x) > weight(y); });

  std::ofstream out(output);
  if (!out) {
    std::cerr << "cannot write " << output << "\n";
    return 1;
  }
  out << "noise,model,columns,noise_model,methods,replicate,status,seconds,dof,chosen,parameter,"
         "truth,value,stderr,ci_lo,ci_hi,stderr_sandwich,hc3_lo,hc3_hi,profile_lo,profile_hi,"
         "profile_closed,stderr_bootstrap,bootstrap_lo,bootstrap_hi,bootstrap_refits\n";
  for (int k = 0; k < kConditionCount; ++k)
    for (int m = 0; m < 3; ++m) {
      std::cerr << "sigma_abs " << kConditions[k].name << " " << model_name(models[m]) << ":";
      for (int c = 0; c < kChannelCount; ++c) std::cerr << " " << s_abs[m][k][c];
      std::cerr << "\n";
    }
  std::cerr << tasks.size() << " fits in " << cells.size() << " cells on " << jobs << " jobs\n";

  std::mutex mu;
  std::atomic<std::size_t> next_task{0}, done{0};
  const auto t0 = std::chrono::steady_clock::now();
  auto worker = [&]() {
    for (;;) {
      const std::size_t t = next_task++;
      if (t >= tasks.size()) return;
      const Cell& cell = cells[tasks[t].cell];
      const int m = cell.model == ModelKind::Seed ? 0 : cell.model == ModelKind::Corrected ? 1 : 2;
      const Dataset data =
          make_data(clean[m], s_abs[m][cell.condition], kConditions[cell.condition], cell.columns,
                    noise_seed(cell.condition, cell.model, tasks[t].replicate));
      FitSettings s = FitSettings::defaults(cell.model, law, "hertz");
      s.noise_model = cell.noise_model;
      s.threads = 1;  // the bootstrap's refits too: the fits run in parallel instead
      if (cell.profile) s.intervals = IntervalMethod::Profile;
      s.bootstrap = cell.bootstrap;
      std::ostringstream line;
      const std::string head = std::string(kConditions[cell.condition].name) + "," +
                               model_name(cell.model) + "," + (cell.columns ? "yes" : "no") + "," +
                               noise_model_name(cell.noise_model) + "," +
                               (cell.profile ? "profile+bootstrap" : "default") + "," +
                               std::to_string(tasks[t].replicate);
      line.precision(17);
      const auto f0 = std::chrono::steady_clock::now();
      try {
        const FitResult r = Fitter(s).fit(data);
        const double secs =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count();
        std::string chosen;
        for (const auto& ch : r.channel_summaries) {
          if (!chosen.empty()) chosen += "/";
          chosen += ch.noise                            ? ch.noise->model
                    : ch.scale_source == "sigma column" ? "columns"
                                                        : "?";
        }
        const double tq =
            r.dof > 0 ? student_t_quantile(0.975, static_cast<double>(r.dof)) : 1.959963984540054;
        const std::string status = r.solver.converged ? "ok" : "not_converged";
        for (const auto& p : r.parameters) {
          if (p.fixed) continue;
          const int pi = *param_index(p.name);
          line << head << "," << status << "," << secs << "," << r.dof << "," << chosen << ","
               << p.name << "," << truth[pi] << "," << p.value << ",";
          if (p.std_error && p.ci95)
            line << *p.std_error << "," << (*p.ci95)[0] << "," << (*p.ci95)[1] << ",";
          else
            line << ",,,";
          if (p.std_error_sandwich)
            line << *p.std_error_sandwich << "," << p.value - tq * *p.std_error_sandwich << ","
                 << p.value + tq * *p.std_error_sandwich << ",";
          else
            line << ",,,";
          if (p.ci95_profile)
            line << (*p.ci95_profile)[0] << "," << (*p.ci95_profile)[1] << ","
                 << (p.profile_closed[0] && p.profile_closed[1] ? 1 : 0) << ",";
          else
            line << ",,,";
          if (p.std_error_bootstrap && p.ci95_bootstrap)
            line << *p.std_error_bootstrap << "," << (*p.ci95_bootstrap)[0] << ","
                 << (*p.ci95_bootstrap)[1] << "," << r.bootstrap_replicates << "\n";
          else
            line << ",,,\n";
        }
      } catch (const std::exception& e) {
        const double secs =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count();
        line << head << ",failed," << secs << ",,,,,,,,,,,,,,,,,,\n";
      }
      const std::size_t n = ++done;
      std::lock_guard<std::mutex> lock(mu);
      out << line.str();
      if (n % 500 == 0 || n == tasks.size())
        std::cerr << n << "/" << tasks.size() << " fits, "
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
                  << " s\n";
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  std::cerr << "wall "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
            << " s\n";
  return 0;
}
