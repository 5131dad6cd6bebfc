// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The parts of the extension module _restitution, one registration function per file; the public Python
// API (argument conversion, broadcasting, docstrings) is restitution/__init__.py on top of these.
#include <pybind11/pybind11.h>

namespace restitution::python {

void bind_errors(pybind11::module_& m);       // errors.cpp
void bind_collision(pybind11::module_& m);    // collision.cpp: eps, solve and their result types
void bind_material(pybind11::module_& m);     // material.cpp
void bind_calibration(pybind11::module_& m);  // calibration.cpp
void bind_series(pybind11::module_& m);       // series.cpp
void bind_fast(pybind11::module_& m);         // fast.cpp: the certified fast table
void bind_fit(pybind11::module_& m);          // fit.cpp: fit_data, measured eps(v)
void bind_build_info(pybind11::module_& m);   // build_info.cpp: version and SUNDIALS build
void bind_sweep_file(pybind11::module_& m);   // sweep_file.cpp: sweep_to_file, resumable
void bind_gas(pybind11::module_& m);          // gas.cpp: the freely cooling gas
void bind_oblique(pybind11::module_& m);      // oblique.cpp: oblique impacts, tangential models
void bind_adhesion(pybind11::module_& m);     // adhesion.cpp: adhesive collisions, the sticking speed

}  // namespace restitution::python
