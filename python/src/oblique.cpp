// SPDX-License-Identifier: BSD-3-Clause
// restitution.oblique: oblique impacts with a LAMMPS tangential model (src/oblique/, docs/oblique.md), from
// the arguments of `restitution oblique` as keywords, one impact per (angle, spin) pair;
// restitution/_oblique.py broadcasts the arrays and wraps the columns in ObliqueResult.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "parameter_arguments.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution_oblique/oblique_parameters.hpp"
#include "restitution_oblique/oblique_study.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

using namespace restitution::oblique;

py::array_t<double> array_of(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

// The impacts as columns: one float64 array per scalar output, lists of the switch times and modes.
py::dict columns_of(const ObliqueSetup& setup, const std::vector<ObliqueImpact>& impacts) {
  const std::vector<std::pair<const char*, double (*)(const ObliqueImpact&)>> scalars = {
      {"angle_deg", [](const ObliqueImpact& i) { return i.angle_deg; }},
      {"initial_spin_rad_s", [](const ObliqueImpact& i) { return i.initial_spin_rad_s; }},
      {"normal_restitution", [](const ObliqueImpact& i) { return i.result.normal_restitution; }},
      {"tangential_restitution", [](const ObliqueImpact& i) { return i.result.tangential_restitution; }},
      {"rebound_angle", [](const ObliqueImpact& i) { return i.result.rebound_angle_rad; }},
      {"impact_angle", [](const ObliqueImpact& i) { return i.result.impact_angle_rad; }},
      {"spin_rad_s", [](const ObliqueImpact& i) { return i.result.spin_first_rad_s; }},
      {"spin2_rad_s", [](const ObliqueImpact& i) { return i.result.spin_second_rad_s; }},
      {"slip_velocity", [](const ObliqueImpact& i) { return i.result.slip_velocity_m_s; }},
      {"tangential_velocity", [](const ObliqueImpact& i) { return i.result.tangential_velocity_m_s; }},
      {"normal_velocity", [](const ObliqueImpact& i) { return i.result.normal_velocity_m_s; }},
      {"impulse_ratio", [](const ObliqueImpact& i) { return i.result.impulse_ratio; }},
      {"line_of_centres_turn", [](const ObliqueImpact& i) { return i.result.line_of_centres_turn_rad; }},
      {"contact_time_s", [](const ObliqueImpact& i) { return i.result.contact_time_s; }},
      {"stick_time_s", [](const ObliqueImpact& i) { return i.result.stick_time_s; }},
      {"slip_time_s", [](const ObliqueImpact& i) { return i.result.slip_time_s; }},
      {"psi_in", [](const ObliqueImpact& i) { return i.psi_in; }},
      {"psi_out", [](const ObliqueImpact& i) { return i.psi_out; }},
  };
  py::dict out;
  for (const auto& [name, get] : scalars) {
    std::vector<double> values;
    values.reserve(impacts.size());
    for (const ObliqueImpact& i : impacts) values.push_back(get(i));
    out[name] = array_of(values);
  }
  py::list switch_times;
  py::list modes;
  for (const ObliqueImpact& i : impacts) {
    std::vector<double> times;
    py::list names;
    for (const ModeSwitch& m : i.result.switches) {
      times.push_back(m.time_s);
      names.append(mode_name(m.mode));
    }
    switch_times.append(array_of(times));
    modes.append(py::tuple(names));
  }
  py::list ill_conditioned;  // what the accuracy contract could not show, per impact ("" where it could)
  for (const ObliqueImpact& i : impacts) ill_conditioned.append(i.ill_conditioned ? i.conditioning : "");
  out["ill_conditioned"] = ill_conditioned;
  out["switch_times"] = switch_times;
  out["modes"] = modes;
  py::list failures;  // why an impact was not solved ("" where it was): its outputs are NaN
  for (const ObliqueImpact& i : impacts) failures.append(i.failure);
  out["failure"] = failures;
  out["rigid_wall"] = setup.rigid_wall;
  out["dissipative_constant_s"] = setup.dissipative_constant_s;
  out["tangential_model"] = tangential_name(setup.tangential.kind);
  out["maw_chi"] = maw_chi(setup);
  return out;
}

// angles and spins are paired, one impact each (the Python side broadcast them); the other arguments by the
// names of the study's table (restitution_oblique/oblique_parameters.hpp), their types checked.
py::dict oblique_impacts(const Material& material, const std::vector<double>& angles,
                         const std::vector<double>& spins, const py::dict& arguments) {
  if (angles.size() != spins.size()) throw InvalidInput("angle and spin must broadcast to one shape");
  ObliqueInputs in = parameter_arguments(arguments, oblique_fields(), "oblique",
                                         [](const ObliqueField&, const py::handle&, ObliqueInputs&) {});
  in.material = material;
  // The material's dissipation when it has one (A, or the viscosities' A), or eps at velocity: one of the
  // two, never a silent elastic default.
  if (material.dissipative_constant_s || material.viscosities) {
    in.dissipative_constant_s = material_constants(material).dissipative_constant_s;
  }
  in.angles_deg = angles;
  in.spins_rad_s = spins.empty() ? std::vector<double>{0.0} : spins;
  const ObliqueSetup setup = oblique_setup(in, ArgumentStyle::keyword);
  const std::vector<ObliqueImpact> impacts = without_gil([&] {
    std::vector<ObliqueImpact> solved;
    solved.reserve(angles.size());
    for (std::size_t k = 0; k < angles.size(); ++k)
      solved.push_back(solve_impact(setup, angles[k], spins[k]));
    return solved;
  });
  return columns_of(setup, impacts);
}

}  // namespace

void bind_oblique(py::module_& m) {
  // The tangential models oblique_impacts runs, in the table's order (the docstring and the .pyi read them).
  m.attr("oblique_tangential_names") = py::tuple(py::cast(oblique_tangential_names()));
  m.def("oblique_impacts", &oblique_impacts, py::arg("material"), py::arg("angles"), py::arg("spins"),
        py::arg("arguments"),
        "One oblique impact per (angle, spin) pair as columns (restitution.oblique documents the arguments): "
        "the arguments by the names of oblique_parameters.");
  m.attr("oblique_parameters") = parameter_rows(oblique_fields());
}

}  // namespace restitution::python
