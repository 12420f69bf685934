// frictionid: identify the parameters of the coupled dry-friction model of a rolling, sliding and
// spinning contact from force/torque data. The only translation unit that includes CLI11.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "io/input_error.hpp"

namespace {

using namespace frictionid::cli;

const char* const kLawHelp =
    "pressure law: uniform, hertz, parabolic, power:N (N >= 0), table:FILE";

void add_coefficients(CLI::App& app, CoefficientsOptions& o) {
  auto* c = app.add_subcommand("coefficients",
                               "Moments of a pressure law and the coefficients a, b, m it implies");
  c->add_option("--pressure", o.pressure, kLawHelp)->capture_default_str();
  c->add_option("--kappa", o.kappa, "friction anisotropy kappa > 0")->capture_default_str();
  c->add_option("--alpha", o.alpha, "slip direction [rad], for m(alpha)")->capture_default_str();
  c->add_option("--format", o.format, "json or table")
      ->check(CLI::IsMember({"json", "table"}))
      ->capture_default_str();
}

void add_eval(CLI::App& app, EvalOptions& o) {
  auto* c = app.add_subcommand("eval", "Evaluate a model at one point or for every row of a CSV");
  c->add_option("--model", o.model, "seed, corrected or exact")->capture_default_str();
  c->add_option("--pressure", o.pressure, kLawHelp)->capture_default_str();
  c->add_option("--param", o.params,
                "parameters f=..,kappa=..,h=..[,a=..,b=..,m=..,n=..,p0=..,b_tilde=..]; "
                "omitted coefficients follow the pressure law");
  c->add_option("--vx", o.vx, "slip velocity along x [m/s]");
  c->add_option("--vy", o.vy, "slip velocity along y [m/s] (default 0)");
  c->add_option("--omega", o.omega, "spin [rad/s]");
  c->add_option("--N", o.N, "normal load [N]")->capture_default_str();
  c->add_option("--R", o.R, "contact radius [m]")->capture_default_str();
  c->add_option("--input", o.input, "CSV of kinematics (dataset columns)");
  c->add_option("--output", o.output, "CSV to write: the input columns plus the predictions");
  c->add_option("--columns", o.columns, "rename columns: canonical=header,...");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "frictionid: identify coupled dry-friction parameters (f, kappa, h, a, b, m) "
      "from force and torque data"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "frictionid 0.1.0");
  CoefficientsOptions coefficients;
  EvalOptions eval;
  add_coefficients(app, coefficients);
  add_eval(app, eval);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "frictionid: error: %s (see --help)\n", e.what());
    return kExitBadInput;
  }

  try {
    if (app.got_subcommand("coefficients")) return run_coefficients(coefficients);
    if (app.got_subcommand("eval")) return run_eval(eval);
  } catch (const frictionid::InputError& e) {
    std::fprintf(stderr, "frictionid: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "frictionid: error: %s\n", e.what());
    return kExitFailure;
  }
  return kExitFailure;
}
