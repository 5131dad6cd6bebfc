// SPDX-License-Identifier: BSD-3-Clause
// The recomputed series coefficients in two working precisions (see coefficient_generator.hpp).
#include <fmt/core.h>

#include <algorithm>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/float128.hpp>
#include <cmath>

#include "restitution/errors.hpp"
#include "restitution_series_study/series_coefficients.hpp"
#include "series_study/coefficient_generator.hpp"

namespace restitution::series {
namespace {

using Quad = boost::multiprecision::float128;
using Decimal50 = boost::multiprecision::cpp_bin_float_50;

// Truncations of the trajectory series in q = τ^{5/2}: the sums at τ_max0 converge like 0.177^m, so
// q^40 leaves < 1e-30 (measured: q^30 already gives 25 digits, q^38 30 digits).
constexpr int kTruncationDouble = 40;
constexpr int kTruncationQuad = 45;
constexpr int kTruncationDecimal50 = 60;
constexpr int kMaxCertifiedDigits = 32;  // __float128 carries 34 digits; the arithmetic costs about two

void check_order(int order) {
  if (order < 1 || order > kMaxOrder)
    throw InvalidInput(fmt::format("series order {} out of range [1, {}]", order, kMaxOrder));
}

template <typename T>
std::vector<double> to_double(const std::vector<T>& values) {
  std::vector<double> out;
  out.reserve(values.size());
  for (const T& v : values) out.push_back(static_cast<double>(v));
  return out;
}

CertifiedValue certify(const Quad& low, const Decimal50& high) {
  CertifiedValue out;
  out.approx = static_cast<double>(high);
  if (high == 0 && low == 0) {
    out.value = "0";
    out.digits = kMaxCertifiedDigits;
    return out;
  }
  // the relative difference as a double: enough to count digits (it is >= 1e-40 or exactly 0)
  const Decimal50 relative = abs(Decimal50(low) - high) / abs(high);
  const auto difference = static_cast<double>(relative);
  int digits = kMaxCertifiedDigits;
  if (difference > 0.0) digits = static_cast<int>(std::floor(-std::log10(difference)));
  out.digits = std::clamp(digits, 0, kMaxCertifiedDigits);
  out.value = high.str(std::max(out.digits - 1, 0), std::ios_base::scientific);  // digits after the point
  return out;
}

std::vector<CertifiedValue> certify_all(const std::vector<Quad>& low, const std::vector<Decimal50>& high) {
  std::vector<CertifiedValue> out;
  for (std::size_t i = 0; i < high.size(); ++i) out.push_back(certify(low[i], high[i]));
  return out;
}

}  // namespace

Coefficients compute_coefficients(int order) {
  check_order(order);
  const auto g = detail::generate<Quad>(order, kTruncationDouble);
  return {to_double(g.a), to_double(g.b), to_double(g.c), to_double(g.h), to_double(g.v)};
}

CertifiedCoefficients certify_coefficients(int order) {
  check_order(order);
  const auto low = detail::generate<Quad>(order, kTruncationQuad);
  const auto high = detail::generate<Decimal50>(order, kTruncationDecimal50);
  return {certify_all(low.a, high.a), certify_all(low.b, high.b), certify_all(low.c, high.c),
          certify_all(low.h, high.h)};
}

}  // namespace restitution::series

namespace restitution::series {

DigitCheck check_published_digits(double published, int printed_digits, double certified) {
  DigitCheck check;
  check.printed = printed_digits;
  if (printed_digits <= 0)
    for (check.printed = 1; check.printed < 17; ++check.printed)
      if (std::stod(fmt::format("{:.{}g}", published, check.printed)) == published) break;
  if (certified == 0.0) {
    check.correct = published == 0.0 ? check.printed : 0;
    return check;
  }
  const double leading = std::floor(std::log10(std::abs(certified)));
  const double error = std::abs(published - certified);
  while (check.correct < 17 && error <= 0.5 * std::pow(10.0, leading - check.correct)) ++check.correct;
  check.correct = std::min(check.correct, check.printed);
  return check;
}

}  // namespace restitution::series
