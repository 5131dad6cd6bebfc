// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The figures the commands draw: the plot scripts run as child processes, their file names and the warning
// when none was made. Writing the data they read is files/output_files.hpp's.
#include <filesystem>
#include <string>
#include <vector>

namespace restitution::cli {

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
