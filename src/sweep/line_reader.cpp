// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/line_reader.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "restitution/errors.hpp"

namespace restitution {
namespace {

// 8 windows of 64 KiB: a partial file written by up to 8 workers is read in grid order without re-reading.
constexpr std::size_t kWindows = 8;
constexpr std::size_t kWindowBytes = std::size_t{1} << 16;
// A longer line is held only in part (its text is cut there), whatever the file holds.
constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

}  // namespace

LineReader::LineReader(ReadAt read) : read_(std::move(read)), windows_(kWindows) {}

LineReader LineReader::of_text(std::string_view text) {
  return LineReader([text](std::uint64_t offset, char* into, std::size_t size) -> std::size_t {
    if (offset >= text.size()) return 0;
    const std::size_t n = std::min<std::size_t>(size, text.size() - offset);
    std::memcpy(into, text.data() + offset, n);
    return n;
  });
}

LineReader::Line LineReader::at(std::uint64_t offset) {
  ++clock_;
  for (Window& w : windows_) {
    if (w.bytes.empty() || offset < w.start || offset >= w.start + w.bytes.size()) continue;
    const std::string_view rest = std::string_view(w.bytes).substr(offset - w.start);
    const std::size_t end = rest.find('\n');
    if (end == std::string_view::npos) break;  // runs past the window: read again from the line's start
    w.last_use = clock_;
    return {rest.substr(0, end), end, true};
  }
  // The least recently used window is read from the line's start, grown until it holds the whole line.
  Window& w = *std::min_element(windows_.begin(), windows_.end(),
                                [](const Window& a, const Window& b) { return a.last_use < b.last_use; });
  w.start = offset;
  w.last_use = clock_;
  w.bytes.clear();
  std::size_t searched = 0;
  for (std::size_t want = kWindowBytes; want <= kMaxLineBytes; want *= 2) {
    const std::size_t held = w.bytes.size();
    w.bytes.resize(want);
    const std::size_t got = read_(offset + held, w.bytes.data() + held, want - held);
    w.bytes.resize(held + got);
    const std::size_t end = std::string_view(w.bytes).find('\n', searched);
    if (end != std::string_view::npos) return {std::string_view(w.bytes).substr(0, end), end, true};
    searched = w.bytes.size();
    if (held + got < want) return {w.bytes, w.bytes.size(), false};  // the data ends inside this line
  }
  // Longer than any line the program writes (e.g. a block of zeros a crash left): only its length is found.
  std::uint64_t length = w.bytes.size();
  std::string chunk(kWindowBytes, '\0');
  for (;;) {
    const std::size_t got = read_(offset + length, chunk.data(), chunk.size());
    const std::size_t end = std::string_view(chunk.data(), got).find('\n');
    if (end != std::string_view::npos) return {w.bytes, length + end, true};
    length += got;
    if (got < chunk.size()) return {w.bytes, length, false};
  }
}

FileLines::FileLines(const std::filesystem::path& path)
    : path_(path),
      fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)),  // NOLINT(cppcoreguidelines-pro-type-vararg)
      lines_([this](std::uint64_t offset, char* into, std::size_t size) {
        std::size_t done = 0;
        while (done < size) {
          const ssize_t n = ::pread(fd_, into + done, size - done, static_cast<off_t>(offset + done));
          if (n == 0) break;
          if (n < 0 && errno == EINTR) continue;
          if (n < 0) throw IoError(fmt::format("cannot read '{}': {}", path_.string(), std::strerror(errno)));
          done += static_cast<std::size_t>(n);
        }
        return done;
      }) {
  if (fd_ < 0) throw IoError(fmt::format("cannot read '{}': {}", path.string(), std::strerror(errno)));
}

FileLines::~FileLines() {
  ::close(fd_);
}

}  // namespace restitution
