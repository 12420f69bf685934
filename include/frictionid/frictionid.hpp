// frictionid: identification of the coupled dry-friction model of a wheel that rolls, slides and
// spins (docs/physics.md), as a library. This umbrella header brings in the whole public API;
// docs/design.md describes it, examples/fit_from_csv.cpp shows the user path.
#pragma once

// Physics (header-only, templated on the scalar type; target frictionid::model).
#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/exact_model.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/sliding_spinning_body.hpp>

// Identification (target frictionid::core).
#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/fit_settings.hpp>
#include <frictionid/fitter.hpp>
#include <frictionid/joint_fit.hpp>
#include <frictionid/model_comparison.hpp>
#include <frictionid/model_variant.hpp>
#include <frictionid/parameters.hpp>
#include <frictionid/synthetic_data.hpp>

// Files (target frictionid::io).
#include <frictionid/io/compare_report.hpp>
#include <frictionid/io/data_form.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/dataset_reader.hpp>
#include <frictionid/io/dataset_writer.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/io/pressure_map_reader.hpp>
#include <frictionid/io/report_writer.hpp>
#include <frictionid/io/summary_table.hpp>
#include <frictionid/io/tydex_reader.hpp>
#include <frictionid/io/units.hpp>
#include <frictionid/io/wheel_form.hpp>
