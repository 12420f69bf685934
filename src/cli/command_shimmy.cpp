// frictionid shimmy: a towed wheel or nose landing gear under a model's friction
// (docs/physics.md §10); JSON summary on stdout, trajectory CSV on request, and with
// --speed-sweep the stability map DIR/shimmy.csv and DIR/shimmy.html.
#include <unistd.h>

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <frictionid/io/input_error.hpp>
#include "app/shimmy.hpp"
#include "app/shimmy_sweep.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "io/atomic_file.hpp"

namespace frictionid::cli {

namespace {

bool shows_progress(const app::ShimmyRequest& r) {
  return r.progress || ::isatty(STDERR_FILENO) == 1;
}

// The contact spot's table while it is built (a rough map's takes seconds to minutes), on the
// progress line; *shown set once it is there (null: the caller clears the line anyway).
app::TableProgress table_progress(bool tty, bool* shown = nullptr) {
  if (!tty) return {};
  return [shown](std::size_t points) {
    std::fprintf(stderr, "\rcontact table: %zu points", points);
    std::fflush(stderr);
    if (shown) *shown = true;
  };
}

int run_sweep(const app::ShimmyRequest& r) {
  const bool tty = shows_progress(r);
  const auto progress = [tty](int done, int total) {
    if (!tty) return;
    std::fprintf(stderr, "\r\033[Kshimmy sweep: run %d of %d", done, total);
    std::fflush(stderr);
  };
  app::SweepResult s = app::shimmy_sweep(r, progress, table_progress(tty));
  if (tty) std::fprintf(stderr, "\r\033[K");
  const std::filesystem::path dir(r.sweep_dir);
  write_file_atomically((dir / "shimmy.csv").string(), app::sweep_csv(s));
  write_file_atomically((dir / "shimmy.html").string(),
                        app::sweep_html(s, "frictionid shimmy: stability map"));
  s.summary["files"] = {(dir / "shimmy.csv").string(), (dir / "shimmy.html").string()};
  std::cout << s.summary.dump(2) << "\n";
  return kExitOk;
}

}  // namespace

int run_shimmy(const app::ShimmyRequest& r) {
  if (!r.speed_sweep.empty()) {
    if (!r.output.empty())
      throw InputError("--output writes one run's trajectory: not with --speed-sweep");
    return run_sweep(r);
  }
  if (!r.sweep_param.empty()) throw InputError("--sweep-param needs --speed-sweep");
  bool shown = false;
  app::ShimmyResult out = app::shimmy(r, table_progress(shows_progress(r), &shown));
  if (shown) std::fprintf(stderr, "\r\033[K");
  if (!r.output.empty()) {
    write_file_atomically(r.output, app::shimmy_csv(out.rows));
    out.summary["trajectory_rows"] = out.rows.size();
  }
  std::cout << out.summary.dump(2) << "\n";
  if (out.run.step_limit) {
    std::cerr << "frictionid: error: the integration reached its step limit before --duration\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace frictionid::cli
