// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the freely cooling and the driven gas check alike (cooling.hpp, driven.hpp): the request's spheres,
// gas and a₂, and the output times it asks for.
#include <vector>

#include "restitution_gas/cooling.hpp"

namespace restitution::gas {

// Throws InvalidInput unless value is finite and > 0, naming it with its unit.
void require_positive(double value, const char* name, const char* unit);
// Throws InvalidInput naming the argument: mass, diameter, packing_fraction outside (0, 0.5),
// initial_temperature, a2, collision_rate_factor.
void check_cooling_request(const CoolingRequest& r);
// The request's span of time in s (a duration in Haff times scaled by tau0_s); throws InvalidInput unless it
// is finite and > 0.
double duration_in_seconds(const CoolingRequest& r, double tau0_s);
// The output times: the requested ones, or the log-spaced grid up to duration_s.
std::vector<double> output_times(const CoolingRequest& r, double duration_s);

}  // namespace restitution::gas
