#pragma once
// Closed forms and published numbers the tests compare with. The published tables live in the series
// module once it exists; here only what the core tests need, with their sources.
#include <cmath>

namespace restitution::test_support {

// Undamped collision (ζ = 0): x_max = (5/4)^{2/5}, τ_max0 = (4/5)^{3/5} Γ(2/5) Γ(1/2) / (2 Γ(9/10))
// (DESIGN.md §4, from the energy integral x'^2/2 + (2/5) x^{5/2} = 1/2).
inline double undamped_max_compression() {
  return std::pow(1.25, 0.4);
}
inline double undamped_max_time() {
  return std::pow(0.8, 0.6) * std::tgamma(0.4) * std::tgamma(0.5) / (2.0 * std::tgamma(0.9));
}

// C1 in closed form (1999 paper, Eq. 30): sqrt(π) / (2^{1/5} 5^{2/5}) Γ(3/5) / Γ(21/10) = 1.15344885809...
inline double c1_closed_form() {
  return std::sqrt(M_PI) / (std::pow(2.0, 0.2) * std::pow(5.0, 0.4)) * std::tgamma(0.6) / std::tgamma(2.1);
}

// Naive series ε = 1 + Σ c_k ζ^k, 2008 paper Table III (c_1 ... c_4).
inline constexpr double kPaperC[] = {-1.153448854, 0.7982665553, -0.5228825609, 0.3487426678};
// Delayed-recovery series ε = 1 + Σ h_k ζ^{k/2}, 2008 paper Table V (h_0 ... h_8).
inline constexpr double kPaperH[] = {1.0,          0.0,           -1.153448856,  0.0,         0.7982665581,
                                     0.2666666667, -0.5228825657, -0.4613795424, 0.3487426737};

}  // namespace restitution::test_support
