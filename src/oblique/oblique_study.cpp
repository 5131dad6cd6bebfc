// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_oblique/oblique_study.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "oblique/oblique_accuracy.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::oblique {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The argument as the caller spells it.
std::string spelled(const char* keyword, ArgumentStyle style) {
  if (style == ArgumentStyle::keyword) return keyword;
  std::string option = std::string("--") + keyword;
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

// The lists are named as the command and Python take them, one value or several: --angle, angle (a scene's
// parser checks its own `angles` and `spins` before).
void check_lists(const ObliqueInputs& in, ArgumentStyle style) {
  const std::string angle = spelled("angle", style);
  if (in.angles_deg.empty())
    throw InvalidInput(fmt::format("give {} (one or more impact angles from the normal, degrees)", angle));
  for (const double a : in.angles_deg) {
    if (!(a >= 0.0 && a < 90.0)) {
      throw InvalidInput(fmt::format("{} must be in [0, 90) degrees from the normal, got {}", angle, a));
    }
  }
  const std::string spin = spelled("spin", style);
  if (in.spins_rad_s.empty()) throw InvalidInput(fmt::format("give {} (one or more, rad/s)", spin));
  for (const double w : in.spins_rad_s) {
    if (!std::isfinite(w)) throw InvalidInput(fmt::format("{} must be finite rad/s, got {}", spin, w));
  }
  if (!(in.speed_m_s > 0.0) || !std::isfinite(in.speed_m_s)) {
    throw InvalidInput(
        fmt::format("{} must be a positive number of m/s, got {}", spelled("speed", style), in.speed_m_s));
  }
}

}  // namespace

ObliqueSetup oblique_setup(const ObliqueInputs& in, ArgumentStyle style) {
  const auto name = [style](const char* keyword) { return spelled(keyword, style); };
  const Material& m = in.material;
  check_material(m);
  if (!(in.dissipative_constant_s >= 0.0) || !std::isfinite(in.dissipative_constant_s)) {
    throw InvalidInput(fmt::format("{} must be a non-negative number of seconds, got {}",
                                   name("dissipative_constant"), in.dissipative_constant_s));
  }
  if (!in.friction)
    throw InvalidInput(fmt::format("give {} MU (0 for a frictionless contact)", name("friction")));
  if (in.wall && (m.radius1_m != m.radius2_m || m.mass1_kg != m.mass2_kg)) {
    throw InvalidInput(
        fmt::format("{} takes one sphere: the material has two sizes or masses", name("wall")));
  }
  ObliqueSetup s;
  const auto mass = [&](double radius, const std::optional<double>& given) {
    return given ? *given : sphere_mass_kg(radius, *m.density_kg_m3);
  };
  s.geometry.first = solid_sphere(m.radius1_m, mass(m.radius1_m, m.mass1_kg));
  if (!in.wall) s.geometry.second = solid_sphere(m.radius2_m, mass(m.radius2_m, m.mass2_kg));
  s.geometry.fixed_normal = in.fixed_normal;
  if (in.torque_arm != "lammps" && in.torque_arm != "radius" &&
      in.torque_arm != "radius-minus-half-overlap") {
    throw InvalidInput(fmt::format("{} must be lammps, radius or radius-minus-half-overlap, got '{}'",
                                   name("torque_arm"), in.torque_arm));
  }
  // "lammps": what LAMMPS does, R - δ/2 for a pair (pair_granular.cpp:663), R for a wall
  // (fix_wall_gran.cpp:1512); LIGGGHTS's model takes its own arm R - δ/2 for both, in the torque and the
  // contact-point velocity (surface_model_default.h:174-188).
  const bool liggghts = in.tangential == "liggghts_history";
  const bool half_overlap =
      in.torque_arm == "radius-minus-half-overlap" || (in.torque_arm == "lammps" && (!in.wall || liggghts));
  s.geometry.torque_arm = half_overlap ? TorqueArm::radius_minus_half_overlap : TorqueArm::radius;
  if (liggghts && in.torque_arm == "lammps")
    s.geometry.contact_point_arm = TorqueArm::radius_minus_half_overlap;
  s.effective_modulus_pa = effective_modulus_pa(m.young_modulus_pa, m.poisson_ratio);
  s.poisson_ratio = m.poisson_ratio;
  // F = ρ δ^{3/2} + (3/2) A ρ sqrt(δ) δ', ρ = (4/3) E* sqrt(R*): a wall of the sphere's material has the same
  // E*.
  const double rho = hertz_stiffness(s.effective_modulus_pa, effective_radius_m(s.geometry));
  s.normal = {LawKind::viscoelastic_hertz, rho, 1.5 * in.dissipative_constant_s * rho};
  try {
    s.tangential.kind = tangential_from_name(in.tangential);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", name("tangential"), e.what()));
  }
  if (s.tangential.kind == TangentialKind::yade_viscel) {
    throw InvalidInput(fmt::format(
        "{} yade_viscel: YADE's ViscElPhys pairs its shear spring with a linear normal force (kn delta + cn "
        "delta'), and this models viscoelastic Hertz; the model is in the library (docs/oblique.md)",
        name("tangential")));
  }
  if (s.tangential.kind == TangentialKind::yade_mindlin) {
    throw InvalidInput(fmt::format(
        "{} yade_mindlin: YADE's MindlinPhys pairs its shear spring with the Tsuji normal force (kno "
        "delta^1.5 "
        "+ cn delta', cn = 2 betan sqrt(m* kn)), and this models viscoelastic Hertz; `restitution dem --code "
        "yade --friction MU` prints its oblique impacts (docs/oblique.md)",
        name("tangential")));
  }
  s.tangential.damping_factor = in.tangential_damping;
  s.tangential.friction = *in.friction;
  if (in.tangential_stiffness) {
    s.tangential.stiffness = *in.tangential_stiffness;
  } else if (is_lammps_mindlin(s.tangential.kind) || s.tangential.kind == TangentialKind::liggghts_history) {
    // LAMMPS's `mindlin NULL`: 8 G* with 1/G* = 2 · 2(2 - ν)(1 + ν)/E for two spheres of one material
    // (pair_granular.cpp:1021-1023, mix_stiffnessG at line 1790).
    const double nu = m.poisson_ratio;
    s.tangential.stiffness = 8.0 * m.young_modulus_pa / (4.0 * (2.0 - nu) * (1.0 + nu));
  } else if (s.tangential.kind == TangentialKind::linear_history) {
    throw InvalidInput(fmt::format("linear_history needs {} K_T in N/m", name("tangential_stiffness")));
  }
  try {
    s.options.end = end_from_name(in.end);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", name("end"), e.what()));
  }
  require_oblique_tolerance(in.tolerance, name("tolerance").c_str());
  s.tolerance = in.tolerance;
  s.options.relative_tolerance = in.tolerance * kObliqueRtolFactor;
  check_lists(in, style);
  s.speed_m_s = in.speed_m_s;
  s.angles_deg = in.angles_deg;
  s.spins_rad_s = in.spins_rad_s;
  return s;
}

