// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Running a DEM code as a child process and reading back the lines the deck printed for itself: the codes
// print banners and warnings too, so only lines starting with the deck's own tag count.
#include <functional>
#include <string>
#include <vector>

namespace restitution::dem {

// Standard output of `command` run by the shell ("" when it cannot start).
std::string output_of(const std::string& command);

// The output of the command that command_for(path) builds, run with `input` written to a temporary file at
// `path` (its name ends in `suffix`, which YADE needs to be ".py"); the file is removed afterwards.
std::string output_with_input_file(const std::string& input, const std::string& suffix,
                                   const std::function<std::string(const std::string& path)>& command_for);

// Per index 0 .. count-1 the two numbers of the last "TAG index eps gap" line in `output` (NaN where none).
struct TaggedEps {
  std::vector<double> eps, gap_m;
};
TaggedEps tagged_eps(const std::string& output, const std::string& tag, std::size_t count);

}  // namespace restitution::dem
