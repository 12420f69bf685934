// JSON values the app layer builds (a report, a coefficient table, a simulation summary) as
// Python objects, converted value by value: numbers keep their bits, objects their key order,
// and no text lies between the C++ result and Python.
#pragma once

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace frictionid::python {

// null -> None, booleans, integers and doubles as such, strings (invalid UTF-8 replaced),
// arrays -> list, objects -> dict in their order.
pybind11::object to_python(const nlohmann::ordered_json& j);

}  // namespace frictionid::python
