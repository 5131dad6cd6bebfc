// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a code's printed lines give oblique impacts (`restitution dem --friction MU`, docs/dem.md, "Oblique
// impacts"): the lines' own normal and tangential numbers read as the code reads them (LAMMPS's pair
// granular, or fix wall/gran granular for a wall; LIGGGHTS's hertz/stiffness with `tangential history`;
// YADE's MindlinPhys), solved by src/oblique/ under the accuracy contract at the listed impact angles; how
// many steps per contact the code needs for a requested accuracy of e_t; and with a target e_t at a
// reference angle the tangential parameter that gives it, with the line that carries it. The CLI words it.
#include <optional>
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "oblique/oblique_accuracy.hpp"
#include "oblique/oblique_inverse.hpp"

namespace restitution::dem {

// The impact angles reported when none are asked for and the lines have friction.
inline const std::vector<double> kDefaultObliqueAngles{5.0, 15.0, 30.0, 45.0, 60.0, 80.0};

// What is asked of the lines' oblique impacts (the options of `dem` name each field).
struct ObliqueLinesRequest {
  std::vector<double> angles_deg;             // --angle; empty: kDefaultObliqueAngles when there is friction
  double et_accuracy = 1e-4;                  // --et-accuracy: the e_t accuracy the steps per contact are for
  std::optional<double> target_et;            // --target-et
  std::optional<double> reference_angle_deg;  // --reference-angle
  // --tangential: LAMMPS's tangential model of the printed line (mindlin NULL 1 MU by default), with
  // --tangential-stiffness k_t (N/m; N/m² for mindlin, whose stiffness is k_t a) and --tangential-damping
  // x_gamma_t (default 1: the tangential dash-pot as strong as the normal one).
  std::string tangential = "mindlin";
  std::optional<double> tangential_stiffness;
  std::optional<double> tangential_damping;
};

// The lines' oblique impacts at one speed (the reference speed of the lines).
struct ObliqueLines {
  Code code = kDefaultCode;      // whose lines: lammps, liggghts or yade
  std::string tangential_words;  // as the line has them, e.g. "mindlin NULL 1 0.3"
  oblique::ObliqueGeometry geometry;
  oblique::NormalForce normal;
  oblique::TangentialForce tangential;
  oblique::ObliqueOptions options;  // the end of the lines
  double speed_m_s = 0.0;
  double tolerance = 0.0;
  std::vector<double> angles_deg;
  std::vector<oblique::ContractedOblique> impacts;
  // Steps per contact for e_t within et_accuracy, and the step that gives it for the shortest contact.
  double et_accuracy = 0.0;
  double error_coefficient = 0.0;
  double steps_per_contact = 0.0;
  double timestep_s = 0.0;
  // The target e_t: the parameter found, the line carrying it, and the impacts of the new line.
  std::optional<oblique::TangentialInverseResult> inverse;
  double target_et = 0.0;
  double reference_angle_deg = 0.0;
  std::vector<std::string> inverse_lines;
  std::vector<oblique::ContractedOblique> inverse_impacts;
};

// Whether --tangential, --tangential-stiffness or --tangential-damping change the printed tangential model.
bool tangential_chosen(const ObliqueLinesRequest& o);
// Puts --tangential's model into the deck's LAMMPS line (the pair's pair_coeff or the wall's fix wall/gran,
// dem::set_granular_tangential) and its note, in place of the printed mindlin; nothing when none is chosen.
// mindlin without --tangential-stiffness keeps the printed k_t (the pair's NULL, the wall's number). Throws
// InvalidInput naming the option: not --code lammps, no --friction, linear_history without
// --tangential-stiffness, linear_nohistory with it, a stiffness not positive or a damping negative.
void apply_tangential_choice(Deck& deck, const ObliqueLinesRequest& o, double friction);

// Whether the request or the friction ask for oblique outputs; InvalidInput naming the options when the code
// has no oblique reader (--tangential: not LAMMPS) or they are out of range.
bool wants_oblique(const ObliqueLinesRequest& o, Code code, double friction);

// The pair's lines read by the code's reader (CodeEntry::oblique; pair granular: the pair's 8 G* for
// `mindlin NULL`, torque arm R - δ/2, the line of centres turning; LIGGGHTS: kn, kt, gamman, gammat,
// coefficientFriction, arms R - δ/2; YADE: yade_pair_oblique); none for a code without a reader, or for
// YADE's lines that are not modelled unless angles are asked for. And the wall's (LAMMPS's fix wall/gran
// granular: its E, its NULL, torque arm R). The tolerance is clamped into the oblique contract's range.
std::optional<ObliqueLines> pair_oblique(const Deck& deck, const Pair& pair, const ObliqueLinesRequest& o,
                                         double speed_m_s, double tolerance);
ObliqueLines wall_oblique(const Deck& deck, const Pair& contact, const ObliqueLinesRequest& o,
                          double speed_m_s, double tolerance);

// YADE 2023.02a's lines for `pair` (FrictMat, Ip2_FrictMat_FrictMat_MindlinPhys(betan),
// Law2_ScGeom_MindlinPhys_Mindlin): yade_mindlin over the Tsuji normal force with Ip2's kno, kso and betas =
// betan, the torque to ScGeom's contact point (R - δ/2) and getIncidentVel's contact-point velocity
// (oblique_contact.hpp). Only lines with betan are modelled (yade_lines_modelled): YADE 2024.02a's (en, vn)
// damp otherwise.
bool yade_lines_modelled(const Deck& deck);
ObliqueLines yade_pair_oblique(const Deck& deck, const Pair& pair, const ObliqueLinesRequest& o,
                               double speed_m_s, double tolerance);

}  // namespace restitution::dem
