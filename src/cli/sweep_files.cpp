// SPDX-License-Identifier: BSD-3-Clause
#include "cli/sweep_files.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <system_error>

#include "cli/io_error.hpp"

namespace restitution::cli {
namespace {
namespace fs = std::filesystem;

// A crash loses at most the rows of the last interval, which --resume computes again. A flush per row (a
// system call each) cost more than a Taylor solve and, serialized, kept a second thread from paying off.
constexpr long long kFlushIntervalNs = 100'000'000;
// Large stdio buffers: with the default 4 KiB one, a 15 MB table is some 3700 write calls.
constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

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

PartialFile::PartialFile(const fs::path& path, std::size_t keep_bytes, const std::string& preamble)
    : path_(path), last_flush_ns_(steady_ns()) {
  if (keep_bytes > 0) fs::resize_file(path, keep_bytes);  // drop a half-written last line
  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  file_ = open_buffered(path, keep_bytes > 0 ? "ab" : "wb");
  if (file_ == nullptr) throw IoError(fmt::format("--out: cannot write '{}'", path.string()));
  if (keep_bytes == 0) {
    if (std::fputs(preamble.c_str(), file_) < 0) fail();
    flush();
  }
}

PartialFile::~PartialFile() {
  if (file_ == nullptr) return;
  std::fflush(file_);
  std::fclose(file_);
}

void PartialFile::append(std::size_t index, const std::string& row) {
  fmt::print(file_, "{},{}\n", index, row);
  if (std::ferror(file_) != 0) fail();
  if (const long long now = steady_ns(); now - last_flush_ns_ >= kFlushIntervalNs) {
    flush();
    last_flush_ns_ = now;
  }
}

void PartialFile::flush() {
  if (std::fflush(file_) != 0) fail();
}

void PartialFile::fail() const {
  throw IoError(fmt::format("--out: cannot write '{}': {}", path_.string(), std::strerror(errno)));
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
