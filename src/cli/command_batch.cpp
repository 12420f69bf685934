// frictionid batch: fit many runs (files, manifest entries or groups of one file) on threads and
// write one summary table. DIR is a plain directory, not a swapped report: it holds the journal
// (appended as runs finish), runs/<label>/ (each file written atomically) and summary.csv and
// summary.json, written atomically once every run has an outcome.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

#include <frictionid/fit_error.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/report_writer.hpp>
#include <frictionid/io/summary_html.hpp>
#include <frictionid/io/summary_table.hpp>
#include "app/batch_fit_run.hpp"
#include "app/batch_journal.hpp"
#include "app/batch_runs.hpp"
#include "app/batch_shared_fit.hpp"
#include "app/batch_warm_start.hpp"
#include "app/fit_request.hpp"
#include "app/report_provenance.hpp"
#include "app/request_json.hpp"
#include "app/requests.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/signals.hpp"
#include "cli/terminal_observer.hpp"
#include "identify/thread_budget.hpp"
#include "io/atomic_file.hpp"
#include "io/report_directory_lock.hpp"
#include "io/text.hpp"

namespace frictionid::cli {

namespace {

namespace fs = std::filesystem;
using namespace app;
using seconds = std::chrono::duration<double>;

struct BatchContext {
  const BatchRequest& options;
  fs::path dir;
  int fit_threads = 1;
  const std::atomic<bool>* interrupted = nullptr;
};

// A run's report names the batch's command, the run's own resolved options and the bytes of its
// file as the batch planned them (the fingerprint the journal keys on).
Provenance run_provenance(const BatchRequest& o, const BatchRun& run) {
  Provenance p;
  p.command_line = o.fit.command_line;
  p.options = fit_request_json(run.options);
  p.inputs.push_back(InputFile{run.path, run.input.size, run.input.sha256});
  return p;
}

void write_run_report(const BatchContext& c, const BatchRun& run, const FitResult& r,
                      const Dataset& data) {
  const fs::path dir = c.dir / "runs" / run.directory;
  if (c.options.per_run_reports == "full") {
    ReportOptions options;  // as many threads as each run fits on
    options.threads = c.fit_threads;
    options.provenance = run_provenance(c.options, run);
    write_report(dir.string(), r, data, options);
  } else if (c.options.per_run_reports == "json") {
    fs::create_directories(dir);
    const auto json = report_json(r, run_provenance(c.options, run))
                          .dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    // Durable with the journal's next sync (batch_journal.hpp), not one flush per run.
    write_file_atomically((dir / "report.json").string(), json + "\n", Flush::Later);
  }
}

// One run's outcome: a failure of any kind is a failed row, never the end of the batch.
// `fitted`, when given, receives the successful fit.
// `read` receives the fingerprint of the bytes the fit read (for the journal).
SummaryRow fit_run(const BatchContext& c, const BatchRun& run, const WarmStart* warm,
                   FileFingerprint& read, std::optional<FitResult>* fitted = nullptr) {
  TerminalObserver observer(c.interrupted, /*progress=*/false);
  return fit_batch_run(
      run, c.fit_threads, &observer,
      [&](const FitResult& r, const Dataset& data) {
        write_run_report(c, run, r, data);
        if (fitted) *fitted = r;
      },
      warm, &read);
}

// With --warm-start every run but the first depends on the first run's fit: a journal entry
// fitted from another first run is not this run's outcome.
void key_on_first_run(std::vector<BatchRun>& runs) {
  for (std::size_t i = 1; i < runs.size(); ++i)
    runs[i].key ^= runs[0].key + 0x9e3779b97f4a7c15ULL + (runs[i].key << 6) + (runs[i].key >> 2);
}

// Whether a run the journal holds still has the report file it was written with: a power cut
// between two syncs may keep a journal line and lose its report (batch_journal.hpp), and a
// deleted runs/<label>/ means the user wants it back. Such a run is fitted again.
bool has_run_report(const fs::path& dir, const std::string& per_run_reports, const BatchRun& run) {
  if (per_run_reports == "none") return true;
  std::error_code ec;
  const auto size = fs::file_size(dir / "runs" / run.directory / "report.json", ec);
  return !ec && size > 0;
}

std::string duration_text(double s) {
  char buf[32];
  const long t = static_cast<long>(s + 0.5);
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", t / 60, t % 60);
  return buf;
}

SummaryHtmlOptions summary_page_options(const BatchRequest& o, const std::vector<BatchRun>& runs) {
  SummaryHtmlOptions h;
  h.trend_x = o.trend_x;
  h.run_reports = o.per_run_reports == "full"   ? RunReports::Full
                  : o.per_run_reports == "json" ? RunReports::Json
                                                : RunReports::None;
  for (const auto& run : runs) h.run_directories[run.label] = run.directory;
  // The batch's command and options, and every file its runs read, each once.
  h.provenance.command_line = o.fit.command_line;
  h.provenance.options = fit_request_json(o.fit);
  for (const auto& run : runs) {
    const bool seen = std::any_of(h.provenance.inputs.begin(), h.provenance.inputs.end(),
                                  [&](const InputFile& f) { return f.path == run.path; });
    if (!seen) h.provenance.inputs.push_back(InputFile{run.path, run.input.size, run.input.sha256});
  }
  return h;
}

}  // namespace

int run_batch(const BatchRequest& o) {
  const auto t_start = std::chrono::steady_clock::now();
  if (o.jobs < 0) throw InputError("--jobs must be 0 (every hardware thread) or more");
  // Bad options fail before any work.
  const FitSettings command_line = fit_settings(o.fit, o.fit.model);
  const std::vector<std::string>& shared = o.shared;
  check_shared_option(shared, command_line);
  if (o.fit.report.empty()) throw InputError("batch needs --report DIR");
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  const ReportDirectoryLock lock(o.fit.report, /*wait=*/!o.fit.no_wait);
  std::error_code ec;
  if (fs::exists(o.fit.report, ec) && !fs::is_directory(o.fit.report, ec))
    throw InputError(o.fit.report, 0, 0, "--report: exists and is not a directory");

  std::vector<std::string> skipped;
  std::vector<BatchRun> runs =
      plan_batch_runs(o.inputs, o.fit, o.group_by, "reports=" + o.per_run_reports, &skipped);
  for (const auto& s : skipped)
    std::fprintf(stderr, "frictionid: skipped %s\n", text::for_terminal(s).c_str());
  if (o.warm_start) key_on_first_run(runs);
  check_shared_parameters(runs, shared);
  check_trend_x(o.trend_x, runs);
  fs::create_directories(o.fit.report);
  // A killed batch may have left a run's report half-renamed: its temporary files go, as a
  // fit's leftovers do (the lock keeps any other writer out).
  remove_atomic_leftovers(o.fit.report);
  if (std::error_code list_error; fs::is_directory(fs::path(o.fit.report) / "runs", list_error))
    for (const auto& e : fs::directory_iterator(fs::path(o.fit.report) / "runs", list_error))
      if (e.is_directory(list_error) && !e.is_symlink(list_error))
        remove_atomic_leftovers(e.path().string());
  BatchJournal journal((fs::path(o.fit.report) / "journal.jsonl").string(), o.force);

  std::vector<std::optional<SummaryRow>> rows(runs.size());
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    bool changed = false;
    const SummaryRow* done = journal.finished(runs[i].label, runs[i].key, runs[i].input, &changed);
    if (changed)
      std::fprintf(stderr,
                   "frictionid: run '%s': its journal line is of other bytes than %s holds now "
                   "(the file changed while it was fitted); fitting it again\n",
                   text::for_terminal(runs[i].label).c_str(),
                   text::for_terminal(runs[i].path).c_str());
    if (done && has_run_report(o.fit.report, o.per_run_reports, runs[i]))
      rows[i] = *done;
    else
      pending.push_back(i);
  }
  const std::size_t from_journal = runs.size() - pending.size();

