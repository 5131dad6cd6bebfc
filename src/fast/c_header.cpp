#include "fast/c_header.hpp"

#include <fmt/core.h>

#include <sstream>
#include <vector>

namespace restitution::fast {
namespace {

// The evaluation, written once in C99 for the library and the exported header alike. Why each step is there:
// docs/fast.md. The series by Horner's rule, the table polynomials by Estrin's scheme (estrin_function).
constexpr const char* kEvaluation = R"C(
static inline double restitution_fast_poly_(const double *c, int terms, double t) {
  double p = c[0];
  int k;
  for (k = 1; k < terms; ++k) p = p * t + c[k];
  return p;
}

/* A piecewise table at u = (x - start) * RESTITUTION_FAST_PER_UNIT, 0 <= u <= intervals (clamped). */
static inline double restitution_fast_piece_(const double *coef, int intervals, double u) {
  int i = (int)u;
  if (i > intervals - 1) i = intervals - 1;
  if (i < 0) i = 0;
  return restitution_fast_estrin_(coef + i * (RESTITUTION_FAST_DEGREE + 1), 2.0 * (u - (double)i) - 1.0);
}

/* eps (complement = 0) or 1 - eps (complement = 1); NaN for zeta < 0 or NaN. */
static inline double restitution_fast_eps_(const restitution_fast_end_ *e, double zeta, int complement) {
  double s, u, g, d, y;
  if (!(zeta >= 0.0)) return NAN;
  if (zeta < RESTITUTION_FAST_ZETA_LO) {
    y = zeta * restitution_fast_poly_(e->small, RESTITUTION_FAST_SMALL_TERMS, sqrt(zeta));
    return complement ? y : 1.0 - y;
  }
  if (zeta > 1.79769313486231570e308) return complement ? 1.0 : 0.0;
  s = log(zeta);
  u = (s - RESTITUTION_FAST_S_LO) * RESTITUTION_FAST_PER_UNIT;
  if (u < (double)e->intervals) {
    g = restitution_fast_piece_(e->logit, e->intervals, u);
    return 1.0 / (1.0 + exp(complement ? g : -g));
  }
  if (e->naive) {
    d = RESTITUTION_FAST_KAPPA * exp(-5.0 * s);
  } else {
    y = exp(-(5.0 / 3.0) * s);
    d = RESTITUTION_FAST_X_M * y *
        (1.0 - (y / RESTITUTION_FAST_Q) * ((10.0 / 3.0) * s + RESTITUTION_FAST_LOG_A - 2.5));
  }
  return complement ? 1.0 - d : d;
}

/* zeta with eps(zeta) = eps, eps in (0, 1]; NaN otherwise. */
static inline double restitution_fast_zeta_(const restitution_fast_end_ *e, double eps) {
  double g, u, y, z, r;
  int k;
  if (!(eps > 0.0 && eps <= 1.0)) return NAN;
  g = log(eps / (1.0 - eps));
  u = (g - e->g_lo) * RESTITUTION_FAST_PER_UNIT;
  if (u >= 0.0 && u <= (double)e->inverse_intervals)
    return exp(restitution_fast_piece_(e->inverse, e->inverse_intervals, u));
  if (u > 0.0) { /* small zeta: 1 - eps = zeta P(sqrt zeta), solved by fixed point */
    y = 1.0 - eps;
    z = y / e->small[RESTITUTION_FAST_SMALL_TERMS - 1];
    for (k = 0; k < 2; ++k) z = y / restitution_fast_poly_(e->small, RESTITUTION_FAST_SMALL_TERMS, sqrt(z));
    return z;
  }
  if (e->naive) return exp(0.2 * (log(RESTITUTION_FAST_KAPPA) - log(eps)));
  r = eps / RESTITUTION_FAST_X_M; /* delta = zeta^(-5/3), solved by fixed point */
  z = r;
  for (k = 0; k < 3; ++k) z = r / (1.0 - (z / RESTITUTION_FAST_Q) * (-2.0 * log(z) + RESTITUTION_FAST_LOG_A - 2.5));
  return exp(-0.6 * log(z));
}

/* A large-zeta law (docs/fast.md), delta = zeta^(-5/3):
   e^(power s) [c1 s + c0 + delta (d2 s^2 + d1 s + d0) + delta^2 e0]. */
static inline double restitution_fast_law_at_(const restitution_fast_law_ *w, double s) {
  double delta = exp(-(5.0 / 3.0) * s);
  return exp(w->power * s) * (w->c1 * s + w->c0 + delta * ((w->d2 * s + w->d1) * s + w->d0 + delta * w->e0));
}

/* A table of ln f on the forward grid, f linear between zeta = 0 and zeta_lo, the law above; NaN for
   negative or NaN zeta. */
static inline double restitution_fast_log_table_(const double *coef, int intervals, double zero, double lo,
                                                 const restitution_fast_law_ *law, double zeta) {
  double s, u;
  if (!(zeta >= 0.0)) return NAN;
  if (zeta < RESTITUTION_FAST_ZETA_LO) return zero + (lo - zero) * (zeta / RESTITUTION_FAST_ZETA_LO);
  if (zeta > 1.79769313486231570e308) return law->power > 0.0 ? HUGE_VAL : 0.0;
  s = log(zeta);
  u = (s - RESTITUTION_FAST_S_LO) * RESTITUTION_FAST_PER_UNIT;
  if (u < (double)intervals) return exp(restitution_fast_piece_(coef, intervals, u));
  return restitution_fast_law_at_(law, s);
}

/* The public functions. */
static inline double restitution_eps_naive(double zeta) {
  return restitution_fast_eps_(&restitution_fast_naive_, zeta, 0);
}
static inline double restitution_eps_delayed_recovery(double zeta) {
  return restitution_fast_eps_(&restitution_fast_delayed_, zeta, 0);
}
static inline double restitution_one_minus_eps_naive(double zeta) {
  return restitution_fast_eps_(&restitution_fast_naive_, zeta, 1);
}
static inline double restitution_one_minus_eps_delayed_recovery(double zeta) {
  return restitution_fast_eps_(&restitution_fast_delayed_, zeta, 1);
}
static inline double restitution_zeta_from_eps_naive(double eps) {
  return restitution_fast_zeta_(&restitution_fast_naive_, eps);
}
static inline double restitution_zeta_from_eps_delayed_recovery(double eps) {
  return restitution_fast_zeta_(&restitution_fast_delayed_, eps);
}
static inline double restitution_duration_naive(double zeta) {
  const restitution_fast_end_ *e = &restitution_fast_naive_;
  return restitution_fast_log_table_(e->log_tau, e->tau_intervals, e->tau_zero, e->tau_lo, &e->tau_law, zeta);
}
static inline double restitution_duration_delayed_recovery(double zeta) {
  const restitution_fast_end_ *e = &restitution_fast_delayed_;
  return restitution_fast_log_table_(e->log_tau, e->tau_intervals, e->tau_zero, e->tau_lo, &e->tau_law, zeta);
}
static inline double restitution_max_compression(double zeta) {
  return restitution_fast_log_table_(restitution_fast_log_x_max_, restitution_fast_delayed_.tau_intervals,
                                     RESTITUTION_FAST_X_MAX_ZERO, RESTITUTION_FAST_X_MAX_LO,
                                     &restitution_fast_x_max_law_, zeta);
}
static inline double restitution_max_compression_time(double zeta) {
  return restitution_fast_log_table_(restitution_fast_log_tau_max_, restitution_fast_delayed_.tau_intervals,
                                     RESTITUTION_FAST_TAU_MAX_ZERO, RESTITUTION_FAST_TAU_MAX_LO,
                                     &restitution_fast_tau_max_law_, zeta);
}

/* clang-format on */
/* NOLINTEND */
#endif /* RESTITUTION_FAST_H */
)C";

// A polynomial of the tables (highest power first) by Estrin's scheme, written out for the degree: pairs
// combined with t, then with t^2, t^4, ...; the independent pairs shorten the chain of dependent operations
// that Horner's rule makes.
std::string estrin_function(int degree) {
  std::string out =
      "\n/* Estrin's scheme for the table polynomials, written out for RESTITUTION_FAST_DEGREE. */\n"
      "static inline double restitution_fast_estrin_(const double *c, double t) {\n  double x0 = t;\n";
  std::vector<std::string> terms;  // lowest power first
  for (int k = 0; k <= degree; ++k) terms.push_back(fmt::format("c[{}]", degree - k));
  for (int level = 0; terms.size() > 1; ++level) {
    std::vector<std::string> next;
    for (std::size_t i = 0; 2 * i + 1 < terms.size(); ++i) {
      next.push_back(fmt::format("p{}_{}", level, i));
      out +=
          fmt::format("  double {} = {} + {} * x{};\n", next.back(), terms[2 * i], terms[2 * i + 1], level);
    }
    if (terms.size() % 2 == 1) next.push_back(terms.back());
    if (next.size() > 1) out += fmt::format("  double x{} = x{} * x{};\n", level + 1, level, level);
    terms = next;
  }
  return out + "  return " + terms[0] + ";\n}\n";
}

std::string number(double value) {
  return fmt::format("{:.17g}", value);
}

void define(std::ostringstream& out, const char* name, double value) {
  out << "#define RESTITUTION_FAST_" << name << " (" << number(value) << ")\n";
}

// A static array, `per_line` numbers a line (one polynomial a line for the tables).
void array(std::ostringstream& out, const std::string& name, const std::vector<double>& values,
           int per_line) {
  out << "static const double " << name << "[" << values.size() << "] = {";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i % static_cast<std::size_t>(per_line) == 0) out << "\n ";
    out << ' ' << number(values[i]) << (i + 1 < values.size() ? "," : "");
  }
  out << "};\n";
}

