// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution_series_study/series_coefficients.hpp"
#include "restitution_series_study/series_named.hpp"
#include "series/published_tables.hpp"

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

constexpr std::pair<Approximation, const char*> kApproximationNames[] = {
    {Approximation::naive_series, "naive-series"},
    {Approximation::delayed_recovery_series, "delayed-recovery-series"},
    {Approximation::pade_1999, "pade-1999"},
    {Approximation::pade_1999_corrected, "pade-1999-corrected"},
    {Approximation::simple_theory_1999, "simple-theory-1999"},
    {Approximation::pade_2011_1_4, "pade-2011-1-4"},
    {Approximation::pade_2011_3_6, "pade-2011-3-6"},
};

// A series name with its coefficients spelled in: KIND:published or KIND:computed-N (the names of the
// series variants in `series validate`), or a plain name with the coefficients of the options.
struct SeriesVariant {
  std::string kind;
  std::optional<int> terms;
  bool published = false;
};

SeriesVariant series_variant(const std::string& name, std::optional<int> terms, bool published,
                             std::string_view prefix) {
  const std::size_t colon = name.find(':');
  if (colon == std::string::npos) return {name, terms, published};
  const std::string kind = name.substr(0, colon);
  const std::string variant = name.substr(colon + 1);
  if (terms || published) {
    throw InvalidInput(
        fmt::format("{0}kind {1} names its coefficients: give no {0}terms or {0}coefficients", prefix, name));
  }
  const std::optional<Approximation> a = approximation_named(kind);
  const bool is_series =
      a && (*a == Approximation::naive_series || *a == Approximation::delayed_recovery_series);
  if (is_series && variant == "published") return {kind, std::nullopt, true};
  constexpr std::string_view computed = "computed-";
  if (is_series && variant.rfind(computed, 0) == 0) {
    const std::string count = variant.substr(computed.size());
    if (!count.empty() && count.size() < 4 && std::all_of(count.begin(), count.end(), ::isdigit)) {
      return {kind, std::stoi(count), false};
    }
  }
  throw InvalidInput(
      fmt::format("{}kind '{}': only naive-series and delayed-recovery-series take :published or :computed-N",
                  prefix, name));
}

}  // namespace

const std::vector<std::string>& coefficient_kinds() {
  static const std::vector<std::string> kinds = {"naive", "delayed-recovery", "max-compression"};
  return kinds;
}

const char* approximation_name(Approximation kind) {
  for (const auto& [k, name] : kApproximationNames) {
    if (k == kind) return name;
  }
  return "unknown";
}

std::optional<Approximation> approximation_named(std::string_view name) {
  if (name == "naive") return Approximation::naive_series;
  if (name == "delayed-recovery") return Approximation::delayed_recovery_series;
  for (const auto& [kind, spelled] : kApproximationNames) {
    if (name == spelled) return kind;
  }
  return std::nullopt;
}

Pade1999 pade_1999_corrected() {
  const Coefficients k = compute_coefficients(4);
  const double c1 = -k.c[1];
  return pade_1999_coefficients(0.6, -k.c[3] / std::pow(c1, 3), k.c[4] / std::pow(c1, 4));
}

const std::vector<std::string>& evaluation_kinds() {
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> names;
    for (const auto& entry : kApproximationNames) names.emplace_back(entry.second);
    return names;
  }();
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
  const SeriesVariant variant = series_variant(kind, terms, published, prefix);
  const std::optional<Approximation> named = approximation_named(variant.kind);
  if (!named) {
    throw InvalidInput(
        fmt::format("{}kind must be one of {} (or the aliases naive, delayed-recovery), got '{}'", prefix,
                    fmt::join(evaluation_kinds(), ", "), kind));
  }
  terms = variant.terms;
  published = variant.published;
  std::function<Value(double)> evaluate;
  int used = 0;
  const bool naive = *named == Approximation::naive_series;
  if (naive || *named == Approximation::delayed_recovery_series) {
    const std::string coefficient_kind = naive ? "naive" : "delayed-recovery";
    const int available =
        published ? static_cast<int>(naive ? published::kTable3C.size() : published::kTable5H.size() - 1)
                  : max_count(coefficient_kind);
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
      const Coefficients k = compute_coefficients(order_for(coefficient_kind, used));
      coefficients = naive ? slice(k.c, 1, used) : slice(k.h, 0, used);
    }
    evaluate = [naive, c = std::move(coefficients)](double zeta) {
      return naive ? naive_series(zeta, c) : delayed_recovery_series(zeta, c);
    };
  } else {
    if (terms) {
      throw InvalidInput(
          fmt::format("{0}terms applies to {0}kind naive-series and delayed-recovery-series only, not {1}",
                      prefix, kind));
    }
    switch (*named) {
      case Approximation::pade_1999:
        evaluate = [d = pade_1999_published()](double zeta) { return pade_1999(zeta, d); };
        break;
      case Approximation::pade_1999_corrected:
        evaluate = [d = pade_1999_corrected()](double zeta) { return pade_1999(zeta, d); };
        break;
      case Approximation::simple_theory_1999:
        evaluate = simple_theory_1999;
        break;
      case Approximation::pade_2011_1_4:
        evaluate = pade_2011_1_4;
        break;
      case Approximation::pade_2011_3_6:
        evaluate = pade_2011_3_6;
        break;
      case Approximation::naive_series:
      case Approximation::delayed_recovery_series:
        throw std::logic_error(
            "the series are evaluated above");  // no default: a new member must be named here
    }
  }
  // The domain, the same for the command line and Python: the checked range of every solver path and, for a
  // partial sum, its radius of convergence (beyond it the sums diverge however many terms are taken).
  const std::optional<double> radius =
      naive ? std::optional(kNaiveSeriesRadius)
            : (*named == Approximation::delayed_recovery_series ? std::optional(kDelayedRecoverySeriesRadius)
                                                                : std::nullopt);
  const auto check_domain = [&](double zeta) {
    require_checked_zeta(zeta);
    if (radius && zeta >= *radius) {
      throw InvalidInput(fmt::format(
          "zeta = {} is outside the radius of convergence of the {} series (zeta < {:g}, docs/series.md): "
          "its "
          "partial sums diverge there; use an approximant ({}kind pade-2011-3-6) or `restitution eps`",
          zeta, kind, *radius, prefix));
    }
  };
  NamedEvaluation result{{}, used, published};
  result.values.reserve(zetas.size());
  for (std::size_t i = 0; i < zetas.size(); ++i) {
    try {
      check_domain(zetas[i]);
      result.values.push_back(evaluate(zetas[i]));
    } catch (const InvalidInput& e) {
      if (zetas.size() == 1) throw;
      throw InvalidInput(fmt::format("{} (zeta at index {})", e.what(), i));
    }
  }
  return result;
}

}  // namespace restitution::series
