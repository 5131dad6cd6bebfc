#pragma once
// Calibration: the damping constant β that gives a measured coefficient of restitution ε at an impact speed
// v, found by root finding on ζ = β v^{1/5} with the collision solver (ε decreases monotonically with ζ).
// With a material, also the dissipative constant A a DEM code needs; always the 1999 paper's g*.
#include <optional>

#include "restitution/collision_solver.hpp"
#include "restitution/units.hpp"

namespace restitution {

struct CalibrationRequest {
  double eps = 0.0;           // measured ε in (0, 1)
  double velocity_m_s = 0.0;  // impact speed v > 0 [m/s]
  CollisionEnd end = CollisionEnd::delayed_recovery;
  double tolerance = 1e-10;  // accuracy of each solve (SolveOptions::tolerance)
  Method method = Method::automatic;
  // true: ζ from the certified fast table (restitution/fast.hpp, |Δε| <= 1e-13 min(ε, 1 − ε), every ε in
  // (0, 1)) instead of root finding with the solver; tolerance and method are then unused and no collision
  // is integrated.
  bool fast = false;
  std::optional<double> k;  // ρ/m_eff [s^-2 m^-1/2] of a material (ElasticConstants::k): gives A
};

struct Calibration {
  double zeta = 0.0;         // ζ with ε(ζ) = eps at the requested end
  double beta = 0.0;         // β = ζ / v^{1/5} [s^{1/5} m^{-1/5}]
  double eps_at_zeta = 0.0;  // ε(ζ) re-solved at the root (fast: the table's), for the record
  double characteristic_velocity_m_s = 0.0;      // 1999 paper's g* = (C1 β)^{-5} [m/s]
  std::optional<double> dissipative_constant_s;  // A [s], when a material was given
  int solves = 0;                                // collisions integrated by the root finder
};

// ζ at which ε(ζ) = eps for the given end, to a relative accuracy of about options.tolerance in ζ.
// Throws InvalidInput when eps is not in (0, 1) or lies below ε(kLargestCheckedZeta), outside the checked
// range.
double zeta_for_eps(double eps, CollisionEnd end, const SolveOptions& options, CollisionSolver& solver,
                    int* solves = nullptr);

Calibration calibrate(const CalibrationRequest& request, CollisionSolver& solver);

}  // namespace restitution
