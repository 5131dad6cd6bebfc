// SPDX-License-Identifier: BSD-3-Clause
#include "adhesion/adhesive_study.hpp"

namespace restitution {

AdhesiveStudy study_adhesive_contact(const AdhesiveContact& contact, const std::vector<double>& speeds_m_s,
                                     double tolerance) {
  AdhesiveStudy study;
  study.elastic_hysteresis_work_j = elastic_hysteresis_work_j(contact);
  study.break_overlap_m = break_overlap_m(contact);
  for (const double v : speeds_m_s) {
    study.collisions.push_back(solve_adhesive(contact, v, tolerance));
    if (study.collisions.back().outcome == AdhesiveOutcome::stuck) ++study.stuck;
  }
  study.sticking = sticking_speed(contact, tolerance);
  return study;
}

}  // namespace restitution
