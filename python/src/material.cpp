// SPDX-License-Identifier: BSD-3-Clause
// restitution.Material: a pair of spheres of one material in SI units, the same fields as a scene's
// [material] table, with the constants of their collision equation.
#include <fmt/core.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <type_traits>

#include "bindings.hpp"
#include "pickle_state.hpp"
#include "repr_text.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

using Pair = std::array<double, 2>;

Material make_material(double young_modulus, double poisson_ratio, std::optional<double> radius,
                       std::optional<Pair> radii, std::optional<double> density, std::optional<double> mass,
                       std::optional<Pair> masses, std::optional<double> dissipative_constant,
                       std::optional<Pair> viscosities) {
  MaterialFields f;
  f.young_modulus_pa = young_modulus;
  f.poisson_ratio = poisson_ratio;
  f.radius_m = radius;
  f.radii_m = radii;
  f.density_kg_m3 = density;
  f.mass_kg = mass;
  f.masses_kg = masses;
  f.dissipative_constant_s = dissipative_constant;
  if (viscosities) f.viscosities = Viscosities{(*viscosities)[0], (*viscosities)[1]};
  const Material m = material_from_fields(f);
  check_material(m);  // the elastic data now, the dissipation when given
  return m;
}

// The fields in the order of the docstring; the first two are required.
constexpr std::array<const char*, 9> kFields = {
    "young_modulus", "poisson_ratio",        "radius",     "radii", "density", "mass",
    "masses",        "dissipative_constant", "viscosities"};

std::string field_list() {
  std::string list;
  for (const char* field : kFields) list += (list.empty() ? "" : ", ") + std::string(field);
  return list;
}

// One keyword's value as T, None as absent; a value of the wrong type raises TypeError naming the field
// (pybind11's own message would dump the constructor's signature instead).
// True for Python's and numpy's booleans, which pybind11 would read as 1 and 0.
bool is_boolean(const py::handle& value) {
  return py::isinstance<py::bool_>(value) ||
         py::isinstance(value, py::module_::import("numpy").attr("bool_"));
}

bool holds_boolean(const py::handle& value) {
  if (is_boolean(value)) return true;
  if (!py::isinstance<py::tuple>(value) && !py::isinstance<py::list>(value)) return false;
  const auto items = py::reinterpret_borrow<py::sequence>(value);
  return std::any_of(items.begin(), items.end(), [](const py::handle item) { return is_boolean(item); });
}

template <typename T>
std::optional<T> field(const py::kwargs& kwargs, const char* name) {
  if (!kwargs.contains(name) || kwargs[name].is_none()) return std::nullopt;
  try {
    if (holds_boolean(kwargs[name])) throw py::cast_error();  // True is no modulus, radius or mass
    return py::cast<T>(kwargs[name]);
  } catch (const py::cast_error&) {
    throw py::type_error(fmt::format("Material: {} must be {}, got {}", name,
                                     std::is_same_v<T, Pair> ? "a pair of real numbers" : "a real number",
                                     py::type::of(kwargs[name]).attr("__name__").cast<std::string>()));
  }
}

// Material(**fields) in the module's words: positional arguments, unknown and missing fields are named.
Material material_from_keywords(const py::args& args, const py::kwargs& kwargs) {
  if (!args.empty())
    throw py::type_error(
        fmt::format("Material takes keyword arguments only, got {} positional; the fields are {}",
                    args.size(), field_list()));
  for (const auto& item : kwargs) {
    const auto key = item.first.cast<std::string>();
    if (std::find_if(kFields.begin(), kFields.end(), [&](const char* f) { return key == f; }) ==
        kFields.end())
      throw py::type_error(fmt::format("Material has no field '{}'; the fields are {}", key, field_list()));
  }
  for (const char* required : {"young_modulus", "poisson_ratio"})
    if (!kwargs.contains(required) || kwargs[required].is_none())
      throw py::type_error(fmt::format("Material needs {} (young_modulus [Pa], poisson_ratio)", required));
  return make_material(*field<double>(kwargs, "young_modulus"), *field<double>(kwargs, "poisson_ratio"),
                       field<double>(kwargs, "radius"), field<Pair>(kwargs, "radii"),
                       field<double>(kwargs, "density"), field<double>(kwargs, "mass"),
                       field<Pair>(kwargs, "masses"), field<double>(kwargs, "dissipative_constant"),
                       field<Pair>(kwargs, "viscosities"));
}

// Pairs go out as tuples (as they may come in), missing ones as None.
py::object masses_of(const Material& m) {
  if (!m.mass1_kg) return py::none();
  return py::make_tuple(*m.mass1_kg, *m.mass2_kg);
}

py::object viscosities_of(const Material& m) {
  if (!m.viscosities) return py::none();
  return py::make_tuple(m.viscosities->eta1_pa_s, m.viscosities->eta2_pa_s);
}

std::string pair_text(const py::object& pair, const char* unit) {
  if (pair.is_none()) return "None";
  const auto t = pair.cast<py::tuple>();
  return fmt::format("({}, {}) {}", t[0].cast<double>(), t[1].cast<double>(), unit);
}

// Every field as given, with its SI unit (the repr is for reading, not for eval()).
std::string material_repr(const Material& x) {
  return fmt::format(
      "Material(young_modulus={} Pa, poisson_ratio={}, radii=({}, {}) m, density={}, masses={}, "
      "dissipative_constant={}, viscosities={})",
      x.young_modulus_pa, x.poisson_ratio, x.radius1_m, x.radius2_m, optional_text(x.density_kg_m3, "kg/m^3"),
      pair_text(masses_of(x), "kg"), optional_text(x.dissipative_constant_s, "s"),
      pair_text(viscosities_of(x), "Pa s"));
}

