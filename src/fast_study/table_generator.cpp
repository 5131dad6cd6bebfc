// SPDX-License-Identifier: BSD-3-Clause
#include "fast_study/table_generator.hpp"

#include <fmt/core.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "reference/reference_solution.hpp"
#include "restitution/errors.hpp"
#include "restitution_series_study/series_coefficients.hpp"

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
  // T_{k-1}, T_k and the sum, lowest power first
  std::vector<Real> previous(n, 0);
  std::vector<Real> current(n, 0);
  std::vector<Real> mono(n, 0);
  previous[0] = 1;            // T_0
  if (n > 1) current[1] = 1;  // T_1
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
  [[nodiscard]] Real s_hi() const { return s_lo + static_cast<Real>(pieces.size()) / per_unit; }
  // The interpolant at s; `as_stored`: with its coefficients rounded to double, as the header holds them.
  [[nodiscard]] Real at(Real s, bool as_stored = false) const {
    const Real u = (s - s_lo) * per_unit;
    const long i = std::clamp(static_cast<long>(floorq(u)), 0L, static_cast<long>(pieces.size()) - 1);
    const Poly& p = pieces[static_cast<std::size_t>(i)];
    return horner(as_stored ? rounded(p) : p, 2 * (u - i) - 1);
  }
};

