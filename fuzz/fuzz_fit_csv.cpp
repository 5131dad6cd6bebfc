// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the fit CSV reader (restitution/fit.hpp, what `fit-data` and scenes' [[fit]] read).
// Any bytes give measurements or InvalidInput naming the file; anything else is a finding. Accepted data must
// be consistent (one eps and at most one sigma per speed, every value finite and in range, no more rows than
// lines or the bound) and round-trip: written back as v,eps[,sigma] with 17 digits they read back identical.
// A refusal's message carries no raw control byte (the excerpt escapes them).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "restitution/errors.hpp"
#include "restitution/fit.hpp"

namespace {

void check(bool condition) {
  if (!condition) std::abort();
}

void check_accepted(const restitution::FitData& d, const std::string& text,
                    const restitution::FitCsvLimits& limits) {
  const std::size_t n = d.velocity_m_s.size();
  check(n >= 1 && n <= limits.max_rows && d.eps.size() == n && (d.sigma.empty() || d.sigma.size() == n));
  const auto line_ends = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n') +
                                                  std::count(text.begin(), text.end(), '\r'));
  check(n <= line_ends);  // the header takes a line of its own
  for (std::size_t i = 0; i < n; ++i) {
    check(std::isfinite(d.velocity_m_s[i]) && d.velocity_m_s[i] > 0.0);
    check(d.eps[i] > 0.0 && d.eps[i] < 1.0);
    if (!d.sigma.empty()) {
      check(d.sigma[i] >= restitution::kSmallestFitSigma && d.sigma[i] <= restitution::kLargestFitSigma);
    }
  }
  std::string canonical = d.sigma.empty() ? "v,eps\n" : "v,eps,sigma\n";
  for (std::size_t i = 0; i < n; ++i) {
    canonical += fmt::format("{:.17g},{:.17g}", d.velocity_m_s[i], d.eps[i]);
    canonical += d.sigma.empty() ? "\n" : fmt::format(",{:.17g}\n", d.sigma[i]);
  }
  restitution::FitCsvLimits unbounded;
  unbounded.max_rows = n;
  const restitution::FitData again = restitution::parse_fit_csv(canonical, "again.csv", unbounded);
  check(again.velocity_m_s == d.velocity_m_s && again.eps == d.eps && again.sigma == d.sigma);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Small bounds so that the fuzzer reaches each of them; the defaults for the rest.
  restitution::FitCsvLimits limits;
  if (size > 0 && data[0] % 2 == 0) {
    limits.max_bytes = 512;
    limits.max_line_bytes = 64;
    limits.max_rows = 8;
  }
  try {
    check_accepted(restitution::parse_fit_csv(text, "fit.csv", limits), text, limits);
  } catch (const restitution::InvalidInput& e) {
    const std::string message = e.what();
    check(message.rfind("fit.csv", 0) == 0);
    check(std::none_of(message.begin(), message.end(),
                       [](char c) { return (c >= 0 && c < 0x20) || c == 0x7f; }));
  }
  return 0;
}
