// SPDX-License-Identifier: BSD-3-Clause
// Adhesive collisions (docs/adhesion.md): one collision at an impact speed and the sticking speed, for two
// spheres of a Material; restitution/__init__.py checks the arguments and documents them.
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "restitution/adhesion.hpp"
#include "restitution/adhesive_contact.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

// The result with the speed it was solved at, named as `restitution eps --adhesion --json` names them.
struct AdhesiveResult {
  std::string adhesion;
  double velocity_m_per_s = 0.0;
  AdhesiveCollision collision;
};

// The model's adhesion parameter: γ per surface [J/m²] for jkr-lammps, jkr and dmt, LIGGGHTS's cohesion
// energy density k_c [J/m³] for sjkr, as `eps --adhesion` takes them (--surface-energy,
// --cohesion-energy-density).
struct Adhesion {
  std::string model;
  std::optional<double> surface_energy;
  std::optional<double> cohesion_energy_density;
};

// A given as an argument, else the Material's dissipation (A or its viscosities' A), else elastic (A = 0) as
// `eps --adhesion` without --dissipative-constant.
AdhesiveContact adhesive_contact_for(const Material& material, const Adhesion& adhesion,
                                     std::optional<double> dissipative_constant) {
  if (!dissipative_constant && (material.dissipative_constant_s || material.viscosities)) {
    dissipative_constant = material_constants(material).dissipative_constant_s;
  }
  const AdhesiveModel model = adhesive_model_from_name(adhesion.model);
  const bool sjkr = model == AdhesiveModel::sjkr;
  if (sjkr ? !adhesion.cohesion_energy_density : !adhesion.surface_energy) {
    throw InvalidInput(fmt::format(
        "adhesion='{}' needs {}", adhesion.model,
        sjkr ? "cohesion_energy_density (k_c, J/m^3)" : "surface_energy (gamma per surface, J/m^2)"));
  }
  if (sjkr ? adhesion.surface_energy.has_value() : adhesion.cohesion_energy_density.has_value()) {
    throw InvalidInput(fmt::format("adhesion='{}' does not take {}", adhesion.model,
                                   sjkr ? "surface_energy" : "cohesion_energy_density (sjkr's)"));
  }
  AdhesiveContact contact = adhesive_contact_of(model, material, adhesion.surface_energy.value_or(0.0),
                                                dissipative_constant.value_or(0.0));
  contact.cohesion_energy_density_j_per_m3 = adhesion.cohesion_energy_density.value_or(0.0);
  return contact;
}

AdhesiveResult adhesive_collision(const Material& material, double velocity, const std::string& adhesion,
                                  std::optional<double> surface_energy,
                                  std::optional<double> cohesion_energy_density,
                                  std::optional<double> dissipative_constant, double tolerance) {
  const AdhesiveContact contact = adhesive_contact_for(
      material, {adhesion, surface_energy, cohesion_energy_density}, dissipative_constant);
  AdhesiveResult r{adhesion, velocity, {}};
  r.collision = without_gil([&] { return solve_adhesive(contact, velocity, tolerance); });
  return r;
}

double sticking_speed_m_per_s(const Material& material, const std::string& adhesion,
                              std::optional<double> surface_energy,
                              std::optional<double> cohesion_energy_density,
                              std::optional<double> dissipative_constant, double tolerance) {
  const AdhesiveContact contact = adhesive_contact_for(
      material, {adhesion, surface_energy, cohesion_energy_density}, dissipative_constant);
  return without_gil([&] { return sticking_speed(contact, tolerance).speed_m_per_s; });
}

// The elastic model's closed forms (adhesion.hpp), named as the JSON of `eps --adhesion` names them (sjkr:
// no pull-off force, as there).
py::dict adhesive_closed_forms_of(const Material& material, const std::string& adhesion,
                                  std::optional<double> surface_energy,
                                  std::optional<double> cohesion_energy_density) {
  const AdhesiveContact contact =
      adhesive_contact_for(material, {adhesion, surface_energy, cohesion_energy_density}, 0.0);
  py::dict out;
  out["break_overlap_m"] = break_overlap_m(contact);
  out["elastic_hysteresis_work_j"] = elastic_hysteresis_work_j(contact);
  if (contact.model != AdhesiveModel::sjkr) out["pull_off_force_n"] = jkr_pull_off_force_n(contact);
  out["effective_modulus_pa"] = contact.effective_modulus_pa;
  return out;
}

