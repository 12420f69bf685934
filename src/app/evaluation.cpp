#include "app/evaluation.hpp"

#include <cmath>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/dataset_writer.hpp>
#include <frictionid/io/input_error.hpp>
#include "app/option_parsers.hpp"
#include "identify/observer_progress.hpp"
#include "identify/row_predictions.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_cell.hpp"

namespace frictionid::app {

nlohmann::ordered_json evaluate_point(const EvalRequest& r) {
  const ModelSetup s = make_model_setup(r.model);
  if (!r.vx || !r.omega) throw InputError("eval needs --vx and --omega (or --input FILE)");
  model::Kinematics k{*r.vx, r.vy.value_or(0.0), *r.omega, r.N, r.R};
  for (double x : {k.v_x, k.v_y, k.omega})
    if (!std::isfinite(x)) throw InputError("--vx, --vy and --omega must be finite");
  if (!(k.N > 0.0) || !std::isfinite(k.N)) throw InputError("--N must be a finite number > 0");
  if (!(k.R > 0.0) || !std::isfinite(k.R)) throw InputError("--R must be a finite number > 0");
  const ModelEvaluator<double> eval(s.kind, s.law, s.params.data(), nullptr, nullptr, s.contact);
  const auto out = eval(k);
  nlohmann::ordered_json j;
  j["T_x"] = out.T_x;
  j["T_y"] = out.T_y;
  j["M_z"] = out.M_z;
  j["M_roll"] = out.M_roll;
  if (shows_tilt(s)) j["M_tilt"] = out.M_tilt;
  j["N"] = out.N;
  return j;
}

std::size_t evaluate_file(const EvalRequest& r, FitObserver* observer) {
  const ModelSetup s = make_model_setup(r.model);
  if (r.output.empty()) throw InputError("eval --input needs --output FILE");
  if (r.vx || r.vy || r.omega)
    throw InputError("give either --input or --vx/--vy/--omega, not both");
  check_thread_option(r.threads);
  const Dataset d = load_dataset_csv(r.input, r.columns, false);
  const ModelEvaluator<double> eval(
      s.kind, s.law, s.params.data(),
      ring_table_for_rows(s.kind, s.law, s.params[kN], false, d.rows(), s.contact), nullptr,
      observed_spot_for_rows(s.kind, s.law, s.params[kQ], s.params[kN], d.rows(), s.contact,
                             r.threads, observer));
  std::vector<model::Resultants<double>> values(d.rows());
  predict_rows(
      eval, d.rows(),
      [&d](std::size_t i) {
        return model::Kinematics{d.v_x[i], d.v_y[i], d.omega[i], d.N[i], d.R[i], d.tilt_sign_at(i)};
      },
      [&values](std::size_t i, const model::Resultants<double>& p) { values[i] = p; }, r.threads,
      observer);
  const bool tilt = shows_tilt(s);
  std::string text = dataset_csv_text(d);
  const std::size_t header_end = text.find('\n');
  std::string header = text.substr(0, header_end);
  for (const auto& name : d.extra_names) header += "," + csv_cell(name);
  std::vector<const char*> predicted = {"T_x", "T_y", "M_z", "M_roll"};
  if (tilt) predicted.push_back("M_tilt");
  predicted.push_back("N");
  for (const char* name : predicted) {
    const bool taken =
        (name == std::string("N")) ||
        ("," + header + ",").find("," + std::string(name) + ",") != std::string::npos;
    header += "," + std::string(name) + (taken ? "_model" : "");
  }
  std::string out = header + "\n";
  std::size_t pos = header_end + 1;
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const std::size_t eol = text.find('\n', pos);
    out.append(text, pos, eol - pos);
    pos = eol + 1;
    for (const auto& column : d.extra_values) (out += ',') += csv_cell(column[i]);
    const model::Resultants<double>& p = values[i];
    fmt::format_to(std::back_inserter(out), ",{:.17g},{:.17g},{:.17g},{:.17g}", p.T_x, p.T_y, p.M_z,
                   p.M_roll);
    if (tilt) fmt::format_to(std::back_inserter(out), ",{:.17g}", p.M_tilt);
    fmt::format_to(std::back_inserter(out), ",{:.17g}\n", p.N);
  }
  write_file_atomically(r.output, out);
  return d.rows();
}

ResultantColumns evaluate_columns(const ModelSetup& s, const KinematicsColumns& k, int threads,
                                  FitObserver* observer) {
  check_thread_option(threads);
  const double* inputs[] = {k.v_x, k.v_y, k.omega, k.N, k.R};
  const char* names[] = {"v_x", "v_y", "omega", "N", "R"};
  for (int c = 0; c < 5; ++c)
    for (std::size_t i = 0; i < k.rows; ++i) {
      const double x = inputs[c][i];
      if (!std::isfinite(x) || (c >= 3 && !(x > 0.0)))
        throw InputError(fmt::format("{} at index {} is {}; expected a finite number{}", names[c],
                                     i, x, c >= 3 ? " > 0" : ""));
    }
  ResultantColumns out;
  for (auto* column : {&out.T_x, &out.T_y, &out.M_z, &out.M_roll, &out.M_tilt, &out.N})
    column->resize(k.rows);
  const ModelEvaluator<double> eval(
      s.kind, s.law, s.params.data(),
      ring_table_for_rows(s.kind, s.law, s.params[kN], false, k.rows, s.contact), nullptr,
      observed_spot_for_rows(s.kind, s.law, s.params[kQ], s.params[kN], k.rows, s.contact, threads,
                             observer));
  predict_rows(
      eval, k.rows,
      [&k](std::size_t i) {
        return model::Kinematics{k.v_x[i], k.v_y[i], k.omega[i], k.N[i], k.R[i]};
      },
      [&out](std::size_t i, const model::Resultants<double>& p) {
        out.T_x[i] = p.T_x;
        out.T_y[i] = p.T_y;
        out.M_z[i] = p.M_z;
        out.M_roll[i] = p.M_roll;
        out.M_tilt[i] = p.M_tilt;
        out.N[i] = p.N;
      },
      threads, observer);
  return out;
}

}  // namespace frictionid::app
