// Turns a ModelRequest (--model, --pressure, --contact, --param) into a model variant with a full
// parameter vector: values the user leaves out follow from the pressure law and the contact spot
// (docs/physics.md §3, §9).
#pragma once

#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model_variant.hpp>
#include "app/requests.hpp"

namespace frictionid::app {

struct ModelSetup {
  ModelKind kind;
  model::PressureLaw<double> law;
  std::string law_label;
  model::ContactSpot contact;
  std::string contact_label;  // as --contact spells it ("circle", "ellipse:0.6", "map:FILE")
  std::array<double, kParamCount> params;
};

// Throws InputError on an unknown model, law, spot or parameter name, an out-of-range value, a
// spot the model does not support, --pressure with a pressure map, or a tilt (h, h_y) that makes
// the pressure negative somewhere on the spot.
ModelSetup make_model_setup(const ModelRequest& r);

// The spot of --contact (parse_contact_option), with the checks that need the other options: a
// pressure map is the pressure, so --pressure given with it is an error, and a spot other than
// the circle needs the exact model.
model::ContactSpot checked_contact(const std::string& contact, bool pressure_given, ModelKind kind);

// The pressure law's label in reports and outputs: "map" for a pressure map (the map is the
// pressure), else pressure_law_label.
std::string law_label_for(const model::PressureLaw<double>& law, const std::string& pressure,
                          const model::ContactSpot& contact);

// Throws InputError when the tilted pressure 1 + h x + h_y y is negative somewhere on the spot
// (model::tilt_violation), naming `option`, h, h_y and the point (x, y).
void check_tilt(const std::string& option, const model::ContactSpot& contact,
                const std::string& contact_label, double q, double h, double h_y);

// Whether a model's outputs carry M_tilt: on any spot but the circle, or with a tilt across the
// rolling direction (a circle without it gives what it always gave).
bool shows_tilt(const ModelSetup& s);

// The model, the pressure law's label, the spot (unless the circle) and the model's parameters
// by name, as the JSON outputs (simulate, the truth file of generate) start.
nlohmann::ordered_json model_json(const ModelSetup& s);

}  // namespace frictionid::app
