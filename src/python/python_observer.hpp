// The FitObserver of a fit started from Python, which runs with the GIL released: it takes the
// GIL back now and then to let Python run its signal handlers, so that Ctrl-C (or any exception
// a handler raises) cancels the fit. After the fit, rethrow_pending() raises that exception.
#pragma once

#include <chrono>
#include <mutex>
#include <optional>
#include <thread>

#include <pybind11/pybind11.h>

#include <frictionid/fit_observer.hpp>

namespace frictionid::python {

class PythonObserver : public FitObserver {
 public:
  // Construct in the thread that runs the fit, with the GIL held.
  PythonObserver();
  bool cancelled() const override;
  // Call with the GIL held after the fit returned or threw: raises the exception a signal
  // handler raised during the fit, if any.
  void rethrow_pending();
  bool has_pending() const;

 private:
  // Signal handlers run at most this often: taking the GIL costs microseconds, a fit's
  // evaluations between polls are much cheaper.
  static constexpr std::chrono::milliseconds kPollInterval{50};

  std::thread::id fit_thread_;
  bool main_thread_;  // the fit runs in Python's main thread, the only one that handles signals
  mutable std::mutex mutex_;
  mutable std::chrono::steady_clock::time_point last_poll_;
  mutable std::optional<pybind11::error_already_set> pending_;
};

}  // namespace frictionid::python
