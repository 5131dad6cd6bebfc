// SPDX-License-Identifier: BSD-3-Clause
// sweep_to_file from Python: a long sweep into a CSV file that Ctrl-C does not lose. The library keeps every
// finished row in PATH.partial; the same call with resume=True continues from it. The sweep runs with the
// GIL released; this thread takes it back every ~20 ms to run Python's signal handlers and the caller's stop
// callback, as parallel_solve.cpp does.
#include <cxxabi.h>
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <future>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "solve_options.hpp"
#include "without_gil.hpp"

namespace restitution::python {
namespace {
namespace py = pybind11;

// FNV-1a over the bytes of the ζ values: the grid's identity in the settings line, so that a resume with
// another grid of the same size and bounds is refused rather than silently recomputed row by row.
std::uint64_t grid_fingerprint(const std::vector<double>& zetas) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const double zeta : zetas) {
    unsigned char bytes[sizeof zeta];
    std::memcpy(bytes, &zeta, sizeof zeta);
    for (const unsigned char b : bytes) hash = (hash ^ b) * 0x100000001b3ULL;
  }
  return hash;
}

std::string settings_line(const std::vector<double>& zetas, const std::string& end, const std::string& method,
                          double tolerance, const std::string& law) {
  return fmt::format(
      "# restitution sweep_to_file: law={} points={} zeta-first={:.17g} zeta-last={:.17g} zeta-fnv1a={:016x} "
      "end={} method={} tolerance={:.17g}",
      law, zetas.size(), zetas.empty() ? 0.0 : zetas.front(), zetas.empty() ? 0.0 : zetas.back(),
      grid_fingerprint(zetas), end, method, tolerance);
}

const char* status_name(SweepFileOutcome::Status status) {
  switch (status) {
    case SweepFileOutcome::Status::complete:
      return "complete";
    case SweepFileOutcome::Status::already_complete:
      return "already_complete";
    case SweepFileOutcome::Status::stopped:
      return "stopped";
  }
  return "?";
}

py::dict sweep_to_file_py(const std::vector<double>& zetas, const std::string& path, bool resume,
                          const std::string& end, double tolerance, const std::string& method,
                          unsigned threads, const std::string& law, const py::object& stop) {
  const LawKind kind = law_from_name(law);
  const SolveOptions options = solve_options(end, tolerance, method, true);
  SweepFile file;
  file.path = path;
  file.resume = resume;
  file.settings = settings_line(zetas, end, method, tolerance, law);
  file.resume_option = "resume=True";
  std::atomic<bool> stopping{false};
  SweepControl control;
  control.threads = threads;
  control.stop_requested = [&stopping] { return stopping.load(); };

  bool raised = false;  // a Python error (KeyboardInterrupt, the stop callback's) is set until thrown below
  SweepFileOutcome outcome;
  PyThreadState* const caller = PyThreadState_Get();
  run_without_gil([&] {
    auto sweep =
        std::async(std::launch::async, [&] { return sweep_to_file(zetas, options, control, file, kind); });
    try {
      while (sweep.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) {
        if (stopping) continue;
        briefly_with_gil(caller, [&] {
          if (PyErr_CheckSignals() != 0) {
            raised = true;
            stopping = true;
            return;
          }
          if (stop.is_none()) return;
          try {
            if (py::cast<bool>(stop())) stopping = true;
          } catch (py::error_already_set& e) {
            e.restore();
            raised = true;
            stopping = true;
          }
        });
      }
    } catch (abi::__forced_unwind&) {
      stopping =
          true;  // the interpreter exits and ends this thread; the future's destructor awaits the sweep
      throw;
    }
    try {
      outcome = sweep.get();  // rethrows the sweep's own errors (InvalidInput, IoError)
    } catch (...) {
      if (!raised) throw;  // else the Python error, already set, takes precedence
    }
  });
  if (raised) throw py::error_already_set();
  py::dict result;
  result["status"] = status_name(outcome.status);
  result["path"] = path;
  result["partial_path"] = outcome.partial_path.string();
  result["points"] = outcome.points;
  result["finished"] = outcome.finished;
  result["resumed"] = outcome.resumed;
  result["damaged_lines"] = outcome.damaged_lines;
  result["first_damaged_line"] = outcome.first_damaged_line;
  result["failed"] = outcome.failed;
  return result;
}

}  // namespace

void bind_sweep_file(py::module_& m) {
  m.def(
      "sweep_to_file",
      [](const std::vector<double>& zetas, const std::string& path, bool resume, const std::string& end,
         double tolerance, const std::string& method, unsigned threads, const std::string& law,
         const py::object& stop) {
        try {
          return sweep_to_file_py(zetas, path, resume, end, tolerance, method, threads, law, stop);
        } catch (const IoError& e) {  // a file that cannot be written: Python's OSError
          PyErr_SetString(PyExc_OSError, e.what());
          throw py::error_already_set();
        }
      },
      py::arg("zetas"), py::arg("path"), py::arg("resume"), py::arg("end"), py::arg("tolerance"),
      py::arg("method"), py::arg("threads"), py::arg("law"), py::arg("stop"),
      "A sweep into the CSV file `path` (the command line's table) that keeps every finished row in "
      "path.partial; resume continues from it. Returns the outcome as a dict.");
}

}  // namespace restitution::python
