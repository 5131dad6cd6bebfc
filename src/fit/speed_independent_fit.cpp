// SPDX-License-Identifier: BSD-3-Clause
// The speed-independent members (Tsuji, the linear dash-pot): one ε for every speed, so the least-squares ε
// is the weighted mean and χ²(ε) = χ²_min + W (ε - ε̂)² is exactly quadratic: the profile intervals in ε are
// ε̂ ± sqrt(Δ/W). ε decreases monotonically with the law's ζ, and the profile of χ² is invariant under a
// monotone change of parameter, so the value and the bounds map to ζ by inverting ε(ζ) with the solver: one
// root finding per number, not per data point.
#include <fmt/core.h>

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <string>

#include "fit/fit_internal.hpp"
#include "restitution/errors.hpp"

namespace restitution::fit_detail {
namespace {

class EpsInverse {
 public:
  EpsInverse(const FitCandidate& candidate, const FitOptions& options, CollisionSolver& solver)
      : candidate_(candidate), solver_(solver) {
    options_.tolerance = options.tolerance;
    options_.method = options.method;
    options_.ends = EndSet{candidate.end};
    if (candidate.end == CollisionEnd::delayed_recovery) {
      log_eps_high_ = log_eps(zeta_high_);
      return;
    }
    // The naive end of these members exists below ζ = 2 sqrt(b + 1) (contact_law.hpp), ε -> 0 there, and the
    // solver refuses the tolerance close to it (rounding grows near critical damping): the edge is the
    // closest approach it accepts.
    const double critical = 2.0 * std::sqrt(law_exponents(candidate.law).damping + 1.0);
    for (const double gap : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2}) {
      zeta_high_ = critical * (1.0 - gap);
      try {
        log_eps_high_ = log_eps(zeta_high_);
        return;
      } catch (const InvalidInput&) {
      } catch (const NumericalFailure&) {
      }
    }
    log_eps_high_ = log_eps(zeta_high_);  // reports why, as the fit's message
  }

  // ln ε at ζ from whichever of ε and 1 - ε carries the relative accuracy.
  double log_eps(double zeta) {
    const CollisionResult r = solver_.solve(ContactLaw::natural(candidate_.law, zeta), options_);
    const EndResult& e = end_of(r, candidate_.end);
    return e.eps < 0.5 ? std::log(e.eps) : std::log1p(-e.one_minus_eps);
  }

  // ζ with ε(ζ) = eps: 0 for eps >= 1, nullopt beyond the end of the range.
  std::optional<double> zeta_for(double eps) {
    if (eps >= 1.0) return 0.0;
    if (eps <= 0.0) return std::nullopt;
    const double target = std::log(eps);
    if (target < log_eps_high_) return std::nullopt;
    auto f = [&](double zeta) { return zeta == 0.0 ? -target : log_eps(zeta) - target; };
    double lo = 0.0;
    double f_lo = -target;
    double hi = std::min(0.25, zeta_high_);
    double f_hi = f(hi);
    while (f_hi > 0.0) {
      lo = hi;
      f_lo = f_hi;
      hi = std::min(4.0 * hi, zeta_high_);
      f_hi = hi == zeta_high_ ? log_eps_high_ - target : f(hi);
    }
    if (f_hi == 0.0) return hi;
    const int bits = std::min(50, static_cast<int>(std::ceil(-std::log2(options_.tolerance))) + 4);
    std::uintmax_t iterations = 200;
    const auto [a, b] = boost::math::tools::toms748_solve(
        f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(bits), iterations);
    return 0.5 * (a + b);
  }

  [[nodiscard]] double zeta_high() const { return zeta_high_; }

  // Where the range ends and why (docs/fit.md, "the edge of the checked range").
  [[nodiscard]] std::string edge() const {
    if (candidate_.end == CollisionEnd::delayed_recovery) {
      return fmt::format("zeta = {:g}, the edge of the checked range", zeta_high_);
    }
    return fmt::format(
        "zeta = {:.6g}, the edge of the naive end's range (the closest approach to critical damping, zeta = "
        "{:g}, where eps -> 0, that the solver accepts)",
        zeta_high_, 2.0 * std::sqrt(law_exponents(candidate_.law).damping + 1.0));
  }

 private:
  FitCandidate candidate_;
  CollisionSolver& solver_;
  SolveOptions options_;
  double zeta_high_ = kLargestCheckedZeta;
  double log_eps_high_ = 0.0;
};

}  // namespace

void fit_speed_independent(const Problem& problem, const FitOptions& options, CollisionSolver& solver,
                           LawFit& fit) {
  const FitData& d = *problem.data;
  double total = 0.0;
  double weighted = 0.0;
  for (std::size_t i = 0; i < problem.size(); ++i) {
    total += problem.weight[i];
    weighted += problem.weight[i] * d.eps[i];
  }
  const double eps_best = weighted / total;
  fit.model_eps.assign(problem.size(), eps_best);
  fit.chi2 = chi_square(problem, fit.model_eps);
  // The parameter is the law's labelled one (law_parameter): ζ (Tsuji) or r = ζ/2 (the dash-pot).
  const double zeta_per_parameter = law_parameter(fit.candidate.law).zeta_per_parameter;
  EpsInverse inverse(fit.candidate, options, solver);
  const auto zeta = inverse.zeta_for(eps_best);
  if (!zeta) {
    fit.status = FitStatus::at_edge;
    fit.message = fmt::format("eps = {:.6g} lies below eps at {}", eps_best, inverse.edge());
    set_edge_high(fit.ci68);
    set_edge_high(fit.ci95);
    return;
  }
  fit.status = FitStatus::converged;
  fit.value = *zeta / zeta_per_parameter;
  const double scale = problem.sigma_estimated ? fit.chi2 / static_cast<double>(problem.size() - 1) : 1.0;
  auto interval = [&](double delta) {
    const double half = std::sqrt(delta * scale / total);
    FitInterval out;
    // ε decreases with ζ: the upper ε gives the lower bound.
    out.low = *inverse.zeta_for(eps_best + half) / zeta_per_parameter;
    if (const auto high = inverse.zeta_for(eps_best - half)) {
      out.high = *high / zeta_per_parameter;
    } else {
      set_edge_high(out);
    }
    // Noise-free data give half ~ 0, where the inverse's own tolerance could order the bounds backwards by
    // ~1e-12: the interval holds the value by construction.
    out.low = std::min(out.low, fit.value);
    if (!out.high_at_edge) out.high = std::max(out.high, fit.value);
    return out;
  };
  fit.ci68 = interval(problem.delta68);
  fit.ci95 = interval(problem.delta95);
}

}  // namespace restitution::fit_detail
