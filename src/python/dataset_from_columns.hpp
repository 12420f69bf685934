// A Dataset from named columns in memory (a pandas DataFrame or a dict of numpy arrays), checked
// like the CSV reader checks a file (include/frictionid/io/dataset_csv.hpp): the same required
// columns, the same value rules, NaN where the CSV would have an empty field.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>

namespace frictionid::python {

// columns: canonical name -> values, all of one length; other names are ignored. A channel or
// sigma value that is NaN means "not measured in this row". Throws InputError naming `source`,
// the row and the column: by its label in row_labels (a DataFrame's index, as text) when given,
// else by position (1-based, with its 0-based index). Takes the columns by value and moves them
// into the Dataset: large datasets are not copied twice.
Dataset dataset_from_columns(std::map<std::string, std::vector<double>> columns,
                             const std::string& source,
                             const std::vector<std::string>& row_labels = {});

}  // namespace frictionid::python
