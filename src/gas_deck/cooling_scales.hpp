// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scales of a freely cooling gas of monodisperse spheres with a constant ε that a deck needs
// (docs/gas.md, "The LAMMPS deck"): Haff's time τ0, the mean free path, and the box length above which the
// homogeneous cooling state is unstable to the shear (vortex) mode, with how far that mode grows in a given
// time.
//
// Temperature T = m <v^2> / 3 per particle [J]. Enskog–Maxwell cooling (Brilliantov & Pöschel, Kinetic Theory
// of Granular Gases, OUP 2004, ch. 6; Haff, J. Fluid Mech. 134, 401 (1983)):
//   dT/dt = -ζ T, ζ = (4 sqrt(pi) / 3) (1 - ε^2) n g2 σ^2 sqrt(T / m) = 2 / τ0 at T0,
// g2 = (1 - φ/2) / (1 - φ)^3 (Carnahan–Starling). The shear mode of wavenumber k decays as ν k^2 (ν = η / (m
// n), η Enskog's viscosity, η0 (1/g2 + 0.8 (4φ) + 0.7614 (4φ)^2 g2), η0 = (5 / (16 σ^2)) sqrt(m T / pi);
// Chapman & Cowling, ch. 16) while the thermal speed decays at ζ/2: scaled by the thermal speed it grows when
// k < k_c = sqrt(ζ / (2 ν)) (Goldhirsch & Zanetti, PRL 70, 1619 (1993); Brilliantov & Pöschel ch. 20), i.e.
// in a box longer than
//   L_c = 2 pi / k_c = 2 pi l0 sqrt((15 pi / 16) g2 (η / η0)) / sqrt(1 - ε^2),  l0 = 1 / (sqrt 2 pi n σ^2
//   g2).
// Both ν and ζ scale as sqrt(T): L_c does not change as the gas cools. In Haff's state the longest mode
// (wavelength L) grows by (1 + t/τ0)^{1 - (L_c/L)^2} in time t.
namespace restitution::gas_deck {

struct GasScales {
  double number_density_m3 = 0.0;        // n
  double pair_correlation = 0.0;         // g2 at contact
  double mean_free_path_m = 0.0;         // l0
  double viscosity_factor = 0.0;         // η / η0 (Enskog)
  double haff_time_s = 0.0;              // τ0 at the initial temperature
  double shear_critical_length_m = 0.0;  // L_c
};

// Spheres of diameter σ [m] and mass m [kg] at packing fraction φ in (0, 0.5), temperature T [J], constant ε
// in [0, 1) (InvalidInput naming the value otherwise).
GasScales gas_scales(double diameter_m, double mass_kg, double packing_fraction, double temperature_j,
                     double eps);

// How many times the longest shear mode of a cube of side L [m] grows in `duration_s` of Haff cooling (1 when
// L <= L_c: it decays).
double shear_mode_growth(const GasScales& scales, double box_m, double duration_s);

}  // namespace restitution::gas_deck
