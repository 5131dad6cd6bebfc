// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The series and approximations by name, as the command line (`restitution series`) and the Python
// module (restitution.series) offer them. Coefficients are recomputed (series_coefficients.hpp) or, for
// evaluation on request, the published tables (series_tables.hpp).
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/series.hpp"

namespace restitution::series {

// Coefficient kinds: naive (c_1..c_N), delayed-recovery (h_0..h_N), max-compression (a_1..a_N, b_0..b_N).
const std::vector<std::string>& coefficient_kinds();
// The approximations by name: one spelling each, the same in scene files, `series eval`, `series validate`
// and Python: naive-series, delayed-recovery-series, pade-1999, pade-1999-corrected, simple-theory-1999,
// pade-2011-1-4, pade-2011-3-6.
const char* approximation_name(Approximation kind);
// The approximation a name spells; also the two aliases "naive" and "delayed-recovery" of the series
// (their spelling before the names were unified, kept so that existing scripts keep working).
std::optional<Approximation> approximation_named(std::string_view name);
// The 1999 paper's Padé [1/4] form (Table I) with a_3 = -c_3/C1³, a_4 = c_4/C1⁴ from the recomputed c_k
// in place of the printed a_3, a_4 of Eq. (33).
Pade1999 pade_1999_corrected();

// Evaluation kinds: the approximation names above. evaluate_by_kind also takes the aliases and, for the two
// series, the names `series validate` gives its variants: KIND:published and KIND:computed-N.
const std::vector<std::string>& evaluation_kinds();

// One list of coefficients: symbol ("c", "h", "a", "b"), the index of values[0], the values.
struct NamedCoefficients {
  std::string symbol;
  int first_index = 0;
  std::vector<double> values;
};
// count coefficients of the kind (one list; two, a then b, for max-compression). Throws InvalidInput naming
// kind or count (count in [1, 60], [1, 120] for delayed-recovery). Messages spell argument names with
// `prefix` before them: "--" for the command line, "" for Python.
std::vector<NamedCoefficients> coefficients_by_kind(const std::string& kind, int count,
                                                    std::string_view prefix = "");

struct NamedEvaluation {
  std::vector<Value> values;  // one per zeta
  int terms = 0;           // series terms used (c_1..c_N or h_0..h_N); 0 for the closed-form approximations
  bool published = false;  // the series' coefficients were the published tables
};
// The series or approximation `kind` at every zeta >= 0 (natural units); the coefficients are computed once.
// terms applies to the two series only (default: 40 naive, 60 delayed-recovery; all of a published table);
// published: the 2008 paper's Tables III and V instead of the recomputed coefficients. Throws InvalidInput
// naming kind, terms or zeta (with its index when there are several), for zeta outside the checked range
// (require_checked_zeta) and, for the two series, at or beyond their radius of convergence: the one domain
// check of `restitution series eval` and Python's restitution.series.eval.
NamedEvaluation evaluate_by_kind(const std::string& kind, std::span<const double> zetas,
                                 std::optional<int> terms, bool published, std::string_view prefix = "");

}  // namespace restitution::series
