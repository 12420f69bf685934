// frictionid: identify the parameters of the coupled dry-friction model of a rolling, sliding and
// spinning contact from force/torque data. The only translation unit that includes CLI11.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <frictionid/io/input_error.hpp>
#include "app/fit_request.hpp"
#include "app/generation.hpp"
#include "app/option_parsers.hpp"
#include "app/request_text.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "io/huge_pages.hpp"
#include "io/stop_check.hpp"
#include "io/text.hpp"

namespace {

using namespace frictionid::cli;
using namespace frictionid::app;
using frictionid::parse_column_map;
using frictionid::parse_contact_list;
using frictionid::parse_name_list;
using frictionid::parse_number_list;

// Said wherever an option names a file to write (src/io/atomic_file.hpp).
const char* const kOutputNote =
    "; a regular file is replaced atomically, a symlink's target likewise; a FIFO, device or "
    "/dev/stdout is written in place (not atomic)";

const char* const kLawHelp =
    "pressure law: uniform, hertz, parabolic, power:N (N >= 0), annulus:B (0 <= B < 1), ring, "
    "table:FILE";

const char* const kContactHelp =
    "contact spot: circle, ellipse:Q or rect:Q (semi-axis or half-width along y = Q R, "
    "0 < Q <= 4), or map:FILE (a measured pressure map x,y,sigma0 in units of R; it is the "
    "pressure, so no --pressure with it)";

// Counts and seeds are read by parse_whole_number (cli/option_parsers.hpp), not by CLI11, which
// would wrap "-1" into 2^64-1: out-of-range values are rejected before anything is allocated.
template <typename T>
CLI::Option* add_whole_number(CLI::App* c, const std::string& name, T& target, std::uint64_t lo,
                              std::uint64_t hi, const std::string& help) {
  return c
      ->add_option_function<std::string>(
          name,
          [&target, name, lo, hi](const std::string& text) {
            try {
              target = static_cast<T>(frictionid::parse_whole_number(name, text, lo, hi));
            } catch (const frictionid::InputError& e) {
              throw CLI::ValidationError(e.what());
            }
          },
          help + " (" + std::to_string(lo) + " to " + std::to_string(hi) + ")")
      ->type_name("UINT")
      ->default_str(std::to_string(target));
}

// What the command line reads as text before it becomes a request's typed values
// (app/request_text.hpp): the values of --param, --loads, --models and the like.
struct Texts {
  std::string coefficients_format = "json";
  std::string eval_params, eval_columns;
  std::string generate_params, loads = "2000,4000,6000", slip_angles = "0";
  FitText fit, compare, batch;
  std::string models = "seed,corrected,exact";
  std::string compare_contacts = "circle";
  std::string group_by, shared;
  std::string simulate_params;
  std::string shimmy_params;
};

void add_coefficients(CLI::App& app, CoefficientsRequest& o, std::string& format) {
  auto* c = app.add_subcommand("coefficients",
                               "Moments of a pressure law and the coefficients a, b, m it implies");
  c->add_option("--pressure", o.pressure, kLawHelp)->capture_default_str();
  c->add_option("--contact", o.contact,
                std::string(kContactHelp) + "; its a, b, m, p0, b_tilde by the same slope matching")
      ->capture_default_str();
  c->add_option("--kappa", o.kappa, "friction anisotropy kappa > 0")->capture_default_str();
  c->add_option("--alpha", o.alpha, "slip direction [rad], for m(alpha)")->capture_default_str();
  c->add_option("--format", format, "json or table")
      ->check(CLI::IsMember({"json", "table"}))
      ->capture_default_str();
}

void add_eval(CLI::App& app, EvalRequest& o, Texts& t) {
  auto* c = app.add_subcommand("eval", "Evaluate a model at one point or for every row of a CSV");
  c->add_option("--model", o.model.model, "seed, corrected or exact")->capture_default_str();
  c->add_option("--pressure", o.model.pressure, kLawHelp)->capture_default_str();
  c->add_option("--contact", o.model.contact, kContactHelp)->capture_default_str();
  c->add_option("--param", t.eval_params,
                "parameters f=..,kappa=..,h=..[,a=..,b=..,m=..,n=..,p0=..,b_tilde=..]; "
                "omitted coefficients follow the pressure law");
  c->add_option("--vx", o.vx, "slip velocity along x [m/s]");
  c->add_option("--vy", o.vy, "slip velocity along y [m/s] (default 0)");
  c->add_option("--omega", o.omega, "spin [rad/s]");
  c->add_option("--N", o.N, "normal load [N]")->capture_default_str();
  c->add_option("--R", o.R, "contact radius [m]")->capture_default_str();
  c->add_option("--input", o.input, "CSV of kinematics (dataset columns)");
  c->add_option("--output", o.output,
                std::string("CSV to write: the input columns plus the predictions") + kOutputNote);
  c->add_option("--columns", t.eval_columns, "rename columns: canonical=header,...");
  c->add_option("--threads", o.threads,
                "threads for the rows (0: every hardware thread); the output does not depend on "
                "it")
      ->capture_default_str();
  c->add_flag("--progress", o.progress,
              "progress line on stderr for --input (default: when it is a terminal)");
}

void add_generate(CLI::App& app, GenerateRequest& o, Texts& t) {
  auto* c = app.add_subcommand("generate", "Make a synthetic dataset from a model, with its truth");
  c->add_option("--model", o.model.model, "seed, corrected or exact")->capture_default_str();
  c->add_option("--pressure", o.model.pressure, kLawHelp)->capture_default_str();
  c->add_option("--contact", o.model.contact, kContactHelp)->capture_default_str();
  c->add_option("--param", t.generate_params, "true parameters f=..,kappa=..,h=..[,a=..,...]");
  add_whole_number(c, "--rows", o.rows, 1, kMaxGeneratedRows, "number of rows");
  c->add_option("--noise", o.noise, "relative Gaussian noise (fraction of each value)")
      ->capture_default_str();
  c->add_option("--noise-abs", o.noise_abs, "absolute Gaussian noise [channel units]")
      ->capture_default_str();
  c->add_flag("--sigma-columns", o.sigma_columns, "write the noise sigma as sigma_* columns");
  add_whole_number(c, "--seed", o.seed, 0, UINT64_MAX, "random seed");
  c->add_option("--output", o.output, std::string("CSV file to write") + kOutputNote)->required();
  c->add_option("--truth", o.truth,
                std::string("JSON file for the true parameters and design") + kOutputNote);
  c->add_option("--eps-min", o.eps_min, "smallest eps = v/(|omega| R)")->capture_default_str();
  c->add_option("--eps-max", o.eps_max, "largest eps")->capture_default_str();
  c->add_option("--loads", t.loads, "normal loads N [N], comma separated")->capture_default_str();
  c->add_option("--R", o.R, "contact radius [m]")->capture_default_str();
  c->add_option("--spin", o.spin, "|omega| [rad/s]; signs alternate")->capture_default_str();
  c->add_option("--slip-angles", t.slip_angles, "slip directions [deg], comma separated")
      ->capture_default_str();
  c->add_flag("--forward-only", o.forward_only, "no rows with backward slip (v_x < 0)");
  c->add_option("--threads", o.threads,
                "threads for the rows (0: every hardware thread); the data do not depend on it")
      ->capture_default_str();
  c->add_flag("--progress", o.progress, "progress line on stderr (default: when it is a terminal)");
}

// The options fit, compare and batch share (batch takes its own inputs instead of `data`).
void add_fit_options(CLI::App* c, FitRequest& o, FitText& t, bool with_data = true) {
  if (with_data) c->add_option("data", o.data, "dataset CSV")->required();
  c->add_option("--pressure", o.pressure, kLawHelp)->capture_default_str();
  c->add_option("--fix", t.fix, "hold parameters fixed: name=value,...");
  c->add_option("--free", t.free,
                "fit parameters held by default: h_y (held at 0 on a circle without an M_tilt "
                "column), q (the aspect of ellipse:Q or rect:Q, held at Q)");
  c->add_option("--bounds", t.bounds, "parameter bounds: name=lo:hi,...");
  c->add_option("--param", t.start, "initial values (used with --no-global): name=value,...");
  c->add_option("--loss", o.loss, "none, huber:S, cauchy:S or soft_l1:S (per row, S in sigmas)")
      ->capture_default_str();
  c->add_option("--noise-model", o.noise_model,
                "per-channel noise: auto (sigma columns where given, else the variance function "
                "with the smallest BIC), constant, relative, affine (sqrt(s_abs^2 + s_rel^2 "
                "fitted^2)), additive (s_abs + s_rel |fitted|), each estimated from the "
                "residuals, or columns (the sigma columns as given)")
      ->check(CLI::IsMember({"auto", "constant", "relative", "affine", "additive", "columns"}))
      ->capture_default_str();
  c->add_option("--intervals", o.intervals,
                "the 95 % interval report.md shows first: model (from the covariance), sandwich "
                "(HC3, no noise assumption) or profile (asymmetric, from the profile of the "
                "cost; refits per step)")
      ->check(CLI::IsMember({"model", "sandwich", "profile"}))
      ->capture_default_str();
  add_whole_number(c, "--bootstrap", o.bootstrap, 0, 100000,
                   "wild (Rademacher) bootstrap refits for percentile intervals, seeded by --seed "
                   "(0: none)");
  c->add_option("--starts", o.starts, "local fits from the best distinct global points")
      ->capture_default_str();
  add_whole_number(c, "--seed", o.seed, 0, kMaxFitSeed, "seed of the global stage");
  c->add_option("--global-evaluations", o.global_evaluations, "budget of the global stage")
      ->capture_default_str();
  add_whole_number(c, "--global-subsample", o.global_subsample, 1, 1'000'000'000,
                   "rows the global stage sees");
  c->add_option("--global-algorithm", o.global_algorithm,
                "crs2, isres, direct, esch or random (see experiments/global_search)")
      ->check(CLI::IsMember({"crs2", "isres", "direct", "esch", "random"}))
      ->capture_default_str();
  c->add_flag("--no-global", o.no_global, "skip the global stage; start from --param values");
  c->add_option("--channels", t.channels, "channels to fit, e.g. T_x,M_z (default: all measured)");
  c->add_option("--columns", t.columns, "rename columns: canonical=header,...");
  c->add_option("--threads", o.threads,
                "threads for the passes over the rows (0: every hardware thread); the results "
                "do not depend on it")
      ->capture_default_str();
  c->add_option("--report", o.report,
                with_data ? "directory for report.json, report.md, report.html and plots; replaced "
                            "as a whole, in one atomic step (DIR becomes a symlink to "
                            ".DIR.r-XXXXXX)"
                          : "directory for summary.csv, summary.json, journal.jsonl and runs/")
      ->required();
  c->add_flag("--no-wait", o.no_wait,
              "fail at once when another run is writing the same --report directory "
              "(default: wait for it)");
  c->add_flag("--progress", o.progress, "progress line on stderr (default: when it is a terminal)");
  c->add_option("--input-form", o.input_form,
                "the data's form: native (v_x, omega, N, R, T_x, ...), wheel (V, alpha, "
                "slip_ratio or omega_w, r_e, gamma, Fz, Fx, ... as a rig records them; CSV or "
                "TYDEX .tdx) or auto (wheel when the header has V and alpha and no v_x)")
      ->check(CLI::IsMember({"auto", "native", "wheel"}))
      ->capture_default_str();
  c->add_option("--axes", o.axes,
                "the wheel form's axes: iso (x heading, y left, z up) or sae (SAE J670: y right, "
                "z down)")
      ->check(CLI::IsMember({"iso", "sae"}))
      ->capture_default_str();
  c->add_option("--contact-radius", o.contact_radius,
                "contact radius R [m] of every row of a wheel-form file without an R column");
}

void add_fit(CLI::App& app, FitRequest& o, FitText& t) {
  auto* c =
      app.add_subcommand("fit", "Identify a model's parameters from a CSV and write a report");
  c->add_option("--model", o.model, "seed, corrected or exact")->capture_default_str();
  c->add_option("--contact", o.contact, kContactHelp)->capture_default_str();
  add_fit_options(c, o, t);
  c->add_option("--plot-x", o.plot_x,
                "report: also plot every channel against these CSV columns (e.g. slip_angle)")
      ->delimiter(',');
  c->add_option("--color-by", o.color_by,
                "report: colour the collapse plots by this column (default: N when it has at "
                "most 8 levels)");
}

void add_compare(CLI::App& app, CompareRequest& o, Texts& t) {
  auto* c = app.add_subcommand(
      "compare", "Fit seed, corrected and exact to the same rows and report them side by side");
  c->add_option("--models", t.models, "models to compare, comma separated")->capture_default_str();
  c->add_option("--contact", t.compare_contacts,
                "contact spots, comma separated (e.g. circle,ellipse:0.7): every model is fitted "
                "on each; " +
                    std::string(kContactHelp))
      ->capture_default_str();
  add_fit_options(c, o.fit, t.compare);
}

void add_batch(CLI::App& app, BatchRequest& o, Texts& t) {
  auto* c = app.add_subcommand(
      "batch",
      "Fit many runs (files, a directory, a manifest or groups of one CSV) into one "
      "summary table: DIR/summary.csv, DIR/summary.json and DIR/summary.html");
  c->add_option("inputs", o.inputs,
                "CSV files, globs, directories (their *.csv) or manifest CSVs (a `path` column)")
      ->required();
  c->add_option("--model", o.fit.model, "seed, corrected or exact")->capture_default_str();
  c->add_option("--contact", o.fit.contact,
                std::string(kContactHelp) + "; a manifest's contact column replaces it per run")
      ->capture_default_str();
  add_fit_options(c, o.fit, t.batch, /*with_data=*/false);
  c->add_option("--group-by", t.group_by, "split each CSV into one run per value of COL[,COL]");
  c->add_option("--per-run-reports", o.per_run_reports,
                "none, json (runs/<label>/report.json) or full (the whole report in "
                "runs/<label>/)")
      ->check(CLI::IsMember({"none", "json", "full"}))
      ->capture_default_str();
  c->add_flag("--force", o.force, "fit every run again, ignoring DIR/journal.jsonl");
  c->add_option("--jobs", o.jobs, "runs fitted at once (0: every hardware thread)")
      ->capture_default_str();
  c->add_flag("--warm-start", o.warm_start,
              "fit the first run in full, then start every other run's local fit from its "
              "parameters without the global stage; a run whose warm fit does not converge or "
              "fits a channel over twice as loosely (sqrt(1 - R^2)) gets the full search");
  c->add_option("--shared", t.shared,
                "P[,P]: after the runs' own fits, one joint fit in which these parameters are "
                "common to every run (DIR/shared.csv, DIR/shared.json), e.g. kappa,h");
  c->add_option("--trend-x", o.trend_x,
                "the covariate on the x axis of summary.html's trend plots (mean_N, mean_speed, "
                "mean_omega_R, a manifest or --group-by column)")
      ->capture_default_str();
  c->add_option("--keep", o.fit.keep,
                "COL[,COL]: columns of the data (a tire id, the pressure, a run number) whose "
                "value in each run goes to summary.csv; a run whose rows differ lists them "
                "joined by '|'")
      ->delimiter(',');
}

void add_simulate(CLI::App& app, SimulateRequest& o, Texts& t) {
  auto* c = app.add_subcommand(
      "simulate", "Slide and spin a flat body to rest under a model's friction (physics §4)");
  c->add_option("--model", o.model.model, "seed, corrected or exact")->capture_default_str();
  c->add_option("--pressure", o.model.pressure, kLawHelp)->capture_default_str();
  c->add_option("--contact", o.model.contact, kContactHelp)->capture_default_str();
  c->add_option("--param", t.simulate_params,
                "friction parameters f=..,kappa=..,h=..[,a=..,...] as eval");
  c->add_option("--inertia-ratio", o.inertia_ratio,
                "I/(M_b R^2): 0.5 uniform disk, 1 thin ring (required)");
  c->add_option("--v0", o.v0, "initial slip speed [m/s]")->capture_default_str();
  c->add_option("--omega0", o.omega0, "initial spin [rad/s]")->capture_default_str();
  c->add_option("--slip-angle", o.slip_angle_deg, "initial slip direction from x [deg]")
      ->capture_default_str();
  c->add_option("--mass", o.mass, "body mass M_b [kg]")->capture_default_str();
  c->add_option("--R", o.R, "contact radius [m]")->capture_default_str();
  c->add_option("--N", o.N, "normal load [N] (default M_b g, g = 9.81)");
  c->add_option(
      "--output", o.output,
      std::string("trajectory CSV: t,v_x,v_y,omega,eps,T_x,T_y,M_z,energy") + kOutputNote);
  c->add_option("--tol", o.tol, "integrator tolerance (relative and absolute)")
      ->capture_default_str();
  c->add_option("--stop-fraction", o.stop_fraction,
                "end when |(v, omega R)| falls below this fraction of its start")
      ->capture_default_str();
  c->add_option("--max-steps", o.max_steps, "step limit")->capture_default_str();
}

void add_shimmy(CLI::App& app, ShimmyRequest& o, Texts& t) {
  auto* c = app.add_subcommand(
      "shimmy", "Shimmy of a towed wheel or nose gear under a model's friction (physics §10)");
  c->add_option("--model", o.model.model, "seed, corrected or exact")->capture_default_str();
  c->add_option("--pressure", o.model.pressure, kLawHelp)->capture_default_str();
  c->add_option("--contact", o.model.contact, kContactHelp)->capture_default_str();
  c->add_option("--param", t.shimmy_params,
                "friction parameters f=..,kappa=..,h=..[,a=..,...] as eval");
  c->add_option("--from-report", o.from_report,
                "report.json of a fit: its model, pressure, contact and parameters (no --param)");
  c->add_option("--N", o.N, "normal load [N]")->capture_default_str();
  c->add_option("--R", o.R, "contact radius [m]")->capture_default_str();
  c->add_option("--speed", o.speed, "forward speed V of the king pin [m/s]")->capture_default_str();
  c->add_option("--caster", o.caster, "caster e: the contact trails the king pin by e [m]")
      ->capture_default_str();
  c->add_option("--yaw-inertia", o.yaw_inertia, "yaw inertia J of the fork [kg m^2]")
      ->capture_default_str();
  c->add_option("--yaw-stiffness", o.yaw_stiffness, "torsional stiffness k_psi [N m/rad]")
      ->capture_default_str();
  c->add_option("--yaw-damping", o.yaw_damping, "torsional damping c_psi [N m s/rad]")
      ->capture_default_str();
  c->add_option("--lateral-mass", o.lateral_mass, "lateral mass m_y of the strut [kg]")
      ->capture_default_str();
  c->add_option("--lateral-stiffness", o.lateral_stiffness, "lateral stiffness k_y [N/m]")
      ->capture_default_str();
  c->add_option("--lateral-damping", o.lateral_damping, "lateral damping c_y [N s/m]")
      ->capture_default_str();
  c->add_option("--lateral", o.lateral, "elastic, or rigid (y = 0)")
      ->check(CLI::IsMember({"elastic", "rigid"}))
      ->capture_default_str();
  c->add_option("--contact-law", o.contact_law,
                "friction (the model), or nonholonomic (Keldysh's no-slip u_y = 0)")
      ->check(CLI::IsMember({"friction", "nonholonomic"}))
      ->capture_default_str();
  c->add_option("--psi0", o.psi0, "initial yaw angle [rad]")->capture_default_str();
  c->add_option("--y0", o.y0, "initial lateral displacement [m]")->capture_default_str();
  c->add_option("--duration", o.duration, "time to integrate [s]")->capture_default_str();
  c->add_option("--output", o.output,
                std::string("trajectory CSV: t,y,y_dot,psi,psi_dot,u_y,T_y,M_z") + kOutputNote);
  c->add_option("--output-step", o.output_step,
                "rows at k*DT from the dense output (0: every integrator step)")
      ->capture_default_str();
  c->add_option("--tol", o.tol, "integrator tolerance (relative, and absolute per state scale)")
      ->capture_default_str();
  c->add_option("--integrator", o.integrator,
                "switching (implicit RODAS steps where the friction is stiff) or explicit "
                "(Dormand-Prince only)")
      ->check(CLI::IsMember({"switching", "explicit"}))
      ->capture_default_str();
  c->add_option("--stick-threshold", o.stick_threshold,
                "slip below this fraction of its scale ends a slip phase (the cohesion test)")
      ->capture_default_str();
  c->add_option("--cycle-tol", o.cycle_tol, "relative amplitude change per cycle of a limit cycle")
      ->capture_default_str();
  c->add_option("--speed-sweep", o.speed_sweep,
                "A:B:N: N speeds, each continued from the last limit cycle; writes "
                "DIR/shimmy.csv and DIR/shimmy.html");
  c->add_option("--sweep-param", o.sweep_param,
                "NAME:A:B:M with --speed-sweep: repeat it for M values of yaw-damping, caster, "
                "yaw-stiffness or lateral-damping (a 2-D map)");
  c->add_option("--sweep-dir", o.sweep_dir, "directory of shimmy.csv and shimmy.html")
      ->capture_default_str();
  c->add_option("--onset-tol", o.onset_tol,
                "onset speeds by bisection to this [m/s] (0: 1e-3 of the sweep's range)")
      ->capture_default_str();
  c->add_flag("--progress", o.progress, "progress line on stderr (default: when it is a terminal)");
  add_whole_number(c, "--table-directions", o.table_directions, 0, 1 << 20,
                   "tabulate the friction over this many slip directions (0: the model itself; "
                   "e.g. 4096 for the exact model's speed)");
}

// A fit allocates and frees arrays of every row again and again (dataset copies, residuals,
// predictions). Above glibc's mmap threshold each would come fresh from the kernel and fault in
// page by page, a fifth of a 1e5-row fit; kept in the heap, freed blocks are reused. Not under
// AddressSanitizer, whose allocator ignores mallopt and would poison the primed block's 30 MiB of
// shadow twice, half of every start (the sanitizer stage of .ci/run starts thousands).
void keep_large_blocks_in_the_heap() {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  // The heap's first 240 MiB ask for transparent huge pages: one fault per 2 MiB, where 4 KiB
  // pages cost ~7000 faults (a quarter of the time) in a 1e5-row fit on a virtual machine. It is
  // address space only: pages are committed as they are written, and stay with the heap after
  // the free (below the trim threshold).
  constexpr std::size_t kPrimed = std::size_t{240} << 20;  // below the mmap threshold
  if (void* block = std::malloc(kPrimed)) {
    frictionid::io_detail::advise_huge_pages(block, kPrimed);
    std::free(block);
  }
#endif
}

}  // namespace

