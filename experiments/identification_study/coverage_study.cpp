// Coverage study of the per-channel noise models (experiments/README.md, "Identification
// study"). For every cell (noise condition x model x with/without sigma columns x noise-model
// setting) it generates replicated datasets with known per-channel noise, fits each with the
// library's Fitter (default settings apart from the noise model and one thread per fit), and
// writes one CSV line per fit and parameter: estimate, model-based standard error and ci95, HC3
// sandwich standard error and its interval. The interval cells (fewer replicates: each fit
// refits hundreds of times) also ask for the profile interval and the wild bootstrap
// (--intervals profile --bootstrap B) and add those intervals and the bootstrap standard error.
// The design cells change the data rather than the method: additive noise on 600 and 60 rows,
// 20 and 8 rows, eps only above 1.5 (nearly collinear kappa, b, m) and two noise-free channels;
// each fit also asks for the profile intervals of every parameter (--intervals profile), which
// leaves the estimate, ci95 and the HC3 interval as the default fit has them (the profile runs
// after the fit), and marks the parameters the default profiles anyway (|r| > 0.99). The
// designs with few rows are also fitted with the true sigma columns and with the noise model of
// the generating form, to tell the noise estimate's share of a shortfall.
// summarize.py turns the lines into tables and a plot.
//
//   coverage_study [--replicates N] [--replicates-exact N] [--baseline-replicates N]
//                  [--interval-replicates N] [--bootstrap-resamples B]
//                  [--design-replicates N] [--designs rows600,rows60,...]
//                  [--design-intervals profile|model]
//                  [--cells all|default|intervals|designs] [--conditions relative,absolute,...]
//                  [--rows R] [--jobs J] [--output FILE]
//
// Deterministic: replicate i of a (noise, model) pair uses the same noise draw in every cell
// (with and without sigma columns, default and constant noise model, interval cells, design
// cells: there on that design's rows), whatever --jobs is.
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

// The designs of the design cells: generate's default design changed in one respect each. The
// default cells use design 0 ("default": --rows rows, eps 1e-2 to 1e2, every channel noisy).
struct DesignSpec {
  const char* name;
  const char* condition;  // the noise condition (kConditions) of its cells
  std::size_t rows = 600;
  double eps_min = 1e-2;
  std::array<bool, kChannelCount> noise_free{};  // channels left without noise
  // Also fitted with the true sigma in sigma columns and with the noise model of the form that
  // generated the noise (relative or additive): is a shortfall the noise estimate's?
  bool variants = false;
};
const DesignSpec kDesigns[] = {
    {"default", "", 0},
    // Additive noise with very different floor and proportional parts per channel.
    {"rows600", "additive", 600},
    {"rows60", "additive", 60, 1e-2, {}, true},
    // Small samples (docs/physics.md section 8.10: below k + 2 rows per channel one sigma
    // pooled over all cells; below 20 only constant or relative per channel).
    {"rows20", "relative", 20, 1e-2, {}, true},
    {"rows8", "relative", 8, 1e-2, {}, true},
    // eps only in 1.5-100: kappa, b and m nearly collinear (the default profiles them).
    {"eps1.5", "relative", 600, 1.5},
    // T_x and M_z noise-free (the default floors their sigma at 1e-6 of the RMS, with a
    // warning); T_y and M_roll with the relative condition's noise.
    {"noisefree", "relative", 600, 1e-2, {true, false, true, false}},
};
constexpr int kDesignCount = static_cast<int>(std::size(kDesigns));

int condition_index(const std::string& name) {
  for (int k = 0; k < kConditionCount; ++k)
    if (name == kConditions[k].name) return k;
  std::cerr << "unknown noise condition " << name << "\n";
  std::exit(2);
}

