// Datasets (from a CSV file or from columns in memory), the fit options of the command line,
// and fit itself: the same settings code as `frictionid fit` (cli::fit_settings_from_options),
// run with the GIL released and cancellable by Ctrl-C.
#include <memory>

#include <pybind11/stl.h>

#include <frictionid/fitter.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/report_writer.hpp>
#include "cli/commands.hpp"
#include "cli/fit_options.hpp"
#include "cli/option_parsers.hpp"
#include "python/bindings.hpp"
#include "python/dataset_from_columns.hpp"
#include "python/numpy_columns.hpp"
#include "python/python_observer.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

// A finished fit and the rows it was fitted to (reports plot them).
struct FitOutput {
  FitResult result;
  std::shared_ptr<Dataset> data;
};

std::shared_ptr<Dataset> from_columns(const py::dict& columns, const std::string& source) {
  std::map<std::string, std::vector<double>> values;
  for (const auto& [key, array] : columns)
    values[py::cast<std::string>(key)] = to_vector(py::cast<DoubleArray>(array));
  return std::make_shared<Dataset>(dataset_from_columns(std::move(values), source));
}

std::shared_ptr<FitOutput> run_fit(const std::shared_ptr<Dataset>& data, cli::FitOptions o) {
  // The command line requires a report directory; the Python API writes reports on request.
  if (o.report.empty()) o.report = ".";
  const FitSettings s = cli::fit_settings_from_options(o, o.model);
  auto out = std::make_shared<FitOutput>();
  out->data = data;
  PythonObserver observer;
  try {
    py::gil_scoped_release release;
    out->result = Fitter(s).fit(*data, &observer);
  } catch (const FitError&) {
    observer.rethrow_pending();  // Ctrl-C: KeyboardInterrupt rather than FitError("interrupted")
    throw;
  } catch (const std::invalid_argument& e) {
    throw InputError(data->source, 0, 0, e.what());  // as `frictionid fit` reports it
  }
  observer.rethrow_pending();
  return out;
}

}  // namespace

void register_fit(py::module_& m) {
  py::class_<Dataset, std::shared_ptr<Dataset>>(m, "Dataset")
      .def_property_readonly("rows", &Dataset::rows)
      .def_readonly("source", &Dataset::source)
      .def("columns", &dataset_columns,
           "Canonical columns as float64 arrays (channels NaN where not measured).");

  m.def(
      "load_dataset_csv",
      [](const std::string& path, const std::string& columns) {
        const ColumnMap map = parse_column_map(columns);
        py::gil_scoped_release release;
        return std::make_shared<Dataset>(load_dataset_csv(path, map));
      },
      py::arg("path"), py::arg("columns") = "");
  m.def("dataset_from_columns", &from_columns, py::arg("columns"), py::arg("source"));
  m.def(
      "parse_column_map",
      [](const std::string& spec) { return parse_column_map(spec).canonical_to_header; },
      py::arg("spec"));

  py::class_<cli::FitOptions>(m, "FitOptions")
      .def(py::init<>())
      .def_readwrite("model", &cli::FitOptions::model)
      .def_readwrite("pressure", &cli::FitOptions::pressure)
      .def_readwrite("fix", &cli::FitOptions::fix)
      .def_readwrite("bounds", &cli::FitOptions::bounds)
      .def_readwrite("initial", &cli::FitOptions::initial)
      .def_readwrite("loss", &cli::FitOptions::loss)
      .def_readwrite("channels", &cli::FitOptions::channels)
      .def_readwrite("columns", &cli::FitOptions::columns)
      .def_readwrite("intervals", &cli::FitOptions::intervals)
      .def_readwrite("bootstrap", &cli::FitOptions::bootstrap)
      .def_readwrite("noise_model", &cli::FitOptions::noise_model)
      .def_readwrite("starts", &cli::FitOptions::starts)
      .def_readwrite("seed", &cli::FitOptions::seed)
      .def_readwrite("global_evaluations", &cli::FitOptions::global_evaluations)
      .def_readwrite("global_subsample", &cli::FitOptions::global_subsample)
      .def_readwrite("no_global", &cli::FitOptions::no_global)
      .def_readwrite("global_algorithm", &cli::FitOptions::global_algorithm)
      .def_readwrite("threads", &cli::FitOptions::threads);

  py::class_<FitOutput, std::shared_ptr<FitOutput>>(m, "FitOutput")
      .def("report_json", [](const FitOutput& f) { return report_json(f.result).dump(2); })
      .def(
          "write_report",
          [](const FitOutput& f, const std::string& dir) {
            py::gil_scoped_release release;
            return write_report(dir, f.result, *f.data);
          },
          py::arg("dir"))
      .def_property_readonly("data", [](const FitOutput& f) { return f.data; })
      .def_property_readonly("eps", [](const FitOutput& f) { return to_numpy(f.result.eps); })
      .def_property_readonly("fitted",
                             [](const FitOutput& f) {
                               py::dict out;
                               for (Channel c : f.result.channels)
                                 out[channel_name(c)] =
                                     to_numpy(f.result.fitted[static_cast<int>(c)]);
                               return out;
                             })
      .def_property_readonly("time_s", [](const FitOutput& f) { return f.result.solver.time_s; });

  m.def("fit", &run_fit, py::arg("data"), py::arg("options"));
}

}  // namespace frictionid::python
