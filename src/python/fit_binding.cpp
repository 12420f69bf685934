// Datasets (from a CSV file or from columns in memory), the fit request, and fit itself: the
// same app code as `frictionid fit` (app::fit_settings, app::fit_dataset), run with the GIL
// released and cancellable by Ctrl-C.
#include <limits>
#include <memory>

#include <pybind11/stl.h>

#include <frictionid/fit_error.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/report_writer.hpp>
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"
#include "app/request_text.hpp"
#include "app/requests.hpp"
#include "identify/thread_budget.hpp"
#include "io/text.hpp"
#include "python/bindings.hpp"
#include "python/dataset_from_columns.hpp"
#include "python/json_values.hpp"
#include "python/numpy_columns.hpp"
#include "python/python_observer.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

// A finished fit, the rows it was fitted to (reports plot them) and the sigma of every residual.
struct FitOutput {
  FitResult result;
  std::shared_ptr<Dataset> data;
  app::RowSigmas sigma;
};

std::shared_ptr<Dataset> from_columns(const py::dict& columns, const std::string& source,
                                      const std::vector<std::string>& row_labels) {
  std::map<std::string, std::vector<double>> values;
  for (const auto& [key, array] : columns)
    values[py::cast<std::string>(key)] = to_vector(py::cast<DoubleArray>(array));
  return std::make_shared<Dataset>(dataset_from_columns(std::move(values), source, row_labels));
}

std::shared_ptr<FitOutput> run_fit(const std::shared_ptr<Dataset>& data,
                                   const app::FitRequest& request, const py::object& cancel,
                                   const py::object& progress) {
  const FitSettings s = app::fit_settings(request, request.model, *data);
  auto out = std::make_shared<FitOutput>();
  out->data = data;
  run_observed(cancel, progress, [&](FitObserver& observer) {
    ThreadBudget budget(request.threads);  // threads= bounds the fit's and its report's threads
    const ThreadBudgetScope scope(&budget);
    out->result = app::fit_dataset(s, *data, &observer, out->sigma);
  });
  return out;
}

py::dict channel_arrays(const FitResult& r,
                        const std::array<std::vector<double>, kChannelCount>& values) {
  py::dict out;
  for (Channel c : r.channels) out[channel_name(c)] = to_numpy(values[static_cast<int>(c)]);
  return out;
}

}  // namespace