// The end's tag in the private C names (trailing underscore): restitution_fast_naive_,
// restitution_fast_delayed_. The public functions are spelled with end_key (…_delayed_recovery); the short
// tag only keeps the table names short, and changing it would change every committed generated header.
std::string c_tag(CollisionEnd end) {
  return end == CollisionEnd::naive ? "naive" : "delayed";
}

void end_tables(std::ostringstream& out, CollisionEnd end, const EndTable& e, int per_line) {
  const std::string tag = c_tag(end);
  array(out, "restitution_fast_" + tag + "_logit_", e.logit, per_line);
  array(out, "restitution_fast_" + tag + "_log_tau_", e.log_tau, per_line);
  array(out, "restitution_fast_" + tag + "_inverse_", e.inverse, per_line);
  array(out, "restitution_fast_" + tag + "_small_", e.small, 4);
}

std::string law(const Law& w) {
  return fmt::format("{{{}, {}, {}, {}, {}, {}, {}}}", number(w.power), number(w.c1), number(w.c0),
                     number(w.d2), number(w.d1), number(w.d0), number(w.e0));
}

void end_struct(std::ostringstream& out, CollisionEnd end, const EndTable& e) {
  const std::string p = "restitution_fast_" + c_tag(end);
  out << "static const restitution_fast_end_ " << p << "_ = {" << e.intervals << ", " << p << "_logit_, "
      << e.tau_intervals << ", " << p << "_log_tau_, " << law(e.tau_law) << ", " << number(e.g_lo) << ", "
      << e.inverse_intervals << ", " << p << "_inverse_, " << p << "_small_, " << number(e.tau_zero) << ", "
      << number(e.tau_lo) << ", " << (end == CollisionEnd::naive ? 1 : 0) << "};\n";
}

}  // namespace

