// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A check deck (docs/dem.md, "Check the lines in one command"): a complete input for a DEM code that pastes
// the lines `restitution dem` prints unchanged, collides every type pair head-on at every speed, measures ε
// in the code itself from the separation velocity after the contact ends, and prints one check line per type
// pair and speed. Each collision runs twice, at dt = T/n and T/(10 n) (T = k^{-2/5} v^{-1/5}, the natural
// time; the codes' integrators are first order in dt for this velocity-dependent force), and the line gives
// both raw ε and their Richardson extrapolation:
//
//   restitution-check code=lammps types=1,1 speed=1 eps_10dt=... eps_dt=... eps_code=... eps_restitution=...
//   rel_diff=... gap_m=...
//
// (one line). eps_code = (10 eps_dt - eps_10dt) / 9, rel_diff = (eps_code - eps_restitution) /
// eps_restitution, gap_m the distance between the surfaces at the end of the fine run (> 0: the contact is
// over). Runnable here: LAMMPS (`lmp -in FILE`), LIGGGHTS (`liggghts -in FILE`), YADE (`yade -n -x FILE`).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "dem/deck.hpp"

namespace restitution::dem {

// The tag every check line starts with.
inline constexpr std::string_view kCheckTag = "restitution-check";

// One type pair the deck collides: its atom types (1-based; YADE ignores them), its two spheres, and the ε
// restitution states the lines give it, one per speed of the deck.
struct CheckPair {
  int type1 = 1;
  int type2 = 1;
  Pair pair;
  std::vector<double> eps_restitution;
};

struct CheckDeckRequest {
  Code code = kDefaultCode;
  std::vector<std::string> lines;     // as `restitution dem` prints them, pasted unchanged
  std::vector<std::string> comments;  // written at the top of the deck (what made it), one per line
  int type_count = 1;                 // atom types the lines define (LAMMPS, LIGGGHTS)
  std::vector<CheckPair> pairs;
  std::vector<double> speeds_m_s;
  // n of the coarse dt = T/n; 0: the default of the code (LAMMPS, LIGGGHTS 2000; YADE 5000, whose Tsuji-type
  // damping converges more slowly in dt).
  int steps_per_time = 0;
  std::string yade_version;  // YADE: the version the lines are for; the deck warns when another one runs it
};

// The most collisions (type pairs × speeds) a check deck holds. LAMMPS and LIGGGHTS run every collision in
// one system at one dt, about 3e7 sphere-steps a second on one core: 500 collisions take seconds when the
// collisions last about as long as each other and a minute or more when they differ tenfold (radii 1 to
// 10 mm, speeds 0.1 to 10 m/s; kMaxDeckSphereSteps bounds that). YADE runs each collision as its own scene,
// about 2 s each.
inline constexpr std::size_t kMaxDeckCollisionsLammps = 500;
inline constexpr std::size_t kMaxDeckCollisionsYade = 30;
// LAMMPS and LIGGGHTS: the most sphere-steps (spheres × the steps of both passes) a deck may take, about
// three minutes on one core. The steps grow with how much longer the longest collision lasts than the
// shortest (T ∝ R v^{-1/5}): 17 classes of radii 1 to 10 mm at 0.1, 1 and 10 m/s take 2.2e9.
inline constexpr double kMaxDeckSphereSteps = 5e9;
std::size_t max_deck_collisions(Code code);
// The most atom types whose every pair I <= J fits in one deck at `speeds` speeds (of `collisions` at most).
std::size_t max_deck_types(Code code, std::size_t speeds);
std::size_t max_deck_types(std::size_t collisions, std::size_t speeds);
// InvalidInput naming the bound unless type_pairs × speeds <= max_deck_collisions(code) (and both > 0 are
// left to check_deck()).
void require_deck_size(Code code, std::size_t type_pairs, std::size_t speeds);

// False for MercuryDPM and Chrono: they are C++ libraries, not programs with an input file, and not packaged.
bool has_check_deck(Code code);
// InvalidInput saying why unless has_check_deck(code).
void require_check_deck(Code code);
// InvalidInput unless `path` ends with what the code needs to run it (CodeEntry::check_deck_suffix: ".py"
// for YADE), saying why and the name that works.
void require_check_deck_name(Code code, const std::string& path);
// How to run a deck written to `path`: "lmp -in PATH", "liggghts -in PATH", "yade -n -x PATH".
std::string check_deck_command(Code code, const std::string& path);

// The deck's text. Throws InvalidInput for a code without a check deck, no pairs or speeds, a pair whose
// eps_restitution does not have one value per speed, types outside 1..type_count, more collisions than
// max_deck_collisions or (LAMMPS, LIGGGHTS) more sphere-steps than kMaxDeckSphereSteps.
std::string check_deck(const CheckDeckRequest& request);

// One check line read back.
struct CheckLine {
  std::string code;
  int type1 = 0, type2 = 0;
  double speed_m_s = 0.0;
  double eps_10dt = 0.0, eps_dt = 0.0, eps_code = 0.0, eps_restitution = 0.0, rel_diff = 0.0, gap_m = 0.0;
};
// Every check line in a code's output, in order (the codes print banners and warnings too: only lines
// starting with kCheckTag count; a line missing a field reads as NaN there).
std::vector<CheckLine> read_check_lines(const std::string& output);

}  // namespace restitution::dem
