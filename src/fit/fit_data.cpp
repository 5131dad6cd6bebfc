// SPDX-License-Identifier: BSD-3-Clause
// fit_data: the checks, the candidates' shared statistics (AIC, BIC, χ²/dof), the choice of the best law and
// the conversions of β into g* and A (restitution/fit.hpp, docs/fit.md).
#include <fmt/core.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>

#include "fit/fit_internal.hpp"
#include "restitution/errors.hpp"
#include "restitution/fast.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

// One standard deviation of a normal distribution: the coverage of Δχ² = 1.
constexpr double kLevel68 = 0.6826894921370859;
constexpr double kLevel95 = 0.95;

void check_point(const FitData& data, std::size_t i) {
  const double v = data.velocity_m_s[i];
  const double e = data.eps[i];
  if (!std::isfinite(v) || v <= 0.0) {
    throw InvalidInput(fmt::format("point {}: the speed v must be finite and > 0 m/s, got {}", i, v));
  }
  if (!std::isfinite(e) || e <= 0.0 || e >= 1.0) {
    throw InvalidInput(fmt::format("point {}: eps must be in (0, 1), got {}", i, e));
  }
  if (!data.sigma.empty() && !(data.sigma[i] >= kSmallestFitSigma && data.sigma[i] <= kLargestFitSigma)) {
    throw InvalidInput(fmt::format("point {}: sigma must be in [{:g}, {:g}] (docs/fit.md), got {}", i,
                                   kSmallestFitSigma, kLargestFitSigma, data.sigma[i]));
  }
}

// A monotone map of an interval's bounds (increasing or decreasing); an edge stays an edge.
FitInterval map_interval(const FitInterval& in, bool increasing, double (*f)(double)) {
  FitInterval out;
  auto image = [f](double x, bool edge, bool& out_edge, double& out_value) {
    out_edge = edge || !std::isfinite(f(x));
    out_value = out_edge ? std::numeric_limits<double>::quiet_NaN() : f(x);
  };
  if (increasing) {
    image(in.low, in.low_at_edge, out.low_at_edge, out.low);
    image(in.high, in.high_at_edge, out.high_at_edge, out.high);
  } else {
    image(in.high, in.high_at_edge, out.low_at_edge, out.low);
    image(in.low, in.low_at_edge, out.high_at_edge, out.high);
  }
  return out;
}

double g_star_or_inf(double beta) {
  return beta > 0.0 ? characteristic_velocity_m_s(beta) : std::numeric_limits<double>::infinity();
}

void add_hertz_conversions(LawFit& fit, std::optional<double> k) {
  if (fit.candidate.law != LawKind::viscoelastic_hertz || fit.status != FitStatus::converged) return;
  fit.characteristic_velocity_m_s = g_star_or_inf(fit.value);
  fit.characteristic_velocity_ci68 = map_interval(fit.ci68, false, g_star_or_inf);
  fit.characteristic_velocity_ci95 = map_interval(fit.ci95, false, g_star_or_inf);
  if (!k) return;
  // A = β / ((3/2) k^{2/5}): a constant factor, increasing.
  const double factor = dissipative_constant_from(1.0, *k);
  auto scale = [factor](FitInterval i) {
    if (!i.low_at_edge) i.low *= factor;
    if (!i.high_at_edge) i.high *= factor;
    return i;
  };
  fit.dissipative_constant_s = fit.value * factor;
  fit.dissipative_constant_ci68 = scale(fit.ci68);
  fit.dissipative_constant_ci95 = scale(fit.ci95);
}

