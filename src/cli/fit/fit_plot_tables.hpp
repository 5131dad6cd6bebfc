// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The two tables scripts/plots/fit_data.py draws, for `fit-data --plot` and a scene's [[fit]]: the data with
// each law's model and residual, and each converged law's curve with its 95 % band.
#include <string>

#include "restitution/fit.hpp"

namespace restitution::cli {

// v, eps, sigma (nan without), then per law model_<law>_<end>, residual_<law>_<end>.
std::string fit_data_table(const FitData& data, const FitResult& result);

// fit/fit_curves.hpp's curves: v on a log grid over the data's speeds, then per converged law eps_<law>_<end>
// and the 95 % band's edges low_<law>_<end>, high_<law>_<end> (nan where a bound lies at the edge of the
// checked range).
std::string fit_curves_table(const FitData& data, const FitResult& result, const FitOptions& options);

}  // namespace restitution::cli
