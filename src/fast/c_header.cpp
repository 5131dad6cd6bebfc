// SPDX-License-Identifier: BSD-3-Clause
#include "fast/c_header.hpp"

#include <fmt/core.h>

#include <sstream>
#include <vector>

namespace restitution::fast {
namespace {

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
/* SPDX-License-Identifier: BSD-3-Clause (the license of the project "restitution", which made this file) */
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
  out << estrin_function(d.degree) << evaluation_code();
  return out.str();
}

}  // namespace restitution::fast