  // --threads bounds every busy thread of the batch: its runs at once and whatever each run's
  // reading, fitting and report take (identify/thread_budget.hpp). --jobs is at most that.
  ThreadBudget budget(o.fit.threads);
  const ThreadBudgetScope budget_scope(&budget);
  const std::size_t jobs = std::clamp<std::size_t>(
      o.jobs > 0 ? static_cast<std::size_t>(o.jobs) : static_cast<std::size_t>(budget.total()), 1,
      std::min<std::size_t>(static_cast<std::size_t>(budget.total()),
                            std::max<std::size_t>(1, pending.size())));
  // Several fits at once each take one thread; alone, a fit may use --threads. The results do
  // not depend on either.
  const BatchContext context{o, fs::path(o.fit.report), jobs == 1 ? o.fit.threads : 1, interrupted};
  const bool progress = show_progress(o.fit.progress);

  std::atomic<std::size_t> next{0};
  std::mutex mutex;  // guards the counters below, the progress line and first_error
  std::size_t fitted = 0, failed = 0;
  std::exception_ptr first_error;
  const auto t_fits = std::chrono::steady_clock::now();

  // --warm-start: the first run is fitted in full before the others, which start from it. When
  // the journal has its row, it is fitted again for its parameters only (same fit, same numbers).
  // Alone, it may use --threads (the numbers do not depend on it).
  std::optional<WarmStart> warm;
  if (o.warm_start && !pending.empty() && runs.size() > 1) {
    const BatchContext alone{o, context.dir, o.fit.threads, interrupted};
    std::optional<FitResult> first;
    // Interrupted, the workers stop at once and the batch ends as any interrupted batch does.
    if (pending.front() == 0) {
      FileFingerprint read;
      SummaryRow row = fit_run(alone, runs[0], nullptr, read, &first);
      if (!interrupted->load()) {
        journal.record(runs[0].key, row, read);
        ++fitted;
        if (!row.ok) ++failed;
        rows[0] = std::move(row);
        next = 1;
      }
    } else {
      TerminalObserver observer(interrupted, /*progress=*/false);
      fit_batch_run(runs[0], o.fit.threads, &observer,
                    [&](const FitResult& r, const Dataset&) { first = r; });
    }
    if (first) warm = warm_start_from(runs[0].label, *first);
  }
  const WarmStart* warm_start = warm ? &*warm : nullptr;
  auto worker = [&] {
    for (;;) {
      if (interrupted->load()) return;
      {
        std::lock_guard<std::mutex> guard(mutex);
        if (first_error) return;
      }
      const std::size_t k = next.fetch_add(1);
      if (k >= pending.size()) return;
      const BatchRun& run = runs[pending[k]];
      FileFingerprint read;
      SummaryRow row = fit_run(context, run, warm_start, read);
      if (interrupted->load()) return;  // a cancelled fit is not an outcome: fit it next time
      try {
        journal.record(run.key, row, read);
      } catch (...) {
        std::lock_guard<std::mutex> guard(mutex);
        if (!first_error) first_error = std::current_exception();
        return;
      }
      std::lock_guard<std::mutex> guard(mutex);
      ++fitted;
      if (!row.ok) ++failed;
      rows[pending[k]] = std::move(row);
      if (progress) {
        const double elapsed = seconds(std::chrono::steady_clock::now() - t_fits).count();
        const double eta = elapsed / fitted * (pending.size() - fitted);
        std::fprintf(stderr, "\rfrictionid batch: %zu/%zu runs fitted, %zu failed, ETA %s   ",
                     fitted, pending.size(), failed, duration_text(eta).c_str());
      }
    }
  };
  std::vector<std::thread> threads;
  const int helpers = budget.acquire(static_cast<int>(jobs) - 1);
  for (int t = 0; t < helpers; ++t)
    threads.emplace_back([&] {
      const ThreadBudgetScope scope(&budget);
      worker();
    });
  worker();
  for (auto& t : threads) t.join();
  budget.release(helpers);
  if (progress && fitted > 0) std::fprintf(stderr, "\r%80s\r", "");
  if (first_error) std::rethrow_exception(first_error);
  journal.sync();  // every line and run report durable before the summary names them
  if (interrupted->load()) {
    std::fprintf(stderr,
                 "frictionid: interrupted after %zu of %zu runs; they are in %s/journal.jsonl, "
                 "run the same command again to fit the rest\n",
                 fitted + from_journal, runs.size(), text::for_terminal(o.fit.report).c_str());
    return kExitInterrupted;
  }

