// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The accuracy contract of the oblique outputs (docs/oblique.md, "Accuracy and cost"): for a requested
// tolerance T the reported ε and e_t are within T absolute, the rebound angle within T radians, and each
// spin within T times max(|ω'|, v/R) (v the impact speed, R that sphere's radius: the spin a slip of v
// gives), against the exact solution of the model. It is met by CVODE's relative tolerance
// T·kObliqueRtolFactor, and checked where a solve's stick/slip sequence is near changing or its e_t divides
// by a small slip (kCheckMargin, kCheckSlip): the impact is solved again at 10× that rtol, and when the
// two find different stick/slip sequences, or disagree by more than T in the contract's measure while a third
// solve at a tenth of the rtol does not agree with the first within T, the outcome is reported as
// ill-conditioned (near the stick/slip boundary a switch function can touch 0 without crossing it, and a
// perturbation of the size of the error changes which modes follow) instead of silently.
// An impact that slides on the Coulomb cap (ObliqueResult::slides_on_cap: LIGGGHTS's and YADE's rule) is
// reported too, as not modelled, whatever the solves find.
#include <string>

#include "oblique_contact.hpp"  // beside it: the Python module includes this through restitution_oblique/

namespace restitution::oblique {

// The accepted tolerances: below 1e-10 the independent reference (tests/oblique_reference.hpp) no longer
// checks the outputs with a margin (it agrees with itself at two step sizes to about 1e-12), and from 1e-2
// on CVODE's rtol (1e-4) no longer resolves the short stick phases of near-head-on impacts.
inline constexpr double kSmallestObliqueTolerance = 1e-10;
inline constexpr double kLargestObliqueTolerance = 1e-2;  // excluded
// CVODE's rtol per unit of T: measured against the reference, the outputs' error is at most about 6× rtol
// (rtol 1e-10: e_t within 6e-10; rtol 1e-8: 5e-8), so rtol = T/100 leaves a margin of about 16.
inline constexpr double kObliqueRtolFactor = 1e-3;

// A switch function that comes back within this fraction of the size of its terms without crossing 0 (seen at
// CVODE's step ends: ObliqueResult::closest_switch_approach) nearly switched. Measured across the boundary
// near 18.2° of tests/test_oblique_accuracy.cpp: a solve that missed a real short stick phase by 1.3e-7 in
// e_t came within 5.3e-6; impacts away from every boundary stay beyond 9.8e-5.
inline constexpr double kNearSwitch = 5e-5;

// The check is skipped where the solve's stick/slip sequence keeps this margin (ObliqueResult::switch_margin)
// and the slip at impact is at least kCheckSlip of the largest of the normal, tangential and slip speeds:
// the impacts the check flagged came within 9.4e-3 (a short phase one solve resolves and the other does not),
// and e_t = -s'/s amplifies the error of s' by 1/s, measured to need the check below 2e-3.
inline constexpr double kCheckMargin = 3e-2;
inline constexpr double kCheckSlip = 5e-2;

struct ContractedOblique {
  ObliqueResult result;             // the solve at rtol = T·kObliqueRtolFactor
  double tolerance = 0.0;           // T
  double relative_tolerance = 0.0;  // CVODE's rtol of `result`
  // The largest difference of the contract's outputs between `result` and the solve at 10× its rtol, each
  // over its bound (so <= 1 where the outputs are well conditioned).
  double check_ratio = 0.0;  // 0 where not checked
  bool checked = false;      // whether the check ran (see kCheckMargin)
  bool ill_conditioned = false;
  std::string conditioning;  // "well-conditioned", or what was found, in words
};

// where_needed: the check runs where the solve could be wrong (kCheckMargin, kCheckSlip); always: on every
// solve (what the skipped impacts are tested against).
enum class ObliqueCheck { where_needed, always };

// Throws InvalidInput naming T outside [kSmallestObliqueTolerance, kLargestObliqueTolerance) and whatever
// solve_oblique refuses; `options.relative_tolerance` is ignored (set from T).
ContractedOblique solve_oblique_within(const ObliqueGeometry& geometry, const NormalForce& normal,
                                       const TangentialForce& tangential, const ImpactVelocity& impact,
                                       double tolerance, const ObliqueOptions& options = {},
                                       ObliqueCheck check = ObliqueCheck::where_needed);

// Throws InvalidInput unless T is in [kSmallestObliqueTolerance, kLargestObliqueTolerance); `name` is how the
// caller spells it (an option, a keyword).
void require_oblique_tolerance(double tolerance, const char* name);

}  // namespace restitution::oblique
