// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_oblique/oblique_study.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "oblique/oblique_accuracy.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/parameter_table.hpp"
#include "restitution/units.hpp"
#include "units/contact_compliance.hpp"

namespace restitution::oblique {
namespace {

// The outputs of an impact that was not solved: NaN, no switches.
ObliqueResult failed_result() {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  ObliqueResult r;
  for (double* field : {&r.normal_restitution, &r.tangential_restitution, &r.slip_velocity_m_s,
                        &r.tangential_velocity_m_s, &r.normal_velocity_m_s, &r.spin_first_rad_s,
                        &r.spin_second_rad_s, &r.impact_angle_rad, &r.rebound_angle_rad, &r.impulse_ratio,
                        &r.line_of_centres_turn_rad, &r.contact_time_s, &r.stick_time_s, &r.slip_time_s}) {
    *field = nan;
  }
  return r;
}

// The argument as the caller spells it.
std::string spelled(const char* keyword, ArgumentStyle style) {
  return style == ArgumentStyle::keyword ? keyword : option_name(keyword);
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
    throw InvalidInput(fmt::format("{} must be a positive number of m/s, got {}",
                                   spelled("impact_velocity", style), in.speed_m_s));
  }
}

// E* and G* of the contact: two spheres of one material, a sphere on a rigid wall or on a wall of its own
// material (the compliances summed, as `dem --wall`).
void contact_moduli(const ObliqueInputs& in, ArgumentStyle style, ObliqueSetup& s) {
  const Material& m = in.material;
  const std::string young = spelled("wall_young_modulus", style);
  const std::string ratio = spelled("wall_poisson_ratio", style);
  if (!in.wall && (in.wall_young_modulus_pa || in.wall_poisson_ratio)) {
    throw InvalidInput(fmt::format("{} and {} need {}", young, ratio, spelled("wall", style)));
  }
  if (in.wall_young_modulus_pa.has_value() != in.wall_poisson_ratio.has_value()) {
    throw InvalidInput(fmt::format("give both {} and {}, or neither (a rigid wall)", young, ratio));
  }
  s.rigid_wall = in.wall && !in.wall_young_modulus_pa;
  if (!in.wall) {
    // Two spheres of one material, evaluated as before walls had materials: E* = E/(2(1 - ν²)), 8 G* =
    // 8 E/(4 (2 - ν)(1 + ν)) (pair_granular.cpp:1021-1023, mix_stiffnessG at line 1790).
    const double nu = m.poisson_ratio;
    s.effective_modulus_pa = effective_modulus_pa(m.young_modulus_pa, nu);
    s.effective_shear_modulus_pa = m.young_modulus_pa / (4.0 * (2.0 - nu) * (1.0 + nu));
    return;
  }
  double normal = normal_compliance_per_pa(m.young_modulus_pa, m.poisson_ratio);
  double shear = shear_compliance_per_pa(m.young_modulus_pa, m.poisson_ratio);
  if (in.wall_young_modulus_pa) {
    const double y = *in.wall_young_modulus_pa;
    const double nu = *in.wall_poisson_ratio;
    if (!(y > 0.0) || !std::isfinite(y)) {
      throw InvalidInput(fmt::format("{} must be finite and > 0 Pa, got {}", young, y));
    }
    if (!(nu > -1.0 && nu < 0.5)) {
      throw InvalidInput(fmt::format("{} must lie in (-1, 0.5), got {}", ratio, nu));
    }
    normal += normal_compliance_per_pa(y, nu);
    shear += shear_compliance_per_pa(y, nu);
  }
  s.effective_modulus_pa = 1.0 / normal;
  s.effective_shear_modulus_pa = 1.0 / shear;
}

// The normal force's damping coefficient γ [N s/m^{1+b}] of the law on this contact (stiffness ρ [N/m^{3/2}],
// effective mass [kg]): from A (viscoelastic Hertz, γ = (3/2) A ρ; 0 for any law: elastic), or calibrated
// so that the head-on impact gives ε at the given speed, as `calibrate`, `eps` and `dem` do it. Exactly one
// of the two, never a silent elastic default. Sets setup.dissipative_constant_s (A; 0 for the other laws).
double normal_damping(const ObliqueInputs& in, ArgumentStyle style, LawKind law, double rho, double mass_kg,
                      ObliqueSetup& setup) {
  const std::string a = spelled("dissipative_constant", style);
  const std::string eps = spelled("eps", style);
  const std::string velocity = spelled("velocity", style);
  if (in.dissipative_constant_s.has_value() == in.eps.has_value()) {
    throw InvalidInput(fmt::format(
        "give either {} A (seconds; 0 for an elastic contact) or {} and {} (A calibrated on this contact)", a,
        eps, velocity));
  }
  if (in.dissipative_constant_s) {
    const double given = *in.dissipative_constant_s;
    if (!(given >= 0.0) || !std::isfinite(given)) {
      throw InvalidInput(fmt::format("{} must be a non-negative number of seconds, got {}", a, given));
    }
    if (in.eps_velocity_m_s)
      throw InvalidInput(fmt::format("{} goes with {}, not with {}", velocity, eps, a));
    if (law != LawKind::viscoelastic_hertz && given != 0.0) {
      throw InvalidInput(
          fmt::format("{} is viscoelastic Hertz's A; give {}'s damping by {} and {} (or {} 0: "
                      "elastic)",
                      a, law_name(law), eps, velocity, a));
    }
    setup.dissipative_constant_s = given;
    return 1.5 * given * rho;
  }
  if (!in.eps_velocity_m_s) {
    throw InvalidInput(fmt::format("{} needs {}, the impact speed it was measured at (m/s)", eps, velocity));
  }
  CalibrationRequest request;
  request.law = law;
  request.eps = *in.eps;
  request.velocity_m_s = *in.eps_velocity_m_s;
  request.end = setup.options.end;
  if (law == LawKind::viscoelastic_hertz) request.k = rho / mass_kg;
  CollisionSolver solver;
  try {
    const Calibration c = calibrate(request, solver);
    if (c.dissipative_constant_s) {
      setup.dissipative_constant_s = *c.dissipative_constant_s;
      return 1.5 * setup.dissipative_constant_s * rho;
    }
    // ζ = (γ/m) v^b T^{b+1} (ContactLaw::physical), so γ = ζ m / (v^b T^{b+1}).
    const double v = request.velocity_m_s;
    const double b = law_exponents(law).damping;
    const double t = physical_time_scale_s(law, rho, mass_kg, v);
    return c.zeta * mass_kg / (std::pow(v, b) * std::pow(t, b + 1.0));
  } catch (const InvalidInput& e) {
    throw InvalidInput(
        fmt::format("{} {} at {} {} m/s: {}", eps, *in.eps, velocity, *in.eps_velocity_m_s, e.what()));
  }
}

// The normal law: the Hertz members of the family (the material gives their stiffness); not the linear
// dash-pot, whose stiffness is no material's, and LIGGGHTS's model only over viscoelastic Hertz (its
// hertz/stiffness).
LawKind normal_law(const ObliqueInputs& in, ArgumentStyle style) {
  const std::string name = spelled("law", style);
  const std::string hertz_members = "viscoelastic-hertz, tsuji-hertz or hertz-constant-damping";
  LawKind law = LawKind::viscoelastic_hertz;
  try {
    law = law_from_name(in.law);
  } catch (const InvalidInput&) {
    throw InvalidInput(fmt::format("{} must be {}, got '{}'", name, hertz_members, in.law));
  }
  if (law == LawKind::linear_dashpot) {
    throw InvalidInput(
        fmt::format("{} linear-dashpot: its stiffness is no material's Hertz constant; oblique "
                    "takes {}",
                    name, hertz_members));
  }
  // A model the study runs that its code pairs with one normal law only.
  const TangentialModel* model = find_tangential_model(in.tangential);
  if (model != nullptr && model->runs_in_study() && model->normal_law && law != *model->normal_law) {
    throw InvalidInput(fmt::format("{} {}: {}; choose a LAMMPS model or {}", name, in.law,
                                   model->normal_law_words, law_name(*model->normal_law)));
  }
  return law;
}

// Refuses a tangential spring or damper faster than the solve resolves (tangential_limits) at any of the
// impacts: the spring's limit is lowest at the smallest normal speed (the longest contact), the damper's at
// the largest (the strongest normal damping).
void check_tangential_limits(const ObliqueSetup& s, ArgumentStyle style) {
  if (s.tangential.friction == 0.0) return;
  const auto [lowest, highest] = std::minmax_element(s.angles_deg.begin(), s.angles_deg.end());
  TangentialLimits limits{HUGE_VAL, HUGE_VAL};
  for (const double angle : {*lowest, *highest}) {
    const TangentialLimits at = tangential_limits(s.geometry, s.normal, s.tangential.kind,
                                                  s.speed_m_s * std::cos(angle * kRadiansPerDegree));
    limits.stiffness = std::min(limits.stiffness, at.stiffness);
    limits.damping_factor = std::min(limits.damping_factor, at.damping_factor);
  }
  const char* unit = tangential_model(s.tangential.kind).stiffness_unit;
  if (s.tangential.stiffness > limits.stiffness) {
    throw InvalidInput(fmt::format(
        "{} must be at most {:.3g} {} for these impacts, got {:g}: a stiffer spring oscillates more than "
        "{:g} radians per unit of the contact's natural time, beyond what the solve resolves",
        spelled("tangential_stiffness", style), limits.stiffness, unit != nullptr ? unit : "",
        s.tangential.stiffness, kFastestTangentialRate));
  }
  if (s.tangential.damping_factor > limits.damping_factor) {
    throw InvalidInput(fmt::format(
        "{} must be at most {:.3g} for these impacts, got {:g}: a stronger damper relaxes the slip more than "
        "{:g} times per unit of the contact's natural time, beyond what the solve resolves",
        spelled("tangential_damping", style), limits.damping_factor, s.tangential.damping_factor,
        kFastestTangentialDampingRate));
  }
}

}  // namespace

