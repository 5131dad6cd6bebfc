// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The DEM codes restitution writes lines for, one entry each (docs/design.md, "DEM codes"): the name, whether
// the code clamps the attractive force, its program and version query, and what it supports (several atom
// types, a check deck, runs in a scene), with the writer and reader behind each. Every name list in help
// texts, messages and the scene parser comes from this table.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace restitution::dem {

enum class Code { lammps, liggghts, mercurydpm, yade, chrono };
// The code a request means until it names one (the first of the table).
inline constexpr Code kDefaultCode = Code::lammps;

struct Deck;
struct Pair;
struct TypePairLines;
struct CheckDeckRequest;

// The elastic and dissipative coefficients K [N m^-3/2], D [N s m^-3/2] of m_eff ξ'' = -K ξ^{3/2} - D sqrt(ξ)
// ξ': what a code's parameters give a pair, read as the code reads them.
struct Coefficients {
  double elastic = 0.0;
  double damping = 0.0;
};

// The constant-eps companion of a code's law lines (`dem --constant-eps`, `gas --deck`): the code's own
// speed-independent damping given the law's eps at the calibration speed
// (damping_check/constant_eps_lines.hpp, gas_deck/lammps_gas_deck.cpp).
enum class Companion { none, damping_tsuji, model_hertz };

// Which reader of src/dem/oblique_lines.hpp gives the oblique impacts of the code's lines with friction:
// the code's own normal and tangential contact, read from the deck the writer made.
enum class ObliqueReader { none, lammps_granular, liggghts_history, yade_mindlin };

struct CodeEntry {
  Code code;
  const char* name;           // --code, a scene's `code`, the JSON "code"
  const char* title;          // the code as prose names it: "LAMMPS"
  bool always_clamps;         // the code always clamps the normal force at zero: delayed-recovery end only
  const char* comment;        // how the code's input comments a line: "#" or "//"
  const char* program;        // the program that runs its input; "" for a C++ library
  const char* version_query;  // the command naming the installed version the lines are for; "": any version
  bool eps_conversion;        // the code turns a measured (en, vn) into A itself: report what it makes of ε
  // A [[dem]] scene section runs the program on the lines: a LAMMPS-family input (dem/code_runner.hpp).
  bool scene_runs;
  // The lines and parameters giving `pair` the law with A [s], YADE's vn [m/s], Coulomb mu [1]
  // (dem/deck_<code>.hpp).
  void (*write)(Deck& deck, const Pair& pair, double dissipative_constant_s, double reference_velocity_m_s,
                double friction);
  // What the deck's parameters give `other`, a pair of the deck's material.
  Coefficients (*read)(const Deck& deck, const Pair& other);
  // Several atom types: the lines from every type pair's own deck (pairs I <= J of `n` types); nullptr:
  // one radius only, for the reason `one_radius_only`.
  std::vector<std::string> (*polydisperse)(const std::vector<TypePairLines>& pairs, std::size_t n);
  const char* one_radius_only;    // why several atom types are refused (nullptr when they are not)
  const char* polydisperse_note;  // how the code reads the per-type-pair lines
  // The check deck at n coarse steps per natural time (dem/check_deck_codes.hpp); nullptr: none.
  std::string (*check_deck)(const CheckDeckRequest& request, int n);
  const char* check_deck_run;  // the command before the deck's path
  // What the deck's file name must end with for the code to run it ("" when any name does): YADE 2023.02a
  // runs `yade -n -x FILE` as a Python script only when FILE ends in .py; any other name runs nothing and
  // exits 0, which reads like a check that passed.
  const char* check_deck_suffix = "";
  int check_deck_steps;             // the default n
  std::size_t max_deck_collisions;  // type pairs x speeds in one deck
  // A sphere on a wall (dem/wall_lines.hpp): the lines giving `contact` (E*, R* = R, m_eff = m; G* [Pa] of
  // Mindlin's k_t = 8 G* a) the law with A [s] and Coulomb mu [1] in the code's wall convention; nullptr: not
  // supported, for the reason `wall`.
  void (*write_wall)(Deck& deck, const Pair& contact, double effective_shear_modulus_pa,
                     double dissipative_constant_s, double friction);
  const char* wall;  // the code's wall convention against its pair convention, in words
  // A LAMMPS-family check deck's atom style and ghost-velocity lines; nullptr for the other codes.
  const char* check_deck_atom_style;
  // Its input evaluates $(...) in place (LAMMPS); otherwise values go through equal-style variables.
  bool immediate_variables;
  // Its integrator is velocity-Verlet, whose eps error at a time step `--timestep` and `--max-eps-error`
  // report (dem/integrator_eps.hpp).
  bool velocity_verlet;
  bool gas_deck;  // `gas --deck` writes its input (a data file and a log-spaced schedule)
  Companion companion;
  const char* companion_words;  // the companion as its header names it; nullptr with none
  // Oblique impacts (`--friction`, `--angle`): the reader (the cap rule is the tangential model's row), the
  // coarse steps per shortest contact of the check deck's oblique pass (0: none), and why --tangential or
  // --target-et/--reference-angle are refused (nullptr: taken).
  ObliqueReader oblique;
  int oblique_check_steps;
  const char* tangential_refusal;
  const char* inverse_refusal;
};

// Every code, in the order of the help texts.
const std::vector<CodeEntry>& dem_codes();
const CodeEntry& code_entry(Code code);

// A name of the table; throws InvalidInput naming the code and the table's names otherwise.
Code code_from_name(std::string_view name);
const char* code_name(Code code);
bool always_clamps(Code code);

// The names of the codes `keep` accepts (all when nullptr), for CLI11's IsMember.
std::vector<std::string> code_names(bool (*keep)(const CodeEntry&) = nullptr);
// The same names as text: "a, b, c" joined by ", " and `last` before the last ("a, b or c" with " or ").
std::string code_list(std::string_view last, bool (*keep)(const CodeEntry&) = nullptr);

}  // namespace restitution::dem
