// The pieces of `frictionid batch` that the Python scale-out (python/frictionid/dask.py) runs on
// a Dask cluster: the client plans the runs with the batch's own planner, each worker reads and
// fits one run with the batch's own fit_batch_run and sends back its summary row as JSON, and the
// client writes the table with the batch's own summary_csv / summary_json. So the table is the
// batch's, byte for byte (docs/design.md §2.4, §4.5).
//
// A run travels as JSON text (its label, file, group rows, options and covariates): plain data
// that Dask pickles cheaply and that holds no loaded rows, which the worker reads itself.
#include <algorithm>
#include <map>
#include <memory>
#include <numeric>
#include <tuple>
#include <vector>

#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/report_writer.hpp>
#include <frictionid/io/summary_html.hpp>
#include <frictionid/io/summary_table.hpp>
#include "app/batch_fit_run.hpp"
#include "app/batch_runs.hpp"
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"
#include "app/request_json.hpp"
#include "app/requests.hpp"
#include "identify/thread_budget.hpp"
#include "io/atomic_file.hpp"
#include "io/report_directory_lock.hpp"
#include "io/text.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;
using ojson = nlohmann::ordered_json;

namespace frictionid::python {

namespace {

std::string dump(const ojson& j, int indent = -1) {
  return j.dump(indent, ' ', false, ojson::error_handler_t::replace);
}

ojson covariates_json(const std::vector<Covariate>& covariates) {
  ojson out = ojson::array();
  for (const auto& c : covariates)
    out.push_back({c.name, std::holds_alternative<double>(c.value)
                               ? ojson(std::get<double>(c.value))
                               : ojson(std::get<std::string>(c.value))});
  return out;
}

std::string run_json(const app::BatchRun& run) {
  ojson j = {{"label", run.label},
             {"directory", run.directory},
             {"path", run.path},
             {"options", app::fit_request_json(run.options)},
             {"covariates", covariates_json(run.covariates)}};
  j["group_rows"] = run.file_data ? ojson(run.group_rows) : ojson(nullptr);
  return dump(j);
}

app::BatchRun run_from_json(const std::string& text) {
  const ojson j = ojson::parse(text);
  app::BatchRun run;
  run.label = j.at("label").get<std::string>();
  run.directory = j.at("directory").get<std::string>();
  run.path = j.at("path").get<std::string>();
  run.options = app::fit_request_from_json(j.at("options"));
  for (const auto& c : j.at("covariates")) {
    if (c.at(1).is_string())
      run.covariates.push_back({c.at(0).get<std::string>(), c.at(1).get<std::string>()});
    else
      run.covariates.push_back({c.at(0).get<std::string>(), c.at(1).get<double>()});
  }
  if (!j.at("group_rows").is_null())
    run.group_rows = j.at("group_rows").get<std::vector<std::size_t>>();
  return run;
}

// The checks `frictionid batch` makes before any work, then its plan, one JSON text per run.
std::vector<std::string> plan(const std::vector<std::string>& inputs, const app::FitRequest& o,
                              const std::vector<std::string>& group_by) {
  std::vector<app::BatchRun> runs;
  std::vector<std::string> skipped;
  {
    py::gil_scoped_release release;
    (void)app::fit_settings(o, o.model);
    runs = app::plan_batch_runs(inputs, o, group_by, "", &skipped);
  }
  // As `frictionid batch` names them on stderr: a FIFO, a device or a loop of links in a
  // directory or a glob's matches is left out with a warning.
  for (const auto& s : skipped)
    if (PyErr_WarnEx(PyExc_UserWarning, ("frictionid: skipped " + text::for_terminal(s)).c_str(),
                     1) != 0)
      throw py::error_already_set();
  std::vector<std::string> out;
  for (const auto& run : runs) out.push_back(run_json(run));
  return out;
}

// A run over rows held in memory (a DataFrame's group): the same JSON, without a file.
std::string table_run(const std::string& label, const app::FitRequest& o,
                      const std::vector<std::pair<std::string, std::string>>& covariates) {
  (void)app::fit_settings(o, o.model);
  app::BatchRun run;
  run.label = label;
  run.options = o;
  for (const auto& [name, value] : covariates) {
    app::check_covariate_name(name, "group_by");
    run.covariates.push_back({name, value});
  }
  return run_json(run);
}

// Fits one run: its file (read here, on the worker) or `data` (a DataFrame's group). Returns its
// summary row as JSON and, with `report`, report.json's text as `frictionid batch` writes it.
std::pair<std::string, std::optional<std::string>> fit_run(
    const std::string& run_text, int threads, bool report,
    const std::optional<std::shared_ptr<Dataset>>& data) {
  app::BatchRun run = run_from_json(run_text);
  if (data) {
    run.file_data = *data;
    run.group_rows.resize((*data)->rows());
    std::iota(run.group_rows.begin(), run.group_rows.end(), std::size_t{0});
  }
  std::optional<std::string> report_text;
  SummaryRow row;
  {
    py::gil_scoped_release release;
    // A worker's `threads` bound the run's reading and fitting together (thread_budget.hpp).
    ThreadBudget budget(threads);
    const ThreadBudgetScope scope(&budget);
    row = app::fit_batch_run(run, threads, nullptr, [&](const FitResult& r, const Dataset&) {
      if (report) report_text = dump(report_json(r, contact_label(run.options.contact)), 2) + "\n";
    });
  }
  return {dump(summary_row_json(row)), report_text};
}

// The failed row of a run whose rows could not be made (a DataFrame group the reader rejects).
std::string failed_run(const std::string& run_text, const std::string& error) {
  const app::BatchRun run = run_from_json(run_text);
  return dump(summary_row_json(failed_summary_row(run.label, 0, error, run.covariates)));
}

// summary.csv, summary.json and summary.html's text from the rows' JSON, sorted by label as the
// batch sorts; the page as `frictionid batch --trend-x X --per-run-reports R` writes it.
std::tuple<std::string, std::string, std::string> summary_files(
    const std::vector<std::string>& row_texts, const std::string& trend_x,
    const std::string& per_run_reports, const std::map<std::string, std::string>& directories) {
  std::vector<SummaryRow> rows;
  for (const auto& text : row_texts) rows.push_back(summary_row_from_json(ojson::parse(text)));
  std::stable_sort(rows.begin(), rows.end(),
                   [](const SummaryRow& a, const SummaryRow& b) { return a.label < b.label; });
  SummaryHtmlOptions page;
  page.trend_x = trend_x;
  page.run_reports = per_run_reports == "full"   ? RunReports::Full
                     : per_run_reports == "json" ? RunReports::Json
                                                 : RunReports::None;
  page.run_directories = directories;
  return {summary_csv(rows), dump(summary_json(rows), 2) + "\n", summary_html(rows, page)};
}

// `frictionid batch --trend-x`'s check, on planned runs: InputError for an unknown covariate.
void check_trend_x(const std::vector<std::string>& run_texts, const std::string& trend_x) {
  std::vector<app::BatchRun> runs;
  for (const auto& text : run_texts) runs.push_back(run_from_json(text));
  app::check_trend_x(trend_x, runs);
}

// `frictionid batch`'s lock on its output directory, taken by python3 -m frictionid batch too:
// one lock, one rule for both front ends. Python waits for it itself, between attempts, so that
// Ctrl-C ends the wait.
class BatchLock {
 public:
  explicit BatchLock(std::string dir) : dir_(std::move(dir)) {}
  // True when taken; false when another process holds it.
  bool try_acquire() {
    py::gil_scoped_release release;
    try {
      lock_ = std::make_unique<ReportDirectoryLock>(dir_, /*wait=*/false);
    } catch (const DirectoryLocked&) {
      return false;
    }
    return true;
  }
  void release() { lock_.reset(); }

