// SPDX-License-Identifier: BSD-3-Clause
#include "parallel_solve.hpp"

#include <cxxabi.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <future>

#include "restitution/sweep.hpp"
#include "without_gil.hpp"

namespace restitution::python {

std::optional<PointFailure> parallel_solve(
    LawKind law, const std::vector<double>& zetas, const SolveOptions& options, unsigned threads,
    const std::function<void(std::size_t index, const CollisionResult& result)>& store) {
  std::atomic<bool> stop{false};
  std::optional<PointFailure> failure;  // written under the sweep's callback serialization
  SweepControl control;
  control.threads = threads;
  control.stop_requested = [&stop] { return stop.load(); };
  control.point_finished = [&](const SweepPoint& point) {
    if (point.result) {
      store(point.index, *point.result);
    } else if (!failure) {
      failure = PointFailure{point.index, point.error};
      stop = true;
    }
  };
  bool interrupted = false;
  PyThreadState* const caller = PyThreadState_Get();
  run_without_gil([&] {
    // The sweep runs beside this thread so that this one can poll for signals, which Python delivers to
    // the main thread only and only with the GIL held.
    auto sweep = std::async(std::launch::async, [&] { return run_sweep(zetas, options, control, law); });
    try {
      while (sweep.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) {
        if (interrupted) continue;
        briefly_with_gil(caller, [&] {
          if (PyErr_CheckSignals() != 0) {
            interrupted = true;  // the Python error stays set until thrown below
            stop = true;
          }
        });
      }
    } catch (abi::__forced_unwind&) {
      stop = true;  // the interpreter exits and ends this thread; the future's destructor awaits the sweep
      throw;
    }
    try {
      sweep.get();  // rethrows the sweep's own errors (InvalidInput for bad options)
    } catch (...) {
      if (!interrupted) throw;  // else KeyboardInterrupt, already set, takes precedence
    }
  });
  if (interrupted) throw pybind11::error_already_set();
  return failure;
}

}  // namespace restitution::python
