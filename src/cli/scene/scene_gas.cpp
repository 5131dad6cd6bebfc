// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_gas.hpp"

#include <fmt/core.h>

#include "cli/gas/gas_table.hpp"

namespace restitution::cli {

namespace {

std::string gas_markdown(const scene::GasTask& task, const scene::GasOutcome& outcome) {
  const gas::CoolingRequest& r = outcome.request;
  const gas::CoolingCurve& c = outcome.curve;
  std::string markdown = fmt::format(
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
  if (outcome.steady) {
    markdown += fmt::format(
        "Driven by {}: the steady temperature T_s = {:.6g} J with the stationary a₂ = {:.4g}, reached from "
        "T₀ "
        "with the relaxation time {:.4g} s; d ln T_s/d ln {} = {:.4f} (a constant ε: {:.4f}).\n\n",
        outcome.thermostat->kind == gas::ThermostatKind::langevin
            ? fmt::format("a Langevin bath (T_b = {:.6g} J, τ_b = {:.6g} s)",
                          outcome.thermostat->bath_temperature_j, outcome.thermostat->bath_time_s)
            : fmt::format("white noise ({:.6g} W per sphere)", outcome.thermostat->power_w),
        outcome.steady->temperature_j, outcome.steady->a2, outcome.steady->relaxation_time_s,
        outcome.thermostat->kind == gas::ThermostatKind::langevin ? "T_b" : "P",
        outcome.steady->driving_exponent, outcome.steady->constant_eps_driving_exponent);
  }
  return markdown;
}

}  // namespace

void write_gas_section(const scene::Scene& /*scene*/, const scene::GasTask& task,
                       const scene::GasOutcome& outcome, SectionOutput& out) {
  const gas::CoolingCurve& c = outcome.curve;
  out.file(task.name + ".csv", gas_csv(c));
  out.report(fmt::format("## {}\n\n", task.title));
  out.report(out.plot("gas_cooling", task.name, gas_plot_arguments(outcome.request, c)));
  out.report(gas_markdown(task, outcome));
  JsonWriter& json = out.summary();
  json.key("gas_" + task.name).begin_object();
  json.field("tau0_s", c.tau0_s).field("haff_eps", c.haff_eps).field("duration_s", c.duration_s);
  json.field("final_temperature_j", c.temperature_j.back());
  json.field("final_local_exponent", c.local_exponent.back());
  if (const std::optional<gas::SteadyState>& steady = outcome.steady) {
    json.field("steady_temperature_j", steady->temperature_j).field("steady_a2", steady->a2);
    json.field("relaxation_time_s", steady->relaxation_time_s);
    json.field("driving_exponent", steady->driving_exponent);
  }
  json.end_object();
}

}  // namespace restitution::cli
