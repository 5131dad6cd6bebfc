// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/adhesion_options.hpp"

#include <fmt/format.h>

#include <algorithm>
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
                              "LAMMPS's jkr), dmt LAMMPS's DMT; needs --surface-energy; sjkr LIGGGHTS's "
                              "cohesion sjkr on Hertz, needs --cohesion-energy-density",
                              fmt::join(models, ", ")))
      ->check(CLI::IsMember(models));
  command.add_option("--surface-energy", o.surface_energy,
                     "with --adhesion: surface energy gamma of one surface in J/m^2 (work of adhesion w = 2 "
                     "gamma, JKR pull-off force 3 pi gamma R_eff; LAMMPS's jkr/dmt coefficient)");
  if (std::find(models.begin(), models.end(), "sjkr") != models.end()) {
    command.add_option(
        "--cohesion-energy-density", o.cohesion_energy_density,
        "with --adhesion sjkr: LIGGGHTS's cohesionEnergyDensity k_c in J/m^3 (force -k_c times "
        "the area of the spheres' intersection circle while they overlap)");
  }
}

AdhesiveContact adhesive_contact_from(AdhesiveModel model, const AdhesionOptions& o, const Material& material,
                                      double dissipative_constant_s) {
  const bool sjkr = model == AdhesiveModel::sjkr;
  if (sjkr ? !o.cohesion_energy_density : !o.surface_energy) {
    throw InvalidInput(fmt::format("--adhesion {} needs {}", adhesive_model_name(model),
                                   sjkr ? "--cohesion-energy-density" : "--surface-energy"));
  }
  if (sjkr ? o.surface_energy.has_value() : o.cohesion_energy_density.has_value()) {
    throw InvalidInput(fmt::format("--adhesion {} does not take {}", adhesive_model_name(model),
                                   sjkr ? "--surface-energy" : "--cohesion-energy-density"));
  }
  const double a = dissipative_constant_s;
  if (!(a >= 0.0) || !std::isfinite(a)) {
    throw InvalidInput(fmt::format("--dissipative-constant must be finite and not negative (got {})", a));
  }
  AdhesiveContact contact = adhesive_contact_of(model, material, o.surface_energy.value_or(0.0), a);
  contact.cohesion_energy_density_j_per_m3 = o.cohesion_energy_density.value_or(0.0);
  return contact;
}

}  // namespace restitution::cli
