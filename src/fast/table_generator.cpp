#include "fast/table_generator.hpp"

#include <fmt/core.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "restitution/errors.hpp"
#include "restitution/reference_solution.hpp"
#include "restitution/series_coefficients.hpp"

namespace restitution::fast {
namespace {

using Real = __float128;
using Poly = std::vector<Real>;  // monomial coefficients in t ∈ [-1, 1], highest power first
const Real kPi = 4 * atanq(1);

Real horner(const Poly& p, Real t) {
  Real v = p[0];
  for (std::size_t k = 1; k < p.size(); ++k) v = v * t + p[k];
  return v;
}

Real logit(const ReferenceEnd& e) {
  return logq(e.eps) - logq(e.one_minus_eps);
}

// Chebyshev nodes of the first kind in t, where the interpolant is built.
std::vector<Real> chebyshev_nodes(int degree) {
  std::vector<Real> t(static_cast<std::size_t>(degree) + 1);
  for (std::size_t j = 0; j < t.size(); ++j)
    t[j] = cosq(kPi * (static_cast<Real>(j) + (Real(1) / 2)) / static_cast<Real>(t.size()));
  return t;
}

// The interpolant through values at chebyshev_nodes, as monomials (the tables evaluate it by Horner's rule;
// on intervals this short the coefficients decay, so nothing is lost to cancellation).
Poly interpolate(const std::vector<Real>& values) {
  const std::size_t n = values.size();
  std::vector<Real> cheb(n);
  for (std::size_t k = 0; k < n; ++k) {
    Real sum = 0;
    for (std::size_t j = 0; j < n; ++j)
      sum += values[j] *
             cosq(kPi * static_cast<Real>(k) * (static_cast<Real>(j) + (Real(1) / 2)) / static_cast<Real>(n));
    cheb[k] = sum * 2 / static_cast<Real>(n);
  }
  cheb[0] /= 2;
  std::vector<Real> previous(n, 0), current(n, 0), mono(n, 0);  // lowest power first
  previous[0] = 1;                                              // T_0
  if (n > 1) current[1] = 1;                                    // T_1
  for (std::size_t k = 0; k < n; ++k) {
    const std::vector<Real>& tk = k == 0 ? previous : current;
    for (std::size_t i = 0; i < n; ++i) mono[i] += cheb[k] * tk[i];
    if (k >= 1 && k + 1 < n) {  // T_{k+1} = 2 t T_k − T_{k−1}
      std::vector<Real> next(n, 0);
      for (std::size_t i = 0; i + 1 < n; ++i) next[i + 1] = 2 * current[i];
      for (std::size_t i = 0; i < n; ++i) next[i] -= previous[i];
      previous = current;
      current = next;
    }
  }
  return {mono.rbegin(), mono.rend()};
}

void append(std::vector<double>& table, const Poly& p) {
  for (const Real c : p) table.push_back(static_cast<double>(c));
}

Poly rounded(const Poly& p) {
  Poly r;
  for (const Real c : p) r.push_back(static_cast<double>(c));
  return r;
}

// The forward polynomials of one quantity on the grid, unrounded, for the inverse and the checks.
struct Grid {
  double s_lo, per_unit;
  std::vector<Poly> pieces;
  [[nodiscard]] Real at(Real s) const {
    const Real u = (s - s_lo) * per_unit;
    const long i = std::clamp(static_cast<long>(floorq(u)), 0L, static_cast<long>(pieces.size()) - 1);
    return horner(pieces[static_cast<std::size_t>(i)], 2 * (u - i) - 1);
  }
};

// s with g(s) = target by bisection (g decreases in s; checked by the caller).
Real solve_for_s(const Grid& g, Real target) {
  Real lo = g.s_lo, hi = g.s_lo + static_cast<Real>(g.pieces.size()) / g.per_unit;
  for (int k = 0; k < 130; ++k) {
    const Real mid = (lo + hi) / 2;
    (g.at(mid) > target ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

void make_inverse(const Grid& forward, const std::vector<Real>& nodes, double per_unit, EndTable& end) {
  const Real top = forward.at(forward.s_lo);
  const Real bottom = forward.at(forward.s_lo + static_cast<Real>(forward.pieces.size()) / per_unit);
  for (Real s = forward.s_lo; s < forward.s_lo + static_cast<Real>(forward.pieces.size()) / per_unit;
       s += (Real(1) / 100))
    if (forward.at(s + (Real(1) / 100)) >= forward.at(s))
      throw NumericalFailure(
          fmt::format("ln(eps/(1-eps)) is not decreasing near ln zeta = {}", static_cast<double>(s)));
  end.g_lo = std::ceil(static_cast<double>(bottom) * per_unit) / per_unit;
  const double g_hi = std::floor(static_cast<double>(top) * per_unit) / per_unit;
  end.inverse_intervals = static_cast<int>(std::lround((g_hi - end.g_lo) * per_unit));
  for (int i = 0; i < end.inverse_intervals; ++i) {
    std::vector<Real> values;
    for (const Real t : nodes)
      values.push_back(solve_for_s(forward, end.g_lo + (static_cast<Real>(i) + (t + 1) / 2) / per_unit));
    append(end.inverse, interpolate(values));
  }
}

// (1 − ε)/ζ as a polynomial in w = sqrt ζ, highest power first, from the recomputed series (docs/series.md):
// naive 1 − ε = −Σ c_k ζ^k, delayed recovery 1 − ε = −Σ h_k w^k.
std::vector<double> small_series(int terms, bool naive) {
  const series::Coefficients c = series::compute_coefficients(terms);
  std::vector<double> p;
  for (int j = terms - 1; j >= 0; --j) {
    const auto k = static_cast<std::size_t>(j);
    const double value = naive ? (j % 2 == 0 ? -c.c[k / 2 + 1] : 0.0) : -c.h[k + 2];
    p.push_back(value == 0.0 ? 0.0 : value);  // never -0, which C reads back as the integer 0
  }
  return p;
}

struct Errors {
  double eps = 0, tau = 0, x_max = 0, tau_max = 0;
};

double relative_eps_error(Real g_table, const ReferenceEnd& e) {
  const Real eps = 1 / (1 + expq(-g_table)), complement = 1 / (1 + expq(g_table));
  const Real bound = std::min(e.eps, e.one_minus_eps);
  return static_cast<double>(std::max(fabsq(eps - e.eps), fabsq(complement - e.one_minus_eps)) / bound);
}

double relative(Real value, Real exact) {
  return static_cast<double>(fabsq(value / exact - 1));
}

}  // namespace

TableData generate_tables(const GeneratorSettings& s) {
  if (s.degree < 2 || s.degree > 30) throw InvalidInput(fmt::format("degree {} is not in [2, 30]", s.degree));
  if (!(s.per_unit >= 1 && s.per_unit <= 64 && s.per_unit == std::round(s.per_unit)))
    throw InvalidInput(fmt::format("intervals per unit {} is not an integer in [1, 64]", s.per_unit));
  if (!(s.s_lo >= -30 && s.s_lo < s.s_hi_naive && s.s_hi_naive <= s.s_hi_delayed && s.s_hi_naive <= 4 &&
        s.s_hi_delayed <= std::log(1e6)))
    throw InvalidInput(
        "the table range must satisfy -30 <= s_lo < s_hi_naive <= min(4, s_hi_delayed), s_hi_delayed <= ln "
        "1e6");
  TableData d;
  d.degree = s.degree;
  d.small_terms = 8;
  d.s_lo = s.s_lo;
  d.per_unit = s.per_unit;
  d.zeta_lo = std::exp(s.s_lo);
  d.naive.intervals = static_cast<int>(std::lround((s.s_hi_naive - s.s_lo) * s.per_unit));
  d.delayed.intervals = static_cast<int>(std::lround((s.s_hi_delayed - s.s_lo) * s.per_unit));

  const std::vector<Real> nodes = chebyshev_nodes(s.degree);
  Grid g_naive{s.s_lo, s.per_unit, {}}, g_delayed{s.s_lo, s.per_unit, {}};
  Grid tau_naive = g_naive, tau_delayed = g_naive, x_max = g_naive, tau_max = g_naive;
  long solves = 0;
  for (int i = 0; i < d.delayed.intervals; ++i) {
    const bool with_naive = i < d.naive.intervals;
    std::vector<Real> gn, gd, tn, td, xm, tm;
    for (const Real t : nodes) {
      const double zeta = std::exp(s.s_lo + (i + static_cast<double>((t + 1) / 2)) / s.per_unit);
      // the node in s as the table sees it: ln of the ζ actually solved
      const ReferenceSolution r = hertz_reference(zeta, with_naive);
      ++solves;
      gd.push_back(logit(*r.delayed_recovery));
      td.push_back(logq(r.delayed_recovery->tau));
      xm.push_back(logq(r.x_max));
      tm.push_back(logq(r.tau_max));
      if (with_naive) {
        gn.push_back(logit(*r.naive));
        tn.push_back(logq(r.naive->tau));
      }
    }
    g_delayed.pieces.push_back(interpolate(gd));
    tau_delayed.pieces.push_back(interpolate(td));
    x_max.pieces.push_back(interpolate(xm));
    tau_max.pieces.push_back(interpolate(tm));
    if (with_naive) {
      g_naive.pieces.push_back(interpolate(gn));
      tau_naive.pieces.push_back(interpolate(tn));
    }
  }
  for (const Poly& p : g_naive.pieces) append(d.naive.logit, p);
  for (const Poly& p : tau_naive.pieces) append(d.naive.log_tau, p);
  for (const Poly& p : g_delayed.pieces) append(d.delayed.logit, p);
  for (const Poly& p : tau_delayed.pieces) append(d.delayed.log_tau, p);
  for (const Poly& p : x_max.pieces) append(d.log_x_max, p);
  for (const Poly& p : tau_max.pieces) append(d.log_tau_max, p);
  make_inverse(g_naive, nodes, s.per_unit, d.naive);
  make_inverse(g_delayed, nodes, s.per_unit, d.delayed);
  d.naive.small = small_series(d.small_terms, true);
  d.delayed.small = small_series(d.small_terms, false);

  const ReferenceSolution zero = hertz_reference(0.0), lo = hertz_reference(d.zeta_lo);
  solves += 2;
  d.naive.tau_zero = static_cast<double>(zero.naive->tau);
  d.delayed.tau_zero = static_cast<double>(zero.delayed_recovery->tau);
  d.naive.tau_lo = static_cast<double>(lo.naive->tau);
  d.delayed.tau_lo = static_cast<double>(lo.delayed_recovery->tau);
  d.x_max_zero = static_cast<double>(zero.x_max);
  d.tau_max_zero = static_cast<double>(zero.tau_max);
  d.x_max_lo = static_cast<double>(lo.x_max);
  d.tau_max_lo = static_cast<double>(lo.tau_max);

  // Large-ζ laws (docs/asymptotics.md). κ from the reference at ζ = 30, where the correction to κ ζ^-5 is
  // below 1e-30 relative.
  const ReferenceSolution at30 = hertz_reference(30.0);
  ++solves;
  d.kappa = static_cast<double>(at30.naive->eps * powq(30, 5));
  const Real x_m = powq((Real(3) / 2), (Real(2) / 3)), q = cbrtq((Real(3) / 2));
  d.x_m = static_cast<double>(x_m);
  d.q = static_cast<double>(q);
  d.log_a = static_cast<double>(logq(x_m) + logq(2) + logq(3) / 2 - kPi / (2 * sqrtq(3)));

  // Checks at random points of every interval, against fresh reference solves, through the rounded tables.
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Errors naive_err, delayed_err;
  auto rounded_at = [&](const Grid& grid, Real sv) {
    Grid r{grid.s_lo, grid.per_unit, {}};
    const Real u = (sv - grid.s_lo) * grid.per_unit;
    const long i = std::clamp(static_cast<long>(floorq(u)), 0L, static_cast<long>(grid.pieces.size()) - 1);
    return horner(rounded(grid.pieces[static_cast<std::size_t>(i)]), 2 * (u - i) - 1);
  };
  long checks = 0;
  for (int i = 0; i < d.delayed.intervals; ++i) {
    const bool with_naive = i < d.naive.intervals;
    for (int c = 0; c < s.checks_per_interval; ++c) {
      const double zeta = std::exp(s.s_lo + (i + unit(rng)) / s.per_unit);
      const Real sv = logq(zeta);
      const ReferenceSolution r = hertz_reference(zeta, with_naive);
      ++solves;
      ++checks;
      delayed_err.eps =
          std::max(delayed_err.eps, relative_eps_error(rounded_at(g_delayed, sv), *r.delayed_recovery));
      delayed_err.tau =
          std::max(delayed_err.tau, relative(expq(rounded_at(tau_delayed, sv)), r.delayed_recovery->tau));
      delayed_err.x_max = std::max(delayed_err.x_max, relative(expq(rounded_at(x_max, sv)), r.x_max));
      delayed_err.tau_max = std::max(delayed_err.tau_max, relative(expq(rounded_at(tau_max, sv)), r.tau_max));
      if (with_naive) {
        naive_err.eps = std::max(naive_err.eps, relative_eps_error(rounded_at(g_naive, sv), *r.naive));
        naive_err.tau = std::max(naive_err.tau, relative(expq(rounded_at(tau_naive, sv)), r.naive->tau));
      }
    }
  }
  // The asymptotic laws just above their switch points.
  double law_naive = 0, law_delayed = 0;
  for (const double zeta : {std::exp(s.s_hi_naive), 10.0, 30.0}) {
    const ReferenceSolution r = hertz_reference(zeta, true);
    ++solves;
    const Real e = d.kappa * powq(zeta, -5);
    law_naive = std::max(law_naive, static_cast<double>(fabsq(e - r.naive->eps) / r.naive->eps));
  }
  for (const double zeta : {std::exp(s.s_hi_delayed), 3e5, 1e6}) {
    const ReferenceSolution r = hertz_reference(zeta, false);
    ++solves;
    const Real sv = logq(zeta), delta = expq(-sv * 5 / 3);
    const Real e = x_m * delta * (1 - (delta / q) * (sv * 10 / 3 + d.log_a - (Real(5) / 2)));
    law_delayed = std::max(law_delayed,
                           static_cast<double>(fabsq(e - r.delayed_recovery->eps) / r.delayed_recovery->eps));
  }

  d.settings = fmt::format(
      "generator: restitution fast-table --degree {} --per-unit {} --s-lo {} --s-hi-naive {} --s-hi-delayed "
      "{} "
      "--checks {} --seed {}\n"
      "values: __float128 Taylor reference engine (restitution/reference_solution.hpp, two orders agreeing "
      "to {:.0e}), {} solves\n"
      "forward: Chebyshev interpolation at {} nodes per interval of ln zeta, as monomials in t in [-1, 1]\n"
      "inverse: interpolation of ln zeta against ln(eps/(1-eps)) from the unrounded forward polynomials\n"
      "below zeta_lo: series of docs/series.md, {} terms in sqrt(zeta); above: kappa zeta^-5, two-term "
      "delayed law\n"
      "measured at {} random points (ln zeta uniform per interval), rounded tables in __float128:\n"
      "  max |d eps| / min(eps, 1-eps): naive {:.2e}, delayed recovery {:.2e}\n"
      "  max relative error of tau_c: naive {:.2e}, delayed recovery {:.2e}; x_max {:.2e}, tau_max {:.2e}\n"
      "  asymptotic laws, relative: naive at zeta = e^{} 10 30: {:.2e}; delayed at zeta = e^{} 3e5 1e6: "
      "{:.2e}",
      s.degree, s.per_unit, s.s_lo, s.s_hi_naive, s.s_hi_delayed, s.checks_per_interval, s.seed,
      kReferenceAgreement, solves, s.degree + 1, d.small_terms, checks, naive_err.eps, delayed_err.eps,
      naive_err.tau, delayed_err.tau, delayed_err.x_max, delayed_err.tau_max, s.s_hi_naive, law_naive,
      s.s_hi_delayed, law_delayed);
  return d;
}

}  // namespace restitution::fast
