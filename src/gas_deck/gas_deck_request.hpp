// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The deck of a gas the kinetic theory describes (`gas --deck`, `gas --compare`): the theory's gas (its
// spheres, law, packing fraction, T0 and duration, docs/gas.md) turned into a GasDeckRequest, with the deck's
// own settings beside it.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "gas_deck/lammps_gas_deck.hpp"
#include "restitution/material.hpp"
#include "restitution_gas/cooling.hpp"
#include "restitution_gas/driven.hpp"
#include "restitution_gas/gas_inputs.hpp"

namespace restitution::gas_deck {

// What the deck takes beyond the gas.
struct DeckSettings {
  dem::Code code = dem::kDefaultCode;
  std::size_t particles = 2000;
  std::uint64_t seed = 1;
  double max_eps_error = 1e-3;
};

// Throws InvalidInput unless `law` names viscoelastic Hertz, the one law of the deck (LAMMPS's damping
// viscoelastic).
void require_deck_law(const std::string& law);

// The deck of the gas of `inputs`, whose theory is `theory` (its duration in Haff times turned into seconds
// with the theory's τ0), of spheres of `material`, driven by `thermostat` when given: then the bath's
// relaxation time is the theory's steady state's. Throws InvalidInput for a thermostat other than Langevin.
GasDeckRequest gas_deck_request(const gas::GasInputs& inputs, const gas::CoolingRequest& theory,
                                const Material& material, const std::optional<gas::Thermostat>& thermostat,
                                const DeckSettings& settings);

}  // namespace restitution::gas_deck
