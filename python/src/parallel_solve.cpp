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
namespace {

// A few calls a second: enough for a progress bar, too few to slow the sweep (each takes the GIL back).
constexpr auto kProgressInterval = std::chrono::milliseconds(250);

}  // namespace

std::optional<PointFailure> parallel_solve(
    LawKind law, const std::vector<double>& zetas, const SolveOptions& options, unsigned threads,
    const std::function<void(std::size_t index, const CollisionResult& result)>& store,
    const pybind11::object& progress) {
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> done{0};
  std::optional<PointFailure> failure;  // written under the sweep's callback serialization
  SweepControl control;
  control.threads = threads;
  control.stop_requested = [&stop] { return stop.load(); };
  control.point_finished = [&](const SweepPoint& point) {
    ++done;
    if (point.result) {
      store(point.index, *point.result);
    } else if (!failure) {
      failure = PointFailure{point.index, point.error};
      stop = true;
    }
  };
  bool interrupted = false;
  const std::size_t total = zetas.size();
  // Python's signal handlers and the progress callback run here, on the calling thread with the GIL; an
  // error either raises stays set (interrupted) until thrown below.
  auto report = [&] {
    if (progress.is_none()) return;
    try {
      progress(done.load(), total);
    } catch (pybind11::error_already_set& error) {
      error.restore();
      interrupted = true;
      stop = true;
    }
  };
  auto last_report = std::chrono::steady_clock::now();
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
          } else if (std::chrono::steady_clock::now() - last_report >= kProgressInterval) {
            report();
            last_report = std::chrono::steady_clock::now();
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
  if (!interrupted && !failure) report();  // the final (total, total)
  if (interrupted) throw pybind11::error_already_set();
  return failure;
}

}  // namespace restitution::python
