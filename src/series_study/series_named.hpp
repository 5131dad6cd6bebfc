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
// Evaluation kinds: naive, delayed-recovery, pade-1999, simple-theory-1999, pade-2011-1-4, pade-2011-3-6.
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
  int terms = 0;  // series terms used (c_1..c_N or h_0..h_N); 0 for the closed-form approximations
};
// The series or approximation `kind` at every zeta >= 0 (natural units); the coefficients are computed once.
// terms applies to the two series only (default: 40 naive, 60 delayed-recovery; all of a published table);
// published: the 2008 paper's Tables III and V instead of the recomputed coefficients. Throws InvalidInput
// naming kind, terms or zeta (with its index when there are several).
NamedEvaluation evaluate_by_kind(const std::string& kind, std::span<const double> zetas,
                                 std::optional<int> terms, bool published, std::string_view prefix = "");

}  // namespace restitution::series
