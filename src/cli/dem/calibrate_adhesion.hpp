// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution calibrate --adhesion MODEL --surface-energy γ --eps E --velocity V` with a material: the
// damping A that gives the measured ε; with `--sticking-speed VS` instead of the surface energy, γ and A
// together (restitution/adhesive_calibration.hpp).
#include <optional>

#include "cli/common/adhesion_options.hpp"
#include "cli/common/material_options.hpp"

namespace restitution::cli {

int run_adhesive_calibrate(const AdhesionOptions& adhesion, const MaterialOptions& material, double eps,
                           double velocity_m_per_s, std::optional<double> sticking_speed_m_per_s,
                           double tolerance, bool json);

}  // namespace restitution::cli
