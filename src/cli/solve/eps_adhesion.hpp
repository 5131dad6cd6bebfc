// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution eps --adhesion MODEL`: one adhesive collision (when --velocity is given) and the sticking
// speed, as a table or one JSON object.
#include <optional>

#include "restitution/adhesion.hpp"

namespace restitution::cli {

int run_adhesive_eps(const AdhesiveContact& contact, std::optional<double> velocity_m_per_s, double tolerance,
                     bool json);

}  // namespace restitution::cli
