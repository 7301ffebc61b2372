// The optional progress callback of smooth, fill_holes, fair and blend: called (with the GIL) after
// every trial flow step with the step's dict; returning False stops the run through
// FlowOptions::interrupted, which keeps the last accepted state. An exception raised by the callback
// also stops the run and is re-raised once the library call has returned.
#pragma once

#include <fairsurf/applications/fill.h>
#include <fairsurf/flow/flow.h>

#include <pybind11/pybind11.h>

#include <map>
#include <memory>

namespace fairsurf::python {

namespace py = pybind11;

class Progress {
 public:
  /// `callback`: None or a callable taking one dict.
  explicit Progress(py::object callback);

  /// Sets options.interrupted so that the run stops once the callback has said so.
  void attach(FlowOptions& options) const;
  /// Observers for the library calls (no-ops without a callback). The fill observer also records
  /// each group's steps, for the report's steps_log.
  FlowObserver flow_observer();
  FillObserver fill_observer();
  /// Step dicts by the first hole of each jointly faired group (fill only).
  const std::map<int, py::list>& fill_steps() const { return fill_steps_; }
  /// Re-raises the callback's exception, if it raised one. Call with the GIL held.
  void rethrow() const;

 private:
  void call(py::dict step);

  py::object callback_;
  bool stop_ = false;
  std::unique_ptr<py::error_already_set> error_;
  std::map<int, py::list> fill_steps_;
};

}  // namespace fairsurf::python
