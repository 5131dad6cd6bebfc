// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/io_error.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace restitution::cli {

void flush_standard_output() {
  if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
    throw IoError(fmt::format("cannot write to standard output: {}", std::strerror(errno)));
  }
}

}  // namespace restitution::cli
