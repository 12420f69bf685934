// Writes a model comparison: DIR/compare.json, DIR/compare.md, DIR/compare.html (one
// self-contained page: models side by side, plots inline), one plot per channel with every model
// over the data (DIR/compare_<channel>.svg), and each model's full report in DIR/<model>/.
//
// `contacts` holds each fit's contact spot as --contact spells it, in c.fits' order (empty: every
// fit on the circle). A fit on another spot than the circle is named MODEL@SPOT on the pages and
// plots ("exact@ellipse:0.7") and in preferred_by_aic/bic, compare.json states its "contact",
// and its report is in DIR/MODEL@SPOT/ (characters other than letters, digits and ._+=@- as _);
// a comparison on the circle alone is what it always was.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/dataset.hpp>
#include <frictionid/io/provenance.hpp>
#include <frictionid/model_comparison.hpp>

namespace frictionid {

// Every page and compare.json name the provenance `p` (io/provenance.hpp): compare.json as its
// last key "provenance", the pages in a section "Traceability"; each model's report too.
nlohmann::ordered_json compare_json(const ModelComparison& c, const Provenance& p = {},
                                    const std::vector<std::string>& contacts = {});
std::string compare_markdown(const ModelComparison& c, const std::vector<std::string>& plots,
                             const Provenance& p = {},
                             const std::vector<std::string>& contacts = {});
std::string compare_html(const ModelComparison& c, const Dataset& d, const Provenance& p = {},
                         const std::vector<std::string>& contacts = {});
// Sentences on what the freely fitted closed-form coefficients mean next to the ones the exact
// fit's pressure shape implies.
std::vector<std::string> coefficient_notes(const ModelComparison& c);
std::vector<std::string> write_compare_report(const std::string& dir, const ModelComparison& c,
                                              const Dataset& d, const Provenance& p = {},
                                              const std::vector<std::string>& contacts = {},
                                              const std::function<bool()>& stop = {});

// The name of fit k of a comparison on the pages: its model, and "@SPOT" unless contacts[k] is
// the circle (or contacts is empty).
std::string compare_variant_name(const ModelComparison& c, const std::vector<std::string>& contacts,
                                 std::size_t k);
// c as the pages show it: each fit named as its variant (compare_variant_name), and the
// preferred models by those names.
ModelComparison compare_named_variants(const ModelComparison& c,
                                       const std::vector<std::string>& contacts);
// The directory of that fit's report inside DIR: the name with characters other than letters,
// digits and ._+=@- replaced by _.
std::string compare_variant_directory(const std::string& name);

}  // namespace frictionid
