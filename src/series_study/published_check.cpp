// SPDX-License-Identifier: BSD-3-Clause
// The published tables against the certified recomputation, digit by digit.
#include <array>
#include <cmath>
#include <span>

#include "restitution/errors.hpp"
#include "restitution_series_study/series_coefficients.hpp"
#include "series/published_tables.hpp"

namespace restitution::series {
namespace {

// printed: the significant digits of each entry (empty: the shortest form of the double).
void add(std::vector<PublishedCheck>& out, const char* source, const char* symbol, int first_index,
         std::span<const double> published, const std::vector<CertifiedValue>& recomputed,
         std::span<const int> printed = {}) {
  for (std::size_t i = 0; i < published.size(); ++i) {
    const int k = first_index + static_cast<int>(i);
    const double value = recomputed.at(static_cast<std::size_t>(k)).approx;
    const int digits = printed.empty() ? 0 : printed[i];
    out.push_back(
        {source, symbol, k, published[i], value, check_published_digits(published[i], digits, value)});
  }
}

void add_one(std::vector<PublishedCheck>& out, const char* source, const char* symbol, int k,
             double published, double recomputed) {
  out.push_back({source, symbol, k, published, recomputed, check_published_digits(published, 0, recomputed)});
}

}  // namespace

std::vector<PublishedCheck> check_published_tables(const CertifiedCoefficients& certified) {
  if (certified.c.size() < 11 || certified.h.size() < 21)
    throw InvalidInput("checking the published tables needs certified coefficients of order >= 10");
  std::vector<PublishedCheck> out;
  std::array<int, published::kTable3B.size()> table3_digits{};
  table3_digits.fill(published::kTable3Digits);
  add(out, "2008 Table III", "a", 1, published::kTable3A, certified.a, std::span(table3_digits).first(10));
  add(out, "2008 Table III", "b", 0, published::kTable3B, certified.b, table3_digits);
  add(out, "2008 Table III", "c", 1, published::kTable3C, certified.c, std::span(table3_digits).first(10));
  add(out, "2008 Table V", "h", 0, published::kTable5H, certified.h, published::kTable5HDigits);
  const double c1 = -certified.c[1].approx;
  add_one(out, "1999 Eq. (31)", "C", 1, published::kC1Eq31, c1);
  add(out, "1999 Eqs. (A32)-(A34)", "C", 1, published::kAppendixC, certified.c);
  add(out, "1999 Eqs. (A24)-(A27)", "y", 0, published::kAppendixY, certified.b);
  // a_k of the series in w = C1 ζ: c_k = (-1)^k a_k C1^k.
  add_one(out, "1999 Eqs. (33)/(A35)", "a(w)", 3, published::kA3, -certified.c[3].approx / std::pow(c1, 3));
  add_one(out, "1999 Eqs. (33)/(A36)", "a(w)", 4, published::kA4, certified.c[4].approx / std::pow(c1, 4));
  return out;
}

}  // namespace restitution::series
