#pragma once
// Closed forms for the linear dash-pot x'' + 2r x' + x = 0, x(0) = 0, x'(0) = 1 (time in units of 1/ω0),
// the exact reference of the dash-pot check scene. From the exact solution (underdamped
// x = e^{-rτ} sin(ωτ)/ω, ω = sqrt(1 - r²); overdamped with sinh; critical x = τ e^{-τ}) |x'| = e^{-rτ} at
// both ends, so ε = exp(-r τ_c) with
//   naive (r < 1):      ωτ_c = π                       (2008 paper Eq. 10)
//   delayed recovery:   tan(ωτ_c) = 2rω / (2r² - 1)     (tanh for r > 1, τ_c = 2 at r = 1; cf. its Eq. 12)
namespace restitution::scene {

// r is the damping ratio. τ_c of the naive end; throws InvalidInput naming damping-ratio for r >= 1 (x never
// returns to 0).
double dashpot_naive_duration(double r);
double dashpot_delayed_duration(double r);
// ε = exp(-r τ_c).
double dashpot_eps(double r, double duration);

}  // namespace restitution::scene
