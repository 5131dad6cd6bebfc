// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Independent computation of the series coefficients (natural units, ζ = β v^{1/5}):
//   τ_max = τ_max0 + Σ a_k ζ^k,  x_max = Σ b_k ζ^k,  ε_naive = 1 + Σ c_k ζ^k,  ε_delayed = Σ h_k ζ^{k/2}.
// Series arithmetic in extended precision (see docs/series.md and
// src/series_study/coefficient_generator.hpp).
#include <string>
#include <vector>

namespace restitution::series {

// Coefficients rounded to double, computed in __float128. Index k holds the coefficient of ζ^k (a, b, c)
// or ζ^{k/2} (h): a[0] = 0, c[0] = 1, h[0] = 1. a, b, c have order + 1 entries, h has 2·order + 1.
// v: velocity ratio at the premature end of the inverse collision with damping -w, V = Σ v_j λ^j in
// λ = w^{5/2} (2008 paper, Eq. C5: v_1 = 4/15, v_2 = 13/150, ...), order·2/5 + 1 entries.
struct Coefficients {
  std::vector<double> a, b, c, h, v;
};
// order in [1, kMaxOrder]; throws InvalidInput naming `order` otherwise. Cost grows like order²:
// about 0.2 s for order 40.
inline constexpr int kMaxOrder = 60;
Coefficients compute_coefficients(int order);

// One coefficient computed twice: in __float128 with the trajectory series truncated at q^45
// (q = τ^{5/2}) and with 50 significant decimal digits (Boost cpp_bin_float_50) truncated at q^60.
struct CertifiedValue {
  std::string value;  // the 50-digit result, printed with `digits` significant digits (at least 1)
  double approx = 0;  // the same rounded to double
  int digits = 0;     // significant decimal digits on which both computations agree (capped at 32)
};
struct CertifiedCoefficients {
  std::vector<CertifiedValue> a, b, c, h;  // same indexing as Coefficients
};
// Exact zeros (a_0, h_1, h_3) are reported with value "0" and digits = 32.
CertifiedCoefficients certify_coefficients(int order);

}  // namespace restitution::series

namespace restitution::series {

// How many significant digits a published value prints, and how many of them are right: the printed
// value is correct to d digits when it lies within half a unit of the d-th significant digit of the
// certified value. A published digit disagrees when correct < printed. printed_digits <= 0 means "the
// shortest decimal form of the double" (right when the printed value has no trailing zeros).
struct DigitCheck {
  int printed = 0;
  int correct = 0;
};
DigitCheck check_published_digits(double published, int printed_digits, double certified);

// Every published number of series_tables.hpp that has an exact counterpart, checked against the
// certified recomputation (order >= 10 needed for the full tables).
struct PublishedCheck {
  std::string source;  // "2008 Table III", "1999 Eq. (A32)", ...
  std::string symbol;  // "a", "b", "c", "h", "C", "a(w)", "y"
  int index = 0;
  double published = 0;
  double recomputed = 0;
  DigitCheck digits;
};
std::vector<PublishedCheck> check_published_tables(const CertifiedCoefficients& certified);

}  // namespace restitution::series
