// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The adhesion options, declared once for every command that takes them: --adhesion MODEL,
// --surface-energy γ [J/m², per surface] and --cohesion-energy-density k_c [J/m³] (sjkr). The material and
// --dissipative-constant are each command's own (material_options.hpp; `dem` has its own
// --dissipative-constant).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "restitution/adhesion.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {

struct AdhesionOptions {
  std::optional<std::string> model;
  std::optional<double> surface_energy;
  std::optional<double> cohesion_energy_density;  // sjkr's k_c [J/m³]
  [[nodiscard]] bool any() const { return model || surface_energy || cohesion_energy_density; }
};

// `models`: the names --adhesion accepts (default: every adhesive model).
void add_adhesion_options(CLI::App& command, AdhesionOptions& o,
                          const std::vector<std::string>& models = adhesive_model_names());
// The contact of two spheres of the material (adhesive_contact_of, adhesive_contact.hpp: E*, R_eff, m_eff, γ
// or sjkr's k_c, and the model's damping from A [s]). Throws InvalidInput naming the missing or bad option.
AdhesiveContact adhesive_contact_from(AdhesiveModel model, const AdhesionOptions& o, const Material& material,
                                      double dissipative_constant_s);

}  // namespace restitution::cli
