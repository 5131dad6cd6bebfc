// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The adhesion options, declared once for every command that takes them: --adhesion MODEL, --surface-energy
// γ [J/m², per surface] and --dissipative-constant A [s], with the material options (material_options.hpp).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli/common/material_options.hpp"
#include "restitution/adhesion.hpp"

namespace restitution::cli {

struct AdhesionOptions {
  std::optional<std::string> model;
  std::optional<double> surface_energy, dissipative_constant;
  MaterialOptions material;
};

void add_adhesion_options(CLI::App& command, AdhesionOptions& o);
// The contact of two spheres of the material: E* = Y/(2(1 − ν²)), R_eff, m_eff, γ, and the damping from A:
// A itself for `jkr`, LAMMPS's `damping viscoelastic` coefficient damp = 2AE*/m_eff for `jkr-lammps` and
// `dmt` (the Hertz mapping of docs/dem.md, whose force damp·m_eff·a·δ̇ is A·δ̇·dF_Hertz/dδ). Throws
// InvalidInput naming the missing or bad option.
AdhesiveContact adhesive_contact_from(const AdhesionOptions& o);

}  // namespace restitution::cli
