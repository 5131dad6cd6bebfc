// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Running a DEM code as a child process and reading back the lines the deck printed for itself: the codes
// print banners and warnings too, so only lines starting with the deck's own tag count. The codes run without
// a shell (child_process/child_process.hpp): a program's path is one argument whatever it holds.
#include <functional>
#include <string>
#include <vector>

#include "child_process/child_process.hpp"

namespace restitution::dem {

// Standard output of `command` run by the shell ("" when it cannot start). For fixed commands only (a
// version query): nothing a user or the environment gives may be put into `command`.
std::string output_of(const std::string& command);

// The command that command_for(path) builds (program and arguments, no shell), run with `input` written to
// a temporary file at `path` (its name ends in `suffix`, which YADE needs to be ".py"), its output captured;
// the file is removed afterwards. Throws IoError when the temporary file cannot be written.
ChildRun output_with_input_file(
    const std::string& input, const std::string& suffix,
    const std::function<std::vector<std::string>(const std::string& path)>& command_for);

// Per index 0 .. count-1 the two numbers of the last "TAG index eps gap" line in `output` (NaN where none).
struct TaggedEps {
  std::vector<double> eps, gap_m;
};
TaggedEps tagged_eps(const std::string& output, const std::string& tag, std::size_t count);

// What went wrong in a run of `program` that was to print `count` tagged lines: "" when it exited with
// status 0 and printed every one; else its exit (and its last line of output, where a code says why) or the
// indices it printed no line for.
std::string code_run_failure(const ChildRun& run, const std::string& program, const TaggedEps& read);

}  // namespace restitution::dem
