// SPDX-License-Identifier: BSD-3-Clause
#include "adhesion/sjkr_branch.hpp"

namespace restitution::adhesion {

double sjkr_force(const SjkrRadii& radii, double u) {
  const double overlap = u * u;
  const double sum = radii.first + radii.second;
  const double gap = sum - overlap;
  // Written as products so that no difference of nearly equal numbers appears at small overlap.
  const double area_ratio = (2.0 * sum - overlap) * (2.0 * radii.first - overlap) *
                            (2.0 * radii.second - overlap) / (8.0 * radii.effective * gap * gap);
  return overlap * (u - area_ratio);
}

double sjkr_potential(const SjkrRadii& radii, double u) {
  const double overlap = u * u;
  const double sum = radii.first + radii.second;
  const double cohesive_work = overlap * overlap / (8.0 * radii.effective) *
                               (sum * (4.0 * radii.effective - overlap) / (sum - overlap) - overlap / 3.0);
  return 0.4 * overlap * overlap * u - cohesive_work;
}

}  // namespace restitution::adhesion