// The pickled state: the fields as given, so that an unpickled Material reports the same ones.
py::tuple material_state(const Material& x) {
  return py::make_tuple(x.young_modulus_pa, x.poisson_ratio, x.radius1_m, x.radius2_m, x.density_kg_m3,
                        masses_of(x), x.dissipative_constant_s, viscosities_of(x));
}

Material material_from_state(const py::tuple& t) {
  check_state(t, 8, "Material");
  Material x;
  x.young_modulus_pa = t[0].cast<double>();
  x.poisson_ratio = t[1].cast<double>();
  x.radius1_m = t[2].cast<double>();
  x.radius2_m = t[3].cast<double>();
  x.density_kg_m3 = t[4].cast<std::optional<double>>();
  if (const auto masses = t[5].cast<std::optional<Pair>>()) {
    x.mass1_kg = (*masses)[0];
    x.mass2_kg = (*masses)[1];
  }
  x.dissipative_constant_s = t[6].cast<std::optional<double>>();
  if (const auto eta = t[7].cast<std::optional<Pair>>()) x.viscosities = Viscosities{(*eta)[0], (*eta)[1]};
  check_material(x);  // a hand-made state is held to the constructor's rules
  return x;
}

}  // namespace

void bind_material(py::module_& m) {
  py::class_<Material>(
      m, "Material",
      R"(Two spheres of one viscoelastic material, in SI units (the fields of a scene's [material] table).

Parameters
----------
young_modulus : float
    Young's modulus Y [Pa], > 0.
poisson_ratio : float
    Poisson ratio nu, in (-1, 0.5).
radius, radii : float or (float, float)
    R [m] of both spheres, or (R1, R2) [m].
density, mass, masses : float or (float, float)
    Density [kg/m^3], or the mass [kg] of both, or (m1, m2) [kg].
dissipative_constant, viscosities : float or (float, float), optional
    A [s], or (eta1, eta2) [Pa s]; neither for calibrate(), which finds A.

Raises
------
ValueError
    A field out of range, named.
TypeError
    A missing, unknown or mistyped field, or a positional argument.

Examples
--------
>>> import pickle, restitution
>>> rubber = restitution.Material(young_modulus=1e7, poisson_ratio=0.45, radius=0.01, density=1100.0,
...                               dissipative_constant=5.8e-5)
>>> rubber
Material(young_modulus=10000000 Pa, poisson_ratio=0.45, radii=(0.01, 0.01) m, density=1100 kg/m^3, masses=None, dissipative_constant=5.8e-05 s, viscosities=None)
>>> round(rubber.beta, 6)   # s^(1/5) m^(-1/5)
0.201004
>>> pickle.loads(pickle.dumps(rubber)).dissipative_constant
5.8e-05
)")
      .def(py::init(&material_from_keywords),
           "Material(*, young_modulus, poisson_ratio, radius=None, radii=None, density=None, mass=None, "
           "masses=None, dissipative_constant=None, viscosities=None): "
           "young_modulus Y [Pa] > 0, poisson_ratio nu in (-1, 0.5), radius R [m] or radii (R1, R2) [m], "
           "density [kg/m^3] or mass [kg] or masses (m1, m2) [kg], dissipative_constant A [s] or "
           "viscosities (eta1, eta2) [Pa s]. TypeError names a missing, unknown or mistyped field.")
      .def_readonly("young_modulus", &Material::young_modulus_pa, "Young's modulus Y [Pa].")
      .def_readonly("poisson_ratio", &Material::poisson_ratio, "Poisson ratio nu.")
      .def_property_readonly(
          "radii", [](const Material& x) { return py::make_tuple(x.radius1_m, x.radius2_m); },
          "(R1, R2) [m].")
      .def_readonly("density", &Material::density_kg_m3, "Density [kg/m^3], or None when masses are given.")
      .def_property_readonly("masses", &masses_of, "(m1, m2) [kg] as given, or None when density is given.")
      .def_readonly("dissipative_constant", &Material::dissipative_constant_s,
                    "A [s] as given, or None (see A for the value from viscosities).")
      .def_property_readonly("viscosities", &viscosities_of, "(eta1, eta2) [Pa s] as given, or None.")
      .def_property_readonly(
          "effective_radius", [](const Material& x) { return elastic_constants(x).effective_radius_m; },
          "R_eff = R1 R2 / (R1 + R2) [m].")
      .def_property_readonly(
          "effective_mass", [](const Material& x) { return elastic_constants(x).effective_mass_kg; },
          "m_eff = m1 m2 / (m1 + m2) [kg].")
      .def_property_readonly(
          "k", [](const Material& x) { return elastic_constants(x).k; },
          "k = rho / m_eff [s^-2 m^-1/2], rho = 2 Y sqrt(R_eff) / (3 (1 - nu^2)).")
      .def_property_readonly(
          "A", [](const Material& x) { return material_constants(x).dissipative_constant_s; },
          "Dissipative constant A [s] (given, or from the viscosities). ValueError without dissipation data.")
      .def_property_readonly(
          "beta", [](const Material& x) { return material_constants(x).hertz.beta; },
          "beta = (3/2) A k^(2/5) [s^(1/5) m^(-1/5)], so that zeta = beta v^(1/5).")
      .def("__repr__", &material_repr)
      .def(py::pickle(&material_state, &material_from_state));
}

}  // namespace restitution::python
