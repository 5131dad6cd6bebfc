// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A file written for a child process to read (the data of a plot script) and removed afterwards, however the
// scope is left: a failed or stopped plot leaves no IMAGE.<random>.data.csv behind. Its name is random, as a
// temporary's (files/temporary_file.hpp): a link planted under a fixed name is never written through.
#include <filesystem>
#include <string>
#include <string_view>

namespace restitution::files {

class ScratchFile {
 public:
  // Writes `content` to NEAR.<random>.SUFFIX (write_file_atomically: its folder is made when missing). Throws
  // IoError as that does.
  ScratchFile(const std::filesystem::path& near, std::string_view suffix, const std::string& content);
  ~ScratchFile();  // removes the file
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace restitution::files
