// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The files restitution writes (the command line, the scene run, the sweep library): output folders checked
// before any work, files written complete or not at all, never through a planted link, streams in place.
#include <filesystem>
#include <string>

namespace restitution::files {

// Checks, without creating anything, that files can be written into the folder: it exists and is
// writable, or its nearest existing ancestor is a writable folder. Throws IoError naming it. Commands
// call it before their work; the folder itself is created by the first write_file_atomically into it, so
// a run that fails before writing leaves no empty folder behind.
void check_output_folder(const std::filesystem::path& folder);

// check_output_folder for the folder a file named on the command line will be written into (see
// output_target; a stream is always writable here). Throws InvalidInput when the path is a folder, or a
// symbolic link whose target's folder does not exist (writing would create folders along the link's target,
// somewhere the user never pointed).
void check_output_file(const std::filesystem::path& path);

// check_output_file for a figure named with `option` (--plot). A figure is made beside its name as a new file
// and renamed onto it, so a device, FIFO, socket or open stream (/dev/full, /dev/stdout) cannot take one:
// InvalidInput naming the option, rather than a sibling /dev/full.png.
void check_figure_file(const std::filesystem::path& path, const std::string& option);

// Where a file named on the command line is written. A symlink is followed to its target, which is then
// replaced (the link stays); a device, FIFO or socket, and a link into /proc such as /dev/stdout, name an
// open stream rather than a place and are written in place, never replaced. Throws InvalidInput for a folder.
struct OutputTarget {
  std::filesystem::path path;  // the file to create or replace, or the stream to write into
  bool in_place = false;       // true: write straight into path (no temporary file, no rename)
};
OutputTarget output_target(const std::filesystem::path& path);

// Writes the whole content to a temporary beside the target (TARGET.<random>.tmp, created exclusively, never
// through a link: files/temporary_file.hpp), then renames it onto the target: a reader never sees a
// half-written file under the final name (streams are written in place; see output_target). Throws
// IoError naming the file when the write fails.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// Creates the folders above `file` that do not exist yet (none when it has no folder part). Throws IoError
// naming the file when they cannot be made.
void create_folder_of(const std::filesystem::path& file);

// Writes the whole content straight into a device, pipe or stream (an OutputTarget with in_place). Throws
// IoError naming it when it takes less (/dev/full: "No space left on device").
void write_in_place(const std::filesystem::path& path, const std::string& content);

}  // namespace restitution::files
