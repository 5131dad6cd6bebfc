// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Calibration: the damping that gives a measured coefficient of restitution ε, found by root finding on the
// natural form's ζ with the collision solver (ε decreases monotonically with ζ), for any member of the
// contact-law family. For viscoelastic Hertz also β = ζ / v^{1/5} at the impact speed v, the 1999 paper's
// g* and, with a material, the dissipative constant A a DEM code needs.
#include <optional>

#include "restitution/collision_solver.hpp"
#include "restitution/units.hpp"

namespace restitution {

struct CalibrationRequest {
  LawKind law = LawKind::viscoelastic_hertz;
  double eps = 0.0;           // measured ε in (0, 1)
  double velocity_m_s = 0.0;  // impact speed v > 0 [m/s]
  CollisionEnd end = CollisionEnd::delayed_recovery;
  double tolerance = SolveOptions{}.tolerance;  // accuracy of each solve
  Method method = SolveOptions{}.method;
  // true: ζ from the certified fast table (restitution/fast.hpp, |Δε| <= 1e-13 min(ε, 1 − ε), every ε in
  // (0, 1)) instead of root finding with the solver; tolerance and method are then unused and no collision
  // is integrated. Viscoelastic Hertz only.
  bool fast = false;
  std::optional<double> k;  // ρ/m_eff [s^-2 m^-1/2] of a material (ElasticConstants::k): gives A
};

// beta, characteristic_velocity_m_s and dissipative_constant_s belong to viscoelastic Hertz: 0 and empty
// for the other members, whose damping coefficient follows from ζ with ContactLaw::physical's scales.
struct Calibration {
  LawKind law = LawKind::viscoelastic_hertz;
  double zeta = 0.0;         // ζ of the natural form with ε(ζ) = eps at the requested end
  double parameter = 0.0;    // the law's labelled parameter (law_parameter): ζ, or r = ζ/2 (dash-pot)
  double beta = 0.0;         // β = ζ / v^{1/5} [s^{1/5} m^{-1/5}]
  double eps_at_zeta = 0.0;  // ε(ζ) re-solved at the root (fast: the table's), for the record
  double characteristic_velocity_m_s = 0.0;      // 1999 paper's g* = (C1 β)^{-5} [m/s]
  std::optional<double> dissipative_constant_s;  // A [s], when a material was given
  int solves = 0;                                // collisions integrated by the root finder
};

// ζ (natural form of `law`) at which ε(ζ) = eps for the given end, to a relative accuracy of about
// options.tolerance in ζ. Throws InvalidInput when eps is not in (0, 1) or lies below ε(kLargestCheckedZeta),
// outside the checked range. For a member whose naive end exists only below a critical ζ (Tsuji, the
// dash-pot) the naive end's root is sought below it (ε -> 0 there).
double zeta_for_eps(double eps, CollisionEnd end, const SolveOptions& options, CollisionSolver& solver,
                    int* solves = nullptr, LawKind law = LawKind::viscoelastic_hertz);

Calibration calibrate(const CalibrationRequest& request, CollisionSolver& solver);

// ζ of viscoelastic Hertz with ε(ζ) = eps from the certified fast table, inside the checked range: eps in
// (0, 1] (1 gives 0). Throws InvalidInput, in the words of every calibration path, when eps lies below
// ε(kLargestCheckedZeta) (fast::zeta_from_eps itself answers there with the large-ζ law).
double fast_zeta_for_eps(double eps, CollisionEnd end);

}  // namespace restitution
