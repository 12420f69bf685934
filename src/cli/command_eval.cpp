// frictionid eval: the resultants a model predicts, at one point or for every row of a file.
#include <fmt/format.h>
#include <cmath>

#include <iostream>
#include <nlohmann/json.hpp>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/dataset_writer.hpp>
#include <frictionid/io/input_error.hpp>
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/model_setup.hpp"
#include "cli/option_parsers.hpp"
#include "io/atomic_file.hpp"

namespace frictionid::cli {

namespace {

// A CSV field as written: quoted when it holds a comma, a quote or surrounding spaces.
std::string csv_field(const std::string& s) {
  const bool quote = s.find_first_of(",\"\r\n") != std::string::npos ||
                     (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.back() == ' ' ||
                                     s.back() == '\t'));
  if (!quote) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// Every row of a kinematics CSV (dataset columns; channels optional), then the file's other
// columns as they were (slip angle, run ids: so predictions can be plotted against them), then
// the predictions T_x,T_y,M_z,M_roll,N (suffixed _model where the input already has such a
// column).
int eval_file(const EvalOptions& o, const ModelSetup& s) {
  if (o.output.empty()) throw InputError("eval --input needs --output FILE");
  if (o.vx || o.vy || o.omega)
    throw InputError("give either --input or --vx/--vy/--omega, not both");
  const Dataset d = load_dataset_csv(o.input, parse_column_map(o.columns), false);
  const ModelEvaluator<double> eval(
      s.kind, s.law, s.params.data(),
      ring_table_for_rows(s.kind, s.law, s.params[kN], false, d.rows()));
  std::string text = dataset_csv_text(d);
  const std::size_t header_end = text.find('\n');
  std::string header = text.substr(0, header_end);
  for (const auto& name : d.extra_names) header += "," + csv_field(name);
  for (const char* name : {"T_x", "T_y", "M_z", "M_roll", "N"}) {
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
    for (const auto& column : d.extra_values) (out += ',') += csv_field(column[i]);
    const auto r = eval(model::Kinematics{d.v_x[i], d.v_y[i], d.omega[i], d.N[i], d.R[i]});
    fmt::format_to(std::back_inserter(out), ",{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", r.T_x,
                   r.T_y, r.M_z, r.M_roll, r.N);
  }
  write_file_atomically(o.output, out);
  std::cerr << "frictionid: wrote " << d.rows() << " rows to " << o.output << "\n";
  return kExitOk;
}

}  // namespace

int run_eval(const EvalOptions& o) {
  const ModelSetup s = make_model_setup(o.model, o.pressure, o.params);
  if (!o.input.empty()) return eval_file(o, s);
  if (!o.vx || !o.omega) throw InputError("eval needs --vx and --omega (or --input FILE)");
  model::Kinematics k{*o.vx, o.vy.value_or(0.0), *o.omega, o.N, o.R};
  for (double x : {k.v_x, k.v_y, k.omega})
    if (!std::isfinite(x)) throw InputError("--vx, --vy and --omega must be finite");
  if (!(k.N > 0.0) || !std::isfinite(k.N)) throw InputError("--N must be a finite number > 0");
  if (!(k.R > 0.0) || !std::isfinite(k.R)) throw InputError("--R must be a finite number > 0");
  const ModelEvaluator<double> eval(s.kind, s.law, s.params.data());
  const auto r = eval(k);
  nlohmann::ordered_json j;
  j["T_x"] = r.T_x;
  j["T_y"] = r.T_y;
  j["M_z"] = r.M_z;
  j["M_roll"] = r.M_roll;
  j["N"] = r.N;
  std::cout << j.dump(2) << "\n";
  return kExitOk;
}

}  // namespace frictionid::cli