ImpactVelocity impact_at(const ObliqueSetup& setup, double angle_deg, double spin_rad_s) {
  return {setup.speed_m_s * std::cos(angle_deg * kDegree), setup.speed_m_s * std::sin(angle_deg * kDegree),
          spin_rad_s, 0.0};
}

double maw_psi(const ObliqueSetup& setup, double slip_m_s, double normal_speed_m_s) {
  const double nu = setup.poisson_ratio;
  const double kappa = 2.0 * (1.0 - nu) / (2.0 - nu);
  const double mu = setup.tangential.friction;
  if (!(mu > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return kappa * slip_m_s / (mu * normal_speed_m_s);
}

double maw_chi(const ObliqueSetup& setup) {
  const ObliqueGeometry& g = setup.geometry;
  const double m = effective_mass_kg(g);
  // 1 + m* Σ R_i²/I_i: how much more a tangential impulse changes the contact-point velocity than the
  // centre's.
  double inertia_factor = 1.0 + m * g.first.radius_m * g.first.radius_m / g.first.inertia_kg_m2;
  if (g.second) inertia_factor += m * g.second->radius_m * g.second->radius_m / g.second->inertia_kg_m2;
  const double nu = setup.poisson_ratio;
  return (1.0 - nu) / (2.0 - nu) * inertia_factor;
}

ObliqueImpact solve_impact(const ObliqueSetup& setup, double angle_deg, double spin_rad_s) {
  const ImpactVelocity v = impact_at(setup, angle_deg, spin_rad_s);
  ContractedOblique solve =
      solve_oblique_within(setup.geometry, setup.normal, setup.tangential, v, setup.tolerance, setup.options);
  ObliqueImpact impact;
  impact.angle_deg = angle_deg;
  impact.initial_spin_rad_s = spin_rad_s;
  impact.result = std::move(solve.result);
  impact.relative_tolerance = solve.relative_tolerance;
  impact.ill_conditioned = solve.ill_conditioned;
  impact.conditioning = std::move(solve.conditioning);
  const double slip_in = v.tangential_m_s + setup.geometry.first.radius_m * spin_rad_s;
  impact.psi_in = maw_psi(setup, slip_in, v.normal_m_s);
  impact.psi_out = maw_psi(setup, impact.result.slip_velocity_m_s, v.normal_m_s);
  return impact;
}

std::vector<ObliqueImpact> oblique_sweep(const ObliqueSetup& setup) {
  std::vector<ObliqueImpact> out;
  out.reserve(setup.angles_deg.size() * setup.spins_rad_s.size());
  for (const double angle : setup.angles_deg) {
    for (const double spin : setup.spins_rad_s) out.push_back(solve_impact(setup, angle, spin));
  }
  return out;
}

double sticking_limit_restitution(const ObliqueSetup& setup) {
  // μ → ∞: the Coulomb cap is never reached. The equations are then linear in the slip velocity for a fixed
  // normal, so one small angle gives the limit; 1e12 keeps the cap out of reach without overflow.
  TangentialForce sticking = setup.tangential;
  sticking.friction = 1e12;
  const ImpactVelocity v = impact_at(setup, 1.0, 0.0);
  return solve_oblique(setup.geometry, setup.normal, sticking, v, setup.options).tangential_restitution;
}

}  // namespace restitution::oblique
