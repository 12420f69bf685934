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
#include "app/data_input.hpp"
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"
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
using app::BatchJournal;
using app::BatchRequest;
using app::BatchRun;
using app::check_shared_option;
using app::check_shared_parameters;
using app::check_trend_x;
using app::fit_batch_run;
using app::fit_data_form;
using app::fit_request_json;
using app::fit_settings;
using app::plan_batch_runs;
using app::report_provenance;
using app::warm_start_from;
using app::WarmStart;
using app::write_shared_fit;

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
  // A pressure map, fingerprinted as the report is written.
  for (const auto& file : report_provenance(run.options, {}).inputs) p.inputs.push_back(file);
  try {
    p.data_form = fit_data_form(run.options, run.path);
  } catch (const std::exception&) {
    // The run's file was read for its fit; one that cannot be looked at again is named
    // without its form.
  }
  return p;
}

void write_run_report(const BatchContext& c, const BatchRun& run, const FitResult& r,
                      const Dataset& data) {
  const fs::path dir = c.dir / "runs" / run.directory;
  if (c.options.per_run_reports == "full") {
    ReportOptions options;  // as many threads as each run fits on
    options.threads = c.fit_threads;
    options.stop = interrupt_check();
    options.provenance = run_provenance(c.options, run);
    options.contact = contact_label(run.options.contact);
    write_report(dir.string(), r, data, options);
  } else if (c.options.per_run_reports == "json") {
    fs::create_directories(dir);
    const auto json =
        report_json(r, run_provenance(c.options, run), contact_label(run.options.contact))
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

namespace {

// The runs of the request, checked before any fit: what a directory or a glob skipped is named.
std::vector<BatchRun> planned_runs(const BatchRequest& o, const std::vector<std::string>& shared) {
  std::vector<std::string> skipped;
  std::vector<BatchRun> runs =
      plan_batch_runs(o.inputs, o.fit, o.group_by, "reports=" + o.per_run_reports, &skipped);
  for (const auto& s : skipped)
    std::fprintf(stderr, "frictionid: skipped %s\n", text::for_terminal(s).c_str());
  if (o.warm_start) key_on_first_run(runs);
  check_shared_parameters(runs, shared);
  check_trend_x(o.trend_x, runs);
  return runs;
}

// A killed batch may have left a run's report half-renamed: its temporary files go, as a fit's
// leftovers do (the lock keeps any other writer out).
void remove_batch_leftovers(const fs::path& dir) {
  remove_atomic_leftovers(dir.string());
  std::error_code ec;
  if (!fs::is_directory(dir / "runs", ec)) return;
  for (const auto& e : fs::directory_iterator(dir / "runs", ec))
    if (e.is_directory(ec) && !e.is_symlink(ec)) remove_atomic_leftovers(e.path().string());
}

// One batch from its journal to its summary: the runs' rows as they end, the counters, and the
// steps that fill them.
class BatchDriver {
 public:
  BatchDriver(const BatchRequest& o, std::vector<BatchRun> runs,
              const std::atomic<bool>* interrupted)
      : o_(o),
        dir_(o.fit.report),
        runs_(std::move(runs)),
        rows_(runs_.size()),
        interrupted_(interrupted),
        journal_((dir_ / "journal.jsonl").string(), o.force) {}

  // Rows the journal holds for runs whose file still has the bytes their fit read.
  void take_finished_from_journal() {
    for (std::size_t i = 0; i < runs_.size(); ++i) {
      bool changed = false;
      const SummaryRow* done =
          journal_.finished(runs_[i].label, runs_[i].key, runs_[i].input, &changed);
      if (changed)
        std::fprintf(stderr,
                     "frictionid: run '%s': its journal line is of other bytes than %s holds now "
                     "(the file changed while it was fitted); fitting it again\n",
                     text::for_terminal(runs_[i].label).c_str(),
                     text::for_terminal(runs_[i].path).c_str());
      if (done && has_run_report(dir_, o_.per_run_reports, runs_[i]))
        rows_[i] = *done;
      else
        pending_.push_back(i);
    }
    from_journal_ = runs_.size() - pending_.size();
  }

  // Fits the pending runs, `jobs` at once, drawing threads from `budget`.
  void fit_pending(ThreadBudget& budget) {
    jobs_ = std::clamp<std::size_t>(
        o_.jobs > 0 ? static_cast<std::size_t>(o_.jobs) : static_cast<std::size_t>(budget.total()),
        1,
        std::min<std::size_t>(static_cast<std::size_t>(budget.total()),
                              std::max<std::size_t>(1, pending_.size())));
    // Several fits at once each take one thread; alone, a fit may use --threads. The results do
    // not depend on either.
    const BatchContext context{o_, dir_, jobs_ == 1 ? o_.fit.threads : 1, interrupted_};
    progress_ = show_progress(o_.fit.progress);
    t_fits_ = std::chrono::steady_clock::now();
    const std::optional<WarmStart> warm = fit_first_run_for_warm_start();
    const WarmStart* warm_start = warm ? &*warm : nullptr;
    std::vector<std::thread> threads;
    const int helpers = budget.acquire(static_cast<int>(jobs_) - 1);
    for (int t = 0; t < helpers; ++t)
      threads.emplace_back([&] {
        const ThreadBudgetScope scope(&budget);
        fit_runs_until_done(context, warm_start);
      });
    fit_runs_until_done(context, warm_start);
    for (auto& t : threads) t.join();
    budget.release(helpers);
    if (progress_ && fitted_ > 0) std::fprintf(stderr, "\r%80s\r", "");
    if (first_error_) std::rethrow_exception(first_error_);
    journal_.sync();  // every line and run report durable before the summary names them
  }

  // After an interruption: what is done stays in the journal for the rerun.
  int report_interruption() const {
    std::fprintf(stderr,
                 "frictionid: interrupted after %zu of %zu runs; they are in %s/journal.jsonl, "
                 "run the same command again to fit the rest\n",
                 fitted_ + from_journal_, runs_.size(), text::for_terminal(o_.fit.report).c_str());
    return kExitInterrupted;
  }

  // summary.csv, summary.json and summary.html, each atomically, all made before any is
  // written so that a failure cannot leave them out of step. Names the failed runs.
  void write_summaries(std::chrono::steady_clock::time_point t_start) {
    for (auto& row : rows_) {
      if (!row->ok) {
        ++failed_total_;
        std::fprintf(stderr, "frictionid: run '%s' failed: %s\n",
                     text::for_terminal(row->label).c_str(),
                     text::for_terminal(row->error).c_str());
      }
      table_.push_back(std::move(*row));
    }
    const std::string csv = summary_csv(table_);
    const std::string json =
        summary_json(table_).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) +
        "\n";
    page_options_ = summary_page_options(o_, runs_);
    const std::string page = summary_html(table_, page_options_);
    write_file_atomically((dir_ / "summary.csv").string(), csv);
    write_file_atomically((dir_ / "summary.json").string(), json);
    write_file_atomically((dir_ / "summary.html").string(), page);
    std::printf(
        "batch: %zu runs: %zu fitted, %zu from the journal, %zu failed; %.2f s, %zu at once\n",
        runs_.size(), fitted_, from_journal_, failed_total_,
        seconds(std::chrono::steady_clock::now() - t_start).count(), jobs_);
    const std::string report = text::for_terminal(o_.fit.report);
    std::printf("summary: %s/summary.csv, %s/summary.html\n", report.c_str(), report.c_str());
  }

  // --shared: the joint fit of the runs that succeeded; the exit code.
  int shared_fit(const std::vector<std::string>& shared) {
    if (shared.empty()) return failed_total_ > 0 ? kExitSomeRunsFailed : kExitOk;
    std::string shared_text;
    for (const auto& name : shared) shared_text += (shared_text.empty() ? "" : ",") + name;
    shared_text = text::for_terminal(shared_text);
    // The joint fit refits every run alone first: on a terminal, say so before the wait.
    if (progress_)
      std::fprintf(stderr, "frictionid batch: joint fit (--shared %s) of the %zu fitted runs...\n",
                   shared_text.c_str(), runs_.size() - failed_total_);
    try {
      TerminalObserver observer(interrupted_, /*progress=*/false);
      write_shared_fit(runs_, table_, shared, o_.fit.threads, &observer, o_.fit.report,
                       page_options_);
    } catch (const FitError& e) {
      if (interrupted_->load()) return kExitInterrupted;
      std::fprintf(stderr, "frictionid: the joint fit (--shared %s) failed: %s\n",
                   shared_text.c_str(), text::for_terminal(e.what()).c_str());
      return kExitFitFailed;
    }
    return failed_total_ > 0 ? kExitSomeRunsFailed : kExitOk;
  }

 private:
  // --warm-start: the first run is fitted in full before the others, which start from it. When
  // the journal has its row, it is fitted again for its parameters only (same fit, same numbers).
  // Alone, it may use --threads (the numbers do not depend on it). Interrupted, the workers stop
  // at once and the batch ends as any interrupted batch does.
  std::optional<WarmStart> fit_first_run_for_warm_start() {
    if (!o_.warm_start || pending_.empty() || runs_.size() < 2) return std::nullopt;
    const BatchContext alone{o_, dir_, o_.fit.threads, interrupted_};
    std::optional<FitResult> first;
    if (pending_.front() == 0) {
      FileFingerprint read;
      SummaryRow row = fit_run(alone, runs_[0], nullptr, read, &first);
      if (!interrupted_->load()) {
        journal_.record(runs_[0].key, row, read);
        ++fitted_;
        if (!row.ok) ++failed_;
        rows_[0] = std::move(row);
        next_ = 1;
      }
    } else {
      TerminalObserver observer(interrupted_, /*progress=*/false);
      fit_batch_run(runs_[0], o_.fit.threads, &observer,
                    [&](const FitResult& r, const Dataset&) { first = r; });
    }
    if (!first) return std::nullopt;
    return warm_start_from(runs_[0].label, *first);
  }

  // One thread's share: the next pending run until none is left, the batch is interrupted or
  // the journal cannot be written.
  void fit_runs_until_done(const BatchContext& context, const WarmStart* warm_start) {
    for (;;) {
      if (interrupted_->load()) return;
      {
        std::lock_guard<std::mutex> guard(mutex_);
        if (first_error_) return;
      }
      const std::size_t k = next_.fetch_add(1);
      if (k >= pending_.size()) return;
      const BatchRun& run = runs_[pending_[k]];
      FileFingerprint read;
      SummaryRow row = fit_run(context, run, warm_start, read);
      if (interrupted_->load()) return;  // a cancelled fit is not an outcome: fit it next time
      try {
        journal_.record(run.key, row, read);
      } catch (...) {
        std::lock_guard<std::mutex> guard(mutex_);
        if (!first_error_) first_error_ = std::current_exception();
        return;
      }
      std::lock_guard<std::mutex> guard(mutex_);
      ++fitted_;
      if (!row.ok) ++failed_;
      rows_[pending_[k]] = std::move(row);
      if (progress_) {
        const double elapsed = seconds(std::chrono::steady_clock::now() - t_fits_).count();
        const double eta = elapsed / fitted_ * (pending_.size() - fitted_);
        std::fprintf(stderr, "\rfrictionid batch: %zu/%zu runs fitted, %zu failed, ETA %s   ",
                     fitted_, pending_.size(), failed_, duration_text(eta).c_str());
      }
    }
  }

  const BatchRequest& o_;
  const fs::path dir_;
  std::vector<BatchRun> runs_;
  std::vector<std::optional<SummaryRow>> rows_;
  const std::atomic<bool>* interrupted_;
  BatchJournal journal_;
  std::vector<std::size_t> pending_;
  std::size_t from_journal_ = 0, jobs_ = 1;
  bool progress_ = false;
  std::chrono::steady_clock::time_point t_fits_;
  std::atomic<std::size_t> next_{0};
  std::mutex mutex_;  // guards the counters below, the progress line and first_error_
  std::size_t fitted_ = 0, failed_ = 0, failed_total_ = 0;
  std::exception_ptr first_error_;
  std::vector<SummaryRow> table_;
  SummaryHtmlOptions page_options_;
};

}  // namespace

int run_batch(const BatchRequest& o) {
  const auto t_start = std::chrono::steady_clock::now();
  if (o.jobs < 0) throw InputError("--jobs must be 0 (every hardware thread) or more");
  // Bad options fail before any work.
  check_shared_option(o.shared, fit_settings(o.fit, o.fit.model));
  if (o.fit.report.empty()) throw InputError("batch needs --report DIR");
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  const ReportDirectoryLock lock(o.fit.report, /*wait=*/!o.fit.no_wait,
                                 say_waiting_for(o.fit.report), interrupt_check());
  std::error_code ec;
  if (fs::exists(o.fit.report, ec) && !fs::is_directory(o.fit.report, ec))
    throw InputError(o.fit.report, 0, 0, "--report: exists and is not a directory");

  std::vector<BatchRun> runs = planned_runs(o, o.shared);
  fs::create_directories(o.fit.report);
  remove_batch_leftovers(o.fit.report);
  BatchDriver batch(o, std::move(runs), interrupted);
  batch.take_finished_from_journal();
  // --threads bounds every busy thread of the batch: its runs at once and whatever each run's
  // reading, fitting and report take (identify/thread_budget.hpp). --jobs is at most that.
  ThreadBudget budget(o.fit.threads);
  const ThreadBudgetScope budget_scope(&budget);
  batch.fit_pending(budget);
  if (interrupted->load()) return batch.report_interruption();
  batch.write_summaries(t_start);
  return batch.shared_fit(o.shared);
}

}  // namespace frictionid::cli
