// The FitObserver of a fit started from Python, which runs with the GIL released. It stops the
// fit when
//   - a signal handler raises (Ctrl-C: KeyboardInterrupt), in Python's main thread only, where
//     it takes the GIL back now and then to let Python run its handlers;
//   - the caller's cancel token is set (a CancelToken, polled without the GIL, or any object
//     with is_set(), such as a threading.Event, polled with the GIL), from any thread;
//   - the interpreter exits (cancel_all, called by an exit hook of the package).
// It also hands progress to a Python callable, in the fitting thread. After the fit,
// rethrow_pending() raises the exception a handler or the callback raised.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <pybind11/pybind11.h>

#include <frictionid/fit_observer.hpp>

namespace frictionid::python {

// frictionid.CancelToken: a flag any thread may set, read by the fit without the GIL.
class CancelToken {
 public:
  void cancel() { flag_.store(true); }
  bool cancelled() const { return flag_.load(); }

 private:
  std::atomic<bool> flag_{false};
};

class PythonObserver : public FitObserver {
 public:
  // Construct in the thread that runs the fit, with the GIL held. cancel: None, a CancelToken
  // or an object with is_set(); progress: None or a callable taking a dict.
  explicit PythonObserver(pybind11::object cancel = pybind11::none(),
                          pybind11::object progress = pybind11::none());
  // With the GIL held.
  ~PythonObserver() override;
  PythonObserver(const PythonObserver&) = delete;
  PythonObserver& operator=(const PythonObserver&) = delete;

  bool cancelled() const override;
  void on_progress(const FitProgress& progress) override;
  // Call with the GIL held after the fit returned or threw: raises the exception a signal
  // handler or the progress callback raised during the fit, if any.
  void rethrow_pending();
  bool has_pending() const;
  // The fit was stopped by its token or by the interpreter's exit (not by an exception).
  bool stopped() const { return stop_.load(); }

  // Cancels every running fit and every later one: the interpreter is exiting.
  static void cancel_all();

 private:
  // Python is polled at most this often: taking the GIL costs microseconds, a fit's
  // evaluations between polls are much cheaper.
  static constexpr std::chrono::milliseconds kPollInterval{50};

  bool poll_python() const;  // with the lock held

  std::thread::id fit_thread_;
  bool main_thread_;  // the fit runs in Python's main thread, the only one that handles signals
  std::shared_ptr<CancelToken> token_;
  pybind11::object event_;     // a cancel object other than a CancelToken, or None
  pybind11::object progress_;  // None or a callable
  mutable std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  mutable std::chrono::steady_clock::time_point last_poll_, last_progress_;
  mutable std::optional<pybind11::error_already_set> pending_;
};

// Runs `work` with the GIL released and a PythonObserver on cancel and progress (fit()'s
// arguments), as evaluate() and generate() do: Ctrl-C raises KeyboardInterrupt, a set token
// FitCancelled, an exception of the callback itself. Call with the GIL held.
void run_observed(const pybind11::object& cancel, const pybind11::object& progress,
                  const std::function<void(FitObserver&)>& work);

}  // namespace frictionid::python
