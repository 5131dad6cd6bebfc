// SPDX-License-Identifier: BSD-3-Clause
/* A DEM code's use of the exported header (restitution export c-header --out restitution_fast.h): the
 * dissipative constant A from one measured ε, then the ε of a contact at another impact speed.
 * Usage: dem_contact EPS V_MEASURED K V, speeds in m/s, k = ρ/m_eff in s^-2 m^-1/2 (`restitution calibrate`
 * prints it for a material). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "restitution_fast.h" /* cc -std=c99 dem.c -lm */

/* A [s] from ε measured at impact speed v_measured [m/s]; k = ρ/m_eff [s^-2 m^-1/2] */
double dissipative_constant(double eps_measured, double v_measured, double k) {
  double beta = restitution_zeta_from_eps_delayed_recovery(eps_measured) / pow(v_measured, 0.2);
  return beta / (1.5 * pow(k, 0.4));
}
/* ε of a contact at impact speed v [m/s]: ζ = β v^{1/5}, β = (3/2) A k^{2/5} */
double contact_eps(double A, double k, double v) {
  return restitution_eps_delayed_recovery(1.5 * A * pow(k, 0.4) * pow(v, 0.2));
}

int main(int argc, char** argv) {
  if (argc != 5) {
    fprintf(stderr, "usage: dem_contact EPS V_MEASURED K V\n");
    return 2;
  }
  const double k = atof(argv[3]);
  const double A = dissipative_constant(atof(argv[1]), atof(argv[2]), k);
  const double eps = contact_eps(A, k, atof(argv[4]));
  printf("%.17g %.17g\n", A, eps);
  return isnan(A) || isnan(eps) ? 1 : 0;
}
