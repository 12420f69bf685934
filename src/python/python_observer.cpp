#include "python/python_observer.hpp"

#include <utility>

namespace py = pybind11;

namespace frictionid::python {

PythonObserver::PythonObserver()
    : fit_thread_(std::this_thread::get_id()), last_poll_(std::chrono::steady_clock::now()) {
  const auto threading = py::module_::import("threading");
  main_thread_ = threading.attr("current_thread")().is(threading.attr("main_thread")());
}

bool PythonObserver::cancelled() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_) return true;
  // Python runs signal handlers in its main thread only: elsewhere taking the GIL is useless.
  if (!main_thread_ || std::this_thread::get_id() != fit_thread_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_poll_ < kPollInterval) return false;
  last_poll_ = now;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0) return false;
  pending_.emplace();  // takes the exception the handler raised (KeyboardInterrupt for Ctrl-C)
  return true;
}

bool PythonObserver::has_pending() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return pending_.has_value();
}

void PythonObserver::rethrow_pending() {
  std::optional<py::error_already_set> e;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    e.swap(pending_);
  }
  if (e) throw std::move(*e);
}

}  // namespace frictionid::python
