// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Certified fast ε(ζ): piecewise polynomials in ln ζ generated from the quad-precision reference engine, the
// small-ζ series below them and the large-ζ asymptotic laws above (docs/fast.md). Natural units throughout
// (x'' + ζ x' sqrt(x) + x^{3/2} = 0, x'(0) = 1). Accuracy of ε: |Δε| <= 1e-13 · min(ε, 1 − ε) on
// ζ ∈ [0, 1e6] (delayed recovery) and [0, 1e5] (naive); beyond, the error of the asymptotic law
// (docs/fast.md). The evaluation is the C99 code of src/fast/fast_table.h, which `restitution export
// c-header` writes out, so the C header and these functions return the same bits.
#include <string>

#include "restitution/collision_solver.hpp"

namespace restitution::fast {

// ε(ζ) and 1 − ε(ζ) (each to its own relative accuracy), ζ >= 0 (+inf gives ε = 0).
// Throw InvalidInput for ζ < 0 or NaN.
double eps(double zeta, CollisionEnd end);
double one_minus_eps(double zeta, CollisionEnd end);

// The inverse: ζ with ε(ζ) = eps, for eps ∈ (0, 1] (eps = 1 gives 0). Relative accuracy of ε(result): 1e-13
// of min(ε, 1 − ε) within the certified range. Throws InvalidInput for eps outside (0, 1].
double zeta_from_eps(double eps, CollisionEnd end);

// Collision duration τ_c in natural units (time in units of the scaling of contact_law.hpp), ζ >= 0 (+inf
// gives +inf at the naive end, 0 at the delayed-recovery end): tables in ln ζ, large-ζ laws above them
// (docs/fast.md states each one's relative error). Throws InvalidInput for ζ < 0 or NaN.
double collision_duration(double zeta, CollisionEnd end);

// Maximal compression x_max and the time τ_max at which it is reached, natural units, ζ >= 0 (+inf gives
// 0, 0); as collision_duration.
MaxCompression max_compression(double zeta);

// The self-contained C99 header (also valid C++) holding the same tables and evaluation: the text of
// src/fast/fast_table.h as compiled into this library.
std::string c_header();

}  // namespace restitution::fast
