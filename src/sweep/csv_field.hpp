// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Text in a CSV field, such that no content can shift the columns or split the row.
#include <string>
#include <string_view>

namespace restitution {

// A CSV field: quoted, inner quotes doubled, line breaks flattened so that one row stays one line.
std::string quoted_field(std::string_view text);

}  // namespace restitution
