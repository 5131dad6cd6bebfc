// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the lines `restitution dem` prints give (docs/dem.md): A calibrated or given, the deck, the ε these
// lines give this pair at a few impact speeds and other sizes of the material, and, for YADE, what its own
// (en, vn) -> A conversion makes of the true ε. Also the [[dem]] scene section's comparison with the ε a DEM
// code measures when it runs the lines. Typed results; the command line words them.
#include <optional>
#include <vector>

#include "dem/code_runner.hpp"
#include "dem/deck.hpp"
#include "dem/deck_eps.hpp"
#include "dem/yade_versions.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/material.hpp"

namespace restitution::dem {

// A [s] of `material`'s law: the one given, or calibrated so that the law gives `eps` at `velocity_m_s`
// [m/s] at `end` (exactly one of the two; InvalidInput otherwise).
struct DampingSource {
  std::optional<double> dissipative_constant_s;
  std::optional<double> eps;
  std::optional<double> velocity_m_s;
};
double dissipative_constant(const Material& material, const DampingSource& source, CollisionEnd end,
                            double tolerance, Method method, CollisionSolver& solver);
// The same for a contact of k = ρ/m_eff [s^-2 m^-1/2] (a sphere on a wall).
double dissipative_constant(double k, const DampingSource& source, CollisionEnd end, double tolerance,
                            Method method, CollisionSolver& solver);

struct LinesRequest {
  Code code = kDefaultCode;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  Material material;
  DampingSource damping;
  std::vector<double> speeds_m_s;  // empty: v/10, v, 10 v with v the reference speed
  double tolerance = SolveOptions{}.tolerance;
  double friction = 0.0;  // Coulomb mu of the tangential model [1]
};

struct SpeedEps {
  double velocity_m_s = 0.0;
  double eps = 0.0;
};

// What YADE's own (en, vn) -> A conversion makes of the true ε at vn: the error a user typing the measured ε
// would get.
struct YadeCheck {
  double true_eps = 0.0;
  double dissipative_constant_s = 0.0;
  double eps_at_vn = 0.0;
};

struct LinesResult {
  Deck deck;
  double dissipative_constant_s = 0.0;
  double reference_velocity_m_s = 0.0;  // the calibration speed (YADE's vn); 1 m/s when A is given
  double friction = 0.0;
  std::vector<SpeedEps> eps;
  std::vector<SizeCheck> sizes;  // radii x0.5 and x2 at the reference speed
  std::optional<YadeCheck> yade;
  // YADE: the version the lines (and `eps`) are for, once damping_check::target_yade_version has set it; when
  // it cannot express the law (no vn), the deck that would give it on YADE 2024.02a or later, and that deck's
  // ε(v) there.
  std::optional<YadeVersion> yade_version;
  std::optional<Deck> yade_exact_deck;
  std::vector<SpeedEps> yade_exact_eps;
};

LinesResult check_lines(const LinesRequest& request);

// The [[dem]] scene section: ε(v) the lines give (restitution) and, when the code ran, what it measured.
struct CodeComparison {
  double dissipative_constant_s = 0.0;
  Deck deck;
  std::vector<double> predicted_eps;        // per speed, restitution's
  std::optional<DemMeasurement> measured;   // the code's, when it ran
  std::vector<double> relative_difference;  // (measured - predicted) / min(ε, 1 - ε), when it ran
};

// `program` empty: the code is not run (not installed, or not asked for).
CodeComparison compare_with_code(Code code, const Material& material, const DampingSource& damping,
                                 CollisionEnd end, const std::vector<double>& speeds_m_s, double friction,
                                 double tolerance, Method method, const std::string& program);

}  // namespace restitution::dem
