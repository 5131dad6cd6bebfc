// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The fields every `restitution dem --json` output gives of its lines, one writer for the pair and the wall
// outputs: the parameters with their meanings, the prerequisites, the version the lines were checked on, the
// lines and their notes, and the ε the lines give at each listed speed.
#include <vector>

#include "cli/common/json_writer.hpp"
#include "dem/lines_check.hpp"

namespace restitution::cli {

// "parameters", "meanings", "prerequisites", "checked_on" (when known), "lines", "notes".
void write_deck_json(JsonWriter& json, const dem::Deck& deck);
// "eps": [{"velocity_m_s", "eps"}, ...].
void write_speed_eps_json(JsonWriter& json, const std::vector<dem::SpeedEps>& eps);

}  // namespace restitution::cli