 private:
  std::string dir_;
  std::unique_ptr<ReportDirectoryLock> lock_;
};

}  // namespace

void register_batch(py::module_& m) {
  py::class_<BatchLock>(m, "BatchLock",
                        "The lock frictionid batch holds on its output directory (.DIR.lock).")
      .def(py::init<std::string>(), py::arg("dir"))
      .def("try_acquire", &BatchLock::try_acquire)
      .def("release", &BatchLock::release);
  m.def("plan_batch_runs", &plan, py::arg("inputs"), py::arg("options"), py::arg("group_by"));
  m.def("table_run", &table_run, py::arg("label"), py::arg("options"), py::arg("covariates"));
  m.def("fit_batch_run", &fit_run, py::arg("run"), py::arg("threads"), py::arg("report"),
        py::arg("data") = std::nullopt);
  m.def("failed_batch_run", &failed_run, py::arg("run"), py::arg("error"));
  m.def("summary_files", &summary_files, py::arg("rows"), py::arg("trend_x") = "mean_N",
        py::arg("per_run_reports") = "none",
        py::arg("directories") = std::map<std::string, std::string>{});
  m.def("check_trend_x", &check_trend_x, py::arg("runs"), py::arg("trend_x"));
  m.def(
      "write_file_atomically",
      [](const std::string& path, const std::string& content) {
        py::gil_scoped_release release;
        write_file_atomically(path, content);
      },
      py::arg("path"), py::arg("content"));
}

}  // namespace frictionid::python
