#include "python/python_observer.hpp"

#include <set>
#include <utility>

#include "python/bindings.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

// The running fits, for cancel_all; once the interpreter exits no fit starts any more.
std::mutex g_running_mutex;
std::set<const PythonObserver*> g_running;
std::atomic<bool> g_exiting{false};

const char* stage_name(FitStage s) {
  switch (s) {
    case FitStage::GlobalSearch:
      return "global search";
    case FitStage::LocalFit:
      return "local fit";
    case FitStage::ContactTable:
      return "contact table";
    case FitStage::ContactRows:
      return "contact integrals";
    case FitStage::ModelRows:
      return "model rows";
  }
  return "";
}

}  // namespace

PythonObserver::PythonObserver(py::object cancel, py::object progress)
    : fit_thread_(std::this_thread::get_id()),
      progress_(std::move(progress)),
      last_poll_(std::chrono::steady_clock::now()),
      last_progress_(last_poll_ - kPollInterval) {
  const auto threading = py::module_::import("threading");
  main_thread_ = threading.attr("current_thread")().is(threading.attr("main_thread")());
  if (py::isinstance<CancelToken>(cancel))
    token_ = cancel.cast<std::shared_ptr<CancelToken>>();
  else if (!cancel.is_none())
    event_ = std::move(cancel);
  std::lock_guard<std::mutex> lock(g_running_mutex);
  g_running.insert(this);
  if (g_exiting.load()) stop_.store(true);
}

PythonObserver::~PythonObserver() {
  std::lock_guard<std::mutex> lock(g_running_mutex);
  g_running.erase(this);
}

void PythonObserver::cancel_all() {
  g_exiting.store(true);
  std::lock_guard<std::mutex> lock(g_running_mutex);
  for (const PythonObserver* o : g_running) o->stop_.store(true);
}

bool PythonObserver::cancelled() const {
  if (stop_.load() || (token_ && token_->cancelled())) {
    stop_.store(true);
    return true;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_) return true;
  if (g_exiting.load()) return false;  // never take the GIL while the interpreter finalizes
  // Signal handlers run in Python's main thread only; an event is polled from the fit's thread.
  const bool signals = main_thread_ && std::this_thread::get_id() == fit_thread_;
  if (!signals && !event_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_poll_ < kPollInterval) return false;
  last_poll_ = now;
  return poll_python();
}

bool PythonObserver::poll_python() const {
  py::gil_scoped_acquire gil;
  if (main_thread_ && std::this_thread::get_id() == fit_thread_ && PyErr_CheckSignals() != 0) {
    pending_.emplace();  // takes the exception the handler raised (KeyboardInterrupt for Ctrl-C)
    return true;
  }
  if (!event_) return false;
  try {
    if (event_.attr("is_set")().cast<bool>()) {
      stop_.store(true);
      return true;
    }
  } catch (py::error_already_set& e) {
    pending_.emplace(std::move(e));
    return true;
  }
  return false;
}

void PythonObserver::on_progress(const FitProgress& p) {
  if (progress_.is_none() || g_exiting.load()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_progress_ < kPollInterval) return;  // a callback per 50 ms at most
  last_progress_ = now;
  py::gil_scoped_acquire gil;
  try {
    py::dict d;
    d["stage"] = stage_name(p.stage);
    d["done"] = p.done;
    d["total"] = p.total;
    d["start"] = p.start;
    d["starts"] = p.starts;
    d["cost"] = p.cost;
    progress_(d);
  } catch (py::error_already_set& e) {
    pending_.emplace(std::move(e));  // the next poll stops the fit; the error is raised after
  }
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

void run_observed(const pybind11::object& cancel, const pybind11::object& progress,
                  const std::function<void(FitObserver&)>& work) {
  PythonObserver observer(cancel, progress);
  try {
    pybind11::gil_scoped_release release;
    work(observer);
  } catch (const FitError&) {
    observer.rethrow_pending();  // Ctrl-C: KeyboardInterrupt rather than FitError("interrupted")
    if (observer.stopped()) throw FitCancelled("cancelled");
    throw;
  }
  observer.rethrow_pending();
}

}  // namespace frictionid::python
