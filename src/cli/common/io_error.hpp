// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Standard output as an output like any file: a result that never reached it is an I/O failure (IoError,
// exit status 3), not a success.
#include "restitution/errors.hpp"

namespace restitution::cli {

using restitution::IoError;

// Flushes stdout; throws IoError when anything written to it was lost.
void flush_standard_output();

}  // namespace restitution::cli
