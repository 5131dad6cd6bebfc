// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Closed forms the tests compare with. They and the published coefficient tables live once, in the series
// module (include/restitution/series.hpp, include/restitution/series_tables.hpp); the names here are
// the ones the core tests use.
#include "restitution/series.hpp"

namespace restitution::test_support {

// Undamped collision (ζ = 0): x_max = (5/4)^{2/5}, τ_max0 = (4/5)^{3/5} Γ(2/5) Γ(1/2) / (2 Γ(9/10)).
using series::undamped_max_compression;
using series::undamped_max_time;
// C1 in closed form (1999 paper, Eq. 30): sqrt(π) / (2^{1/5} 5^{2/5}) Γ(3/5) / Γ(21/10) = 1.15344885809...
using series::c1_closed_form;

}  // namespace restitution::test_support
