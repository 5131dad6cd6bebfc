// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Rewrites scene text as ASCII-only TOML before toml++ sees it. Debian's toml++ 3.3.0 reaches
// __builtin_unreachable (undefined behaviour) in is_non_ascii_horizontal_whitespace for many code points
// (U+00A1-U+0499, U+2C5E-U+3057, U+FB26-U+FEFE). It asks that question wherever it may skip whitespace,
// including on its error paths, which can scan into the strings of malformed input (found by
// fuzz/fuzz_scene.cpp; the inputs are kept in fuzz/findings/). Handed ASCII only, it never asks. The
// rewrite keeps every value and every line number:
//   * non-ASCII characters in basic strings become \uXXXX or \UXXXXXXXX escapes;
//   * literal strings ('...', '''...''') become basic strings, with \ and " escaped as well;
//   * non-ASCII characters in comments become '?';
//   * a leading byte-order mark is dropped.
// Text that is not strict UTF-8, a non-ASCII character outside strings and comments (TOML allows none
// there) and a backslash followed by a non-ASCII character (no such escape exists) are refused.
#include <string>
#include <string_view>

namespace restitution::scene {

// Returns the ASCII form of `text`; throws InvalidInput "FILE:LINE: ..." for what is refused above.
std::string ascii_toml_text(std::string_view text, std::string_view file_name);

}  // namespace restitution::scene
