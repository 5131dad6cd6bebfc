// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The cooling curve as the command and the [[gas]] scene section write it: the CSV (one column per field of
// gas::CoolingCurve), the law in words, and the arguments of scripts/plots/gas_cooling.py after CSV and PNG.
#include <string>
#include <vector>

#include "gas/cooling.hpp"

namespace restitution::cli {

// One column of the curve: its name (the CSV header, the JSON key) and its values.
struct GasColumn {
  const char* name;
  const std::vector<double>* values;
};
// The columns in the order the CSV and the JSON give them, one per field of gas::CoolingCurve.
std::vector<GasColumn> gas_columns(const gas::CoolingCurve& curve);

std::string gas_csv(const gas::CoolingCurve& curve);
std::string gas_law_text(const gas::CoolingRequest& request);
std::vector<std::string> gas_plot_arguments(const gas::CoolingRequest& request,
                                            const gas::CoolingCurve& curve);

}  // namespace restitution::cli
