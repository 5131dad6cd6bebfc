// SPDX-License-Identifier: BSD-3-Clause
#include "files/scratch_file.hpp"

#include <fmt/format.h>

#include <system_error>

#include "files/output_files.hpp"
#include "files/temporary_file.hpp"

namespace restitution::files {

ScratchFile::ScratchFile(const std::filesystem::path& near, std::string_view suffix,
                         const std::string& content)
    : path_(fmt::format("{}.{}.{}", near.string(), random_name_part(), suffix)) {
  write_file_atomically(path_, content);
}

ScratchFile::~ScratchFile() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

}  // namespace restitution::files
