// Writes a model comparison: DIR/compare.json, DIR/compare.md, DIR/compare.html (one
// self-contained page: models side by side, plots inline), one plot per channel with every model
// over the data (DIR/compare_<channel>.svg), and each model's full report in DIR/<model>/.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/dataset.hpp>
#include <frictionid/io/provenance.hpp>
#include <frictionid/model_comparison.hpp>

namespace frictionid {

// Every page and compare.json name the provenance `p` (io/provenance.hpp): compare.json as its
// last key "provenance", the pages in a section "Traceability"; each model's report too.
nlohmann::ordered_json compare_json(const ModelComparison& c, const Provenance& p = {});
std::string compare_markdown(const ModelComparison& c, const std::vector<std::string>& plots,
                             const Provenance& p = {});
std::string compare_html(const ModelComparison& c, const Dataset& d, const Provenance& p = {});
// Sentences on what the freely fitted closed-form coefficients mean next to the ones the exact
// fit's pressure shape implies.
std::vector<std::string> coefficient_notes(const ModelComparison& c);
std::vector<std::string> write_compare_report(const std::string& dir, const ModelComparison& c,
                                              const Dataset& d, const Provenance& p = {});

}  // namespace frictionid
