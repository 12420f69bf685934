// The data file of a fit request read in its form (native, wheel, TYDEX; io/dataset_reader.hpp),
// the check the wheel form's rolling direction asks of the fit, and the columns a batch keeps.
#pragma once

#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_settings.hpp>
#include <frictionid/io/dataset_reader.hpp>
#include <frictionid/io/summary_table.hpp>
#include "app/requests.hpp"

namespace frictionid::app {

// The reading options of r (--input-form, --axes, --contact-radius, --columns); throws
// InputError naming the option for a value it does not know.
DatasetReadOptions dataset_read_options(const FitRequest& r);

// Reads `path` as r asks (read_dataset).
LoadedDataset load_fit_data(const FitRequest& r, const std::string& path);

// The form `path` would be read in (inspect_dataset_form): for the reports of batch runs.
DataForm fit_data_form(const FitRequest& r, const std::string& path);

// In the wheel form the pressure tilt follows the rolling direction, sgn(Omega) per row
// (Dataset::tilt_sign). A row whose wheel does not turn (tilt_sign 0) has none, so the fit needs
// h and h_y held at 0 (where its model reads them); else an InputError names the first such row.
void check_rolling_direction(const FitSettings& s, const Dataset& d);

// The --keep columns of a run: per name, the column's value in the run's rows (text, as the
// file has it) when every row has the same, else the distinct values in the order they first
// appear joined by "|" (and the summary says so by the "|"). Throws InputError (naming `path`)
// for a name the data does not have, listing the columns it has.
std::vector<Covariate> kept_columns(const Dataset& d, const std::vector<std::string>& keep);

}  // namespace frictionid::app
