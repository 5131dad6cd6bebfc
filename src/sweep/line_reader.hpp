// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Lines of a file (or of a text) read by their byte offset, through a few cached windows, without holding the
// whole file. A sweep's partial file holds its rows in blocks per worker, so reading them in grid order jumps
// between a few places of the file and reads forward from each: one window per place serves it.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace restitution {

class LineReader {
 public:
  // Reads up to `size` bytes at `offset` into `into`; returns how many (fewer only at the end of the data).
  using ReadAt = std::function<std::size_t(std::uint64_t offset, char* into, std::size_t size)>;
  explicit LineReader(ReadAt read);
  // The lines of a text held by the caller (it must outlive the reader).
  static LineReader of_text(std::string_view text);

  struct Line {
    std::string_view text;  // without its '\n'; valid until the next call of at(); cut at 1 MiB
    std::uint64_t length =
        0;  // of the whole line without its '\n' (the next line starts at offset + length + 1)
    bool complete = false;  // false: the data ends before a '\n' (a line cut off while being written)
  };
  // The line that starts at `offset` (at or past the end: an empty, incomplete line). Holds at most 1 MiB of
  // a line however long it is.
  Line at(std::uint64_t offset);

 private:
  struct Window {
    std::uint64_t start = 0;
    std::string bytes;
    std::uint64_t last_use = 0;
  };
  ReadAt read_;
  std::vector<Window> windows_;
  std::uint64_t clock_ = 0;
};

// The file open for reading, closed with the reader; throws IoError naming it when it cannot be read.
class FileLines {
 public:
  explicit FileLines(const std::filesystem::path& path);
  ~FileLines();
  FileLines(const FileLines&) = delete;
  FileLines& operator=(const FileLines&) = delete;
  LineReader& lines() { return lines_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  LineReader lines_;
};

}  // namespace restitution
