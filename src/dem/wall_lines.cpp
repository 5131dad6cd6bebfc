// SPDX-License-Identifier: BSD-3-Clause
#include "dem/wall_lines.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dem/deck_eps.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"
#include "units/contact_compliance.hpp"

namespace restitution::dem {
namespace {

void check_wall(const WallMaterial& w) {
  if (!std::isfinite(w.young_modulus_pa) || w.young_modulus_pa <= 0.0) {
    throw InvalidInput(
        fmt::format("--wall-young-modulus must be finite and > 0 Pa, got {}", w.young_modulus_pa));
  }
  if (!std::isfinite(w.poisson_ratio) || w.poisson_ratio <= -1.0 || w.poisson_ratio >= 0.5) {
    throw InvalidInput(fmt::format("--wall-poisson-ratio must lie in (-1, 0.5), got {}", w.poisson_ratio));
  }
}

}  // namespace

WallResult wall_lines(const WallRequest& request) {
  const CodeEntry& entry = code_entry(request.code);
  if (entry.write_wall == nullptr) throw InvalidInput(entry.wall);
  if (always_clamps(request.code) && request.end == CollisionEnd::naive)
    (void)make_deck(request.code, request.end, {}, 0.0, 1.0);
  check_friction(request.friction);
  if (request.wall) check_wall(*request.wall);
  Material sphere = request.sphere;
  sphere.radius2_m = sphere.radius1_m;
  if (sphere.mass1_kg && !sphere.mass2_kg) sphere.mass2_kg = sphere.mass1_kg;
  const Pair one = pair_of(sphere);

  WallResult r;
  r.rigid_wall = !request.wall;
  Pair& c = r.contact;
  c.young_modulus_pa = one.young_modulus_pa;
  c.poisson_ratio = one.poisson_ratio;
  c.radius1_m = one.radius1_m;
  c.mass1_kg = one.mass1_kg;
  // 1/E* = (1 - ν²)/Y + (1 - ν_w²)/Y_w and 1/G* = (2 - ν)/G + (2 - ν_w)/G_w, the wall's terms 0 when it is
  // rigid.
  double e_compliance = normal_compliance_per_pa(one.young_modulus_pa, one.poisson_ratio);
  double g_compliance = shear_compliance_per_pa(one.young_modulus_pa, one.poisson_ratio);
  if (request.wall) {
    e_compliance += normal_compliance_per_pa(request.wall->young_modulus_pa, request.wall->poisson_ratio);
    g_compliance += shear_compliance_per_pa(request.wall->young_modulus_pa, request.wall->poisson_ratio);
  }
  c.effective_modulus_pa = 1.0 / e_compliance;
  c.effective_radius_m = one.radius1_m;
  c.effective_mass_kg = one.mass1_kg;

  const double k = hertz_stiffness(c.effective_modulus_pa, c.effective_radius_m) / c.effective_mass_kg;
  CollisionSolver solver;
  r.dissipative_constant_s =
      dissipative_constant(k, request.damping, request.end, request.tolerance, Method::automatic, solver);
  r.reference_velocity_m_s = request.damping.velocity_m_s.value_or(1.0);
  r.friction = request.friction;
  r.deck.code = request.code;
  r.deck.end = request.end;
  entry.write_wall(r.deck, c, 1.0 / g_compliance, r.dissipative_constant_s, request.friction);

  // ε as the code reads its wall lines back (LAMMPS: fix_wall_gran.cpp:160 and the viscoelastic damping).
  const double e = r.deck.parameter("E");
  const double nu = r.deck.parameter("nu");
  const double elastic = hertz_stiffness(e / (2.0 * (1.0 - nu)), c.effective_radius_m);
  const double damping = r.deck.parameter("eta_n0") * c.effective_mass_kg * std::sqrt(c.effective_radius_m);
  const double beta = beta_of_coefficients(elastic, damping, c.effective_mass_kg);
  const double v = r.reference_velocity_m_s;
  const std::vector<double> speeds =
      request.speeds_m_s.empty() ? std::vector<double>{v / 10.0, v, 10.0 * v} : request.speeds_m_s;
  for (double s : speeds) r.eps.push_back({s, eps_for(beta, s, request.end, request.tolerance, solver)});
  return r;
}

}  // namespace restitution::dem
