// The model of a shimmy run: --model, --pressure, --contact and --param, or the fitted model, law,
// spot and parameters of a report.json (--from-report, not together with --param).
#pragma once

#include "app/requests.hpp"

namespace frictionid::app {

// Throws InputError: --from-report with --param, a file that is not a report.json of this
// version of frictionid, or one without the model, pressure or parameters.
ModelRequest shimmy_model_request(const ShimmyRequest& r);

}  // namespace frictionid::app