std::string c_header_text(const TableData& d) {
  std::ostringstream out;
  out << R"(/* clang-format off */
/* restitution_fast.h: the coefficient of normal restitution eps of viscoelastic spheres, certified fast.
 * Self-contained C99 (also valid C++), needs only <math.h> (link with -lm). Made by the project
 * "restitution" (`restitution export c-header`); the method and the accuracy are in its docs/fast.md.
 *
 * Natural units: x'' + zeta x' sqrt(x) + x^(3/2) = 0, x(0) = 0, x'(0) = 1, eps = -x'(end); zeta = beta v^(1/5)
 * (Schwager & Poeschel 2008). Two ends of the collision: naive (overlap x = 0) and delayed recovery (force 0).
 *
 *   double restitution_eps_naive(double zeta)                     eps,      zeta >= 0 (+inf gives 0)
 *   double restitution_eps_delayed_recovery(double zeta)
 *   double restitution_one_minus_eps_naive(double zeta)           1 - eps, to its own relative accuracy
 *   double restitution_one_minus_eps_delayed_recovery(double zeta)
 *   double restitution_zeta_from_eps_naive(double eps)            the inverse, eps in (0, 1] (1 gives 0)
 *   double restitution_zeta_from_eps_delayed_recovery(double eps)
 *   double restitution_duration_naive(double zeta)                collision duration tau_c, zeta >= 0
 *   double restitution_duration_delayed_recovery(double zeta)
 *   double restitution_max_compression(double zeta)               x_max and its time tau_max, zeta >= 0
 *   double restitution_max_compression_time(double zeta)
 *
 * Every function returns NaN for an argument outside its domain (negative or NaN zeta, eps outside (0, 1]).
 * Accuracy: |eps - exact| <= 1e-13 min(eps, 1 - eps) for zeta in [0, 1e6] (delayed recovery) and [0, 1e5]
 * (naive); beyond, the error of the asymptotic law (naive: exponentially small; delayed recovery:
 * about 0.4 (zeta^(-5/3) ln zeta^(-5/3))^2 relative). The inverse returns a zeta whose eps meets the same bound.
 * tau_c, x_max, tau_max: the relative errors measured against the reference, in RESTITUTION_FAST_SETTINGS.
 */
#ifndef RESTITUTION_FAST_H
#define RESTITUTION_FAST_H
/* NOLINTBEGIN: C99, which C++ linters would rewrite into C++ */
#include <math.h>

/* How these tables were made (the generator's settings and measured errors): */
#define RESTITUTION_FAST_SETTINGS \
)";
  std::istringstream lines(d.settings);
  std::string line;
  std::vector<std::string> all;
  while (std::getline(lines, line)) all.push_back(line);
  for (std::size_t i = 0; i < all.size(); ++i)
    out << "  \"" << all[i] << "\\n\"" << (i + 1 < all.size() ? " \\" : "") << "\n";
  out << "\n#define RESTITUTION_FAST_DEGREE " << d.degree << "\n";
  out << "#define RESTITUTION_FAST_SMALL_TERMS " << d.small_terms << "\n";
  define(out, "S_LO", d.s_lo);
  define(out, "PER_UNIT", d.per_unit);
  define(out, "ZETA_LO", d.zeta_lo);
  define(out, "KAPPA", d.kappa);
  define(out, "X_M", d.x_m);
  define(out, "Q", d.q);
  define(out, "LOG_A", d.log_a);
  define(out, "X_MAX_ZERO", d.x_max_zero);
  define(out, "X_MAX_LO", d.x_max_lo);
  define(out, "TAU_MAX_ZERO", d.tau_max_zero);
  define(out, "TAU_MAX_LO", d.tau_max_lo);
  out << R"(
