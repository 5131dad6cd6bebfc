// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem` for several atom types (docs/dem.md, "Polydisperse sets"): the per-type-pair lines that
// give every pair of types the exact law in LAMMPS (`pair_coeff I J`) and LIGGGHTS (`peratomtypepair`
// matrices), the ε each pair gets at a few speeds, and for a binned size range the worst ε error the
// binning causes. Typed results; the command line words them.
#include <optional>
#include <string>
#include <vector>

#include "dem/check_deck.hpp"
#include "dem/lines_check.hpp"
#include "dem/particle_types.hpp"

namespace restitution::dem {

// One pair of types I <= J (1-based) and what its lines give it.
struct TypePairLines {
  int type1 = 1, type2 = 1;
  Pair pair;          // E*, R_eff, m_eff of the pair (type_pair)
  Deck deck;          // the pair's single-pair deck: its parameters are the pair's matrix entries
  double beta = 0.0;  // β the code reads from those parameters for this pair [s^{1/5} m^{-1/5}]
  std::vector<SpeedEps> eps;
};

// The worst ε error of binning a size range: spheres of any radii inside the range get the coefficients of
// their classes' pair (the code still uses their true R_eff and m_eff), against the law for their radii.
struct BinningError {
  std::vector<double> edges_m;
  int grid_points_per_class = 0;      // radii per class, edges included
  double worst_abs_error = 0.0;       // max |ε_code − ε_law| over the grid and the speeds
  double worst_relative_error = 0.0;  // max |ε_code − ε_law| / min(ε_law, 1 − ε_law)
  double radius1_m = 0.0, radius2_m = 0.0, velocity_m_s = 0.0;  // where the relative maximum is
  double eps_code = 0.0, eps_law = 0.0;                         // there
};

// Where the pair of types (i, j) (0-based, either order) of n types is in PolydisperseResult::pairs.
std::size_t pair_index(std::size_t i, std::size_t j, std::size_t n);

struct PolydisperseRequest {
  Code code = kDefaultCode;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  std::vector<ParticleType> types;
  DampingSource damping;           // A given, or calibrated for the pair (1, 1)
  std::vector<double> speeds_m_s;  // empty: v/10, v, 10 v with v the reference speed
  double tolerance = SolveOptions{}.tolerance;
  double friction = 0.0;
  std::optional<SizeClasses> classes;  // the types are these classes of a size range: compute BinningError
};

struct PolydisperseResult {
  Code code = kDefaultCode;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  std::vector<ParticleType> types;
  double dissipative_constant_s = 0.0;
  bool calibrated = false;              // A calibrated for the pair (1, 1) from (eps, velocity)
  double reference_velocity_m_s = 0.0;  // the calibration speed; 1 m/s when A is given
  double friction = 0.0;
  std::vector<TypePairLines> pairs;  // (1,1), (1,2), ..., (1,N), (2,2), ...
  std::vector<std::string> lines;    // to paste into the code's input
  std::vector<std::string> notes;
  std::optional<BinningError> binning;
};

// Throws InvalidInput for a code whose entry has no polydisperse writer (dem/dem_codes.hpp), saying why.
PolydisperseResult polydisperse_lines(const PolydisperseRequest& request);

// The check deck (`dem --deck`) of the result: its lines, every type pair at every speed against its ε.
CheckDeckRequest check_deck_request(const PolydisperseResult& r);

}  // namespace restitution::dem
