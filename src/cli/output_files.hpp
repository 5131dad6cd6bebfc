#pragma once
// Files the commands write: output folders, complete-or-absent files, numbers as text, plot scripts.
#include <filesystem>
#include <string>
#include <vector>

namespace restitution::cli {

// Creates the folder (and parents) if needed; throws InvalidInput naming it when it cannot be created or
// written to.
void prepare_output_folder(const std::filesystem::path& folder);

// Writes the whole content to path.tmp, flushes, then renames it to path: a reader never sees a
// half-written file under the final name. Throws InvalidInput naming the file on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// A double with 17 significant digits ("nan"/"inf" for non-finite values), as in CSV tables.
std::string number17(double value);

// Runs scripts/plots/<script>.py with Debian's /usr/bin/python3 and the given arguments. Returns an empty
// string on success, otherwise one line saying why no plot was made (matplotlib missing, script failed):
// callers warn on stderr and keep the data they wrote.
std::string run_plot_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace restitution::cli