  std::vector<SummaryRow> table;
  std::size_t failed_total = 0;
  for (auto& row : rows) {
    if (!row->ok) {
      ++failed_total;
      std::fprintf(stderr, "frictionid: run '%s' failed: %s\n",
                   text::for_terminal(row->label).c_str(), text::for_terminal(row->error).c_str());
    }
    table.push_back(std::move(*row));
  }
  const fs::path dir(o.fit.report);
  // All three are made before any is written, so a failure cannot leave them out of step.
  const std::string csv = summary_csv(table);
  const std::string json =
      summary_json(table).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) +
      "\n";
  const SummaryHtmlOptions page_options = summary_page_options(o, runs);
  const std::string page = summary_html(table, page_options);
  write_file_atomically((dir / "summary.csv").string(), csv);
  write_file_atomically((dir / "summary.json").string(), json);
  write_file_atomically((dir / "summary.html").string(), page);
  std::printf(
      "batch: %zu runs: %zu fitted, %zu from the journal, %zu failed; %.2f s, %zu at once\n",
      runs.size(), fitted, from_journal, failed_total,
      seconds(std::chrono::steady_clock::now() - t_start).count(), jobs);
  const std::string report = text::for_terminal(o.fit.report);
  std::printf("summary: %s/summary.csv, %s/summary.html\n", report.c_str(), report.c_str());
  if (!shared.empty()) {
    std::string shared_text;
    for (const auto& name : shared) shared_text += (shared_text.empty() ? "" : ",") + name;
    shared_text = text::for_terminal(shared_text);
    // The joint fit refits every run alone first: on a terminal, say so before the wait.
    if (progress)
      std::fprintf(stderr, "frictionid batch: joint fit (--shared %s) of the %zu fitted runs...\n",
                   shared_text.c_str(), runs.size() - failed_total);
    try {
      TerminalObserver observer(interrupted, /*progress=*/false);
      write_shared_fit(runs, table, shared, o.fit.threads, &observer, o.fit.report, page_options);
    } catch (const FitError& e) {
      if (interrupted->load()) return kExitInterrupted;
      std::fprintf(stderr, "frictionid: the joint fit (--shared %s) failed: %s\n",
                   shared_text.c_str(), text::for_terminal(e.what()).c_str());
      return kExitFitFailed;
    }
  }
  return failed_total > 0 ? kExitSomeRunsFailed : kExitOk;
}

}  // namespace frictionid::cli
