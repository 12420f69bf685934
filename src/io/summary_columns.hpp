// The columns a summary table has for its rows, shared by summary.csv/json and summary.html so
// that both list the same parameters and covariates in the same order.
#pragma once

#include <string>
#include <vector>

#include <frictionid/io/summary_table.hpp>

namespace frictionid {

// Every parameter some row has, in canonical order (f, kappa, h, ...), whatever the rows' order.
std::vector<std::string> summary_parameter_names(const std::vector<SummaryRow>& rows);

// Every covariate some row has, in order of first appearance over the rows.
std::vector<std::string> summary_covariate_names(const std::vector<SummaryRow>& rows);

}  // namespace frictionid
