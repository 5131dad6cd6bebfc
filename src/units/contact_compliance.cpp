// SPDX-License-Identifier: BSD-3-Clause
#include "units/contact_compliance.hpp"

namespace restitution {

double normal_compliance_per_pa(double young_modulus_pa, double poisson_ratio) {
  return (1.0 - poisson_ratio * poisson_ratio) / young_modulus_pa;
}

double shear_compliance_per_pa(double young_modulus_pa, double poisson_ratio) {
  return 2.0 * (2.0 - poisson_ratio) * (1.0 + poisson_ratio) / young_modulus_pa;
}

}  // namespace restitution
