// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Files the commands write: output folders, complete-or-absent files, numbers as text, plot scripts.
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/number_text.hpp"

namespace restitution::cli {

// Checks, without creating anything, that files can be written into the folder: it exists and is
// writable, or its nearest existing ancestor is a writable folder. Throws InvalidInput naming it. Commands
// call it before their work; the folder itself is created by the first write_file_atomically into it, so
// a run that fails before writing leaves no empty folder behind.
void check_output_folder(const std::filesystem::path& folder);

// check_output_folder for the folder a file named on the command line will be written into (see
// output_target; a stream is always writable here). Throws InvalidInput when the path is a folder.
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
// through a link: sweep/temporary_file.hpp), then renames it onto the target: a reader never sees a
// half-written file under the final name (streams are written in place; see output_target). Throws
// IoError naming the file when the write fails.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// Writes the whole content straight into a device, pipe or stream (an OutputTarget with in_place). Throws
// IoError naming it when it takes less (/dev/full: "No space left on device").
void write_in_place(const std::filesystem::path& path, const std::string& content);

// A double with 17 significant digits, as the sweep library writes its tables (sweep/number_text.hpp).
using restitution::number17;

// The file names of figure STEM in each format: STEM.png, STEM.pdf, ...
std::vector<std::string> figure_file_names(const std::string& stem, const std::vector<std::string>& formats);

// Runs scripts/plots/<script>.py with Debian's /usr/bin/python3 as
// `<script>.py DATA IMAGE ARGUMENTS... --format FORMATS`: one figure in each format (png, pdf, svg; see
// scene/figure_formats.hpp), named IMAGE with its extension replaced by the format's. The script writes
// temporary NAME.<random>.tmp.<format> files that become the figures only once the script succeeded, and it
// never outlives this process (SIGKILL when this process dies, SIGTERM when it is asked to stop): no figure
// appears after the command ended, none half-written under its name. Returns an empty string on success,
// otherwise one line saying why no plot was made (matplotlib missing, script failed): callers warn on
// stderr and keep the data they wrote. Throws Interrupted when the script (or this process) got SIGINT or
// SIGTERM, IoError when a figure cannot be renamed into place.
std::string run_plot_script(const std::string& script, const std::filesystem::path& data,
                            const std::filesystem::path& image,
                            const std::vector<std::string>& arguments = {},
                            const std::vector<std::string>& formats = {"png"});

// The warning line of a command's figure that was not made: "no WHAT plot: " and why (run_plot_script's
// reason without its own "no plot: ", which would say it twice).
std::string no_plot_warning(const std::string& what, const std::string& why);

}  // namespace restitution::cli
