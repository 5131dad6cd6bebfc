// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/calibrate_adhesion.hpp"

#include <fmt/core.h>

#include <string>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "restitution/adhesive_calibration.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

// γ and A from ε at one speed plus the sticking speed.
int run_sticking_calibrate(const std::string& model_name, const MaterialOptions& material, double eps,
                           double velocity_m_per_s, double sticking_speed_m_per_s, double tolerance,
                           bool json) {
  const AdhesiveModel model = adhesive_model_from_name(model_name);
  const AdhesiveStickingCalibration c = calibrate_adhesive_sticking(
      model, material_from(material), eps, velocity_m_per_s, sticking_speed_m_per_s, tolerance);
  const bool lammps_damping = model != AdhesiveModel::jkr;
  if (json) {
    JsonWriter out;
    out.begin_object();
    out.field("adhesion", model_name.c_str()).field("eps", eps).field("velocity_m_per_s", velocity_m_per_s);
    out.field("sticking_speed_m_per_s", sticking_speed_m_per_s).field("tolerance", tolerance);
    out.field("surface_energy_j_per_m2", c.surface_energy_j_per_m2);
    out.field("dissipative_constant_s", c.dissipative_constant_s);
    if (lammps_damping) out.field("lammps_damping_per_m_s", c.contact.damping);
    out.field("eps_at_velocity", c.eps_at_velocity)
        .field("sticking_speed_resolved_m_per_s", c.sticking_speed_m_per_s);
    out.field("undamped_eps", c.undamped_eps).field("solves", c.solves);
    fmt::print("{}\n", finish_json_document(out));
    return 0;
  }
  fmt::print("adhesive calibration: eps = {} at v = {} m/s and sticking speed {} m/s, {} (tolerance {:g})\n",
             eps, velocity_m_per_s, sticking_speed_m_per_s, model_name, tolerance);
  fmt::print("  surface energy gamma        {:.12g} J/m^2\n", c.surface_energy_j_per_m2);
  fmt::print("  A (dissipative constant)    {:.12g} s\n", c.dissipative_constant_s);
  if (lammps_damping) fmt::print("  LAMMPS damp = 2 A E*/m_eff  {:.12g} 1/(m s)\n", c.contact.damping);
  fmt::print("  eps re-solved               {:.12g}   (undamped limit sqrt(1 - (v_s/v)^2): {:.12g})\n",
             c.eps_at_velocity, c.undamped_eps);
  fmt::print("  sticking speed re-solved    {:.12g} m/s\n", c.sticking_speed_m_per_s);
  fmt::print("  {} collisions integrated\n", c.solves);
  return 0;
}

}  // namespace

int run_adhesive_calibrate(const AdhesionOptions& adhesion, const MaterialOptions& material, double eps,
                           double velocity_m_per_s, std::optional<double> sticking_speed_m_per_s,
                           double tolerance, bool json) {
  if (!adhesion.model) {
    throw InvalidInput(fmt::format("{} belongs to --adhesion: give --adhesion MODEL",
                                   sticking_speed_m_per_s ? "--sticking-speed" : "--surface-energy"));
  }
  const AdhesiveModel model = adhesive_model_from_name(*adhesion.model);
  if (model == AdhesiveModel::sjkr || adhesion.cohesion_energy_density) {
    // The calibration searches A with a surface energy; sjkr's cohesion energy density is not wired to it
    // yet.
    throw InvalidInput(
        "calibrate --adhesion takes jkr, jkr-lammps or dmt with --surface-energy; sjkr "
        "(--cohesion-energy-density) "
        "is not calibrated yet: bracket A with `restitution eps --adhesion sjkr` or `sweep --adhesion sjkr`");
  }
  if (eps == 0.0) throw InvalidInput("--eps is required");
  if (sticking_speed_m_per_s) {
    if (adhesion.surface_energy) {
      throw InvalidInput(
          "--sticking-speed and --surface-energy exclude each other: with the sticking speed the surface "
          "energy is calibrated, with the surface energy only the damping");
    }
    return run_sticking_calibrate(*adhesion.model, material, eps, velocity_m_per_s, *sticking_speed_m_per_s,
                                  tolerance, json);
  }
  if (!adhesion.surface_energy) {
    throw InvalidInput(
        fmt::format("--adhesion {} needs --surface-energy (or --sticking-speed)", *adhesion.model));
  }
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
