// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Pieces of the reprs of the result types (Calibration, Material): one spelling of a value that may be
// absent.
#include <optional>
#include <string>

namespace restitution::python {

// "<value> <unit>", or "None" when the value is absent (a law without it: Python's None, as the attribute
// gives).
std::string optional_text(const std::optional<double>& x, const char* unit);

}  // namespace restitution::python
