// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The text of the self-contained C99 header of the fast tables (src/fast/fast_table.h): the numbers of a
// TableData followed by one fixed evaluation code. The library compiles that header, `restitution export
// c-header` writes it out, so both evaluate with the same operations in the same order.
#include <string>

#include "fast/table_data.hpp"

namespace restitution::fast {

std::string c_header_text(const TableData& data);

// The evaluation code that follows the numbers, written once in C99 in fast_table.h itself (why each step is
// there: docs/fast.md) and copied from it at build time (src/CMakeLists.txt, fast_evaluation.cpp.in).
const char* evaluation_code();

}  // namespace restitution::fast
