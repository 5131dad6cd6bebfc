// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Runs LAMMPS (`lmp`) or LIGGGHTS (`liggghts`), also under an MPI launcher, on head-on collisions of pairs of
// spheres (of one or several atom types) fed the lines `restitution dem` makes, and reads back the ε each
// collision ends with. Used by the [[dem]] scene section (dem/code_comparison.hpp) and by the DEM integration
// tests (tests/dem/).
#include <string>
#include <vector>

#include "dem/check_deck.hpp"
#include "dem/deck.hpp"

namespace restitution::dem {

// The program that runs `code` (lmp or liggghts) found on PATH, or "" when it is not there. Throws
// InvalidInput for codes this runner cannot run.
std::string dem_program(Code code);

struct DemRun {
  std::vector<double> eps;    // per speed; NaN where the code printed none
  std::vector<double> gap_m;  // distance between the surfaces at the end (> 0: the collision is over)
  std::string output;         // the program's output, for diagnostics
  std::string failure;        // "" when the code exited 0 and printed every ε; else what went wrong
  bool exited_ok = false;     // the code exited with status 0 (it may still have missed some ε)
};

// One deck with a pair of touching spheres per speed [m/s] (20 radii apart), closing along x, time step
// T / steps_per_time with T = k^{-2/5} v_max^{-1/5} the natural time of the fastest collision, run for five
// natural times of the slowest.
DemRun run_dem_code(const std::string& program, const Deck& deck, const Pair& pair,
                    const std::vector<double>& speeds, int steps_per_time);

// Several atom types: the first pass of the check deck of `request` (every type pair at every speed, a row
// each, pair by pair and speed by speed; dem/check_deck_codes.hpp) at n = steps_per_time, printing "EPS row
// eps gap" per row. `program` is the code's executable (one argument, run without a shell); `launcher` goes
// before it (an MPI launcher: {"mpirun", "-np", "2"}); `processors` is LAMMPS' processor grid set before the
// box ("2 1 1": the first sphere of every row, at x < 0, on rank 0, the second on rank 1), "" for none;
// `after_run` is appended to the deck (e.g. a write_dump).
struct PassOptions {
  int steps_per_time = 2000;
  std::string processors;
  std::string after_run;
  std::vector<std::string> launcher;
};
DemRun run_type_pairs(const std::string& program, const CheckDeckRequest& request,
                      const PassOptions& options);

// ε by Richardson extrapolation of two runs at T/n and T/(10 n): both codes use velocity-Verlet, first order
// in the time step for this velocity-dependent force.
struct DemMeasurement {
  std::vector<double> coarse, fine, extrapolated;
  std::vector<double> gap_m;  // of the fine run
  std::string output;         // of the fine run
  std::string failure;        // "" when both runs succeeded (DemRun::failure), else the first failure
  bool exited_ok = false;     // both runs exited with status 0
};
// The extrapolation of a coarse and a fine run (dt ten times smaller), for any code run this way.
DemMeasurement richardson(const DemRun& coarse, const DemRun& fine);
DemMeasurement measure_dem_eps(const std::string& program, const Deck& deck, const Pair& pair,
                               const std::vector<double>& speeds, int coarse_steps_per_time = 2000);
// run_type_pairs at options.steps_per_time and ten times that, extrapolated.
DemMeasurement measure_type_pairs(const std::string& program, const CheckDeckRequest& request,
                                  const PassOptions& options);

}  // namespace restitution::dem
