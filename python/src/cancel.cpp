// Interruption and progress: Ctrl-C (the interpreter's SIGINT handler, run by PyErr_CheckSignals), a CancelToken
// set from another thread, and a progress callback, all reaching the library through its hooks
// (bsh::ExtractOptions::cancel and ::progress). No global state: each computation has its own Guard.
#include "bindings.hpp"

#include <pybind11/functional.h>

namespace hsxpy {

struct Guard::State {
  std::shared_ptr<CancelToken> token;
  py::object progress;                            // None or a callable; touched only with the GIL held
  std::atomic<bool> stop{false};                  // an interrupt or a failed callback: stop and rethrow
  std::optional<py::error_already_set> error;     // what to rethrow (set with the GIL held)
  std::chrono::steady_clock::time_point last_check = std::chrono::steady_clock::now();
};

Guard::Guard(std::shared_ptr<CancelToken> token, py::object progress) : state_(std::make_shared<State>()) {
  state_->token = std::move(token);
  state_->progress = std::move(progress);
}

std::function<bool()> Guard::cancel() const {
  std::shared_ptr<State> s = state_;
  return [s] {
    if (s->stop.load(std::memory_order_relaxed)) return true;
    if (s->token && s->token->cancelled.load(std::memory_order_relaxed)) return true;
    const auto now = std::chrono::steady_clock::now();
    if (now - s->last_check < std::chrono::milliseconds(20)) return false;
    s->last_check = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {  // the handler raised (KeyboardInterrupt for SIGINT)
      s->error.emplace();             // takes the exception out of the interpreter's error indicator
      s->stop = true;
    }
    return s->stop.load();
  };
}

std::function<void(const hsx::bsh::SearchProgress&)> Guard::progress() const {
  if (state_->progress.is_none()) return {};
  std::shared_ptr<State> s = state_;
  return [s](const hsx::bsh::SearchProgress& p) {
    if (s->stop) return;
    py::gil_scoped_acquire gil;
    try {
      py::dict d;
      d["states_expanded"] = p.states_expanded;
      d["queue_size"] = p.queue_size;
      d["graph_cuts"] = p.graph_cuts;
      if (p.best_energy)
        d["best_energy"] = py::make_tuple(p.best_energy->missing_samples, p.best_energy->measure());
      else
        d["best_energy"] = py::none();
      if (p.lower_bound)
        d["lower_bound"] = py::make_tuple(p.lower_bound->missing_samples, p.lower_bound->measure);
      else
        d["lower_bound"] = py::none();
      s->progress(d);
    } catch (py::error_already_set& e) {
      s->error.emplace(std::move(e));
      s->stop = true;
    }
  };
}

void Guard::finish() const {
  if (state_->error) {
    py::error_already_set e = std::move(*state_->error);
    state_->error.reset();
    throw e;
  }
}

void bind_cancel(py::module_& m) {
  py::class_<CancelToken, std::shared_ptr<CancelToken>>(
      m, "CancelToken",
      "Pass as cancel= to a long computation; cancel() from any thread stops it at its next check (the result says "
      "stopped_by 'cancelled', like a time limit)")
      .def(py::init<>())
      .def("cancel", [](CancelToken& t) { t.cancelled = true; }, "Ask the computation to stop")
      .def_property_readonly("cancelled", [](const CancelToken& t) { return t.cancelled.load(); });
}

}  // namespace hsxpy
