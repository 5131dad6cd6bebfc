// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_gas.hpp"

#include <fmt/core.h>

#include <utility>

#include "cli/gas/gas_options.hpp"
#include "cli/gas/gas_table.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

// The section as the command's options, so that both take one path to the request.
GasOptions options_of(const scene::Scene& scene, const scene::GasTask& task) {
  const Material& m = scene.materials.at(task.material);
  if (m.radius1_m != m.radius2_m || (m.mass1_kg && m.mass1_kg != m.mass2_kg)) {
    throw InvalidInput(fmt::format("material: [materials.{}] has two sizes; the gas is of one (monodisperse)",
                                   task.material));
  }
  GasOptions o;
  o.material.radius = m.radius1_m;
  o.material.density = m.density_kg_m3;
  if (!m.density_kg_m3) o.material.mass = m.mass1_kg;
  o.material.young_modulus = m.young_modulus_pa;
  o.material.poisson_ratio = m.poisson_ratio;
  o.eps = task.eps;
  o.velocity = task.velocity_m_s;
  if (!task.eps) o.dissipative_constant = material_constants(m).dissipative_constant_s;
  o.law = law_name(task.law);
  o.end = end_name(task.end);
  o.packing_fraction = task.packing_fraction;
  o.rms_speed = task.rms_speed_m_s;
  o.temperature = task.temperature_j;
  o.duration = task.duration_s;
  o.haff_times = task.haff_times;
  o.points_per_decade = task.points_per_decade;
  o.a2 = task.a2;
  o.first_time = task.first_time_s;
  o.collision_rate_factor = task.collision_rate_factor;
  o.tolerance = task.tolerance.value_or(scene.tolerance);
  o.thermostat = task.thermostat;
  o.bath_temperature = task.bath_temperature_j;
  o.bath_time = task.bath_time_s;
  o.power = task.power_w;
  return o;
}

}  // namespace

GasSection gas_section(const scene::Scene& scene, const scene::GasTask& task) {
  GasSection s;
  try {
    const GasOptions options = options_of(scene, task);
    s.request = cooling_request(options);
    s.thermostat = thermostat_of(options);
    if (s.thermostat) {
      gas::DrivenCurve driven = gas::driven_curve({s.request, *s.thermostat});
      s.curve = std::move(driven.curve);
      s.steady = driven.steady;
    } else {
      s.curve = gas::cooling_curve(s.request);
    }
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: gas \"{}\": {}", scene.file_name, task.name, e.what()));
  }
  s.csv = gas_csv(s.curve);
  s.plot_args = gas_plot_arguments(s.request, s.curve);
  const gas::CoolingCurve& c = s.curve;
  s.markdown = fmt::format(
      "Kinetic theory of the freely cooling gas (docs/gas.md): spheres of [materials.{}] (m = {:.6g} kg, "
      "σ = {:.6g} m) at φ = {:g} (g₂ = {:.6g}), T₀ = {:.6g} J, law {}. Haff's law is the constant ε = {:.6g} "
      "that "
      "cools at the same initial rate, τ₀ = {:.6g} s. After {:.6g} s ({:.4g} τ₀): T/T₀ = {:.4g} (Haff: "
      "{:.4g}), "
      "local exponent {:.4f} (Haff: {:.4f}), ε_eff = {:.6g}, {:.4g} collisions per sphere.\n\n",
      task.material, s.request.particles.mass_kg, s.request.particles.diameter_m,
      s.request.particles.packing_fraction, c.contact_correlation, s.request.initial_temperature_j,
      gas_law_text(s.request), c.haff_eps, c.tau0_s, c.duration_s, c.duration_s / c.tau0_s,
      c.temperature_j.back() / s.request.initial_temperature_j,
      c.haff_temperature_j.back() / s.request.initial_temperature_j, c.local_exponent.back(),
      -2.0 * c.duration_s / (c.tau0_s + c.duration_s), c.effective_eps.back(),
      c.collisions_per_particle.back());
  if (s.steady) {
    s.markdown += fmt::format(
        "Driven by {}: the steady temperature T_s = {:.6g} J with the stationary a₂ = {:.4g}, reached from "
        "T₀ "
        "with the relaxation time {:.4g} s; d ln T_s/d ln {} = {:.4f} (a constant ε: {:.4f}).\n\n",
        s.thermostat->kind == gas::ThermostatKind::langevin
            ? fmt::format("a Langevin bath (T_b = {:.6g} J, τ_b = {:.6g} s)",
                          s.thermostat->bath_temperature_j, s.thermostat->bath_time_s)
            : fmt::format("white noise ({:.6g} W per sphere)", s.thermostat->power_w),
        s.steady->temperature_j, s.steady->a2, s.steady->relaxation_time_s,
        s.thermostat->kind == gas::ThermostatKind::langevin ? "T_b" : "P", s.steady->driving_exponent,
        s.steady->constant_eps_driving_exponent);
  }
  return s;
}

}  // namespace restitution::cli