// AIC and BIC of a Gaussian likelihood: known σ, χ² + penalty; estimated σ, n ln(χ²/n) + penalty with the
// scatter counted as a second parameter (the same for every law, so only differences matter).
void add_information_criteria(const fit_detail::Problem& problem, LawFit& fit) {
  const auto n = static_cast<double>(problem.size());
  fit.dof = static_cast<int>(problem.size()) - 1;
  fit.chi2_per_dof = fit.dof > 0 ? fit.chi2 / fit.dof : std::numeric_limits<double>::quiet_NaN();
  if (problem.sigma_estimated) {
    // Noise-free data give χ² ~ 1e-25: the floor only keeps the logarithm finite.
    const double fit_term = n * std::log(std::max(fit.chi2, 1e-300) / n);
    fit.aic = fit_term + 4.0;
    fit.bic = fit_term + 2.0 * std::log(n);
  } else {
    fit.aic = fit.chi2 + 2.0;
    fit.bic = fit.chi2 + std::log(n);
  }
}

void choose_best(FitResult& result) {
  for (std::size_t i = 0; i < result.fits.size(); ++i) {
    if (result.fits[i].status != FitStatus::converged) continue;
    if (!result.best || result.fits[i].aic < result.fits[*result.best].aic) result.best = i;
  }
  if (!result.best) return;
  const double best_aic = result.fits[*result.best].aic;
  for (std::size_t i = 0; i < result.fits.size(); ++i) {
    const LawFit& f = result.fits[i];
    if (i == *result.best || f.status != FitStatus::converged) continue;
    if (std::abs(f.aic - best_aic) <= 1e-6 * std::max(1.0, std::abs(best_aic))) {
      result.tied_with_best.push_back(i);
    }
  }
}

}  // namespace

void check_fit_data(const FitData& data) {
  const std::size_t n = data.velocity_m_s.size();
  if (data.eps.size() != n) {
    throw InvalidInput(fmt::format("{} speeds but {} values of eps", n, data.eps.size()));
  }
  if (!data.sigma.empty() && data.sigma.size() != n) {
    throw InvalidInput(fmt::format("{} points but {} values of sigma", n, data.sigma.size()));
  }
  // One parameter; without σ the scatter is a second one.
  const std::size_t needed = data.sigma.empty() ? 2 : 1;
  if (n < needed) {
    throw InvalidInput(fmt::format("{} point{} cannot fit one parameter{}: at least {} needed", n,
                                   n == 1 ? "" : "s", data.sigma.empty() ? " and the scatter" : "", needed));
  }
  for (std::size_t i = 0; i < n; ++i) check_point(data, i);
}

std::vector<FitCandidate> default_fit_candidates() {
  return {{LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery},
          {LawKind::viscoelastic_hertz, CollisionEnd::naive},
          {LawKind::tsuji_hertz, kDefaultSpeedIndependentEnd},
          {LawKind::linear_dashpot, kDefaultSpeedIndependentEnd}};
}

std::vector<FitCandidate> fit_candidates(const std::vector<std::string>& law_names,
                                         const std::string& speed_independent_end) {
  const CollisionEnd constant_end = end_from_name(speed_independent_end);
  std::vector<LawKind> laws;
  laws.reserve(law_names.size());
  const std::vector<FitCandidate> all = default_fit_candidates();
  for (const std::string& name : law_names) {
    const LawKind law = law_from_name(name);
    if (std::none_of(all.begin(), all.end(), [law](const FitCandidate& c) { return c.law == law; })) {
      throw InvalidInput(
          fmt::format("the law {} is not a fit candidate: fit-data fits viscoelastic-hertz, tsuji-hertz and "
                      "linear-dashpot",
                      name));
    }
    laws.push_back(law);
  }
  std::vector<FitCandidate> out;
  for (const FitCandidate& c : all) {
    if (!laws.empty() && std::find(laws.begin(), laws.end(), c.law) == laws.end()) continue;
    out.push_back({c.law, c.law == LawKind::viscoelastic_hertz ? c.end : constant_end});
  }
  return out;
}

const char* fit_parameter_name(LawKind law) {
  // β for viscoelastic Hertz (ε depends on the speed); else the law's labelled parameter (law_parameter).
  return law == LawKind::viscoelastic_hertz ? "beta" : law_parameter(law).name;
}

const char* fit_status_name(FitStatus status) {
  switch (status) {
    case FitStatus::converged:
      return "converged";
    case FitStatus::at_edge:
      return "at-edge";
    case FitStatus::not_converged:
      break;
  }
  return "not-converged";
}

