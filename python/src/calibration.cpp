// SPDX-License-Identifier: BSD-3-Clause
// restitution.calibrate: β (and A for a material) from a measured ε at an impact speed.
#include <fmt/core.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "pickle_state.hpp"
#include "repr_text.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "solve_options.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

// β and g* belong to viscoelastic Hertz (restitution/calibration.hpp): the other laws have none, which
// Python says with None, as the CLI leaves them out, rather than with the struct's placeholder 0.
template <double Calibration::*member>
std::optional<double> hertz_only(const Calibration& c) {
  if (!has_dissipative_constant(c.law)) return std::nullopt;
  return c.*member;
}

std::string calibration_repr(const Calibration& c) {
  return fmt::format(
      "Calibration(law='{}', zeta={}, parameter={}, beta={}, eps_at_zeta={}, characteristic_velocity_m_s={}, "
      "dissipative_constant_s={}, solves={})",
      law_name(c.law), c.zeta, c.parameter,
      optional_text(hertz_only<&Calibration::beta>(c), "s^(1/5) m^(-1/5)"), c.eps_at_zeta,
      optional_text(hertz_only<&Calibration::characteristic_velocity_m_s>(c), "m/s"),
      optional_text(c.dissipative_constant_s, "s"), c.solves);
}

py::tuple calibration_state(const Calibration& c) {
  return py::make_tuple(law_name(c.law), c.zeta, c.parameter, c.beta, c.eps_at_zeta,
                        c.characteristic_velocity_m_s, c.dissipative_constant_s, c.solves);
}

Calibration calibration_from_state(const py::tuple& t) {
  check_state(t, 8, "Calibration");
  return Calibration{law_from_name(t[0].cast<std::string>()),
                     t[1].cast<double>(),
                     t[2].cast<double>(),
                     t[3].cast<double>(),
                     t[4].cast<double>(),
                     t[5].cast<double>(),
                     t[6].cast<std::optional<double>>(),
                     t[7].cast<int>()};
}

}  // namespace

void bind_calibration(py::module_& m) {
  py::class_<Calibration>(m, "Calibration", "The damping that gives a measured eps at an impact speed.")
      .def_readonly("zeta", &Calibration::zeta,
                    "zeta with eps(zeta) = eps at the requested end (natural units).")
      .def_property_readonly(
          "law", [](const Calibration& c) { return law_name(c.law); }, "The contact law's name.")
      .def_readonly("parameter", &Calibration::parameter,
                    "The law's parameter: zeta, or the damping ratio r = zeta/2 for the linear dash-pot.")
      .def_property_readonly(
          "beta", &hertz_only<&Calibration::beta>,
          "beta = zeta / v^(1/5) [s^(1/5) m^(-1/5)] (viscoelastic Hertz; None for other laws).")
      .def_readonly("eps_at_zeta", &Calibration::eps_at_zeta, "eps re-solved at zeta, for the record.")
      .def_property_readonly(
          "characteristic_velocity_m_s", &hertz_only<&Calibration::characteristic_velocity_m_s>,
          "The 1999 paper's g* = (C1 beta)^(-5) [m/s] (viscoelastic Hertz; None for other laws).")
      .def_readonly("dissipative_constant_s", &Calibration::dissipative_constant_s,
                    "A [s] for the material, or None without one.")
      .def_readonly("solves", &Calibration::solves, "Collisions integrated by the root finder.")
      .def("__repr__", &calibration_repr)
      .def(py::pickle(&calibration_state, &calibration_from_state));
  m.def(
      "calibrate",
      [](double eps, double velocity, const std::string& end, double tolerance, const std::string& method,
         const std::optional<Material>& material, const std::string& law) {
        CalibrationRequest request;
        request.law = law_from_name(law);
        if (material && !has_dissipative_constant(request.law)) {
          throw InvalidInput(fmt::format(
              "material gives the dissipative constant A of law='viscoelastic-hertz' only, not law='{}'",
              law));
        }
        request.eps = eps;
        request.velocity_m_s = velocity;
        const SolveOptions options = solve_options(end, tolerance, method, false);  // checks all three
        request.end = end_from_name(end);
        request.tolerance = options.tolerance;
        request.method = options.method;
        if (material) request.k = elastic_constants(*material).k;
        return without_gil([&] {
          CollisionSolver solver;
          return calibrate(request, solver);
        });
      },
      py::arg("eps"), py::arg("velocity"), py::arg("end"), py::arg("tolerance"), py::arg("method"),
      py::arg("material"), py::arg("law"), "Calibration for one measured eps at one velocity [m/s].");
}

}  // namespace restitution::python
