// frictionid eval: the resultants a model predicts, at one point or for every row of a file.
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/model_setup.hpp"
#include "io/input_error.hpp"

namespace frictionid::cli {

int run_eval(const EvalOptions& o) {
  const ModelSetup s = make_model_setup(o.model, o.pressure, o.params);
  if (!o.input.empty()) throw InputError("--input is not available yet");
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
