// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Closed forms for the linear dash-pot x'' + 2r x' + x = 0, x(0) = 0, x'(0) = 1 (natural units: time in
// units of 1/ω0, r the damping ratio): the exact reference of the dash-pot checks.
//
// Derivation. The exact solution is x = e^{-rτ} sin(ωτ)/ω with ω = sqrt(1 - r²) (underdamped; sinh and
// ω = sqrt(r² - 1) when overdamped, x = τ e^{-τ} when critical), so
//   x' = e^{-rτ} (cos(ωτ) - (r/ω) sin(ωτ)).
// Naive end, x = 0: sin(ωτ_c) = 0, ωτ_c = π (r < 1 only), where x' = -e^{-rτ_c}   (2008 paper Eq. 10).
// Delayed recovery, force 2r x' + x = 0: (2r² - 1) sin(ωτ) = 2rω cos(ωτ), i.e. tan(ωτ_c) = 2rω / (2r² - 1)
// (tanh when overdamped, τ_c = 2 when critical; the branch with ωτ_c in (0, π)). There cos(ωτ_c) = 2r² - 1,
// sin(ωτ_c) = 2rω, so x' = -e^{-rτ_c} again (cf. the paper's Eq. 12, whose middle regime 1/√2 < r < 1 is
// printed with the wrong sign; tests/test_dashpot.cpp). So at both ends ε = exp(-r τ_c).
namespace restitution {

// τ_c of the naive end; throws InvalidInput naming damping-ratio for r >= 1 (x never returns to 0).
double dashpot_naive_duration(double r);
// τ_c of the delayed-recovery end (the first zero of the force after τ = 0); throws InvalidInput for r <= 0.
double dashpot_delayed_duration(double r);
// ε = exp(-r τ_c).
double dashpot_eps(double r, double duration);

}  // namespace restitution
