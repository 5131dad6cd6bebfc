// SPDX-License-Identifier: BSD-3-Clause
// restitution.gas: the freely cooling granular gas of the kinetic theory (src/gas/, docs/gas.md), from the
// same arguments as `restitution gas` and with the keys of its --json.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "parameter_arguments.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/solve_types.hpp"
#include "restitution_gas/gas_inputs.hpp"
#include "restitution_gas/gas_parameters.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

// a2: None (Maxwellian), a number, "haff" (van Noije & Ernst's a2 of the Haff eps), held constant, or
// "evolving" (a2(t) from the Sonine moment equations).
void read_a2(const gas::GasField& field, const py::object& a2, gas::GasInputs& in) {
  if (a2.is_none()) return;
  if (py::isinstance<py::str>(a2)) {
    const auto word = a2.cast<std::string>();
    if (std::find(field.words.begin(), field.words.end(), word) == field.words.end()) {
      throw InvalidInput("a2 must be a number, 'haff' or 'evolving', got '" + word + "'");
    }
    gas::set_sonine_word(in, word);
    return;
  }
  if (py::isinstance<py::bool_>(a2) || !(py::isinstance<py::float_>(a2) || py::isinstance<py::int_>(a2))) {
    throw py::type_error("a2 must be None, a number, 'haff' or 'evolving'");
  }
  in.a2 = a2.cast<double>();
}

py::dict cooling_dict(const gas::CoolingRequest& r, const gas::CoolingCurve& c) {
  py::dict law;
  law["kind"] = law_name(r.law.kind);
  law["end"] = end_name(r.law.end);
  law["zeta_at_reference"] = r.law.zeta_at_reference;
  law["reference_speed_m_s"] = r.law.reference_speed_m_s;
  py::dict out;
  out["law"] = law;
  out["mass_kg"] = r.particles.mass_kg;
  out["diameter_m"] = r.particles.diameter_m;
  out["packing_fraction"] = r.particles.packing_fraction;
  out["contact_correlation"] = c.contact_correlation;
  out["number_density_m3"] = c.number_density_m3;
  out["initial_temperature_j"] = r.initial_temperature_j;
  out["tau0_s"] = c.tau0_s;
  out["haff_eps"] = c.haff_eps;
  out["a2"] = c.a2;  // evolving: replaced by the curve's array "a2" below
  out["collision_rate_factor"] = r.collision_rate_factor;
  out["duration_s"] = c.duration_s;
  for (const gas::CurveColumn& column : gas::curve_columns(c)) {
    out[column.name] =
        py::array_t<double>(static_cast<py::ssize_t>(column.values->size()), column.values->data());
  }
  return out;
}

// The driven gas's keys of `gas --json`: the thermostat and the steady state.
void add_driving(py::dict& out, const gas::Thermostat& t, const gas::SteadyState& s) {
  py::dict thermostat;
  if (t.kind == gas::ThermostatKind::langevin) {
    thermostat["kind"] = "langevin";
    thermostat["bath_temperature_j"] = t.bath_temperature_j;
    thermostat["bath_time_s"] = t.bath_time_s;
  } else {
    thermostat["kind"] = "white-noise";
    thermostat["power_w"] = t.power_w;
  }
  out["thermostat"] = thermostat;
  out["steady_temperature_j"] = s.temperature_j;
  out["steady_a2"] = s.a2;
  out["relaxation_time_s"] = s.relaxation_time_s;
  out["driving_exponent"] = s.driving_exponent;
  out["constant_eps_driving_exponent"] = s.constant_eps_driving_exponent;
  out["steady_effective_eps"] = s.effective_eps;
  out["steady_collision_frequency_hz"] = s.collision_frequency_hz;
  out["steady_power_w"] = s.power_w;
}

// The arguments restitution.gas checked (their types), by the names of the table
// (restitution_gas/gas_parameters.hpp); a2 is a number or a word.
gas::GasInputs inputs_of(const py::dict& arguments) {
  return parameter_arguments(arguments, gas::gas_fields(), "gas",
                             [](const gas::GasField& f, const py::handle& value, gas::GasInputs& in) {
                               read_a2(f, py::reinterpret_borrow<py::object>(value), in);
                             });
}

py::dict cooling(const py::dict& arguments) {
  const gas::GasInputs in = inputs_of(arguments);
  struct Result {
    gas::CoolingRequest request;
    std::optional<gas::Thermostat> thermostat;
    gas::DrivenCurve curve;
  };
  const Result result = without_gil([&] {
    Result out{gas::cooling_request(in, gas::ArgumentStyle::keyword),
               gas::thermostat_of(in, gas::ArgumentStyle::keyword),
               {}};
    if (out.thermostat) {
      out.curve = gas::driven_curve({out.request, *out.thermostat});
    } else {
      out.curve.curve = gas::cooling_curve(out.request);
    }
    return out;
  });
  py::dict out = cooling_dict(result.request, result.curve.curve);
  if (result.thermostat) add_driving(out, *result.thermostat, result.curve.steady);
  return out;
}

}  // namespace

void bind_gas(py::module_& m) {
  m.def("gas", &cooling, py::arg("arguments"),
        "The cooling curve of the freely cooling gas, or the driven gas's relaxation and steady state "
        "(restitution.gas documents the arguments): the arguments by the names of gas_parameters.");
  m.attr("gas_parameters") = parameter_rows(gas::gas_fields());
}

}  // namespace restitution::python
