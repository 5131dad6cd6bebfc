// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A gas deck's runs against the kinetic theory (restitution_gas/cooling.hpp; docs/gas.md, "The LAMMPS deck"):
// each cooling curve read from LAMMPS's output next to the theory's T(t) at the same times from the same T0,
// for its law (the viscoelastic ε(v), or the companion's constant ε: Haff's law). The theory's collision rate
// carries one factor measured on the constant-ε run (Enskog's rate is a few per cent off at φ = 0.1): the
// least-squares c of sqrt(T0/T) - 1 = c t / τ0 (Haff's law), applied to both laws.
#include <string>
#include <vector>

#include "gas_deck/gas_log.hpp"
#include "gas_deck/gas_log_setup.hpp"
#include "gas_deck/lammps_gas_deck.hpp"
#include "restitution_gas/cooling.hpp"

namespace restitution::gas_deck {

// The late exponent is the least-squares slope of ln T against ln t over the last half decade of a run.
inline constexpr double kLateSpan = 3.1622776601683795;  // sqrt(10)

struct GasSetup {
  gas::GasParticles particles;
  gas::ImpactLaw law;         // the viscoelastic law of the deck
  double constant_eps = 0.0;  // the companion's ε
  GasLogSetup log;            // what the deck's setup line says of this gas (its `law` left empty)
};

struct RunComparison {
  std::string run;                           // the curve's source and law: "gas.log viscoelastic"
  std::string law;                           // "viscoelastic" | "constant-eps"
  std::vector<double> time_s;                // the run's printed times (t > 0)
  std::vector<double> temperature_j;         // the run's T
  std::vector<double> theory_temperature_j;  // the theory's at the same times, same T0
  LocalExponent exponent, theory_exponent;
  double max_relative_deviation = 0.0;  // max |T / T_theory - 1|
  double late_exponent = 0.0, theory_late_exponent = 0.0;
  double haff_times = 0.0;  // the run's duration in τ0 of its own law's theory
};

struct GasComparison {
  double collision_rate_factor = 1.0;           // measured on the constant-ε run (1 without one)
  bool collision_rate_factor_measured = false;  // a constant-ε run was given
  std::vector<RunComparison> runs;
};

// The setup of the gas a deck was written for (lammps_gas_deck's request): the particles, the law with A from
// `request.damping`, the companion's ε.
GasSetup gas_setup(const GasDeckRequest& request);

// Throws InvalidInput naming the run when a curve has no point at t = 0 or fewer than 4 points, or a law
// name that is neither.
GasComparison compare_with_theory(const GasSetup& setup, const std::vector<CoolingCurve>& curves);

// The least-squares slope of ln T against ln t over t >= t_end / kLateSpan.
double late_exponent(const std::vector<double>& time_s, const std::vector<double>& temperature_j);

}  // namespace restitution::gas_deck
