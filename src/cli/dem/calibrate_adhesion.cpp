// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/calibrate_adhesion.hpp"

#include <fmt/core.h>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "restitution/adhesive_calibration.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {

int run_adhesive_calibrate(const AdhesionOptions& adhesion, const MaterialOptions& material, double eps,
                           double velocity_m_per_s, double tolerance, bool json) {
  if (!adhesion.model) throw InvalidInput("--surface-energy belongs to --adhesion: give --adhesion MODEL");
  const AdhesiveModel model = adhesive_model_from_name(*adhesion.model);
  if (model == AdhesiveModel::sjkr || adhesion.cohesion_energy_density) {
    // The calibration searches A with a surface energy; sjkr's cohesion energy density is not wired to it
    // yet.
    throw InvalidInput(
        "calibrate --adhesion takes jkr, jkr-lammps or dmt with --surface-energy; sjkr "
        "(--cohesion-energy-density) "
        "is not calibrated yet: bracket A with `restitution eps --adhesion sjkr` or `sweep --adhesion sjkr`");
  }
  if (!adhesion.surface_energy) {
    throw InvalidInput(fmt::format("--adhesion {} needs --surface-energy", *adhesion.model));
  }
  if (eps == 0.0) throw InvalidInput("--eps is required");
  const AdhesiveDampingCalibration c = calibrate_adhesive_damping(
      model, material_from(material), *adhesion.surface_energy, eps, velocity_m_per_s, tolerance);
  const bool lammps_damping = model != AdhesiveModel::jkr;
  if (json) {
    JsonWriter out;
    out.begin_object();
    out.field("adhesion", adhesion.model->c_str()).field("surface_energy_j_per_m2", *adhesion.surface_energy);
    out.field("eps", eps).field("velocity_m_per_s", velocity_m_per_s).field("tolerance", tolerance);
    out.field("dissipative_constant_s", c.dissipative_constant_s);
    if (lammps_damping) out.field("lammps_damping_per_m_s", c.contact.damping);
    out.field("eps_at_velocity", c.eps_at_velocity).field("elastic_eps", c.elastic_eps);
    out.field("solves", c.solves);
    fmt::print("{}\n", finish_json_document(out));
    return 0;
  }
  fmt::print(
      "adhesive calibration: eps = {} at v = {} m/s, {} with surface energy {} J/m^2 (tolerance {:g})\n", eps,
      velocity_m_per_s, *adhesion.model, *adhesion.surface_energy, tolerance);
  fmt::print("  A (dissipative constant)    {:.12g} s\n", c.dissipative_constant_s);
  if (lammps_damping) fmt::print("  LAMMPS damp = 2 A E*/m_eff  {:.12g} 1/(m s)\n", c.contact.damping);
  fmt::print("  eps re-solved               {:.12g}   (undamped: {:.12g})\n", c.eps_at_velocity,
             c.elastic_eps);
  fmt::print("  {} collisions integrated\n", c.solves);
  return 0;
}

}  // namespace restitution::cli
