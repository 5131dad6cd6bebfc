// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Checks on a file named with --output before anything is computed or written: it is none of the command's
// inputs, and writing it creates no folder the user did not name.
#include <filesystem>
#include <vector>

namespace restitution::cli {

// Throws InvalidInput when writing `output` would replace one of `inputs` (the same file by name, through a
// symbolic link or a hard link).
void check_output_is_not_input(const std::filesystem::path& output,
                               const std::vector<std::filesystem::path>& inputs);

// Throws InvalidInput when `output` is a symbolic link whose target lies in a folder that does not exist:
// writing would create folders along the link's target, somewhere the user never pointed.
void check_no_folder_through_link(const std::filesystem::path& output);

}  // namespace restitution::cli
