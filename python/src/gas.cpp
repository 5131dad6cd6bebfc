// SPDX-License-Identifier: BSD-3-Clause
// restitution.gas: the freely cooling gas from kinetic theory with the law's exact ε(v) (restitution/gas.hpp,
// docs/gas.md). The checks and the dict's keys are those of `restitution gas --json`.
#include <fmt/core.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "restitution/errors.hpp"
#include "restitution/gas.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

// Exactly one of two keyword arguments.
double one_of(const std::optional<double>& a, const char* a_name, const std::optional<double>& b,
              const char* b_name) {
  if (a.has_value() == b.has_value())
    throw InvalidInput(fmt::format("give exactly one of {} and {}", a_name, b_name));
  return a ? *a : *b;
}

gas::ImpactLaw impact_law(const std::optional<double>& eps, const std::optional<double>& velocity,
                          const std::optional<double>& beta, const std::string& law, const std::string& end,
                          double tolerance) {
  const LawKind kind = law_from_name(law);
  const CollisionEnd e = end_from_name(end);
  if (beta) {
    if (eps || velocity) throw InvalidInput("beta excludes eps and velocity");
    if (!has_dissipative_constant(kind))
      throw InvalidInput(fmt::format("beta describes law='viscoelastic-hertz', not '{}'", law));
    return gas::hertz_impact_law(*beta, e);
  }
  if (!eps || !velocity) throw InvalidInput("the law needs eps with velocity (m/s), or beta");
  return gas::impact_law_from_eps(kind, *eps, *velocity, e, tolerance);
}

py::dict curve_dict(const gas::CoolingRequest& r, const gas::CoolingCurve& c) {
  py::dict d;
  d["law"] = law_name(r.law.kind);
  d["end"] = end_name(r.law.end);
  d["zeta_at_reference"] = r.law.zeta_at_reference;
  d["reference_speed_m_s"] = r.law.reference_speed_m_s;
  d["initial_temperature_j"] = r.initial_temperature_j;
  d["contact_correlation"] = c.contact_correlation;
  d["number_density_m3"] = c.number_density_m3;
  d["tau0_s"] = c.tau0_s;
  d["haff_eps"] = c.haff_eps;
  d["a2"] = c.a2;
  d["duration_s"] = c.duration_s;
  d["time_s"] = c.time_s;
  d["temperature_j"] = c.temperature_j;
  d["haff_temperature_j"] = c.haff_temperature_j;
  d["local_exponent"] = c.local_exponent;
  d["cooling_rate_hz"] = c.cooling_rate_hz;
  d["collision_frequency_hz"] = c.collision_frequency_hz;
  d["collisions_per_particle"] = c.collisions_per_particle;
  d["effective_eps"] = c.effective_eps;
  return d;
}

}  // namespace

void bind_gas(py::module_& m) {
  m.def(
      "gas",
      [](double mass, double diameter, double packing_fraction, std::optional<double> eps,
         std::optional<double> velocity, std::optional<double> beta, const std::string& law,
         const std::string& end, std::optional<double> rms_speed, std::optional<double> temperature,
         std::optional<double> duration, std::optional<double> haff_times, int points_per_decade,
         std::optional<double> a2, double collision_rate_factor, double tolerance) {
        gas::CoolingRequest r;
        r.particles = {mass, diameter, packing_fraction};
        const double t0 = one_of(rms_speed, "rms_speed", temperature, "temperature");
        r.initial_temperature_j = rms_speed ? mass * t0 * t0 : t0;
        if (rms_speed && !(*rms_speed > 0.0))
          throw InvalidInput(fmt::format("rms_speed must be > 0 m/s, got {}", *rms_speed));
        r.duration = one_of(duration, "duration", haff_times, "haff_times");
        r.duration_in_haff_times = haff_times.has_value();
        r.points_per_decade = points_per_decade;
        r.a2 = a2;
        r.collision_rate_factor = collision_rate_factor;
        r.tolerance = tolerance;
        const gas::CoolingCurve c = without_gil([&] {
          r.law = impact_law(eps, velocity, beta, law, end, tolerance);
          return gas::cooling_curve(r);
        });
        return curve_dict(r, c);
      },
      py::arg("mass"), py::arg("diameter"), py::arg("packing_fraction"), py::arg("eps"), py::arg("velocity"),
      py::arg("beta"), py::arg("law"), py::arg("end"), py::arg("rms_speed"), py::arg("temperature"),
      py::arg("duration"), py::arg("haff_times"), py::arg("points_per_decade"), py::arg("a2"),
      py::arg("collision_rate_factor"), py::arg("tolerance"),
      "The freely cooling gas (docs/gas.md): a dict with the keys of `restitution gas --json`.");
}

}  // namespace restitution::python
