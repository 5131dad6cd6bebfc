// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A complete LAMMPS (or LIGGGHTS) input for the freely cooling gas of N equal spheres at packing fraction φ
// in a periodic cube (docs/gas.md, "The LAMMPS deck"): a data file of the initial state
// (gas_deck/placement.hpp), the law's lines with their prerequisites, a time step that keeps the ε error of
// LAMMPS's integrator below a bound at the fast end of the impact speeds and grows with the cooling as the
// contact duration does, the temperature printed on a log-spaced schedule of times, and the same gas with the
// constant-ε companion lines (the recipe whose ε at the calibration speed is the law's) for Haff's law.
// LIGGGHTS 3.8.0 reads the same data file; its law is `hertz/stiffness` (dem/deck_liggghts.hpp), its
// companion `model hertz` with the coefficientRestitution that gives the law's ε at the calibration speed
// (damping-check's liggghts-hertz recipe), and, lacking LAMMPS's immediate variables $(...), the schedule
// uses equal-style ones.
//
// Each input prints one line per scheduled time, read back by `restitution gas --compare`:
//   restitution-gas law=viscoelastic time_s=... temperature_j=... timestep_s=... step=...
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dem/lines_check.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::gas_deck {

inline constexpr std::string_view kGasTag = "restitution-gas";
// The fast end of the impact speeds: this many times the rms relative speed sqrt(6 T / m) (a fraction 2e-5
// of the collisions of a Maxwellian gas is faster).
inline constexpr double kFastSpeedFactor = 3.0;

// The most spheres a deck holds. The deck is built in memory before it is written: for 1e6 spheres the data
// file is 161 MB, and writing it took 6.2 s of CPU at a peak of 400 MB of memory, so 1e7 spheres take about
// a minute, 4 GB of memory and a 1.6 GB data file that LAMMPS's rank 0 reads alone. More is refused rather
// than left to run for many minutes towards a file of tens of GB.
inline constexpr std::size_t kMaxParticles = 10'000'000;
// The data file's size per sphere, measured (bytes of STEM.data / N: 159.8 for N = 1e5 and 160.8 for N = 1e6,
// issue 35's gas): an Atoms and a Velocities line, each number in the shortest form that reads back the same.
inline constexpr std::size_t kDataBytesPerSphere = 160;

// The driven gas's deck (issue 49, docs/gas.md "The driven gas"): LAMMPS's `fix langevin` on the translation,
// its moments printed on a line of their own at each scheduled time:
//   restitution-driven law=... time_s=... mean_v2_m2_s2=... mean_v4_m4_s4=...
// after one line restitution-driven-setup bath_temperature_j=... bath_time_s=... steady_from_s=...
inline constexpr std::string_view kDrivenTag = "restitution-driven";
inline constexpr std::string_view kDrivenSetupTag = "restitution-driven-setup";
// Boltzmann's constant as LAMMPS 20220106 holds it under `units si` (src/update.cpp): fix langevin reads T_b
// in K and multiplies it by this.
inline constexpr double kLammpsBoltzmannJK = 1.3806504e-23;
// The steady part is sampled this many times per relaxation time.
inline constexpr int kSteadySamplesPerRelaxation = 4;

struct DeckBath {
  double temperature_j = 0.0;      // T_b [J]
  double time_s = 0.0;             // τ_b, fix langevin's damp [s]
  double relaxation_time_s = 0.0;  // of the theory's steady state: the spacing of the steady samples
  std::uint64_t seed = 1;          // of fix langevin's random numbers
};

struct GasDeckRequest {
  dem::Code code = dem::kDefaultCode;  // lammps or liggghts
  Material material;                   // one radius (radius1 = radius2) and the density
  dem::DampingSource damping;  // A, or ε at a speed (also the constant-ε companion's calibration speed)
  CollisionEnd end = CollisionEnd::delayed_recovery;
  std::size_t particles = 2000;
  double packing_fraction = 0.1;
  double rms_speed_m_s = 1.0;  // initial, per direction: T0 = m rms^2
  double duration_s = 0.0;     // simulated time; 0: `haff_times` τ0 of the companion
  double haff_times = 30.0;
  double max_eps_error = 1e-3;  // bound on the worst-phase |Δε| at the fast end of the impact speeds
  int points_per_decade = 10;   // of the log-spaced temperature schedule
  std::uint64_t seed = 1;
  double tolerance = kDefaultTolerance;
  // A Langevin bath (the driven gas): the run relaxes over 10 relaxation times (at most half of the duration;
  // log-spaced prints) and is sampled in the rest, its steady part (kSteadySamplesPerRelaxation prints per
  // relaxation time).
  std::optional<DeckBath> bath;
};

struct GasDeck {
  std::string data;                // the LAMMPS data file (atom_style sphere)
  std::string law_input;           // the viscoelastic gas; reads the data file by `data_file_name`
  std::string constant_eps_input;  // the same gas, constant-ε companion lines
  double dissipative_constant_s = 0.0;
  double box_m = 0.0;
  double diameter_m = 0.0, mass_kg = 0.0;
  double initial_temperature_j = 0.0;
  double constant_eps = 0.0;  // the companion's ε (the law's at the calibration speed)
  double calibration_speed_m_s = 0.0;
  double haff_time_s = 0.0;  // τ0 of the companion at T0 (Enskog–Maxwell)
  double duration_s = 0.0;
  double fast_speed_m_s = 0.0;   // at T0
  double time_step_s = 0.0;      // at T0; dt = time_step_s (T0 / T)^{1/10} afterwards
  double eps_error_worst = 0.0;  // the largest worst-phase |Δε| at the fast end, over T0 .. T0 1e-6
  double shear_critical_length_m = 0.0;
  double shear_mode_growth = 1.0;  // of the companion's longest shear mode over the duration
  std::vector<double> print_times_s;
  double steady_from_s = 0.0;         // the driven gas: the first time of the steady part
  std::vector<std::string> warnings;  // e.g. the constant-ε gas will cluster
};

// Throws InvalidInput naming the option for a bad request (two radii, N outside [2, kMaxParticles], φ out of
// range, ...).
GasDeck lammps_gas_deck(const GasDeckRequest& request, const std::string& data_file_name);

// How to run an input `path` (with the data file next to it) with `code`, on `ranks` MPI ranks (1: no
// mpirun).
std::string gas_deck_command(dem::Code code, const std::string& path, int ranks);

}  // namespace restitution::gas_deck