const std::vector<std::string>& oblique_tangential_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> runs;
    for (const TangentialModel& model : tangential_models()) {
      if (model.runs_in_study()) runs.emplace_back(model.name);
    }
    return runs;
  }();
  return names;
}

ObliqueSetup oblique_setup(const ObliqueInputs& in, ArgumentStyle style) {
  const auto name = [style](const char* keyword) { return spelled(keyword, style); };
  const Material& m = in.material;
  check_material(m);
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
  if (in.wall && in.fixed_normal) {
    throw InvalidInput(fmt::format("{} is for two spheres: a wall's normal is fixed already; drop it",
                                   name("fixed_normal")));
  }
  s.geometry.fixed_normal = in.fixed_normal;
  if (in.torque_arm != "lammps" && in.torque_arm != "radius" &&
      in.torque_arm != "radius-minus-half-overlap") {
    throw InvalidInput(fmt::format("{} must be lammps, radius or radius-minus-half-overlap, got '{}'",
                                   name("torque_arm"), in.torque_arm));
  }
  // "lammps": what the model's code does (LAMMPS: R - δ/2 for a pair, R for a wall; LIGGGHTS: R - δ/2 for
  // both, in the torque and the contact-point velocity); otherwise the torque arm given.
  if (in.torque_arm == "lammps") {
    const TangentialModel* model = find_tangential_model(in.tangential);
    const ContactArms arms = model != nullptr ? model->arms(!in.wall) : ContactArms{};
    s.geometry.torque_arm = arms.torque;
    s.geometry.contact_point_arm = arms.contact_point;
  } else {
    s.geometry.torque_arm =
        in.torque_arm == "radius" ? TorqueArm::radius : TorqueArm::radius_minus_half_overlap;
  }
  contact_moduli(in, style, s);
  // F = ρ δ^{3/2} + (3/2) A ρ sqrt(δ) δ', ρ = (4/3) E* sqrt(R*).
  const double rho = hertz_stiffness(s.effective_modulus_pa, effective_radius_m(s.geometry));
  try {
    s.options.end = end_from_name(in.end);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", name("end"), e.what()));
  }
  const LawKind law = normal_law(in, style);
  s.normal = {law, rho, normal_damping(in, style, law, rho, effective_mass_kg(s.geometry), s)};
  try {
    s.tangential.kind = tangential_from_name(in.tangential);
  } catch (const InvalidInput&) {
    throw InvalidInput(fmt::format("{} must be one of {}, got '{}'", name("tangential"),
                                   fmt::join(oblique_tangential_names(), ", "), in.tangential));
  }
  const TangentialModel& model = tangential_model(s.tangential.kind);
  if (!model.runs_in_study()) {
    throw InvalidInput(fmt::format("{} {}: {}, and this models viscoelastic Hertz; {}", name("tangential"),
                                   model.name, model.normal_law_words, model.study_refusal));
  }
  s.tangential.damping_factor = in.tangential_damping;
  s.tangential.friction = *in.friction;
  if (in.tangential_stiffness && !model.has_stiffness()) {
    throw InvalidInput(fmt::format("{} has no stiffness: drop {}", model.name, name("tangential_stiffness")));
  }
  if (in.tangential_stiffness) {
    s.tangential.stiffness = *in.tangential_stiffness;
  } else if (model.default_stiffness != nullptr) {
    // LAMMPS's `mindlin NULL`: 8 G*, of the sphere and the wall on a wall (as `dem --wall` prints it).
    s.tangential.stiffness = model.default_stiffness(
        {s.effective_modulus_pa, s.effective_shear_modulus_pa, effective_radius_m(s.geometry)});
  } else if (model.has_stiffness() && *in.friction > 0.0) {
    throw InvalidInput(
        fmt::format("{} needs {} K_T in {}", model.name, name("tangential_stiffness"), model.stiffness_unit));
  }
  require_oblique_tolerance(in.tolerance, name("tolerance").c_str());
  s.tolerance = in.tolerance;
  s.options.relative_tolerance = in.tolerance * kObliqueRtolFactor;
  check_lists(in, style);
  s.speed_m_s = in.speed_m_s;
  s.angles_deg = in.angles_deg;
  s.spins_rad_s = in.spins_rad_s;
  if (!(s.tangential.damping_factor >= 0.0) || !std::isfinite(s.tangential.damping_factor)) {
    throw InvalidInput(fmt::format("{} must be a non-negative finite number, got {}",
                                   spelled("tangential_damping", style), s.tangential.damping_factor));
  }
  if (in.tangential_stiffness &&
      (!(*in.tangential_stiffness > 0.0) || !std::isfinite(*in.tangential_stiffness))) {
    throw InvalidInput(fmt::format("{} must be a positive finite number, got {}",
                                   spelled("tangential_stiffness", style), *in.tangential_stiffness));
  }
  check_tangential_limits(s, style);
  return s;
}

