// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The vocabulary of a solve, shared by the collision solver (collision_solver.hpp), its engines and every
// front end: the methods, the options of a solve, its results at the ends of the collision and its
// statistics, and their names in text.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"

namespace restitution {

// bdf, adams: CVODE; taylor: the Taylor-series engine (taylor/taylor_engine.hpp); automatic: CVODE,
// BDF or Adams per regime.
enum class Method { bdf, adams, automatic, taylor };
inline constexpr std::array<Method, 4> kMethods{Method::bdf, Method::adams, Method::automatic,
                                                Method::taylor};
const char* method_name(Method method);            // "bdf" | "adams" | "auto" | "taylor"
Method method_from_name(const std::string& name);  // the inverse; throws InvalidInput naming the value
// Every method's name, in the order of kMethods (the choices of a front end's method option).
const std::vector<std::string>& method_names();
// "a, b or c": a list of choices (names of methods, ends, ...) as messages and --help give it.
std::string alternatives(const std::vector<std::string>& names);

// The ends of the collision (CollisionEnd, EndSet, PerEnd) are defined in contact_law.hpp, next to the law
// that decides where they lie. Their names in text:
const char* end_name(CollisionEnd end);               // "naive" | "delayed-recovery"
CollisionEnd end_from_name(const std::string& name);  // throws InvalidInput naming the value
const std::vector<std::string>& end_names();          // "naive", "delayed-recovery"
// A set of ends by name: an end's name, or "both" (kBothEnds) for EndSet::both().
inline constexpr const char* kBothEnds = "both";
EndSet end_set_from_name(const std::string& name);  // throws InvalidInput naming the value
const std::vector<std::string>& end_set_names();    // end_names() and "both"
// The end as an identifier, for JSON keys and CSV column prefixes: "naive" | "delayed_recovery".
const char* end_key(CollisionEnd end);

// The accuracy every study, command, scene and Python call defaults to (the command line's --tolerance).
inline constexpr double kDefaultTolerance = 1e-10;

struct SolveOptions {
  // Accuracy the caller gets: |ε - ε_exact| <= tolerance · min(ε, 1 - ε) for every reported end.
  double tolerance = kDefaultTolerance;
  Method method = Method::automatic;
  EndSet ends = EndSet::both();
  bool keep_trajectory = false;  // record (τ, x, x', x'') at every internal step and at every event
  // Laws with ContactLaw::smoothing_root() q > 1: integrate in u = x^{1/q} near x = 0, where the solution
  // is analytic in u but not in τ (docs/design.md §4). false integrates in τ throughout, for comparison.
  bool smooth_ends = true;
  // Most internal CVODE steps per phase of the collision; beyond it the solve fails with CVODE's "too much
  // work" (flag -1). The default never binds on the collisions of this project (at most a few thousand
  // steps); a smaller limit bounds the work spent on a hard point. Must be >= 1.
  long max_steps_per_phase = 1000000;
};

// Tolerances (relative accuracy of ε): the project accepts requests in [kSmallestTolerance,
// kMaxTolerance]; the CVODE engine delivers down to kMinTolerance and refuses smaller ones with a message
// saying so. check_solve_options (src/solver/solve_options.cpp) is the one place that applies them.
inline constexpr double kSmallestTolerance = 1e-14;
inline constexpr double kMinTolerance = 1e-11;
inline constexpr double kMaxTolerance = 1e-2;
// All times and lengths below are in the natural scaling (x'(0) = 1) whatever form the law was given in.
struct EndResult {
  double eps = 0.0;                // ε = -x'(τ_c)/x'(0)
  double one_minus_eps = 0.0;      // 1 - ε, computed without cancellation as ε -> 1
  double tau = 0.0;                // τ_c, duration of the collision
  double x = 0.0;                  // compression at the end (0 at the naive end)
  double velocity = 0.0;           // x'(τ_c) as integrated (-ε up to the choice of the accurate form)
  double dissipated_energy = 0.0;  // D(τ_c) in natural units, where the initial kinetic energy is 1/2
};

struct MaxCompression {
  double tau = 0.0;
  double x = 0.0;
};

struct SolverStats {
  long steps = 0;
  long rhs_evaluations = 0;
  long jacobian_evaluations = 0;
  long root_evaluations = 0;
  long error_test_failures = 0;
  long convergence_failures = 0;
};

// Adds every counter of `more` to `total` (phases of one solve, solves of a scene).
SolverStats& operator+=(SolverStats& total, const SolverStats& more);

struct TrajectoryPoint {
  double tau, x, velocity, acceleration;  // natural scaling
};

struct CollisionResult {
  LawKind law = LawKind::viscoelastic_hertz;
  double parameter = 0.0;  // ζ, or the damping ratio r = ζ/2 for the linear dash-pot
  // ε does not depend on the impact speed for this law (speed_exponent(law) == 0: Tsuji, the dash-pot).
  bool speed_independent = false;
  double tolerance = 0.0;
  // The method actually used (never automatic); auto's naive end at ζ >= 5 reports bdf, which takes over
  // from adams at the delayed-recovery end (docs/accuracy.md).
  Method method = Method::bdf;
  MaxCompression max_compression;
  SolverStats stats;
  std::vector<TrajectoryPoint> trajectory;  // empty unless SolveOptions::keep_trajectory

  // The result at one end: empty when the end was not requested (or does not exist for the law).
  [[nodiscard]] const std::optional<EndResult>& operator[](CollisionEnd end) const { return ends_[end]; }
  [[nodiscard]] std::optional<EndResult>& operator[](CollisionEnd end) { return ends_[end]; }

 private:
  PerEnd<std::optional<EndResult>> ends_;
};

// The requested end of a solve; throws NumericalFailure if the solve did not produce it.
const EndResult& end_of(const CollisionResult& result, CollisionEnd end);

}  // namespace restitution
