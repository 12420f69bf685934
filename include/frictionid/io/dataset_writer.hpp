// Writes a Dataset as CSV in the format load_dataset_csv reads, every number with %.17g so that
// it reads back bit-identical.
#pragma once

#include <string>

#include <frictionid/dataset.hpp>

namespace frictionid {

std::string dataset_csv_text(const Dataset& d);

}  // namespace frictionid
