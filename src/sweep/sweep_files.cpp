// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/sweep_files.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "files/temporary_file.hpp"
#include "restitution/errors.hpp"
#include "sweep/sweep_partial.hpp"

namespace restitution {
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

int open_for_writing(const fs::path& path, int flags) {
  return ::open(path.c_str(),
                O_WRONLY | O_CREAT | O_CLOEXEC | flags,  // NOLINT(cppcoreguidelines-pro-type-vararg)
                0644);
}

}  // namespace

PartialFile::PartialFile(const fs::path& path, std::uint64_t keep_bytes, const std::string& preamble,
                         unsigned writers, const std::string& option)
    : path_(path), failure_prefix_(option.empty() ? "" : option + ": "), buffers_(std::max(1U, writers)) {
  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  // O_APPEND: each write(2) of a writer's whole lines lands at the end, never inside another's. O_NOFOLLOW: a
  // link planted under the name is refused (ELOOP), never truncated or appended to through.
  fd_ = open_for_writing(path, O_APPEND | O_NOFOLLOW | (keep_bytes > 0 ? 0 : O_TRUNC));
  if (fd_ < 0) fail(errno);
  // Drop a half-written last line.
  if (keep_bytes > 0 && ::ftruncate(fd_, static_cast<off_t>(keep_bytes)) != 0) {
    const int reason = errno;
    ::close(fd_);  // no destructor runs for a constructor that throws
    fail(reason);
  }
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
      write(buffer);            // writes nothing once a write has failed
    } catch (const IoError&) {  // the sweep already failed or stopped; its own message is the one to show
    }
  }
  if (fd_ >= 0) ::close(fd_);
}

void PartialFile::append(unsigned writer, std::size_t index, const std::string& row) {
  if (const int error = error_.load(std::memory_order_relaxed); error != 0) fail(error);
  Buffer& buffer = buffers_.at(writer);
  append_partial_line(buffer.lines, index, row);
  // The clock is read only while the buffer is not full.
  if (buffer.lines.size() >= kBufferBytes || steady_ns() - buffer.last_write_ns >= kFlushIntervalNs) {
    write(buffer);
  }
}

void PartialFile::write(Buffer& buffer) {
  buffer.last_write_ns = steady_ns();
  if (buffer.lines.empty()) return;
  const std::lock_guard lock(write_mutex_);
  int error = error_.load();
  // One call for whole lines: another writer's lines never land inside them. After a failure nothing more is
  // written: the file may end in a cut-off line, and a later write (once space was freed) would follow it.
  if (error == 0) error = files::write_all(fd_, buffer.lines.data(), buffer.lines.size());
  buffer.lines.clear();
  if (error != 0) {
    error_ = error;
    fail(error);
  }
}

void PartialFile::fail(int error) const {
  throw IoError(
      fmt::format("{}cannot write '{}': {}", failure_prefix_, path_.string(), std::strerror(error)));
}

OrderedTable::OrderedTable(fs::path target, const std::string& header, std::size_t rows,
                           std::vector<std::uint64_t> done_offsets, const fs::path& partial)
    : target_(std::move(target)), rows_(rows), done_offsets_(std::move(done_offsets)) {
  // Created exclusively under a random name: never a planted link, never another run's temporary.
  files::TemporaryFile temporary = files::create_temporary_beside(target_);
  temporary_ = std::move(temporary.path);
  fd_ = temporary.fd;
  buffer_.reserve(kBufferBytes + kBufferBytes / 4);
  put(header);
  if (!done_offsets_.empty()) partial_ = std::make_unique<FileLines>(partial);
  advance();
}

OrderedTable::~OrderedTable() {
  if (fd_ < 0) return;  // committed, or removed when a write failed
  ::close(fd_);
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

bool OrderedTable::done_before(std::size_t index) const {
  return !done_offsets_.empty() && done_offsets_[index] != PartialSweep::kNotDone;
}

void OrderedTable::add(std::size_t index, std::string row) {
  if (index != next_) {
    waiting_.emplace(index, std::move(row));
    return;
  }
  put(row);
  ++next_;
  advance();
}

void OrderedTable::advance() {
  while (next_ < rows_) {
    if (done_before(next_)) {
      const std::optional<std::string_view> row =
          partial_line_row(partial_->lines().at(done_offsets_[next_]).text);
      // The line was checked when the partial file was read; it changed since.
      if (!row) {
        throw IoError(fmt::format("'{}' changed while the sweep resumed from it", partial_->path().string()));
      }
      put(*row);
    } else if (!waiting_.empty() && waiting_.begin()->first == next_) {
      put(waiting_.begin()->second);
      waiting_.erase(waiting_.begin());
    } else {
      return;
    }
    ++next_;
  }
}

void OrderedTable::put(std::string_view row) {
  buffer_ += row;
  buffer_ += '\n';
  if (buffer_.size() >= kBufferBytes) flush();
}

void OrderedTable::flush() {
  if (error_ != 0) fail(error_);  // rows that other workers add after the failure
  const int error = files::write_all(fd_, buffer_.data(), buffer_.size());
  buffer_.clear();
  if (error != 0) fail(error);
}

void OrderedTable::commit() {
  if (next_ != rows_) throw std::logic_error("OrderedTable::commit before every row was added");
  flush();
  const int closed = ::close(fd_);
  const int error = errno;
  fd_ = -1;
  if (closed != 0) {
    std::error_code ignored;
    fs::remove(temporary_, ignored);
    throw IoError(fmt::format("cannot write '{}': {}", target_.string(), std::strerror(error)));
  }
  files::rename_onto(temporary_, target_);
}

void OrderedTable::fail(int error) {
  // No write after a failed one: the file is closed and removed now, not written again at destruction.
  error_ = error;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ignored;
  fs::remove(temporary_, ignored);
  throw IoError(fmt::format("cannot write '{}': {}", temporary_.string(), std::strerror(error)));
}

}  // namespace restitution