namespace fit_detail {

Problem make_problem(const FitData& data, double level68, double level95) {
  Problem p;
  p.data = &data;
  p.sigma_estimated = data.sigma.empty();
  const std::size_t n = data.eps.size();
  p.weight.assign(n, 1.0);
  if (!p.sigma_estimated) {
    for (std::size_t i = 0; i < n; ++i) p.weight[i] = 1.0 / (data.sigma[i] * data.sigma[i]);
  }
  auto delta = [&](double level) {
    const double q = 0.5 * (1.0 + level);
    double x = 0.0;
    if (p.sigma_estimated) {
      x = boost::math::quantile(boost::math::students_t(static_cast<double>(n - 1)), q);
    } else {
      x = boost::math::quantile(boost::math::normal(), q);
    }
    return x * x;
  };
  p.delta68 = delta(level68);
  p.delta95 = delta(level95);
  return p;
}

double chi_square(const Problem& problem, const std::vector<double>& model_eps) {
  double sum = 0.0;
  for (std::size_t i = 0; i < problem.size(); ++i) {
    const double r = problem.data->eps[i] - model_eps[i];
    sum += problem.weight[i] * r * r;
  }
  return sum;
}

}  // namespace fit_detail

double fit_model_eps(const FitCandidate& candidate, double parameter, double velocity_m_s,
                     CollisionSolver& solver, const SolveOptions& options) {
  if (candidate.law == LawKind::viscoelastic_hertz) {
    return fast::eps(zeta_from(parameter, velocity_m_s), candidate.end);
  }
  if (parameter == 0.0) return 1.0;
  SolveOptions o = options;
  o.ends = EndSet{candidate.end};
  return end_of(solver.solve(ContactLaw::of_parameter(candidate.law, parameter), o), candidate.end).eps;
}

FitResult fit_data(const FitData& data, const FitOptions& options) {
  check_fit_data(data);
  SolveOptions solve_options;
  solve_options.tolerance = options.tolerance;
  solve_options.method = options.method;
  check_solve_options(solve_options);
  if (options.k && (!std::isfinite(*options.k) || *options.k <= 0.0)) {
    throw InvalidInput(fmt::format("k must be finite and > 0, got {}", *options.k));
  }
  FitResult result;
  result.sigma_estimated = data.sigma.empty();
  result.level68 = kLevel68;
  result.level95 = kLevel95;
  result.points = data.eps.size();
  const fit_detail::Problem problem = fit_detail::make_problem(data, kLevel68, kLevel95);
  CollisionSolver solver;
  for (const FitCandidate& candidate : options.candidates) {
    if (candidate.law != LawKind::viscoelastic_hertz && !speed_independent(candidate.law)) {
      throw InvalidInput(fmt::format("fit-data has no fit for the law {}", law_name(candidate.law)));
    }
    LawFit fit;
    fit.candidate = candidate;
    fit.parameter = fit_parameter_name(candidate.law);
    try {
      if (candidate.law == LawKind::viscoelastic_hertz) {
        fit_detail::fit_hertz(problem, fit);
      } else {
        fit_detail::fit_speed_independent(problem, options, solver, fit);
      }
    } catch (const NumericalFailure& e) {
      fit.status = FitStatus::not_converged;
      fit.message = e.what();
    } catch (const InvalidInput& e) {
      // The data and options were checked above: a solve the solver refuses (a tolerance it cannot deliver
      // near critical damping) is this law's failure, not the input's.
      fit.status = FitStatus::not_converged;
      fit.message = e.what();
    }
    if (fit.status != FitStatus::converged) fit.value = std::numeric_limits<double>::quiet_NaN();
    if (!fit.model_eps.empty()) {
      add_information_criteria(problem, fit);
      fit.residuals = fit_detail::residual_tests(problem, fit.model_eps);
    }
    add_hertz_conversions(fit, options.k);
    result.fits.push_back(std::move(fit));
  }
  choose_best(result);
  return result;
}

}  // namespace restitution
