// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The initial state of a freely cooling gas in a periodic cube: non-overlapping random positions (random
// sequential addition on a cell list, so that 1e5 spheres take milliseconds) and Maxwellian velocities with
// zero total momentum and exactly the requested temperature. Seeded: the same seed gives the same gas.
#include <array>
#include <cstdint>
#include <vector>

namespace restitution::gas_deck {

using Vec3 = std::array<double, 3>;

// `count` centres in [0, box)^3 whose periodic distances are all >= `diameter` [m]. Throws InvalidInput
// naming
// --packing-fraction when the packing fraction exceeds kMaxPackingFraction (random sequential addition jams
// at 0.38), or --particles when `count` < 2.
inline constexpr double kMaxPackingFraction = 0.3;
std::vector<Vec3> random_positions(std::size_t count, double diameter_m, double box_m, std::uint64_t seed);

// `count` velocities [m/s] from the Maxwellian, shifted to zero total momentum (equal masses) and scaled so
// that the mean of v^2 / 3 is rms_speed^2 exactly (the temperature m <v^2> / 3 per particle).
std::vector<Vec3> maxwellian_velocities(std::size_t count, double rms_speed_m_s, std::uint64_t seed);

}  // namespace restitution::gas_deck