// s with g(s) = target by bisection (g decreases in s; checked by the caller).
Real solve_for_s(const Grid& g, Real target) {
  Real lo = g.s_lo;
  Real hi = g.s_hi();
  for (int k = 0; k < 130; ++k) {
    const Real mid = (lo + hi) / 2;
    (g.at(mid) > target ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

void make_inverse(const Grid& forward, const std::vector<Real>& nodes, double per_unit, EndTable& end) {
  const Real top = forward.at(forward.s_lo);
  const Real bottom = forward.at(forward.s_hi());
  for (Real s = forward.s_lo; s < forward.s_hi(); s += Real(1) / 100)
    if (forward.at(s + Real(1) / 100) >= forward.at(s))
      throw NumericalFailure(
          fmt::format("ln(eps/(1-eps)) is not decreasing near ln zeta = {}", static_cast<double>(s)));
  end.g_lo = std::ceil(static_cast<double>(bottom) * per_unit) / per_unit;
  const double g_hi = std::floor(static_cast<double>(top) * per_unit) / per_unit;
  end.inverse_intervals = static_cast<int>(std::lround((g_hi - end.g_lo) * per_unit));
  for (int i = 0; i < end.inverse_intervals; ++i) {
    std::vector<Real> values;
    values.reserve(nodes.size());
    for (const Real t : nodes)
      values.push_back(solve_for_s(forward, end.g_lo + (static_cast<Real>(i) + (t + 1) / 2) / per_unit));
    append(end.inverse, interpolate(values));
  }
}

// (1 − ε)/ζ as a polynomial in w = sqrt ζ, highest power first, from the recomputed series (docs/series.md):
// naive 1 − ε = −Σ c_k ζ^k, delayed recovery 1 − ε = −Σ h_k w^k.
std::vector<double> small_series(int terms, CollisionEnd end) {
  const series::Coefficients c = series::compute_coefficients(terms);
  const bool naive = end == CollisionEnd::naive;
  std::vector<double> p;
  for (int j = terms - 1; j >= 0; --j) {
    const auto k = static_cast<std::size_t>(j);
    const double value = naive ? (j % 2 == 0 ? -c.c[k / 2 + 1] : 0.0) : -c.h[k + 2];
    p.push_back(value == 0.0 ? 0.0 : value);  // never -0, which C reads back as the integer 0
  }
  return p;
}

// The ends of a reference solve: the delayed-recovery end always, the naive end where a table needs it.
EndSet reference_ends(bool with_naive) {
  return with_naive ? EndSet::both() : EndSet{CollisionEnd::delayed_recovery};
}

struct Errors {
  double eps = 0, tau = 0, x_max = 0, tau_max = 0;
};

double relative_eps_error(Real g_table, const ReferenceEnd& e) {
  const Real eps = 1 / (1 + expq(-g_table));
  const Real complement = 1 / (1 + expq(g_table));
  const Real bound = std::min(e.eps, e.one_minus_eps);
  return static_cast<double>(std::max(fabsq(eps - e.eps), fabsq(complement - e.one_minus_eps)) / bound);
}

double relative(Real value, Real exact) {
  return static_cast<double>(fabsq(value / exact - 1));
}

// The interpolants of every tabulated quantity, from reference solves at the Chebyshev nodes of each
// interval.
struct Fits {
  Grid g_naive, g_delayed, tau_naive, tau_delayed, x_max, tau_max;
  long solves = 0;
};

using Progress = std::function<void(std::size_t, std::size_t)>;

// Reports interval `done` of the fits and the checks together (2 passes over the delayed-recovery intervals).
void report(const Progress& progress, std::size_t done, std::size_t intervals) {
  if (progress) progress(done, 2 * intervals);
}

Fits fit(const GeneratorSettings& s, int naive_intervals, int naive_tau_intervals, int delayed_intervals,
         const std::vector<Real>& nodes, const Progress& progress) {
  const Grid empty{s.s_lo, s.per_unit, {}};
  Fits f{empty, empty, empty, empty, empty, empty, 0};
  for (int i = 0; i < delayed_intervals; ++i) {
    const bool with_naive = i < naive_tau_intervals;
    std::vector<Real> gn;
    std::vector<Real> gd;
    std::vector<Real> tn;
    std::vector<Real> td;
    std::vector<Real> xm;
    std::vector<Real> tm;
    for (const Real t : nodes) {
      const double zeta = std::exp(s.s_lo + (i + static_cast<double>((t + 1) / 2)) / s.per_unit);
      const ReferenceSolution r = hertz_reference(zeta, reference_ends(with_naive));
      ++f.solves;
      gd.push_back(logit(*r.ends[CollisionEnd::delayed_recovery]));
      td.push_back(logq(r.ends[CollisionEnd::delayed_recovery]->tau));
      xm.push_back(logq(r.x_max));
      tm.push_back(logq(r.tau_max));
      if (with_naive) {
        gn.push_back(logit(*r.ends[CollisionEnd::naive]));
        tn.push_back(logq(r.ends[CollisionEnd::naive]->tau));
      }
    }
    f.g_delayed.pieces.push_back(interpolate(gd));
    f.tau_delayed.pieces.push_back(interpolate(td));
    f.x_max.pieces.push_back(interpolate(xm));
    f.tau_max.pieces.push_back(interpolate(tm));
    if (i < naive_intervals) f.g_naive.pieces.push_back(interpolate(gn));
    if (with_naive) f.tau_naive.pieces.push_back(interpolate(tn));
    report(progress, static_cast<std::size_t>(i) + 1, static_cast<std::size_t>(delayed_intervals));
  }
  return f;
}

std::vector<double> stored(const Grid& grid) {
  std::vector<double> table;
  for (const Poly& p : grid.pieces) append(table, p);
  return table;
}

// Errors of the stored tables at random points of every interval, against fresh reference solves; one line
// for the settings.
std::string measured_errors(const GeneratorSettings& s, const Fits& f, long& solves,
                            const Progress& progress) {
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Errors naive;
  Errors delayed;
  long checks = 0;
  const auto worse = [](double& worst, double e) { worst = std::max(worst, e); };
  for (std::size_t i = 0; i < f.g_delayed.pieces.size(); ++i) {
    const bool with_naive = i < f.tau_naive.pieces.size();
    for (int c = 0; c < s.checks_per_interval; ++c, ++checks, ++solves) {
      const double zeta = std::exp(s.s_lo + (static_cast<double>(i) + unit(rng)) / s.per_unit);
      const Real sv = logq(zeta);
      const ReferenceSolution r = hertz_reference(zeta, reference_ends(with_naive));
      worse(delayed.eps,
            relative_eps_error(f.g_delayed.at(sv, true), *r.ends[CollisionEnd::delayed_recovery]));
      worse(delayed.tau,
            relative(expq(f.tau_delayed.at(sv, true)), r.ends[CollisionEnd::delayed_recovery]->tau));
      worse(delayed.x_max, relative(expq(f.x_max.at(sv, true)), r.x_max));
      worse(delayed.tau_max, relative(expq(f.tau_max.at(sv, true)), r.tau_max));
      if (with_naive)
        worse(naive.tau, relative(expq(f.tau_naive.at(sv, true)), r.ends[CollisionEnd::naive]->tau));
      if (i < f.g_naive.pieces.size())
        worse(naive.eps, relative_eps_error(f.g_naive.at(sv, true), *r.ends[CollisionEnd::naive]));
    }
    report(progress, f.g_delayed.pieces.size() + i + 1, f.g_delayed.pieces.size());
  }
  return fmt::format(
      "measured at {} random points (ln zeta uniform per interval), rounded tables in __float128:\n"
      "  max |d eps| / min(eps, 1-eps): naive {:.2e}, delayed recovery {:.2e}\n"
      "  max relative error of tau_c: naive {:.2e}, delayed recovery {:.2e}; x_max {:.2e}, tau_max {:.2e}",
      checks, naive.eps, delayed.eps, naive.tau, delayed.tau, delayed.x_max, delayed.tau_max);
}

// Errors of the large-ζ laws just above their switch points, against the reference; one line.
std::string law_errors(const GeneratorSettings& s, const TableData& d, long& solves) {
  double law_naive = 0;
  double law_delayed = 0;
  for (const double zeta : {std::exp(s.s_hi_naive), 10.0, 30.0}) {
    const ReferenceSolution r = hertz_reference(zeta);
    ++solves;
    const Real e = d.kappa * powq(zeta, -5);
    law_naive = std::max(law_naive, relative(e, r.ends[CollisionEnd::naive]->eps));
  }
  for (const double zeta : {std::exp(s.s_hi_delayed), 3e5, 1e6}) {
    const ReferenceSolution r = hertz_reference(zeta, EndSet{CollisionEnd::delayed_recovery});
    ++solves;
    const Real sv = logq(zeta);
    const Real delta = expq(-sv * 5 / 3);
    const Real e = d.x_m * delta * (1 - (delta / d.q) * (sv * 10 / 3 + d.log_a - Real(5) / 2));
    law_delayed = std::max(law_delayed, relative(e, r.ends[CollisionEnd::delayed_recovery]->eps));
  }
  return fmt::format(
      "  asymptotic laws, relative: naive at zeta = e^{} 10 30: {:.2e}; delayed at zeta = e^{} 3e5 1e6: "
      "{:.2e}",
      s.s_hi_naive, law_naive, s.s_hi_delayed, law_delayed);
}

// A law at s, in __float128, with its coefficients as stored (doubles).
Real law_at(const Law& w, Real s) {
  const Real delta = expq(-s * 5 / 3);
  return expq(w.power * s) * (w.c1 * s + w.c0 + delta * ((w.d2 * s + w.d1) * s + w.d0 + delta * w.e0));
}

// The solution of a small dense system, by Gaussian elimination with partial pivoting.
std::vector<Real> solve_linear(std::vector<std::vector<Real>> a, std::vector<Real> b) {
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (fabsq(a[i][k]) > fabsq(a[pivot][k])) pivot = i;
    std::swap(a[k], a[pivot]);
    std::swap(b[k], b[pivot]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const Real m = a[i][k] / a[k][k];
      for (std::size_t j = k; j < n; ++j) a[i][j] -= m * a[k][j];
      b[i] -= m * b[k];
    }
  }
  std::vector<Real> x(n);
  for (std::size_t k = n; k-- > 0;) {
    Real sum = b[k];
    for (std::size_t j = k + 1; j < n; ++j) sum -= a[k][j] * x[j];
    x[k] = sum / a[k][k];
  }
  return x;
}

struct Sample {
  Real s, value;
};

// The free constants of a law with the derived power and c1, through as many samples as it has: c0, d2, d1,
// d0 at the delayed-recovery end (the O(δ) drift of docs/asymptotics.md carries powers of ln ζ), c0, d0, e0
// at the naive end (corrections in powers of δ alone: measured, a δ ln ζ term fits worse by 1e4). The δ
// columns are scaled to order one so that the elimination sees comparable pivots.
Law fit_law(double power, double c1, CollisionEnd end, const std::vector<Sample>& at) {
  const bool naive = end == CollisionEnd::naive;
  std::vector<std::vector<Real>> a;
  std::vector<Real> b;
  const Real scale = expq(at.front().s * 5 / 3);
  for (const Sample& p : at) {
    const Real delta = expq(-p.s * 5 / 3) * scale;
    a.push_back(naive ? std::vector<Real>{1, delta, delta * delta}
                      : std::vector<Real>{1, delta * p.s * p.s, delta * p.s, delta});
    b.push_back(p.value * expq(-power * p.s) - c1 * p.s);
  }
  const std::vector<Real> x = solve_linear(a, b);
  const auto unscaled = [&](std::size_t k, int powers) {
    return static_cast<double>(x[k] * (powers == 1 ? scale : scale * scale));
  };
  if (naive) return {power, c1, static_cast<double>(x[0]), 0, 0, unscaled(1, 1), unscaled(2, 2)};
  return {power, c1, static_cast<double>(x[0]), unscaled(1, 1), unscaled(2, 1), unscaled(3, 1), 0};
}

double law_error(const Law& w, const Sample& p) {
  return relative(law_at(w, p.s), p.value);
}

// Reference values of the durations and of the maximal compression at ln ζ = s.
struct Durations {
  Sample naive_tau, delayed_tau, x_max, tau_max;
};

Durations durations_at(Real s, EndSet ends, long& solves) {
  const ReferenceSolution r = hertz_reference(static_cast<double>(expq(s)), ends);
  const bool naive = ends.contains(CollisionEnd::naive);
  ++solves;
  const Real sv = logq(r.parameter);  // the ζ solved, as rounded to double
  return {{sv, naive ? r.ends[CollisionEnd::naive]->tau : Real(0)},
          {sv, r.ends[CollisionEnd::delayed_recovery]->tau},
          {sv, r.x_max},
          {sv, r.tau_max}};
}

// The large-ζ laws of τ_c (both ends), x_max and τ_max (docs/fast.md derives them): their free constants
// fitted through reference solves from the end of each table on (naive: up to 0.5 above it, where the
// reference still costs seconds), their errors measured at reference
// solves between those (and, for x_max, whose law is derived completely, at all of them). One line each.
std::string fit_laws(const GeneratorSettings& s, TableData& d, long& solves) {
  EndTable& naive = d.ends[CollisionEnd::naive];
  EndTable& delayed = d.ends[CollisionEnd::delayed_recovery];
  const Real q = d.q;
  const Real log_a = d.log_a;
  const Real x_m = d.x_m;
  // x_max = X_m ζ^{-2/3} [1 − (δ/q)((5/3) ln ζ + ln A − ln q − 3/2)]
  d.x_max_law = {-2.0 / 3.0,
                 0,
                 d.x_m,
                 0,
                 static_cast<double>(-x_m * 5 / (3 * q)),
                 static_cast<double>(-(x_m / q) * (log_a - logq(q) - Real(3) / 2))};
  const EndSet delayed_only{CollisionEnd::delayed_recovery};
  std::vector<Durations> fit_delayed;
  std::vector<Durations> check_delayed;
  const double span = std::log(1e6) - s.s_hi_delayed;
  for (int k = 0; k < 4; ++k)
    fit_delayed.push_back(durations_at(s.s_hi_delayed + k * span / 3, delayed_only, solves));
  for (int k = 0; k < 3; ++k)
    check_delayed.push_back(durations_at(s.s_hi_delayed + (k + 0.5) * span / 3, delayed_only, solves));
  std::vector<Durations> fit_naive;
  std::vector<Durations> check_naive;
  for (const double ds : {0.0, 0.25, 0.5})
    fit_naive.push_back(durations_at(s.s_hi_naive_duration + ds, EndSet::both(), solves));
  for (const double ds : {0.1, 0.6})
    check_naive.push_back(durations_at(s.s_hi_naive_duration + ds, EndSet::both(), solves));

  const auto samples = [](const std::vector<Durations>& v, Sample Durations::*which) {
    std::vector<Sample> out;
    for (const Durations& p : v) out.push_back(p.*which);
    return out;
  };
  naive.tau_law = fit_law(1.0, 10.0 / 3.0, CollisionEnd::naive, samples(fit_naive, &Durations::naive_tau));
  delayed.tau_law = fit_law(-2.0 / 3.0, static_cast<double>(10 / (3 * q)), CollisionEnd::delayed_recovery,
                            samples(fit_delayed, &Durations::delayed_tau));
  d.tau_max_law = fit_law(-2.0 / 3.0, static_cast<double>(5 / (3 * q)), CollisionEnd::delayed_recovery,
                          samples(fit_delayed, &Durations::tau_max));

  const auto worst = [](const Law& w, const std::vector<Sample>& v) {
    double e = 0;
    for (const Sample& p : v) e = std::max(e, law_error(w, p));
    return e;
  };
  std::vector<Sample> x_max_all = samples(fit_delayed, &Durations::x_max);
  for (const Sample& p : samples(check_delayed, &Durations::x_max)) x_max_all.push_back(p);
  return fmt::format(
      "  laws of tau_c, x_max, tau_max above the tables, relative error at reference points between the fit "
      "points: tau_c naive {:.2e} (zeta = e^({}+0.1, +0.6)), tau_c delayed {:.2e}, tau_max {:.2e}; x_max "
      "(derived, at all 7 points from e^{}) {:.2e}\n"
      "  fitted c0 minus derived: tau_c delayed {:.2e} (ln A / q), tau_max {:.2e} ((ln A - ln q) / q)",
      worst(naive.tau_law, samples(check_naive, &Durations::naive_tau)), s.s_hi_naive_duration,
      worst(delayed.tau_law, samples(check_delayed, &Durations::delayed_tau)),
      worst(d.tau_max_law, samples(check_delayed, &Durations::tau_max)), s.s_hi_delayed,
      worst(d.x_max_law, x_max_all), delayed.tau_law.c0 - static_cast<double>(log_a / q),
      d.tau_max_law.c0 - static_cast<double>((log_a - logq(q)) / q));
}

}  // namespace

TableData generate_tables(const GeneratorSettings& s, const Progress& progress) {
  if (s.degree < kMinDegree || s.degree > kMaxDegree) {
    throw InvalidInput(fmt::format("degree {} is not in [{}, {}]", s.degree, kMinDegree, kMaxDegree));
  }
  if (!(s.per_unit >= 1 && s.per_unit <= kMaxPerUnit && s.per_unit == std::round(s.per_unit))) {
    throw InvalidInput(
        fmt::format("intervals per unit {} is not an integer in [1, {}]", s.per_unit, kMaxPerUnit));
  }
  // The laws above the tables are fitted to reference solves up to 0.6 above s_hi_naive_duration (the naive
  // reference stops at ζ = 1e3) and up to ζ = 1e6 (where the delayed one stops).
  if (!(s.s_lo >= -30 && s.s_lo < s.s_hi_naive && s.s_hi_naive <= s.s_hi_delayed && s.s_hi_naive <= 4 &&
        s.s_hi_naive <= s.s_hi_naive_duration && s.s_hi_naive_duration <= s.s_hi_delayed &&
        s.s_hi_naive_duration + 0.6 <= std::log(kReferenceNaiveZetaMax) &&
        s.s_hi_delayed <= std::log(1e6) - 1))
    throw InvalidInput(
        "the table range must satisfy -30 <= s_lo < s_hi_naive <= min(4, s_hi_naive_duration), "
        "s_hi_naive_duration <= min(s_hi_delayed, ln 1e3 - 0.6), s_hi_delayed <= ln 1e6 - 1");
  if (s.checks_per_interval < 0) throw InvalidInput("checks per interval must be >= 0");
  TableData d;
  EndTable& naive = d.ends[CollisionEnd::naive];
  EndTable& delayed = d.ends[CollisionEnd::delayed_recovery];
  d.degree = s.degree;
  d.small_terms = 8;
  d.s_lo = s.s_lo;
  d.per_unit = s.per_unit;
  d.zeta_lo = std::exp(s.s_lo);
  naive.intervals = static_cast<int>(std::lround((s.s_hi_naive - s.s_lo) * s.per_unit));
  delayed.intervals = static_cast<int>(std::lround((s.s_hi_delayed - s.s_lo) * s.per_unit));
  naive.tau_intervals = static_cast<int>(std::lround((s.s_hi_naive_duration - s.s_lo) * s.per_unit));
  delayed.tau_intervals = delayed.intervals;

  const std::vector<Real> nodes = chebyshev_nodes(s.degree);
  Fits f = fit(s, naive.intervals, naive.tau_intervals, delayed.intervals, nodes, progress);
  naive.logit = stored(f.g_naive);
  naive.log_tau = stored(f.tau_naive);
  delayed.logit = stored(f.g_delayed);
  delayed.log_tau = stored(f.tau_delayed);
  d.log_x_max = stored(f.x_max);
  d.log_tau_max = stored(f.tau_max);
  make_inverse(f.g_naive, nodes, s.per_unit, naive);
  make_inverse(f.g_delayed, nodes, s.per_unit, delayed);
  naive.small = small_series(d.small_terms, CollisionEnd::naive);
  delayed.small = small_series(d.small_terms, CollisionEnd::delayed_recovery);

  const ReferenceSolution zero = hertz_reference(0.0);
  const ReferenceSolution lo = hertz_reference(d.zeta_lo);
  naive.tau_zero = static_cast<double>(zero.ends[CollisionEnd::naive]->tau);
  delayed.tau_zero = static_cast<double>(zero.ends[CollisionEnd::delayed_recovery]->tau);
  naive.tau_lo = static_cast<double>(lo.ends[CollisionEnd::naive]->tau);
  delayed.tau_lo = static_cast<double>(lo.ends[CollisionEnd::delayed_recovery]->tau);
  d.x_max_zero = static_cast<double>(zero.x_max);
  d.tau_max_zero = static_cast<double>(zero.tau_max);
  d.x_max_lo = static_cast<double>(lo.x_max);
  d.tau_max_lo = static_cast<double>(lo.tau_max);

  // Large-ζ laws (docs/asymptotics.md). κ from the reference at ζ = 30, where the correction to κ ζ^-5 is
  // below 1e-30 relative.
  const ReferenceSolution at30 = hertz_reference(30.0);
  f.solves += 3;
  d.kappa = static_cast<double>(at30.ends[CollisionEnd::naive]->eps * powq(30, 5));
  const Real x_m = powq(Real(3) / 2, Real(2) / 3);
  d.x_m = static_cast<double>(x_m);
  d.q = static_cast<double>(cbrtq(Real(3) / 2));
  d.log_a = static_cast<double>(logq(x_m) + logq(2) + logq(3) / 2 - kPi / (2 * sqrtq(3)));

  const std::string measured = measured_errors(s, f, f.solves, progress);
  const std::string laws = law_errors(s, d, f.solves);
  const std::string duration_laws = fit_laws(s, d, f.solves);
  d.settings = fmt::format(
      "generator: restitution fast-table --degree {} --per-unit {} --s-lo {} --s-hi-naive {} "
      "--s-hi-naive-duration {} --s-hi-delayed {} --checks {} --seed {}\n"
      "values: __float128 Taylor reference engine (restitution/reference_solution.hpp, two orders agreeing "
      "to {:.0e}), {} solves\n"
      "forward: Chebyshev interpolation at {} nodes per interval of ln zeta, as monomials in t in [-1, 1]\n"
      "inverse: interpolation of ln zeta against ln(eps/(1-eps)) from the unrounded forward polynomials\n"
      "below zeta_lo: series of docs/series.md, {} terms in sqrt(zeta); above: kappa zeta^-5, two-term "
      "delayed law; tau_c naive tabulated to e^{}, then zeta ((10/3) s + c0 + d0 delta + e0 delta^2), s = "
      "ln zeta, delta = zeta^(-5/3); delayed tau_c, tau_max: zeta^(-2/3) (c1 s + c0 + delta (d2 s^2 + d1 s + "
      "d0)); x_max derived\n{}\n{}\n{}",
      s.degree, s.per_unit, s.s_lo, s.s_hi_naive, s.s_hi_naive_duration, s.s_hi_delayed,
      s.checks_per_interval, s.seed, kReferenceAgreement, f.solves, s.degree + 1, d.small_terms,
      s.s_hi_naive_duration, measured, laws, duration_laws);
  return d;
}

}  // namespace restitution::fast
