// Reading a dataset in whichever form its file has (io/data_form.hpp): the native CSV form, the
// wheel form as CSV, or a TYDEX file, chosen by DatasetReadOptions::form or, by default, from the
// file itself. What fit, compare and batch call; load_dataset_csv, load_wheel_csv and
// load_tydex read one form each.
#pragma once

#include <string>

#include <frictionid/dataset.hpp>
#include <frictionid/io/data_form.hpp>

namespace frictionid {

struct LoadedDataset {
  Dataset data;
  DataForm form;  // which form was read, why, the axes and the units
};

// Reads the file; throws InputError for anything it rejects, including a column map that names
// a column neither form has, and --input-form native for a TYDEX file.
LoadedDataset read_dataset(const std::string& path, const DatasetReadOptions& options = {});

// The form read_dataset would read the file in, without reading its rows (a CSV file's header
// only; a TYDEX file is read whole, for its units). Throws InputError as read_dataset does for
// what it reads.
DataForm inspect_dataset_form(const std::string& path, const DatasetReadOptions& options = {});

}  // namespace frictionid
