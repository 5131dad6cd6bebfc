// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Numbers as the tables write them: one spelling for the sweep's CSV, its partial file (which checks that a
// number reads back as written) and the command line's other tables.
#include <string>

namespace restitution {

// A double with 17 significant digits ("nan"/"inf" for non-finite values), as in CSV tables.
std::string number17(double value);

}  // namespace restitution