ImpactVelocity impact_at(const ObliqueSetup& setup, double angle_deg, double spin_rad_s) {
  return {setup.speed_m_s * std::cos(angle_deg * kRadiansPerDegree),
          setup.speed_m_s * std::sin(angle_deg * kRadiansPerDegree), spin_rad_s, 0.0};
}

namespace {
// κ = 8G*a/(2E*a): Mindlin's tangential stiffness over the normal one.
double maw_kappa(const ObliqueSetup& setup) {
  return 4.0 * setup.effective_shear_modulus_pa / setup.effective_modulus_pa;
}
}  // namespace

double maw_psi(const ObliqueSetup& setup, double slip_m_s, double normal_speed_m_s) {
  const double kappa = maw_kappa(setup);
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
  return 0.5 * maw_kappa(setup) * inertia_factor;
}

ObliqueImpact solve_impact(const ObliqueSetup& setup, double angle_deg, double spin_rad_s) {
  const ImpactVelocity v = impact_at(setup, angle_deg, spin_rad_s);
  ObliqueImpact impact;
  impact.angle_deg = angle_deg;
  impact.initial_spin_rad_s = spin_rad_s;
  const double slip_in = v.tangential_m_s + setup.geometry.first.radius_m * spin_rad_s;
  impact.psi_in = maw_psi(setup, slip_in, v.normal_m_s);
  ContractedOblique solve;
  try {
    solve = solve_oblique_within(setup.geometry, setup.normal, setup.tangential, v, setup.tolerance,
                                 setup.options);
  } catch (const NumericalFailure& e) {
    impact.failure = e.what();
    impact.result = failed_result();
    impact.psi_out = std::numeric_limits<double>::quiet_NaN();
    impact.relative_tolerance = setup.tolerance * kObliqueRtolFactor;
    impact.conditioning = "not solved";
    return impact;
  }
  impact.result = std::move(solve.result);
  impact.relative_tolerance = solve.relative_tolerance;
  impact.ill_conditioned = solve.ill_conditioned;
  impact.conditioning = std::move(solve.conditioning);
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

std::size_t failed_count(const std::vector<ObliqueImpact>& impacts) {
  return static_cast<std::size_t>(
      std::count_if(impacts.begin(), impacts.end(), [](const ObliqueImpact& i) { return !i.solved(); }));
}

StickingLimit sticking_limit_restitution(const ObliqueSetup& setup) {
  // μ → ∞: the cap removed, the contact sticks throughout. The equations are then linear in the slip
  // velocity for a fixed normal, so one small angle gives the limit.
  ObliqueOptions sticking = setup.options;
  sticking.sticking_limit = true;
  const ImpactVelocity v = impact_at(setup, 1.0, 0.0);
  try {
    return {solve_oblique(setup.geometry, setup.normal, setup.tangential, v, sticking).tangential_restitution,
            ""};
  } catch (const NumericalFailure& e) {
    return {std::numeric_limits<double>::quiet_NaN(), e.what()};
  }
}

}  // namespace restitution::oblique
