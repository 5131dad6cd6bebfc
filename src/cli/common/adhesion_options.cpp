// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/adhesion_options.hpp"

#include <fmt/format.h>

#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {

void add_adhesion_options(CLI::App& command, AdhesionOptions& o) {
  const auto& names = adhesive_model_names();
  command
      .add_option(
          "--adhesion", o.model,
          fmt::format("adhesive contact: {} (JKR as LAMMPS 20220106 codes it: its damping, dropped at the "
                      "force-controlled pull-off), {} (textbook JKR, broken where d(overlap)/d(contact "
                      "radius) = 0, viscoelastic damping A dF/d(overlap)) or {} (LAMMPS's DMT); needs "
                      "--surface-energy and the material",
                      names[0], names[1], names[2]))
      ->check(CLI::IsMember(names));
  command.add_option("--surface-energy", o.surface_energy,
                     "with --adhesion: surface energy gamma of one surface in J/m^2 (work of adhesion w = 2 "
                     "gamma, JKR pull-off force 3 pi gamma R_eff; LAMMPS's jkr/dmt coefficient)");
  command.add_option("--dissipative-constant", o.dissipative_constant,
                     "with --adhesion: dissipative constant A in s (default 0: elastic); jkr-lammps and dmt "
                     "use LAMMPS's damp = 2 A E*/m_eff");
  add_material_options(command, o.material);
}

AdhesiveContact adhesive_contact_from(const AdhesionOptions& o) {
  if (!o.model) throw InvalidInput("--surface-energy and --dissipative-constant belong to --adhesion");
  if (!o.surface_energy) throw InvalidInput(fmt::format("--adhesion {} needs --surface-energy", *o.model));
  const Material material = material_from(o.material);
  const ElasticConstants elastic = elastic_constants(material);
  AdhesiveContact contact;
  contact.model = adhesive_model_from_name(*o.model);
  contact.effective_modulus_pa = effective_modulus_pa(material.young_modulus_pa, material.poisson_ratio);
  contact.effective_radius_m = elastic.effective_radius_m;
  contact.effective_mass_kg = elastic.effective_mass_kg;
  contact.surface_energy_j_per_m2 = *o.surface_energy;
  const double a = o.dissipative_constant.value_or(0.0);
  if (!(a >= 0.0) || !std::isfinite(a)) {
    throw InvalidInput(fmt::format("--dissipative-constant must be finite and not negative (got {})", a));
  }
  contact.damping = contact.model == AdhesiveModel::jkr
                        ? a
                        : damping_per_mass(a, contact.effective_modulus_pa, contact.effective_mass_kg);
  return contact;
}

}  // namespace restitution::cli
