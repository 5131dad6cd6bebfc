#pragma once
// The text of the self-contained C99 header of the fast tables (src/fast/fast_table.h): the numbers of a
// TableData followed by one fixed evaluation code. The library compiles that header, `restitution export
// c-header` writes it out, so both evaluate with the same operations in the same order.
#include <string>

#include "fast/table_data.hpp"

namespace restitution::fast {

std::string c_header_text(const TableData& data);

}  // namespace restitution::fast
