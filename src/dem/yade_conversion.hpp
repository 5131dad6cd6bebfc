// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// YADE's (en, vn) -> A conversion for Ip2_FrictMat_FrictMat_MindlinPhys, reimplemented from its
// documentation and pkg/dem/HertzMindlin.cpp: σ solves the Müller–Pöschel 2011 Padé [3/6]
// ε(σ) = en by Newton's method from σ = 0.5, then A = (2/3) σ² vn^{-1/5} (k_n0 / m_eff)^{-2/5} with
// k_n0 = (4/3) E* sqrt(R_eff).
namespace restitution::dem {

// σ with Padé[3/6](σ) = en, as YADE iterates it (at most 1000 Newton steps, stop at |residual| <= 2^-52).
// Throws InvalidInput when en is not in (0, 1].
double yade_sigma(double en);
// A [s] YADE makes of (en, vn [m/s]) for a pair with k = k_n0 / m_eff [s^-2 m^-1/2].
double yade_dissipative_constant(double en, double vn_m_s, double k);

}  // namespace restitution::dem
