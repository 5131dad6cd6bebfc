// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The ε a DEM code's integrator makes of the viscoelastic Hertz law at a finite time step: a head-on
// collision integrated as LAMMPS's `fix nve/sphere` (and LIGGGHTS's) does it, velocity-Verlet with the pair
// force taken at the positions of the new step and the half-step velocity, the force clamped at zero at the
// delayed-recovery end (`limit_damping`). In the natural form x'' + ζ x^{1/2} x' + x^{3/2} = 0 the scheme is
// the same at every speed and size: only the step in natural time, h = dt / T, and ζ matter.
//
// Where the contact starts between two steps depends on where the spheres were (the phase of the first
// overlapping step): a gas samples every phase, so the error is reported as its mean over phases (what a gas
// averages) and its worst phase.
#include <vector>

#include "dem/deck.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::dem {

// Phases sampled, evenly spaced in [0, 1).
inline constexpr int kIntegratorPhases = 16;

// ε of one collision at ζ >= 0, natural step h in (0, 1], the first overlapping step `phase` in [0, 1) of a
// step past the touching point (0: the spheres touch exactly at a step).
double verlet_eps(double zeta, CollisionEnd end, double step, double phase);

struct IntegratorError {
  double velocity_m_s = 0.0;
  double contact_duration_s = 0.0;  // of the law itself (the solver), at `end`
  double eps_law = 0.0;             // the law's ε at this speed (the solver)
  double mean_error = 0.0;          // mean over phases of ε_integrator - ε_law
  double worst_error = 0.0;         // the phase with the largest |ε_integrator - ε_law| (signed)
};

// The law's contact duration [s] of `pair` with A [s] at impact speed v [m/s], at `end` (the solver).
double contact_duration_s(const Pair& pair, double dissipative_constant_s, CollisionEnd end,
                          double velocity_m_s, double tolerance, CollisionSolver& solver);

// The pair of `pair`'s material with dissipative constant A [s] at impact speed v [m/s] integrated at time
// step dt [s]. Throws InvalidInput naming --timestep unless dt > 0 and at most a fifth of the contact
// duration.
IntegratorError integrator_error(const Pair& pair, double dissipative_constant_s, CollisionEnd end,
                                 double velocity_m_s, double time_step_s, double tolerance,
                                 CollisionSolver& solver);

// The largest dt [s] whose worst-phase |Δε| at impact speed v stays at or below `max_eps_error` in
// [1e-7, 0.1] (InvalidInput naming --max-eps-error otherwise), to 1 %.
double largest_time_step_s(const Pair& pair, double dissipative_constant_s, CollisionEnd end,
                           double velocity_m_s, double max_eps_error, double tolerance,
                           CollisionSolver& solver);

}  // namespace restitution::dem
