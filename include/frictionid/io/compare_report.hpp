// Writes a model comparison: DIR/compare.json, DIR/compare.md, DIR/compare.html (one
// self-contained page: models side by side, plots inline), one plot per channel with every model
// over the data (DIR/compare_<channel>.svg), and each model's full report in DIR/<model>/.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/dataset.hpp>
#include <frictionid/model_comparison.hpp>

namespace frictionid {

nlohmann::ordered_json compare_json(const ModelComparison& c);
std::string compare_markdown(const ModelComparison& c, const std::vector<std::string>& plots);
std::string compare_html(const ModelComparison& c, const Dataset& d);
// Sentences on what the freely fitted closed-form coefficients mean next to the ones the exact
// fit's pressure shape implies.
std::vector<std::string> coefficient_notes(const ModelComparison& c);
std::vector<std::string> write_compare_report(const std::string& dir, const ModelComparison& c,
                                              const Dataset& d);

}  // namespace frictionid