/* A large-zeta law of a duration or of the maximal compression. */
typedef struct {
  double power, c1, c0, d2, d1, d0, e0;
} restitution_fast_law_;

/* One end of the collision: forward tables in s = ln zeta, inverse table in g = ln(eps / (1 - eps)). */
typedef struct {
  int intervals;
  const double *logit;
  int tau_intervals;
  const double *log_tau;
  restitution_fast_law_ tau_law;
  double g_lo;
  int inverse_intervals;
  const double *inverse, *small;
  double tau_zero, tau_lo;
  int naive;
} restitution_fast_end_;

)";
  const int per_line = d.degree + 1;
  for (const CollisionEnd end : kCollisionEnds) end_tables(out, end, d.ends[end], per_line);
  array(out, "restitution_fast_log_x_max_", d.log_x_max, per_line);
  array(out, "restitution_fast_log_tau_max_", d.log_tau_max, per_line);
  for (const CollisionEnd end : kCollisionEnds) end_struct(out, end, d.ends[end]);
  out << "static const restitution_fast_law_ restitution_fast_x_max_law_ = " << law(d.x_max_law) << ";\n";
  out << "static const restitution_fast_law_ restitution_fast_tau_max_law_ = " << law(d.tau_max_law) << ";\n";
  out << estrin_function(d.degree) << kEvaluation;
  return out.str();
}

}  // namespace restitution::fast
