// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading the result of `fit-data --out FILE` (docs/fit.md) for `--from-fit`: the file comes from outside
// (it may be edited by hand), so every value used is checked for its type, finiteness and order, every index
// for its range, and the Hertz fit that carries over is judged by the fit's own tests.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/fit.hpp"

namespace restitution::cli {

// The largest fit file read [bytes]: a fit-data report holds a few numbers per data point, so this admits
// about a million points; anything larger (or endless, such as /dev/zero) is refused after reading that much.
inline constexpr std::size_t kMaxFitFileBytes = std::size_t{64} << 20;

struct FitCarryOver {
  std::string file;  // as messages name it
  CollisionEnd end = CollisionEnd::delayed_recovery;
  double beta = 0.0;       // > 0, with a finite g* > 0
  FitInterval ci68, ci95;  // low <= beta <= high where a number; ci95 contains ci68
  bool sigma_estimated = false;
  std::size_t points = 0;
  // Why the fit itself rejects this viscoelastic Hertz fit (empty: it does not): another law has a lower AIC,
  // χ² is too large for the data's σ, or the residual tests find a trend. The intervals then describe the
  // scatter about a law the data do not follow, not the data, and are not carried over.
  std::vector<std::string> rejected_because;
};

// The converged viscoelastic Hertz fit at `end` (nullopt: the one with the lowest AIC) of the report in
// `text`; `file` names it in messages. Throws InvalidInput "--from-fit FILE: KEY: problem" for anything that
// is not a well-formed fit-data report, or when it has no such converged fit.
FitCarryOver parse_fit_result(const std::string& text, const std::string& file,
                              std::optional<CollisionEnd> end);

// The same for the file at `path` (at most kMaxFitFileBytes).
FitCarryOver read_fit_result(const std::filesystem::path& path, std::optional<CollisionEnd> end);

}  // namespace restitution::cli
