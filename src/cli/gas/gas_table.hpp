// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The cooling curve as the command and the [[gas]] scene section write it: the CSV (one column per field of
// gas::CoolingCurve, gas::curve_columns), the law in words, and the arguments of scripts/plots/gas_cooling.py
// after CSV and PNG.
#include <string>
#include <vector>

#include "restitution_gas/cooling.hpp"

namespace restitution::cli {

std::string gas_csv(const gas::CoolingCurve& curve);
std::string gas_law_text(const gas::CoolingRequest& request);
std::vector<std::string> gas_plot_arguments(const gas::CoolingRequest& request,
                                            const gas::CoolingCurve& curve);

}  // namespace restitution::cli
