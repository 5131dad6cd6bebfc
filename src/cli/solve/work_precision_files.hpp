// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The files of a work-precision measurement, shared by `restitution work-precision` and the scenes'
// [[work_precision]] sections: every point, the summary per (engine, end, tolerance) and its plot.
#include <filesystem>
#include <string>
#include <vector>

#include "reference/work_precision.hpp"

namespace restitution::cli {

// data/reference_solutions.csv of the source tree this build belongs to.
std::filesystem::path default_reference_file();

struct WorkPrecisionFiles {
  std::vector<std::string> files;  // names inside the folder
  std::string plot_warning;        // why there is no plot ("" when there is one)
};

// Writes STEM.csv (every point), STEM_summary.csv (per engine, end and tolerance) and the figure STEM.png
// (scripts/plots/work_precision.py; STEM.pdf, STEM.svg as `formats` asks) into an existing folder.
WorkPrecisionFiles write_work_precision_files(const std::vector<WorkPrecisionRow>& rows,
                                              const std::filesystem::path& folder, const std::string& stem,
                                              const std::vector<std::string>& formats = {"png"});

}  // namespace restitution::cli
