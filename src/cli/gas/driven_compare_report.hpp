// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution gas --thermostat langevin ... --compare LOG...` (docs/gas.md, "The driven gas"): a driven
// deck's runs against the kinetic theory (gas_deck/driven_comparison.hpp): the steady temperature and a₂ of
// each run with their block-average error bars, the theory's at the collision-rate factor measured on the
// constant-ε run, and the largest deviation of the relaxation T(t).
#include "cli/common/json_writer.hpp"
#include "gas_deck/driven_comparison.hpp"

namespace restitution::cli {

void print_driven_comparison_text(const gas_deck::DrivenComparison& c);
void write_driven_comparison_json(JsonWriter& json, const gas_deck::DrivenComparison& c);

}  // namespace restitution::cli
