// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/gas_deck_request.hpp"

#include <cmath>

#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"

namespace restitution::gas_deck {

void require_deck_law(const std::string& law) {
  if (law_from_name(law) != LawKind::viscoelastic_hertz)
    throw InvalidInput("--deck and --compare: only --law viscoelastic-hertz (LAMMPS's damping viscoelastic)");
}

GasDeckRequest gas_deck_request(const gas::GasInputs& inputs, const gas::CoolingRequest& theory,
                                const Material& material, const std::optional<gas::Thermostat>& thermostat,
                                const DeckSettings& settings) {
  GasDeckRequest r;
  r.code = settings.code;
  r.material = material;
  r.damping = {inputs.dissipative_constant_s, inputs.eps, inputs.velocity_m_s};
  r.end = end_from_name(inputs.end);
  r.packing_fraction = theory.particles.packing_fraction;
  r.rms_speed_m_s = std::sqrt(theory.initial_temperature_j / theory.particles.mass_kg);
  r.duration_s =
      theory.duration_in_haff_times ? theory.duration * gas::haff_reference(theory).tau0_s : theory.duration;
  r.tolerance = inputs.tolerance;
  r.particles = settings.particles;
  r.seed = settings.seed;
  r.max_eps_error = settings.max_eps_error;
  if (thermostat) {
    if (thermostat->kind != gas::ThermostatKind::langevin) {
      throw InvalidInput(
          "--deck and --compare drive the gas with LAMMPS's fix langevin: give --thermostat langevin (white "
          "noise is its limit of a long --bath-time at fixed --bath-temperature/--bath-time)");
    }
    const gas::SteadyState steady = gas::steady_state({theory, *thermostat});
    r.bath = DeckBath{thermostat->bath_temperature_j, thermostat->bath_time_s, steady.relaxation_time_s,
                      settings.seed};
  }
  return r;
}

}  // namespace restitution::gas_deck
