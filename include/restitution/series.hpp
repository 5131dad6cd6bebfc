// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Analytic series and approximations of the coefficient of restitution ε(ζ), ζ = β v^{1/5} (natural units).
// Every evaluator returns ε and 1 - ε, the latter without cancellation as ε -> 1. Coefficients are
// passed in (published tables: series_tables.hpp; recomputed ones: series_coefficients.hpp).
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <vector>

namespace restitution::series {

struct Value {
  double eps = 1.0;
  double one_minus_eps = 0.0;
};

// Closed forms of the undamped collision and of C1 (1999 paper, Eq. 30; 2008 paper, Eq. 28).
double c1_closed_form();            // sqrt(π)/(2^{1/5} 5^{2/5}) Γ(3/5)/Γ(21/10) = 1.1534488580952888
double undamped_max_time();         // τ_max0 = (4/5)^{3/5} Γ(2/5) Γ(1/2) / (2 Γ(9/10)) = 1.6093...
double undamped_max_compression();  // b_0 = (5/4)^{2/5}

// Radii of convergence in ζ (docs/series.md: Domb-Sykes and root tests on the recomputed coefficients). The
// naive series is limited by a singularity at ζ ≈ -1.39, the delayed-recovery series by a complex pair at
// |ζ| ≈ 1.10; beyond them the partial sums diverge however many terms are taken.
inline constexpr double kNaiveSeriesRadius = 1.39;
inline constexpr double kDelayedRecoverySeriesRadius = 1.10;

// The coefficients a series is evaluated with: a read-only view of contiguous doubles, made from a
// std::vector, a std::array, a C++20 std::span or a pointer and a count. It stands in for std::span<const
// double> because the public headers are C++17 (docs/library.md, "C++ standard"); the container must outlive
// the call.
class CoefficientSpan {
 public:
  constexpr CoefficientSpan(const double* data, std::size_t size) noexcept : data_(data), size_(size) {}
  template <class Contiguous, class = std::enable_if_t<std::is_convertible_v<
                                  decltype(std::data(std::declval<const Contiguous&>())), const double*>>>
  // NOLINTNEXTLINE(google-explicit-constructor,hicpp-explicit-conversions): stands in for std::span's
  // conversion
  constexpr CoefficientSpan(const Contiguous& coefficients) noexcept
      : data_(std::data(coefficients)), size_(std::size(coefficients)) {}
  [[nodiscard]] constexpr const double* data() const noexcept { return data_; }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }

 private:
  const double* data_;
  std::size_t size_;
};

// Naive series ε = 1 + Σ_{k=1}^{N} c_k ζ^k; c holds c_1 ... c_N.
Value naive_series(double zeta, CoefficientSpan c);
// Delayed-recovery series ε = Σ_{k=0}^{N} h_k ζ^{k/2}; h holds h_0 = 1, h_1 ... h_N.
Value delayed_recovery_series(double zeta, CoefficientSpan h);
// Power series Σ_{k=0}^{N} coef_k ζ^k (maximal compression x_max with b_k; τ_max - τ_max0 with a_k, a_0 = 0).
double power_series(double zeta, CoefficientSpan coefficients);

// The 1999 paper's Padé [1/4] (Eq. 35) in w = C1 ζ: ε = (1 + d1 w)/(1 + d2 w + d3 w² + d4 w³ + d5 w⁴).
struct Pade1999 {
  double d1, d2, d3, d4, d5;
};
// d_k from a_2, a_3, a_4 by the formulas of the 1999 paper's Table I (a_1 = 1).
Pade1999 pade_1999_coefficients(double a2, double a3, double a4);
// With the paper's a_2 = 3/5, a_3 = 0.315119, a_4 = 0.161167 (Eq. 33), the approximant DEM codes use.
Pade1999 pade_1999_published();
// w = C1 ζ with the closed-form C1.
Value pade_1999(double zeta, const Pade1999& d);
// The 1999 paper's simple theory (Eq. 27 with Eq. 29): ε + w ε^{3/5} = 1, w = C1 ζ; any w >= 0.
Value simple_theory_1999(double zeta);
// Müller & Pöschel 2011 Padé approximants in σ = sqrt(ζ): [1/4] and [3/6].
Value pade_2011_1_4(double zeta);
Value pade_2011_3_6(double zeta);

// The closed-form approximations and series, for their large-ζ behaviour.
enum class Approximation {
  naive_series,
  delayed_recovery_series,
  pade_1999,
  pade_1999_corrected,  // the 1999 Padé form with the recomputed a_3, a_4 (series_study)
  simple_theory_1999,
  pade_2011_1_4,
  pade_2011_3_6
};
// Large-ζ behaviour ε ~ ζ^p the closed-form approximations imply (the series have no limit).
double implied_large_zeta_exponent(Approximation a);

}  // namespace restitution::series
