// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Running another program as a child process without a shell: fork and exec with an argument vector, so that
// nothing in a path (a space, a `;`, a quote) is ever read as a command. The plot scripts (discarding their
// output) and the DEM codes (whose output is read back) are run this way.
#include <functional>
#include <string>
#include <vector>

namespace restitution {

enum class ChildOutput {
  discard,  // stdout and stderr to /dev/null
  capture,  // stdout and stderr, interleaved, returned
};

struct ChildRun {
  int status = -1;     // the wait status; -1 when the child could not be created
  std::string output;  // what it printed, with ChildOutput::capture
};

// Runs command[0] (looked up on PATH when it has no '/') with the arguments command[1..], stdin from
// /dev/null, and waits for it. The child never outlives this process: the kernel sends it SIGKILL when this
// process dies (PR_SET_PDEATHSIG), and it gets SIGTERM once `stop_requested` (polled every 20 ms while it
// runs) returns true. A program that cannot be executed exits with status 127.
ChildRun run_child(const std::vector<std::string>& command, ChildOutput output,
                   const std::function<bool()>& stop_requested = {});

// True when the child exited with status 0.
bool child_succeeded(int status);

// What became of a child, for messages: "exited with status 1", "was killed by signal 9", "could not be
// started (127: not found or not executable)".
std::string child_status_text(int status);

}  // namespace restitution
