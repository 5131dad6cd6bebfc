// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Checks on the files a command writes, before anything is computed or written: none of them is one of the
// command's inputs, no two of them are one file, and writing them creates no folder the user did not name.
#include <filesystem>
#include <string>
#include <vector>

namespace restitution::files {

// A file named on the command line, with the option that named it ("--deck", "--compare"; may be empty).
struct NamedPath {
  std::string option;
  std::filesystem::path path;
};

// True when writing `output` would replace (or write into) the file `other` names: the same file by name, by
// a symbolic link (followed to its end, dangling or not) or by a hard link (same device and inode).
bool same_file_place(const std::filesystem::path& output, const std::filesystem::path& other);

// Throws InvalidInput naming both options when an output is one of the inputs (writing it would destroy the
// input), or when two outputs are one file (one would replace the other).
void check_outputs_apart(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

}  // namespace restitution::files
