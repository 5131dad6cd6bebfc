// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The inverse of the oblique solve: the tangential parameter of a LAMMPS model that gives a requested
// tangential restitution e_t at a reference impact angle (docs/oblique.md, "The inverse"): the stiffness k_t
// of linear_history (N/m) and mindlin (N/m², LAMMPS's number before `sqrt(R* δ)`), the damping factor γ_t of
// linear_nohistory (its only parameter below the cap). e_t is not monotonic in k_t (a sticking contact
// oscillates: Becker, Schwager & Pöschel), so the parameter is scanned on a log grid from 1e-6 to 1e3 times
// the contact's natural scale, the sign change of e_t - E nearest the natural scale bracketed, and the root
// found there (TOMS 748); the reachable range is the scan's.
#include "oblique/oblique_accuracy.hpp"
#include "oblique/oblique_contact.hpp"

namespace restitution::oblique {

struct TangentialInverseRequest {
  ObliqueGeometry geometry;
  NormalForce normal;
  // The model, its friction and the parameter that is not sought (γ_t for the history models; the
  // stiffness is ignored for linear_nohistory and replaced by the root otherwise).
  TangentialForce tangential;
  ImpactVelocity impact;    // the reference impact (angle = atan2(tangential, normal)), with its spins
  double target_et = 0.0;   // E, the requested e_t = -s'/s
  double tolerance = 1e-8;  // the root's e_t within T of E (the oblique contract, oblique_accuracy.hpp)
  ObliqueOptions options;   // the end of the collision
};

struct TangentialInverseResult {
  // The parameter found: k_t [N/m or N/m²] (history models) or γ_t [1] (linear_nohistory).
  double parameter = 0.0;
  const char* parameter_name = "";   // "tangential_stiffness" or "tangential_damping_factor"
  double lowest_reachable_et = 0.0;  // over the scan
  double highest_reachable_et = 0.0;
  int roots_in_scan = 0;  // sign changes of e_t - E over the scan (more than one: the one nearest the scale)
  ContractedOblique check;  // the impact solved again with the parameter, under the contract at T
};

// Throws InvalidInput naming what is wrong: E not finite or out of the scan's range (naming the range), no
// slip at the reference impact (e_t undefined), no friction, linear_nohistory without normal damping (then
// γ_t does nothing), a tolerance outside the contract; NumericalFailure if a solve fails.
TangentialInverseResult tangential_parameter_for(const TangentialInverseRequest& request);

}  // namespace restitution::oblique
