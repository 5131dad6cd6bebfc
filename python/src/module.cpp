// SPDX-License-Identifier: BSD-3-Clause
// The extension module _restitution: the library's solver, units, calibration, series and fast table for the
// pure-Python package `restitution` (python/restitution/__init__.py).
#include "bindings.hpp"

PYBIND11_MODULE(_restitution, m) {
  m.doc() = "Compiled core of the restitution package; use `import restitution` instead.";
  m.attr("__version__") = RESTITUTION_VERSION;  // the file VERSION, through python/CMakeLists.txt
  restitution::python::bind_errors(m);
  restitution::python::bind_collision(m);
  restitution::python::bind_material(m);
  restitution::python::bind_calibration(m);
  restitution::python::bind_fit(m);
  restitution::python::bind_build_info(m);
  restitution::python::bind_sweep_file(m);
  restitution::python::bind_gas(m);
  restitution::python::bind_oblique(m);
  restitution::python::bind_adhesion(m);
  auto series = m.def_submodule("series", "Analytic series and approximations of eps(zeta).");
  restitution::python::bind_series(series);
  auto fast = m.def_submodule("fast", "The certified fast table of eps(zeta) and its inverse.");
  restitution::python::bind_fast(fast);
}
