// The parts of the extension module frictionid._frictionid, one registration function each
// (module.cpp calls them in order).
#pragma once

#include <pybind11/pybind11.h>

#include <frictionid/fitter.hpp>

namespace frictionid::python {

// A fit stopped by its cancel token or by the interpreter's exit: frictionid.FitCancelled, a
// FitError.
class FitCancelled : public FitError {
 public:
  using FitError::FitError;
};

void register_fit(pybind11::module_& m);       // datasets, FitOptions, fit, FitResult handle
void register_evaluate(pybind11::module_& m);  // evaluate, coefficients
void register_generate(pybind11::module_& m);  // synthetic datasets
void register_simulate(pybind11::module_& m);  // the sliding-spinning body
void register_shimmy(pybind11::module_& m);    // the towed wheel
void register_batch(pybind11::module_& m);     // `frictionid batch` run by run (Dask)

}  // namespace frictionid::python
