// SPDX-License-Identifier: BSD-3-Clause
// The library's fast ε(ζ): thin checked wrappers around the C99 evaluation of the generated header, so that
// the library and the exported header compute the same bits.
#include "restitution/fast.hpp"

#include <fmt/core.h>

#include <cmath>

#include "fast/c_header.hpp"
#include "restitution/errors.hpp"

#include "fast/fast_table.h"  // generated C99 (`restitution fast-table`)

namespace restitution::fast {
namespace {

const restitution_fast_end_& table_of(CollisionEnd end) {
  return end == CollisionEnd::naive ? restitution_fast_naive_ : restitution_fast_delayed_;
}

void check_zeta(double zeta) {
  if (!(zeta >= 0.0)) throw InvalidInput(fmt::format("zeta = {} must be >= 0", zeta));
}

std::vector<double> values(const double* data, int count) {
  return {data, data + count};
}

Law law(const restitution_fast_law_& w) {
  return {w.power, w.c1, w.c0, w.d2, w.d1, w.d0, w.e0};
}

EndTable end_table(const restitution_fast_end_& e) {
  const int per_piece = RESTITUTION_FAST_DEGREE + 1;
  EndTable t;
  t.intervals = e.intervals;
  t.logit = values(e.logit, e.intervals * per_piece);
  t.tau_intervals = e.tau_intervals;
  t.log_tau = values(e.log_tau, e.tau_intervals * per_piece);
  t.tau_law = law(e.tau_law);
  t.g_lo = e.g_lo;
  t.inverse_intervals = e.inverse_intervals;
  t.inverse = values(e.inverse, e.inverse_intervals * per_piece);
  t.small = values(e.small, RESTITUTION_FAST_SMALL_TERMS);
  t.tau_zero = e.tau_zero;
  t.tau_lo = e.tau_lo;
  return t;
}

}  // namespace

double eps(double zeta, CollisionEnd end) {
  check_zeta(zeta);
  return restitution_fast_eps_(&table_of(end), zeta, 0);
}

double one_minus_eps(double zeta, CollisionEnd end) {
  check_zeta(zeta);
  return restitution_fast_eps_(&table_of(end), zeta, 1);
}

double zeta_from_eps(double eps, CollisionEnd end) {
  if (!(eps > 0.0 && eps <= 1.0)) throw InvalidInput(fmt::format("eps = {} is not in (0, 1]", eps));
  return restitution_fast_zeta_(&table_of(end), eps);
}

double collision_duration(double zeta, CollisionEnd end) {
  check_zeta(zeta);
  return end == CollisionEnd::naive ? restitution_duration_naive(zeta)
                                    : restitution_duration_delayed_recovery(zeta);
}

MaxCompression max_compression(double zeta) {
  check_zeta(zeta);
  return {restitution_max_compression_time(zeta), restitution_max_compression(zeta)};
}

std::string c_header() {
  TableData d;
  d.settings = RESTITUTION_FAST_SETTINGS;
  d.degree = RESTITUTION_FAST_DEGREE;
  d.small_terms = RESTITUTION_FAST_SMALL_TERMS;
  d.s_lo = RESTITUTION_FAST_S_LO;
  d.per_unit = RESTITUTION_FAST_PER_UNIT;
  d.zeta_lo = RESTITUTION_FAST_ZETA_LO;
  d.ends[CollisionEnd::naive] = end_table(restitution_fast_naive_);
  d.ends[CollisionEnd::delayed_recovery] = end_table(restitution_fast_delayed_);
  const int count = restitution_fast_delayed_.tau_intervals * (RESTITUTION_FAST_DEGREE + 1);
  d.log_x_max = values(restitution_fast_log_x_max_, count);
  d.log_tau_max = values(restitution_fast_log_tau_max_, count);
  d.x_max_zero = RESTITUTION_FAST_X_MAX_ZERO;
  d.tau_max_zero = RESTITUTION_FAST_TAU_MAX_ZERO;
  d.x_max_lo = RESTITUTION_FAST_X_MAX_LO;
  d.tau_max_lo = RESTITUTION_FAST_TAU_MAX_LO;
  d.x_max_law = law(restitution_fast_x_max_law_);
  d.tau_max_law = law(restitution_fast_tau_max_law_);
  d.kappa = RESTITUTION_FAST_KAPPA;
  d.x_m = RESTITUTION_FAST_X_M;
  d.q = RESTITUTION_FAST_Q;
  d.log_a = RESTITUTION_FAST_LOG_A;
  return c_header_text(d);
}

}  // namespace restitution::fast
