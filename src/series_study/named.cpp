#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <span>

#include "restitution/errors.hpp"
#include "restitution/series_tables.hpp"
#include "series_study/series_coefficients.hpp"
#include "series_study/series_named.hpp"

namespace restitution::series {
namespace {

void check_kind(const std::string& kind, const std::vector<std::string>& kinds, std::string_view prefix) {
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
    throw InvalidInput(
        fmt::format("{}kind must be one of {}, got '{}'", prefix, fmt::join(kinds, ", "), kind));
}

// Largest count per kind: c_1..c_N and a/b need order N, h_0..h_N order ceil(N/2).
int max_count(const std::string& kind) {
  return kind == "delayed-recovery" ? 2 * kMaxOrder : kMaxOrder;
}
int order_for(const std::string& kind, int count) {
  return kind == "delayed-recovery" ? (count + 1) / 2 : count;
}

std::vector<double> slice(const std::vector<double>& v, int first, int last) {
  return {v.begin() + first, v.begin() + last + 1};
}

}  // namespace

const std::vector<std::string>& coefficient_kinds() {
  static const std::vector<std::string> kinds = {"naive", "delayed-recovery", "max-compression"};
  return kinds;
}

const std::vector<std::string>& evaluation_kinds() {
  static const std::vector<std::string> kinds = {
      "naive", "delayed-recovery", "pade-1999", "simple-theory-1999", "pade-2011-1-4", "pade-2011-3-6"};
  return kinds;
}

std::vector<NamedCoefficients> coefficients_by_kind(const std::string& kind, int count,
                                                    std::string_view prefix) {
  check_kind(kind, coefficient_kinds(), prefix);
  if (count < 1 || count > max_count(kind))
    throw InvalidInput(fmt::format("{0}count {1} out of range [1, {2}] for {0}kind {3}", prefix, count,
                                   max_count(kind), kind));
  const Coefficients k = compute_coefficients(order_for(kind, count));
  if (kind == "naive") return {{"c", 1, slice(k.c, 1, count)}};
  if (kind == "delayed-recovery") return {{"h", 0, slice(k.h, 0, count)}};
  return {{"a", 1, slice(k.a, 1, count)}, {"b", 0, slice(k.b, 0, count)}};
}

NamedEvaluation evaluate_by_kind(const std::string& kind, std::span<const double> zetas,
                                 std::optional<int> terms, bool published, std::string_view prefix) {
  check_kind(kind, evaluation_kinds(), prefix);
  std::function<Value(double)> evaluate;
  int used = 0;
  if (kind == "naive" || kind == "delayed-recovery") {
    const bool naive = kind == "naive";
    const int available =
        published ? static_cast<int>(naive ? published::kTable3C.size() : published::kTable5H.size() - 1)
                  : max_count(kind);
    used = terms.value_or(published ? available : (naive ? 40 : 60));
    if (used < 1 || used > available)
      throw InvalidInput(
          fmt::format("{0}terms {1} out of range [1, {2}] for {0}kind {3} with {0}coefficients {4}", prefix,
                      used, available, kind, published ? "published" : "computed"));
    std::vector<double> coefficients;
    if (published) {
      coefficients = naive ? slice({published::kTable3C.begin(), published::kTable3C.end()}, 0, used - 1)
                           : slice({published::kTable5H.begin(), published::kTable5H.end()}, 0, used);
    } else {
      const Coefficients k = compute_coefficients(order_for(kind, used));
      coefficients = naive ? slice(k.c, 1, used) : slice(k.h, 0, used);
    }
    evaluate = [naive, c = std::move(coefficients)](double zeta) {
      return naive ? naive_series(zeta, c) : delayed_recovery_series(zeta, c);
    };
  } else {
    if (terms) {
      throw InvalidInput(
          fmt::format("{0}terms applies to {0}kind naive and delayed-recovery only, not {1}", prefix, kind));
    }
    if (kind == "pade-1999") {
      evaluate = [d = pade_1999_published()](double zeta) { return pade_1999(zeta, d); };
    } else if (kind == "simple-theory-1999") {
      evaluate = simple_theory_1999;
    } else {
      evaluate = kind == "pade-2011-1-4" ? pade_2011_1_4 : pade_2011_3_6;
    }
  }
  NamedEvaluation result{{}, used};
  result.values.reserve(zetas.size());
  for (std::size_t i = 0; i < zetas.size(); ++i) {
    try {
      result.values.push_back(evaluate(zetas[i]));
    } catch (const InvalidInput& e) {
      if (zetas.size() == 1) throw;
      throw InvalidInput(fmt::format("{} (zeta at index {})", e.what(), i));
    }
  }
  return result;
}

}  // namespace restitution::series
