// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_adhesion.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {
namespace {

// The range solve_adhesive accepts (adhesion.hpp).
constexpr double kSmallestAdhesiveTolerance = 1e-12;
constexpr double kLargestAdhesiveTolerance = 1e-2;

bool positive(double v) {
  return v > 0.0 && std::isfinite(v);
}

// γ for the JKR and DMT models, k_c for sjkr: the one the model takes is required, the other refused.
void read_adhesion_strength(TomlReader& r, AdhesionTask& t) {
  t.surface_energy_j_per_m2 = r.number("surface_energy");
  t.cohesion_energy_density_j_per_m3 = r.number("cohesion_energy_density");
  const bool sjkr = t.model == AdhesiveModel::sjkr;
  const char* needed = sjkr ? "cohesion_energy_density" : "surface_energy";
  const char* other = sjkr ? "surface_energy" : "cohesion_energy_density";
  const auto& value = sjkr ? t.cohesion_energy_density_j_per_m3 : t.surface_energy_j_per_m2;
  if (r.has(other)) {
    r.fail(other, fmt::format("model \"{}\" takes {} ({}), not {}", adhesive_model_name(t.model), needed,
                              sjkr ? "J/m^3" : "J/m^2 per surface", other));
  }
  if (!value) {
    r.fail(needed, sjkr ? "missing: LIGGGHTS's cohesionEnergyDensity k_c in J/m^3"
                        : "missing: the surface energy gamma of one surface in J/m^2 (w = 2 gamma)");
  }
  r.check_each(needed, {*value}, positive, fmt::format("a value > 0 ({})", sjkr ? "J/m^3" : "J/m^2"));
}

// eps at velocity (the damping calibrated there), or the material's A.
void read_adhesion_damping(TomlReader& r, AdhesionTask& t, const Material& m) {
  t.eps = r.number("eps");
  t.velocity_m_s = r.number("velocity");
  if (t.eps.has_value() != t.velocity_m_s.has_value()) {
    r.fail(t.eps ? "eps" : "velocity", "eps and velocity go together (the impact speed eps holds at, m/s)");
  }
  if (t.eps) {
    r.check_each(
        "eps", {*t.eps}, [](double e) { return e > 0.0 && e < 1.0; }, "a value in (0, 1)");
    r.check_each("velocity", {*t.velocity_m_s}, positive, "a speed > 0 (m/s)");
    if (t.model == AdhesiveModel::sjkr) {
      r.fail("eps",
             "the damping of sjkr is not calibrated from eps yet: give the material's "
             "dissipative_constant (as `calibrate --adhesion` refuses sjkr)");
    }
    return;
  }
  if (!m.dissipative_constant_s && !m.viscosities) {
    r.fail("material",
           fmt::format("[materials.{}] has no dissipation: give it dissipative_constant (0 for an "
                       "elastic contact) or the viscosities, or give eps and velocity",
                       t.material));
  }
}

}  // namespace

AdhesionTask read_adhesion_task(TomlReader& r, std::string name,
                                const std::map<std::string, Material>& materials) {
  AdhesionTask t;
  t.line = r.line();
  t.name = std::move(name);
  t.title = r.text("title").value_or(t.name);
  t.material = read_section_material(r, materials, "whose spheres collide");
  if (const auto model = r.text("model")) {
    try {
      t.model = adhesive_model_from_name(*model);
    } catch (const InvalidInput& e) {
      r.fail("model", e.what());
    }
  }
  read_adhesion_strength(r, t);
  read_adhesion_damping(r, t, materials.at(t.material));
  const auto speeds = r.numbers("speeds");
  if (!speeds || speeds->empty()) r.fail("speeds", "missing: the impact speeds in m/s (a list or a range)");
  r.check_each("speeds", *speeds, positive, "speeds > 0 (m/s)");
  t.speeds_m_s = *speeds;
  t.tolerance = r.number("tolerance");
  if (t.tolerance) {
    r.check_each(
        "tolerance", {*t.tolerance},
        [](double v) { return v >= kSmallestAdhesiveTolerance && v <= kLargestAdhesiveTolerance; },
        fmt::format("a value in [{:g}, {:g}] (an adhesive solve's range)", kSmallestAdhesiveTolerance,
                    kLargestAdhesiveTolerance));
  }
  return t;
}

}  // namespace restitution::scene::detail
