// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The viscoelastic Hertz fit of a result that a DEM code should take: the converged one with the lowest AIC
// (fit-data's report gives its A; `--from-fit` reads the same choice back, fit/fit_report_reader.hpp).
#include <cstddef>
#include <optional>

#include "restitution/fit.hpp"

namespace restitution {

// The index in FitResult::fits, or nullopt when no Hertz fit converged (the first of equal AICs).
std::optional<std::size_t> best_hertz_fit(const FitResult& result);

}  // namespace restitution
