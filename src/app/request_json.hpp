// A FitRequest as JSON and back: what a batch run carries to a Dask worker, and the text whose
// hash keys the batch journal (a change of any option that changes the fit refits the run).
#pragma once

#include <nlohmann/json.hpp>

#include "app/requests.hpp"

namespace frictionid::app {

// Every field that fit_settings reads and the data's column map, in a fixed order; not the
// threads (results do not depend on them) nor the report's options.
nlohmann::ordered_json fit_request_json(const FitRequest& r);

// The inverse of fit_request_json; throws nlohmann::json::exception on a malformed object.
FitRequest fit_request_from_json(const nlohmann::ordered_json& j);

}  // namespace frictionid::app