struct Cell {
  int condition = 0;
  int design = 0;  // kDesigns
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

// A warning's kind (docs/physics.md section 8.9) from a phrase of its text; "other" otherwise.
std::string warning_kind(const std::string& w) {
  static const std::pair<const char*, const char*> kinds[] = {
      {"HC3 sandwich", "sandwich"},
      {"pressure implies", "law"},
      {"strongly correlated", "correlation"},
      {"at rounding level", "noise-free"},
      {"beyond 6 sigma", "outliers"},
      {"structure against eps", "runs"},
      {"the fit explains", "low-R2"},
      {"not determined by the data", "not-determined"},
      {"poorly determined", "poorly-determined"},
      {"grow with the measured magnitude", "grows-with-signal"},
      {"noise estimate of", "noise-estimate"},
      {"did not converge", "not-converged"},
  };
  for (const auto& [phrase, kind] : kinds)
    if (w.find(phrase) != std::string::npos) return kind;
  return "other";
}

std::uint64_t noise_seed(int condition, ModelKind model, int replicate) {
  return 20261123ULL + 1000003ULL * static_cast<std::uint64_t>(condition) +
         100000007ULL * static_cast<std::uint64_t>(static_cast<int>(model)) +
         static_cast<std::uint64_t>(replicate);
}

// The dataset of replicate `replicate`: the default design's noise-free rows plus Gaussian noise
// with sigma_i^2 = s_abs^2 + (s_rel y_i)^2 (additive: sigma_i = s_abs + s_rel |y_i|) per channel,
// none on the design's noise-free channels; sigma columns hold the true sigma.
Dataset make_data(const Dataset& clean, const std::array<double, kChannelCount>& s_abs,
                  const NoiseCondition& cond, const DesignSpec& design, bool columns,
                  std::uint64_t seed) {
  Dataset d = clean;
  NormalStream normal(seed);
  for (int c = 0; c < kChannelCount; ++c)
    if (columns && !clean.value[c].empty()) d.sigma[c].assign(d.rows(), 0.0);
  for (std::size_t i = 0; i < d.rows(); ++i)
    for (int c = 0; c < kChannelCount; ++c) {
      if (clean.value[c].empty()) continue;  // a channel the design does not have (M_tilt)
      const double y = clean.value[c][i];
      const double sd = design.noise_free[c] ? 0.0
                        : cond.additive      ? s_abs[c] + cond.rel[c] * std::fabs(y)
                                             : std::hypot(s_abs[c], cond.rel[c] * y);
      d.value[c][i] = y + sd * normal.next();
      if (columns) d.sigma[c][i] = sd > 0.0 ? sd : 1e-300;
    }
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  int replicates = 500, replicates_exact = 500, baseline = 300, jobs = 2;
  int interval_replicates = 400, bootstrap_resamples = 199, design_replicates = 500;
  std::string which = "all";  // all, default (model-based and HC3 cells), intervals or designs
  std::string conditions;     // comma-separated noise conditions of the default cells; empty: all
  std::string designs;        // comma-separated designs of the design cells; empty: all
  std::string design_intervals = "profile";  // the design cells' --intervals: profile or model
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
    else if (a == "--design-replicates")
      design_replicates = std::stoi(next());
    else if (a == "--designs")
      designs = next();
    else if (a == "--design-intervals")
      design_intervals = next();
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
  if (which != "all" && which != "default" && which != "intervals" && which != "designs") {
    std::cerr << "--cells must be all, default, intervals or designs, not " << which << "\n";
    return 2;
  }
  if (design_intervals != "profile" && design_intervals != "model") {
    std::cerr << "--design-intervals must be profile or model, not " << design_intervals << "\n";
    return 2;
  }
  auto listed = [](const std::string& list, const std::string& name) {
    if (list.empty()) return true;
    std::stringstream ss(list);
    std::string item;
    while (std::getline(ss, item, ','))
      if (item == name) return true;
    return false;
  };

  const auto law = model::PressureLaw<double>::hertz();
  const auto truth = default_parameters(law, 0.9, 1.15, 0.08);
  const ModelKind models[] = {ModelKind::Seed, ModelKind::Corrected, ModelKind::Exact};

  // Noise-free rows per design and model, and the absolute sigmas per model: a fraction of the
  // channel's RMS over the default design's rows (the RMS depends on the model a little), the
  // same in every design, so that fewer rows or another eps range do not change the noise.
  std::array<std::array<Dataset, 3>, kDesignCount> clean;  // [design][model]
  std::array<std::array<std::array<double, kChannelCount>, kConditionCount>, 3>
      s_abs{};  // [model][cond]
  for (int d = 0; d < kDesignCount; ++d) {
    SyntheticDesign design;
    design.rows = d == 0 ? rows : kDesigns[d].rows;
    design.eps_min = kDesigns[d].eps_min;
    for (int m = 0; m < 3; ++m)
      clean[d][m] = generate_dataset(models[m], law, truth, design, NoiseSpec{}, 1);
  }
  for (int m = 0; m < 3; ++m)
    for (int k = 0; k < kConditionCount; ++k)
      for (int c = 0; c < kChannelCount; ++c) {
        double ss = 0.0;
        for (double y : clean[0][m].value[c]) ss += y * y;
        s_abs[m][k][c] = kConditions[k].abs_rms[c] * std::sqrt(ss / static_cast<double>(rows));
      }

  std::vector<Cell> cells;
  for (int k = 0; k < kConditionCount && (which == "all" || which == "default"); ++k)
    if (conditions.empty() || conditions.find(kConditions[k].name) != std::string::npos)
      for (int m = 0; m < 3; ++m)
        for (bool columns : {false, true}) {
          const int n = models[m] == ModelKind::Exact ? replicates_exact : replicates;
          cells.push_back({k, 0, models[m], columns, NoiseModelKind::Auto, n});
          // The constant-noise baseline (precision comparison) without sigma columns only.
          if (baseline > 0 && !columns)
            cells.push_back(
                {k, 0, models[m], columns, NoiseModelKind::Constant, std::min(n, baseline)});
        }
  // Interval cells: the profile and the wild bootstrap on the same fits, default noise model, no
  // sigma columns; relative and affine noise (the heteroscedastic conditions), every model.
  if ((which == "all" || which == "intervals") && interval_replicates > 0)
    for (int k : {0, 2})
      for (int m = 0; m < 3; ++m)
        cells.push_back({k, 0, models[m], false, NoiseModelKind::Auto, interval_replicates, true,
                         bootstrap_resamples});
  // Design cells: default noise model, no sigma columns, every model; with the profile interval
  // of every parameter (--design-intervals profile) or as the default fit (model). The designs
  // with variants also with the true sigma columns and with the generating noise form.
  if ((which == "all" || which == "designs") && design_replicates > 0)
    for (int d = 1; d < kDesignCount; ++d)
      if (listed(designs, kDesigns[d].name))
        for (int m = 0; m < 3; ++m) {
          const int k = condition_index(kDesigns[d].condition);
          const bool profile = design_intervals == "profile";
          cells.push_back(
              {k, d, models[m], false, NoiseModelKind::Auto, design_replicates, profile, 0});
          if (!kDesigns[d].variants) continue;
          cells.push_back(
              {k, d, models[m], true, NoiseModelKind::Auto, design_replicates, profile, 0});
          cells.push_back(
              {k, d, models[m], false,
               kConditions[k].additive ? NoiseModelKind::Additive : NoiseModelKind::Relative,
               design_replicates, profile, 0});
        }
  std::vector<Task> tasks;
  for (int c = 0; c < static_cast<int>(cells.size()); ++c)
    for (int r = 1; r <= cells[c].replicates; ++r) tasks.push_back({c, r});
  // Slowest first (interval cells, then exact fits) so the workers finish together.
  auto weight = [&](const Task& t) {
    return 2 * (cells[t.cell].bootstrap > 0) + (cells[t.cell].model == ModelKind::Exact);
  };
  std::stable_sort(tasks.begin(), tasks.end(),
                   [&](const Task& x, const Task& y) { return weight(x) > weight(y); });

  std::ofstream out(output);
  if (!out) {
    std::cerr << "cannot write " << output << "\n";
    return 1;
  }
  out << "noise,design,model,columns,noise_model,methods,replicate,status,seconds,dof,chosen,"
         "warnings,floored,warning_kinds,parameter,correlated,truth,value,stderr,ci_lo,ci_hi,"
         "stderr_sandwich,"
         "hc3_lo,hc3_hi,profile_lo,profile_hi,profile_closed,stderr_bootstrap,bootstrap_lo,"
         "bootstrap_hi,bootstrap_refits\n";
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
          make_data(clean[cell.design][m], s_abs[m][cell.condition], kConditions[cell.condition],
                    kDesigns[cell.design], cell.columns,
                    noise_seed(cell.condition, cell.model, tasks[t].replicate));
      FitSettings s = FitSettings::defaults(cell.model, law, "hertz");
      s.noise_model = cell.noise_model;
      s.threads = 1;  // the bootstrap's refits too: the fits run in parallel instead
      if (cell.profile) s.intervals = IntervalMethod::Profile;
      s.bootstrap = cell.bootstrap;
      std::ostringstream line;
      const std::string methods = !cell.profile        ? "default"
                                  : cell.bootstrap > 0 ? "profile+bootstrap"
                                                       : "profile";
      const std::string head = std::string(kConditions[cell.condition].name) + "," +
                               kDesigns[cell.design].name + "," + model_name(cell.model) + "," +
                               (cell.columns ? "yes" : "no") + "," +
                               noise_model_name(cell.noise_model) + "," + methods + "," +
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
                                                        : "fixed";
        }
        const double tq =
            r.dof > 0 ? student_t_quantile(0.975, static_cast<double>(r.dof)) : 1.959963984540054;
        const std::string status = r.solver.converged ? "ok" : "not_converged";
        // Noise-free channels named by the warning that floors their sigma (docs/physics.md
        // section 8.10).
        int floored = 0;
        std::string kinds;  // the fit's warnings by kind, ';'-separated, in order
        for (const auto& w : r.warnings) {
          floored += w.find("at rounding level") != std::string::npos;
          kinds += (kinds.empty() ? "" : ";") + warning_kind(w);
        }
        // The parameters whose profile interval the default computes too: |r| > 0.99 to another.
        auto correlated = [&](const std::string& name) {
          const auto& names = r.correlation_names;
          const auto it = std::find(names.begin(), names.end(), name);
          if (it == names.end()) return false;
          const auto a = static_cast<std::size_t>(it - names.begin());
          for (std::size_t b = 0; b < names.size(); ++b)
            if (b != a && std::fabs(r.correlation[a][b]) > 0.99) return true;
          return false;
        };
        for (const auto& p : r.parameters) {
          if (p.fixed) continue;
          const int pi = *param_index(p.name);
          line << head << "," << status << "," << secs << "," << r.dof << "," << chosen << ","
               << r.warnings.size() << "," << floored << "," << kinds << "," << p.name << ","
               << (correlated(p.name) ? 1 : 0) << "," << truth[pi] << "," << p.value << ",";
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
        line << head << ",failed," << secs << ",,,,,,,,,,,,,,,,,,,,,,\n";
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
