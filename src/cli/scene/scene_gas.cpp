// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_gas.hpp"

#include <fmt/core.h>

#include "cli/gas/gas_table.hpp"

namespace restitution::cli {

GasSection gas_section(const scene::Scene& scene, const scene::GasTask& task) {
  GasSection s;
  s.outcome = scene::run_gas_section(scene, task);
  const gas::CoolingRequest& r = s.outcome.request;
  const gas::CoolingCurve& c = s.outcome.curve;
  s.csv = gas_csv(c);
  s.plot_args = gas_plot_arguments(r, c);
  s.markdown = fmt::format(
      "Kinetic theory of the freely cooling gas (docs/gas.md): spheres of [materials.{}] (m = {:.6g} kg, "
      "σ = {:.6g} m) at φ = {:g} (g₂ = {:.6g}), T₀ = {:.6g} J, law {}. Haff's law is the constant ε = {:.6g} "
      "that "
      "cools at the same initial rate, τ₀ = {:.6g} s. After {:.6g} s ({:.4g} τ₀): T/T₀ = {:.4g} (Haff: "
      "{:.4g}), "
      "local exponent {:.4f} (Haff: {:.4f}), ε_eff = {:.6g}, {:.4g} collisions per sphere.\n\n",
      task.material, r.particles.mass_kg, r.particles.diameter_m, r.particles.packing_fraction,
      c.contact_correlation, r.initial_temperature_j, gas_law_text(r), c.haff_eps, c.tau0_s, c.duration_s,
      c.duration_s / c.tau0_s, c.temperature_j.back() / r.initial_temperature_j,
      c.haff_temperature_j.back() / r.initial_temperature_j, c.local_exponent.back(),
      -2.0 * c.duration_s / (c.tau0_s + c.duration_s), c.effective_eps.back(),
      c.collisions_per_particle.back());
  if (s.outcome.steady) {
    s.markdown += fmt::format(
        "Driven by {}: the steady temperature T_s = {:.6g} J with the stationary a₂ = {:.4g}, reached from "
        "T₀ "
        "with the relaxation time {:.4g} s; d ln T_s/d ln {} = {:.4f} (a constant ε: {:.4f}).\n\n",
        s.outcome.thermostat->kind == gas::ThermostatKind::langevin
            ? fmt::format("a Langevin bath (T_b = {:.6g} J, τ_b = {:.6g} s)",
                          s.outcome.thermostat->bath_temperature_j, s.outcome.thermostat->bath_time_s)
            : fmt::format("white noise ({:.6g} W per sphere)", s.outcome.thermostat->power_w),
        s.outcome.steady->temperature_j, s.outcome.steady->a2, s.outcome.steady->relaxation_time_s,
        s.outcome.thermostat->kind == gas::ThermostatKind::langevin ? "T_b" : "P",
        s.outcome.steady->driving_exponent, s.outcome.steady->constant_eps_driving_exponent);
  }
  return s;
}

}  // namespace restitution::cli
