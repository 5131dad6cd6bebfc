// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/adhesion_options.hpp"

#include <fmt/format.h>

#include <cmath>

#include "restitution/adhesive_contact.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {

void add_adhesion_options(CLI::App& command, AdhesionOptions& o, const std::vector<std::string>& models) {
  command
      .add_option("--adhesion", o.model,
                  fmt::format("adhesive contact ({}; docs/adhesion.md): jkr-lammps is JKR as LAMMPS 20220106 "
                              "codes it (its damping, dropped at the force-controlled pull-off), jkr the "
                              "textbook JKR (broken where d(overlap)/d(contact radius) = 0; with `dem`, "
                              "LAMMPS's jkr), dmt LAMMPS's DMT; needs --surface-energy",
                              fmt::join(models, ", ")))
      ->check(CLI::IsMember(models));
  command.add_option("--surface-energy", o.surface_energy,
                     "with --adhesion: surface energy gamma of one surface in J/m^2 (work of adhesion w = 2 "
                     "gamma, JKR pull-off force 3 pi gamma R_eff; LAMMPS's jkr/dmt coefficient)");
}

AdhesiveContact adhesive_contact_from(AdhesiveModel model, const AdhesionOptions& o, const Material& material,
                                      double dissipative_constant_s) {
  if (!o.surface_energy) {
    throw InvalidInput(fmt::format("--adhesion {} needs --surface-energy", adhesive_model_name(model)));
  }
  const double a = dissipative_constant_s;
  if (!(a >= 0.0) || !std::isfinite(a)) {
    throw InvalidInput(fmt::format("--dissipative-constant must be finite and not negative (got {})", a));
  }
  return adhesive_contact_of(model, material, *o.surface_energy, a);
}

}  // namespace restitution::cli
