// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Key checks that several scene sections share: coefficients of restitution, positive values, ζ in the
// checked range and the `end` key. Each fails through the reader, naming the file, line and key.
#include <vector>

#include "restitution/collision_solver.hpp"

namespace restitution::scene::detail {

class TomlReader;

// A coefficient of restitution: strictly between 0 and 1.
void check_eps(const TomlReader& r, const char* key, const std::vector<double>& values);
void check_positive(const TomlReader& r, const char* key, const std::vector<double>& values);
// 0 <= ζ <= kLargestCheckedZeta.
void check_zeta(const TomlReader& r, const std::vector<double>& zeta);
// `end = "naive" | "delayed-recovery"`; CalibrationRequest's default when absent.
CollisionEnd read_end(TomlReader& r);

}  // namespace restitution::scene::detail
