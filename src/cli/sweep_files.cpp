// SPDX-License-Identifier: BSD-3-Clause
#include "cli/sweep_files.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iterator>
#include <system_error>

#include "cli/io_error.hpp"

namespace restitution::cli {
namespace {
namespace fs = std::filesystem;

// A crash loses at most the rows of the last interval, which --resume computes again. A flush per row (a
// system call each) cost more than a Taylor solve and, serialized, kept a second thread from paying off.
constexpr long long kFlushIntervalNs = 100'000'000;
// Large buffers: with stdio's default 4 KiB, a 15 MB table is some 3700 write calls.
constexpr std::size_t kBufferBytes = std::size_t{1} << 18;

long long steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

std::FILE* open_buffered(const fs::path& path, const char* mode) {
  std::FILE* file = std::fopen(path.c_str(), mode);
  if (file != nullptr) std::setvbuf(file, nullptr, _IOFBF, kBufferBytes);
  return file;
}

}  // namespace

PartialFile::PartialFile(const fs::path& path, std::size_t keep_bytes, const std::string& preamble,
                         unsigned writers)
    : path_(path), buffers_(std::max(1U, writers)) {
  if (keep_bytes > 0) fs::resize_file(path, keep_bytes);  // drop a half-written last line
  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  // O_APPEND: each write(2) of a writer's whole lines lands at the end, never inside another's.
  const int flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (keep_bytes > 0 ? 0 : O_TRUNC);
  fd_ = ::open(path.c_str(), flags, 0644);  // NOLINT(cppcoreguidelines-pro-type-vararg): POSIX API
  if (fd_ < 0) throw IoError(fmt::format("--out: cannot write '{}'", path.string()));
  const long long now = steady_ns();
  for (Buffer& buffer : buffers_) buffer.last_write_ns = now;
  if (keep_bytes == 0) {
    buffers_.front().lines = preamble;
    write(buffers_.front());
  }
}

PartialFile::~PartialFile() {
  for (Buffer& buffer : buffers_) {
    try {
      write(buffer);
    } catch (const IoError&) {  // the sweep already failed or stopped; its own message is the one to show
    }
  }
  ::close(fd_);
}

void PartialFile::append(unsigned writer, std::size_t index, const std::string& row) {
  Buffer& buffer = buffers_.at(writer);
  fmt::format_to(std::back_inserter(buffer.lines), "{},{}\n", index, row);
  // The clock is read only while the buffer is not full.
  if (buffer.lines.size() >= kBufferBytes || steady_ns() - buffer.last_write_ns >= kFlushIntervalNs) {
    write(buffer);
  }
}

void PartialFile::write(Buffer& buffer) {
  buffer.last_write_ns = steady_ns();
  if (buffer.lines.empty()) return;
  // One call: a short write (disk full) would let another writer's lines in after a cut line.
  const ssize_t written = ::write(fd_, buffer.lines.data(), buffer.lines.size());
  if (written < 0 || static_cast<std::size_t>(written) != buffer.lines.size())
    fail(written < 0 ? errno : ENOSPC);
  buffer.lines.clear();
}

void PartialFile::fail(int error) const {
  throw IoError(fmt::format("--out: cannot write '{}': {}", path_.string(), std::strerror(error)));
}

OrderedTable::OrderedTable(fs::path target, const std::string& header, std::size_t rows)
    : target_(std::move(target)), temporary_(target_.string() + ".tmp"), rows_(rows), ready_(rows, 0) {
  file_ = open_buffered(temporary_, "wb");
  if (file_ == nullptr) fail();
  if (std::fputs(header.c_str(), file_) < 0 || std::fputc('\n', file_) < 0) fail();
}

OrderedTable::~OrderedTable() {
  if (file_ == nullptr) return;  // committed
  std::fclose(file_);
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void OrderedTable::add(std::size_t index) {
  ready_[index] = 1;
  for (; next_ < rows_.size() && ready_[next_] != 0; ++next_) {
    std::string& row = rows_[next_];
    row += '\n';
    if (std::fwrite(row.data(), 1, row.size(), file_) != row.size()) fail();
    std::string().swap(row);  // written: free it
  }
}

void OrderedTable::commit() {
  if (next_ != rows_.size()) throw std::logic_error("OrderedTable::commit before every row was added");
  const int flushed = std::fflush(file_);
  const int error = errno;
  const int closed = std::fclose(file_);
  file_ = nullptr;
  std::error_code renamed;
  if (flushed == 0 && closed == 0) fs::rename(temporary_, target_, renamed);
  if (flushed != 0 || closed != 0 || renamed) {
    std::error_code ignored;
    fs::remove(temporary_, ignored);
    throw IoError(fmt::format("cannot write '{}': {}", target_.string(),
                              renamed ? renamed.message() : std::strerror(flushed != 0 ? error : errno)));
  }
}

void OrderedTable::fail() const {
  throw IoError(fmt::format("cannot write '{}': {}", temporary_.string(), std::strerror(errno)));
}

}  // namespace restitution::cli
