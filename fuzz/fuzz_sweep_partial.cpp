// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the reader of a sweep's partial file (what `restitution sweep --resume` trusts). Any
// text must give rows of this sweep only, or InvalidInput naming the file; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cli/sweep_table.hpp"
#include "restitution/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace restitution;
  static const std::vector<double> zetas = zeta_values({0.0, 2.0, 5, false});
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const cli::PartialSweep partial =
        cli::parse_partial_sweep(text, "s.csv.partial", "# restitution sweep: fuzz", "zeta,status", zetas);
    // What was accepted must be consistent: known indices, a length inside the text.
    if (partial.valid_bytes > text.size() || partial.failed > partial.rows.size()) std::abort();
    for (const auto& [index, row] : partial.rows) {
      if (index >= zetas.size() || row.find('\n') != std::string::npos) std::abort();
    }
  } catch (const InvalidInput& e) {
    if (std::string(e.what()).find("s.csv.partial") == std::string::npos) std::abort();
  }
  return 0;
}
