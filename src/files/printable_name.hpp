// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// File names as messages print them. A name may hold any byte but '/' and NUL: a newline or an escape
// sequence printed raw would forge a second message line or move the terminal's cursor (issue 45, item 7), so
// control characters are shown as \xNN. Everything else, UTF-8 included, is shown as it is.
#include <string>
#include <string_view>

namespace restitution::files {

// `name` with every byte below 0x20 and 0x7F written as \xNN (a backslash as \\, so the escape reads back).
std::string printable_name(std::string_view name);

}  // namespace restitution::files