void register_fit(py::module_& m) {
  py::class_<Dataset, std::shared_ptr<Dataset>>(m, "Dataset")
      .def_property_readonly("rows", &Dataset::rows)
      .def_readonly("source", &Dataset::source)
      .def_property_readonly(
          "lines",
          [](const Dataset& d) {
            return py::array_t<std::size_t>(static_cast<py::ssize_t>(d.line.size()), d.line.data());
          },
          "The file line of each row (empty for rows from memory): warnings name them.")
      .def("columns", &dataset_columns,
           "Canonical columns as float64 arrays (channels NaN where not measured).");

  m.def(
      "load_dataset_csv",
      [](const std::string& path, const std::map<std::string, std::string>& columns, int threads) {
        const ColumnMap map = column_map(columns);
        if (threads < 0) throw InputError("--threads must be 0 (every hardware thread) or more");
        py::gil_scoped_release release;
        ThreadBudget budget(threads);  // a large file is read in parts, one per thread
        const ThreadBudgetScope scope(&budget);
        return std::make_shared<Dataset>(load_dataset_csv(path, map));
      },
      py::arg("path"), py::arg("columns") = std::map<std::string, std::string>{},
      py::arg("threads") = 0);
  m.def("dataset_from_columns", &from_columns, py::arg("columns"), py::arg("source"),
        py::arg("row_labels") = std::vector<std::string>{},
        "row_labels: how messages name each row (a DataFrame's index labels); default the "
        "position.");
  m.def(
      "restore_dataset",
      [](const py::dict& columns, const std::string& source,
         const std::vector<std::size_t>& lines) {
        auto d = from_columns(columns, source, {});
        d->line = lines;
        return d;
      },
      py::arg("columns"), py::arg("source"), py::arg("lines"),
      "A dataset rebuilt from its columns, its source and file lines (an unpickled FitResult).");
  m.def(
      "misspelling_distance",
      [](const std::string& candidate, const std::string& target) -> py::object {
        const std::size_t d = text::misspelling_distance(candidate, target);
        if (d == std::numeric_limits<std::size_t>::max()) return py::none();
        return py::int_(d);
      },
      py::arg("candidate"), py::arg("target"),
      "The CSV reader's test of a misspelt column name: the distance, or None when unlike.");

  py::class_<CancelToken, std::shared_ptr<CancelToken>>(
      m, "CancelToken", "A flag that stops the fits given it, set from any thread.")
      .def(py::init<>())
      .def("cancel", &CancelToken::cancel, "Stops the fits using this token (FitCancelled).")
      .def("is_set", &CancelToken::cancelled, "True once cancel() was called (threading.Event).")
      .def_property_readonly("cancelled", &CancelToken::cancelled);
  m.def("cancel_all_fits", &PythonObserver::cancel_all,
        "Cancels every running fit and every later one (the interpreter is exiting).");
  m.def(
      "column_map",
      [](const std::map<std::string, std::string>& columns) {
        return column_map(columns).canonical_to_header;
      },
      py::arg("columns"), "The checked canonical -> header map (as --columns checks it).");

  using app::FitRequest;
  py::class_<FitRequest>(m, "FitRequest")
      .def(py::init<>())
      .def_readwrite("model", &FitRequest::model)
      .def_readwrite("pressure", &FitRequest::pressure)
      .def_readwrite("pressure_given", &FitRequest::pressure_given)
      .def_readwrite("contact", &FitRequest::contact)
      .def_readwrite("free", &FitRequest::free)
      .def_readwrite("fix", &FitRequest::fix)
      .def_readwrite("bounds", &FitRequest::bounds)
      .def_readwrite("start", &FitRequest::start)
      .def_readwrite("loss", &FitRequest::loss)
      .def_readwrite("channels", &FitRequest::channels)
      .def_property(
          "columns", [](const FitRequest& r) { return r.columns.canonical_to_header; },
          [](FitRequest& r, const std::map<std::string, std::string>& columns) {
            r.columns = column_map(columns);
          })
      .def_readwrite("intervals", &FitRequest::intervals)
      .def_readwrite("bootstrap", &FitRequest::bootstrap)
      .def_readwrite("noise_model", &FitRequest::noise_model)
      .def_readwrite("starts", &FitRequest::starts)
      .def_readwrite("seed", &FitRequest::seed)
      .def_readwrite("global_evaluations", &FitRequest::global_evaluations)
      .def_readwrite("global_subsample", &FitRequest::global_subsample)
      .def_readwrite("no_global", &FitRequest::no_global)
      .def_readwrite("global_algorithm", &FitRequest::global_algorithm)
      .def_readwrite("threads", &FitRequest::threads)
      .def(
          "check", [](const FitRequest& r) { (void)app::fit_settings(r, r.model); },
          "Raises InputError for what the fit would reject, before any data is read.")
      .def(
          "default_bounds",
          [](FitRequest r) {
            r.bounds.clear();  // the model's and law's own bounds, whatever else is asked
            r.fix.clear();
            r.start.clear();
            const FitSettings s = app::fit_settings(r, r.model);
            std::map<std::string, std::pair<double, double>> out;
            for (std::size_t i = 0; i < s.params.size(); ++i)
              out[param_names()[i]] = {s.params[i].lower, s.params[i].upper};
            return out;
          },
          "Parameter name -> (lower, upper) that the fit uses when bounds= does not say.");

  // The text form of python3 -m frictionid batch's options, as `frictionid batch` reads it.
  m.def(
      "apply_fit_text",
      [](FitRequest& r, const std::string& fix, const std::string& bounds, const std::string& start,
         const std::string& channels, const std::string& columns, const std::string& free) {
        app::apply(app::FitText{fix, bounds, start, channels, columns, free}, r);
      },
      py::arg("request"), py::kw_only(), py::arg("fix") = "", py::arg("bounds") = "",
      py::arg("start") = "", py::arg("channels") = "", py::arg("columns") = "",
      py::arg("free") = "");
  m.def("name_list", &app::name_list, py::arg("option"), py::arg("text"));

  py::class_<FitOutput, std::shared_ptr<FitOutput>>(m, "FitOutput")
      .def(
          "report",
          [](const FitOutput& f) { return to_python(report_json(f.result, f.result.contact)); },
          "report.json's content as Python values (no JSON text in between).")
      .def(
          "write_report",
          [](const FitOutput& f, const std::string& dir, int threads) {
            py::gil_scoped_release release;
            ThreadBudget budget(threads);  // the plots are drawn side by side
            const ThreadBudgetScope scope(&budget);
            ReportOptions options;
            options.threads = threads;
            options.contact = f.result.contact;
            return write_report(dir, f.result, *f.data, options);
          },
          py::arg("dir"), py::arg("threads") = 0)
      .def_property_readonly(
          "contact", [](const FitOutput& f) { return f.result.contact; },
          "The contact spot the fit was made on, as contact= spells it (FitResult::contact).")
      .def_property_readonly("data", [](const FitOutput& f) { return f.data; })
      .def_property_readonly("eps", [](const FitOutput& f) { return to_numpy(f.result.eps); })
      .def_property_readonly(
          "fitted", [](const FitOutput& f) { return channel_arrays(f.result, f.result.fitted); })
      .def_property_readonly(
          "sigma", [](const FitOutput& f) { return channel_arrays(f.result, f.sigma); },
          "Per fitted channel, the sigma each row's residual was divided by (NaN: not "
          "measured).")
      .def_property_readonly("time_s", [](const FitOutput& f) { return f.result.solver.time_s; });

  m.def("fit", &run_fit, py::arg("data"), py::arg("request"), py::arg("cancel") = py::none(),
        py::arg("progress") = py::none());
}

}  // namespace frictionid::python
