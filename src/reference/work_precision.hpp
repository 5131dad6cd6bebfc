// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Error against run time: every engine (CVODE BDF and Adams with and without the smooth formulation at the
// ends, the Taylor engine) on a fixed ζ set and tolerance ladder, both ends, measured against the reference
// solutions (data/reference_solutions.csv).
#include <functional>
#include <string>
#include <vector>

#include "reference/reference_solution.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution {

// Timed solves per point: at most this many (the command line's --repeats and a scene's repeats).
inline constexpr int kMaxWorkPrecisionRepeats = 100;

struct WorkPrecisionEngine {
  std::string name;  // "taylor", "bdf", "adams", "bdf-plain", "adams-plain"
  Method method;
  bool smooth_ends;  // SolveOptions::smooth_ends ("-plain": integrated in τ throughout)
};

std::vector<WorkPrecisionEngine> work_precision_engines();
bool is_work_precision_engine(const std::string& name);
std::string work_precision_engine_names();   // "taylor, bdf, adams, bdf-plain, adams-plain", for messages
std::vector<double> work_precision_zetas();  // 1e-4, 1e-3, ..., 1e4 (points of the reference grid)
std::vector<double> work_precision_tolerances();  // 1e-4, 1e-5, ..., 1e-13 (each engine: those it accepts)

struct WorkPrecisionRow {
  std::string engine;
  std::string end;  // "naive" | "delayed-recovery"
  double tolerance = 0, zeta = 0;
  double error = 0;           // max(|ε-ε*|, |(1-ε)-(1-ε*)|) / min(ε*, 1-ε*)
  double median_seconds = 0;  // per solve, median over the repeats
  long rhs_evaluations = 0, steps = 0;
};

// The reference row of ζ (matched to 1e-12 relative), or nullptr.
const ReferenceRow* reference_row_for(const std::vector<ReferenceRow>& reference, double zeta);
// The contract's error of a result against the reference: max(|ε-ε*|, |(1-ε)-(1-ε*)|) / min(ε*, 1-ε*),
// where |ε-ε*| does not count one spacing of doubles at ε* (near ε = 1 the double ε cannot resolve
// T·(1-ε); 1-ε carries the accuracy there); the absolute difference where min(ε*, 1-ε*) = 0 (ζ = 0).
double contract_error(const EndResult& result, const ReferenceEndValues& reference);
// The options of one work-precision point: one end only, so that its cost is measured alone.
SolveOptions work_precision_options(const WorkPrecisionEngine& engine, CollisionEnd end, double tolerance);

// Measures every (engine, end, tolerance, ζ) the engine accepts and the reference holds. Adams (a non-stiff
// method) is measured for ζ <= 100 only. Each point is solved once to warm up, then `repeats` times.
// `engines` names a subset of work_precision_engines() (empty: all); throws InvalidInput for an unknown name.
// `progress` (optional) is called with (done, total) after each (engine, end, tolerance) measured.
std::vector<WorkPrecisionRow> measure_work_precision(
    const std::vector<ReferenceRow>& reference, int repeats, const std::vector<std::string>& engines = {},
    const std::function<void(std::size_t done, std::size_t total)>& progress = {});

// The rows of one (engine, end, tolerance) over the ζ set: the worst error, the mean and the worst of the
// per-point median times.
struct WorkPrecisionGroup {
  std::string engine;
  std::string end;
  double tolerance = 0;
  double max_error = 0;
  double mean_median_seconds = 0, max_median_seconds = 0;
  int points = 0;
};

// Groups ordered by engine, end, then tolerance from the loosest to the tightest.
std::vector<WorkPrecisionGroup> group_work_precision(const std::vector<WorkPrecisionRow>& rows);

}  // namespace restitution
