// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The check of a request that every engine makes once per solve, before it integrates (Engine::check), so
// that no engine needs another's headers to refuse the same requests. Private to the library.
#include "restitution/contact_law.hpp"
#include "restitution/solve_types.hpp"

namespace restitution {

// What rounding lets an engine deliver (docs/accuracy.md, "Conditioning"): an engine's double-precision
// steps act like a relative perturbation of ζ of a few DBL_EPSILON, which ε amplifies by the law's condition
// number κ (ContactLaw::input_conditioning). Measured per engine.
struct EngineRounding {
  const char* method;             // method_name of the engine's methods, for messages ("bdf", "taylor")
  double rounding_gain = 1.0;     // delivers T >= rounding_gain · κ · DBL_EPSILON
  double smallest_eps = 0.0;      // smallest naive ε the engine resolves (>= the smallest normal double)
  const char* smallest_why = "";  // why, for the message
};
// The ends that do not exist for this law (the naive end of an overdamped dash-pot)
// and the one conditioning check: a tolerance below what rounding lets `engine` deliver for this law and
// end, or an answer below the engine's smallest ε, is refused with InvalidInput naming the tolerance that can
// be delivered. Every engine checks its request with it, once per solve, after the solver has checked the
// options alone (check_solve_options).
void check_solve_request(const ContactLaw& law, const SolveOptions& options, const EngineRounding& engine);

}  // namespace restitution