std::string adhesive_result_repr(const AdhesiveResult& r) {
  const AdhesiveCollision& c = r.collision;
  return fmt::format(
      "AdhesiveCollision(adhesion='{}', velocity_m_per_s={:.6g}, outcome='{}', eps={:.10g}, "
      "one_minus_eps={:.6g}, contact_time_s={:.6g}, max_compression_m={:.6g}, hysteresis_work_j={:.6g}, "
      "viscous_work_j={:.6g}, kinetic_to_adhesion_energy={:.6g})",
      r.adhesion, r.velocity_m_per_s, adhesive_outcome_name(c.outcome), c.eps, c.one_minus_eps,
      c.contact_time_s, c.max_compression_m, c.hysteresis_work_j, c.viscous_work_j,
      c.kinetic_to_adhesion_energy);
}

template <double AdhesiveCollision::*field>
double adhesive_field(const AdhesiveResult& r) {
  return r.collision.*field;
}

void bind_adhesive_result(py::module_& m) {
  py::class_<AdhesiveResult>(
      m, "AdhesiveCollision",
      "One adhesive collision (restitution.adhesive_collision); SI units, the names of "
      "`restitution eps --adhesion --json`.")
      .def_readonly("adhesion", &AdhesiveResult::adhesion,
                    "The adhesive model: jkr-lammps, jkr, dmt or sjkr.")
      .def_readonly("velocity_m_per_s", &AdhesiveResult::velocity_m_per_s, "Impact speed v [m/s].")
      .def_property_readonly(
          "outcome",
          [](const AdhesiveResult& r) { return std::string(adhesive_outcome_name(r.collision.outcome)); },
          "'bounced' (the neck broke) or 'stuck' (the spheres stay bound; eps = 0).")
      .def_property_readonly("eps", &adhesive_field<&AdhesiveCollision::eps>,
                             "Coefficient of restitution (0 when stuck).")
      .def_property_readonly("one_minus_eps", &adhesive_field<&AdhesiveCollision::one_minus_eps>,
                             "1 - eps from the energy balance, without cancellation near eps = 1.")
      .def_property_readonly(
          "contact_time_s", &adhesive_field<&AdhesiveCollision::contact_time_s>,
          "From first touch to the break, or to the turning point after which they are bound [s].")
      .def_property_readonly("max_compression_m", &adhesive_field<&AdhesiveCollision::max_compression_m>,
                             "Maximal overlap [m].")
      .def_property_readonly(
          "hysteresis_work_j", &adhesive_field<&AdhesiveCollision::hysteresis_work_j>,
          "Work taken by the neck until it breaks (stuck: the kinetic energy it keeps bound) [J].")
      .def_property_readonly("viscous_work_j", &adhesive_field<&AdhesiveCollision::viscous_work_j>,
                             "Work of the damping force over the contact [J].")
      .def_property_readonly("kinetic_to_adhesion_energy",
                             &adhesive_field<&AdhesiveCollision::kinetic_to_adhesion_energy>,
                             "(1/2) m_eff v^2 over the model's adhesion energy unit (docs/adhesion.md).")
      .def_property_readonly(
          "stats", [](const AdhesiveResult& r) { return r.collision.stats; }, "The integrator's work.")
      .def("__repr__", &adhesive_result_repr);
}

}  // namespace

void bind_adhesion(py::module_& m) {
  bind_adhesive_result(m);
  m.attr("adhesive_model_names") = py::tuple(py::cast(adhesive_model_names()));
  m.def("adhesive_collision", &adhesive_collision, py::arg("material"), py::arg("velocity"),
        py::arg("adhesion"), py::arg("surface_energy"), py::arg("cohesion_energy_density"),
        py::arg("dissipative_constant"), py::arg("tolerance"),
        "One adhesive collision at the impact speed (restitution.adhesive_collision documents the "
        "arguments).");
  m.def("sticking_speed", &sticking_speed_m_per_s, py::arg("material"), py::arg("adhesion"),
        py::arg("surface_energy"), py::arg("cohesion_energy_density"), py::arg("dissipative_constant"),
        py::arg("tolerance"), "The impact speed [m/s] below which the spheres stick (0: never).");
  m.def("adhesive_closed_forms", &adhesive_closed_forms_of, py::arg("material"), py::arg("adhesion"),
        py::arg("surface_energy"), py::arg("cohesion_energy_density"),
        "The elastic model's break overlap [m], hysteresis work [J], JKR pull-off force 3 pi gamma R [N] and "
        "E* [Pa].");
}

}  // namespace restitution::python
