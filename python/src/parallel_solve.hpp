// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Many collisions from Python: the library's parallel sweep, run with the GIL released, stoppable by
// Ctrl-C. The one place the module touches threads (the library's sweep owns the worker pool).
#include <pybind11/pybind11.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"

namespace restitution::python {

struct PointFailure {
  std::size_t index = 0;
  std::string message;  // the library's NumericalFailure message
};

// Solves the law's natural form at every ζ on `threads` threads (0: all cores); `store` receives each
// finished point, from worker threads, one call at a time and without the GIL (it must not touch Python
// objects). Must be called with the GIL held. Every ~20 ms the GIL is taken back to run Python's signal
// handlers: if one raises (Ctrl-C -> KeyboardInterrupt) the sweep stops after the points in progress and
// pybind11::error_already_set is thrown. The first numerical failure stops the sweep and is returned.
// `progress` (None, or a Python callable(done, total)) is called with the GIL at most every
// kProgressInterval and once at the end; an exception it raises stops the sweep like Ctrl-C.
std::optional<PointFailure> parallel_solve(
    LawKind law, const std::vector<double>& zetas, const SolveOptions& options, unsigned threads,
    const std::function<void(std::size_t index, const CollisionResult& result)>& store,
    const pybind11::object& progress = pybind11::none());

}  // namespace restitution::python