int main(int argc, char** argv) {
  keep_large_blocks_in_the_heap();
  CLI::App app{
      "frictionid: identify coupled dry-friction parameters (f, kappa, h, a, b, m) "
      "from force and torque data"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "frictionid " FRICTIONID_VERSION);
  Texts texts;
  CoefficientsRequest coefficients;
  EvalRequest eval;
  add_coefficients(app, coefficients, texts.coefficients_format);
  add_eval(app, eval, texts);
  GenerateRequest generate;
  FitRequest fit;
  add_generate(app, generate, texts);
  add_fit(app, fit, texts.fit);
  CompareRequest compare;
  add_compare(app, compare, texts);
  SimulateRequest simulate;
  add_simulate(app, simulate, texts);
  ShimmyRequest shimmy;
  add_shimmy(app, shimmy, texts);
  BatchRequest batch;
  add_batch(app, batch, texts);

  // An empty value ("--param ''", "--fix=") would otherwise read as "option not given".
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool empty_inline = arg.rfind("--", 0) == 0 && !arg.empty() && arg.back() == '=';
    if (arg.empty() || empty_inline) {
      const std::string after = i > 1 ? std::string(" after ") + argv[i - 1] : std::string();
      std::fprintf(stderr,
                   "frictionid: error: empty argument %d%s; expected a value (see --help)\n", i,
                   frictionid::text::for_terminal(empty_inline ? " (" + arg + ")" : after).c_str());
      return kExitBadInput;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "frictionid: error: %s (see --help)\n",
                 frictionid::text::for_terminal(e.what()).c_str());
    return kExitBadInput;
  }

  // The reports name the command that made them; "frictionid" rather than argv[0], which may
  // be a path into a build directory.
  std::vector<std::string> words{"frictionid"};
  for (int i = 1; i < argc; ++i) words.emplace_back(argv[i]);
  fit.command_line = compare.fit.command_line = batch.fit.command_line =
      frictionid::text::command_line(words);
  // A pressure map is the pressure: --pressure with --contact map:FILE is an error, which needs
  // to know whether --pressure was given at all (its default is hertz).
  const auto pressure_given = [&app](const char* subcommand) {
    return app.get_subcommand(subcommand)->count("--pressure") > 0;
  };
  coefficients.pressure_given = pressure_given("coefficients");
  eval.model.pressure_given = pressure_given("eval");
  generate.model.pressure_given = pressure_given("generate");
  fit.pressure_given = pressure_given("fit");
  compare.fit.pressure_given = pressure_given("compare");
  simulate.model.pressure_given = pressure_given("simulate");
  shimmy.model.pressure_given = pressure_given("shimmy");
  batch.fit.pressure_given = pressure_given("batch");

  try {
    if (app.got_subcommand("coefficients"))
      return run_coefficients(coefficients, texts.coefficients_format);
    if (app.got_subcommand("eval")) {
      eval.model.params = parameter_values(texts.eval_params);
      eval.columns = parse_column_map(texts.eval_columns);
      return run_eval(eval);
    }
    if (app.got_subcommand("generate")) {
      generate.model.params = parameter_values(texts.generate_params);
      generate.loads = parse_number_list("--loads", texts.loads);
      generate.slip_angles_deg = parse_number_list("--slip-angles", texts.slip_angles);
      return run_generate(generate);
    }
    if (app.got_subcommand("fit")) {
      apply(texts.fit, fit);
      return run_fit(fit);
    }
    if (app.got_subcommand("compare")) {
      compare.models = parse_name_list("--models", texts.models);
      compare.contacts = parse_contact_list("--contact", texts.compare_contacts);
      apply(texts.compare, compare.fit);
      return run_compare(compare);
    }
    if (app.got_subcommand("simulate")) {
      simulate.model.params = parameter_values(texts.simulate_params);
      return run_simulate(simulate);
    }
    if (app.got_subcommand("shimmy")) {
      shimmy.model.params = parameter_values(texts.shimmy_params);
      return run_shimmy(shimmy);
    }
    if (app.got_subcommand("batch")) {
      batch.group_by = name_list("--group-by", texts.group_by);
      batch.shared = shared_names(texts.shared);
      apply(texts.batch, batch.fit);
      return run_batch(batch);
    }
  } catch (const frictionid::Interrupted& e) {
    std::fprintf(stderr, "frictionid: %s; the earlier report (if any) is unchanged\n",
                 frictionid::text::for_terminal(e.what()).c_str());
    return kExitInterrupted;
  } catch (const frictionid::InputError& e) {
    std::fprintf(stderr, "frictionid: error: %s\n",
                 frictionid::text::for_terminal(e.what()).c_str());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "frictionid: error: %s\n",
                 frictionid::text::for_terminal(e.what()).c_str());
    return kExitFailure;
  }
  return kExitFailure;
}
