#include "progress.h"

#include "reports.h"

#include <pybind11/stl.h>

#include <utility>
#include <vector>

namespace fairsurf::python {

Progress::Progress(py::object callback) : callback_(std::move(callback)) {
  if (!callback_.is_none() && !PyCallable_Check(callback_.ptr()))
    throw py::type_error("progress must be callable or None");
}

void Progress::attach(FlowOptions& options) const {
  options.interrupted = [this] { return stop_; };
}

void Progress::call(py::dict step) {
  if (callback_.is_none() || stop_) return;
  try {
    const py::object answer = callback_(step);
    // Only an explicit False stops: a callback that returns nothing lets the run go on.
    stop_ = answer.is(py::bool_(false));
  } catch (py::error_already_set& e) {
    error_ = std::make_unique<py::error_already_set>(std::move(e));
    stop_ = true;
  }
}

FlowObserver Progress::flow_observer() {
  if (callback_.is_none()) return {};
  return [this](const StepRecord& record) {
    py::gil_scoped_acquire gil;
    call(to_dict(record));
  };
}

FillObserver Progress::fill_observer() {
  return [this](std::span<const int> holes, const StepRecord& record) {
    py::gil_scoped_acquire gil;
    py::dict step = to_dict(record);
    fill_steps_[holes.front()].append(step);
    step = step.attr("copy")();  // the callback gets its own copy, with the holes being faired
    step["holes"] = py::tuple(py::cast(std::vector<int>(holes.begin(), holes.end())));
    call(step);
  };
}

void Progress::rethrow() const {
  if (error_) throw *error_;
}

}  // namespace fairsurf::python
