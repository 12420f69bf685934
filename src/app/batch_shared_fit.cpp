#include "app/batch_shared_fit.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>

#include <frictionid/fit_error.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/joint_fit.hpp>
#include "app/data_input.hpp"
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"
#include "io/atomic_file.hpp"
#include "io/json_number.hpp"
#include "io/text.hpp"

namespace frictionid::app {
namespace {

namespace fs = std::filesystem;

nlohmann::ordered_json estimate_json(const ParameterEstimate& e) {
  nlohmann::ordered_json j;
  j["value"] = json_number(e.value);
  j["stderr"] = json_number(e.std_error);
  j["ci95"] = e.ci95 ? nlohmann::ordered_json{json_number((*e.ci95)[0]), json_number((*e.ci95)[1])}
                     : nlohmann::ordered_json(nullptr);
  j["at_bound"] = e.at_bound;
  return j;
}

// The run's summary row at the joint optimum: its own fit's row with the joint parameters,
// cost and reduced chi².
SummaryRow joint_row(const JointRunResult& run, const SummaryRow& own) {
  FitResult r = run.separate;
  r.parameters = run.parameters;
  r.cost = run.cost;
  r.chi2 = run.chi2;
  r.reduced_chi2 = run.reduced_chi2;
  return summary_row(run.label, r, own.covariates);
}

}  // namespace

void check_shared_option(const std::vector<std::string>& shared, const FitSettings& command_line) {
  if (shared.empty()) return;  // no joint fit
  for (const auto& name : shared)
    if (name.empty()) throw InputError("--shared: expected P[,P], e.g. kappa,h; got an empty name");
  try {
    check_shared_parameters(command_line, shared);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--shared: ") + e.what());
  }
}

void check_shared_parameters(const std::vector<BatchRun>& runs,
                             const std::vector<std::string>& shared) {
  if (shared.empty()) return;  // no --shared
  for (const BatchRun& run : runs) {
    try {
      frictionid::check_shared_parameters(fit_settings(run.options, run.options.model), shared);
    } catch (const std::invalid_argument& e) {
      throw InputError("--shared: run " + run.label + ": " + e.what());
    }
  }
}

void write_shared_fit(const std::vector<BatchRun>& runs, const std::vector<SummaryRow>& table,
                      const std::vector<std::string>& shared, int threads, FitObserver* observer,
                      const std::string& dir, SummaryHtmlOptions page) {
  std::vector<std::unique_ptr<Dataset>> data;
  std::vector<JointRunInput> inputs;
  std::vector<std::size_t> index;  // inputs[k] is runs[index[k]]
  std::vector<std::string> excluded;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!table[i].ok) {
      excluded.push_back(runs[i].label);
      continue;
    }
    const BatchRun& run = runs[i];
    data.push_back(std::make_unique<Dataset>(run.file_data
                                                 ? select_rows(*run.file_data, run.group_rows)
                                                 : load_fit_data(run.options, run.path).data));
    inputs.push_back(
        {run.label, data.back().get(), fit_settings(run.options, run.options.model, *data.back())});
    index.push_back(i);
  }
  if (inputs.empty()) throw FitError("--shared: no run was fitted, so there is no joint fit");
  JointFitResult joint;
  try {
    joint = fit_joint(inputs, shared, threads, observer);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--shared: ") + e.what());
  }

  std::vector<SummaryRow> rows = table;
  for (std::size_t k = 0; k < joint.runs.size(); ++k)
    rows[index[k]] = joint_row(joint.runs[k], table[index[k]]);

  nlohmann::ordered_json j;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& e : joint.shared) params[e.name] = estimate_json(e);
  j["shared"] = params;
  j["runs_fitted"] = joint.runs.size();
  j["runs_excluded"] = excluded;
  j["observations"] = joint.observations;
  j["free_parameters"] = joint.free_parameters;
  j["dof"] = joint.dof;
  j["cost"] = json_number(joint.cost);
  j["chi2"] = json_number(joint.chi2);
  j["reduced_chi2"] = json_number(joint.reduced_chi2);
  j["solver"] = {{"iterations", joint.iterations},
                 {"converged", joint.converged},
                 {"termination", joint.termination},
                 {"linear_solver", joint.linear_solver}};
  j["table"] = summary_json(rows);
  page.title = "frictionid batch: joint fit";
  page.note = "One joint fit of " + std::to_string(joint.runs.size()) + " runs in which";
  for (std::size_t k = 0; k < joint.shared.size(); ++k) {
    const ParameterEstimate& e = joint.shared[k];
    char value[96];
    std::snprintf(value, sizeof value, " %s = %.10g", e.name.c_str(), e.value);
    page.note += (k > 0 ? "," : "") + std::string(value);
    if (e.std_error) {
      std::snprintf(value, sizeof value, " ± %.3g", *e.std_error);
      page.note += value;
    }
  }
  page.note +=
      " are common to every run; every other parameter is the run's own, at the joint "
      "optimum, with standard errors from the joint covariance. summary.html shows the "
      "runs' own fits.";
  const std::string csv = summary_csv(rows);
  const std::string json =
      j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  const std::string html = summary_html(rows, page);
  const fs::path d(dir);
  write_file_atomically((d / "shared.csv").string(), csv);
  write_file_atomically((d / "shared.json").string(), json);
  write_file_atomically((d / "shared.html").string(), html);
  std::printf("shared: %zu runs share", joint.runs.size());
  for (const auto& e : joint.shared) {
    std::printf(" %s = %.10g", e.name.c_str(), e.value);
    if (e.std_error) std::printf(" +- %.3g", *e.std_error);
  }
  std::printf("; %s/shared.csv\n", text::for_terminal(dir).c_str());
}

}  // namespace frictionid::app
