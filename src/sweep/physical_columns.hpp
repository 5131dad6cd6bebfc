// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The physical columns of an ε(v) table, one definition for scene sweeps and `restitution sweep`: the
// impact speed and β after ζ, and for a material the SI duration of each end and the time and size of the
// maximal compression (natural units scaled by natural_scales(k, v)).
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/units.hpp"

namespace restitution {

// "velocity_m_s", "beta" (s^{1/5} m^{-1/5}).
const std::vector<std::string>& velocity_columns();
// "naive_duration_s" | "delayed_recovery_duration_s" (the names of every table: subject, quantity, unit).
std::string duration_column(CollisionEnd end);
// "max_compression_time_s", "max_compression_m".
const std::vector<std::string>& si_max_compression_columns();

// τ_c in seconds.
double duration_s(const EndResult& end, const NaturalScales& scales);
// The time [s] and compression [m] of the maximal compression, in the order of si_max_compression_columns().
std::vector<double> si_max_compression(const MaxCompression& m, const NaturalScales& scales);

}  // namespace restitution
