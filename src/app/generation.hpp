// A synthetic dataset from any model, with its truth (`frictionid generate`,
// `frictionid.generate()`).
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/synthetic_data.hpp>
#include "app/model_setup.hpp"
#include "app/requests.hpp"

namespace frictionid::app {

// Largest number of rows: 10^7 rows are about 1 GB of CSV.
inline constexpr std::uint64_t kMaxGeneratedRows = 10'000'000;

struct GeneratedData {
  ModelSetup setup;
  SyntheticDesign design;
  Dataset data;
};

// Checks the request and makes the rows. Throws InputError naming the option. The observer (may
// be null) hears a spot's table build and the model's rows and may cancel them
// (FitError("interrupted"), generate_dataset).
GeneratedData generate(const GenerateRequest& r, FitObserver* observer = nullptr);

// The truth file's JSON: the model and its parameters, the noise, the seed and the design.
nlohmann::ordered_json truth_json(const GenerateRequest& r, const GeneratedData& g);

// Writes r.output (the dataset CSV) and, when r.truth is set, the truth, each atomically.
void write_generated(const GenerateRequest& r, const GeneratedData& g);

}  // namespace frictionid::app
