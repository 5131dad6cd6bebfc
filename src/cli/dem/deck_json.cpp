// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/deck_json.hpp"

namespace restitution::cli {

void write_deck_json(JsonWriter& json, const dem::Deck& deck) {
  json.key("parameters").begin_object();
  for (const auto& p : deck.parameters) json.field(p.name, p.value);
  json.end_object();
  json.key("meanings").begin_object();
  for (const auto& p : deck.parameters) json.field(p.name, p.meaning);
  json.end_object();
  json.field("prerequisites", deck.prerequisites);
  if (!deck.checked_on.empty()) json.field("checked_on", deck.checked_on);
  json.field("lines", deck.lines);
  json.field("notes", deck.notes);
}

void write_speed_eps_json(JsonWriter& json, const std::vector<dem::SpeedEps>& eps) {
  json.key("eps").begin_array();
  for (const auto& e : eps)
    json.begin_object().field("velocity_m_s", e.velocity_m_s).field("eps", e.eps).end_object();
  json.end_array();
}

}  // namespace restitution::cli
