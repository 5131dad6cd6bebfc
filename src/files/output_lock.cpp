// SPDX-License-Identifier: BSD-3-Clause
#include "files/output_lock.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <system_error>
#include <thread>

#include "files/resolved_path.hpp"
#include "restitution/errors.hpp"

namespace restitution::files {
namespace {
namespace fs = std::filesystem;

constexpr int kAttempts = 20;
constexpr auto kPidWait = std::chrono::milliseconds(5);

// The holder writes its id right after taking the lock: wait a little for it rather than name nobody.
std::string holder_of(const fs::path& path) {
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    long long pid = 0;
    std::ifstream in(path);
    if (in >> pid && pid > 0) return fmt::format("process {}", pid);
    std::this_thread::sleep_for(kPidWait);
  }
  return "a process that has not written its id";
}

// Removes the folders a FolderLock created, innermost first, as long as they are empty.
void remove_empty_folders(fs::path folder, const fs::path& outermost) {
  std::error_code error;
  for (; fs::remove(folder, error) && folder != outermost; folder = folder.parent_path()) {
  }
}

bool same_file(int fd, const fs::path& path) {
  struct stat open_file {};
  struct stat named {};
  return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 &&
         open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

}  // namespace

OutputLock::OutputLock(fs::path lock_file, const std::string& what) : path_(std::move(lock_file)) {
  // The holder removes the lock file when it ends: a lock taken on a file that was removed (or replaced)
  // meanwhile protects nothing, so it is taken again on the file the name now gives.
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC,
                 0644);  // NOLINT(cppcoreguidelines-pro-type-vararg)
    if (fd_ < 0) {
      throw IoError(fmt::format("{}: cannot create the lock file '{}': {}", what, path_.string(),
                                std::strerror(errno)));
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK) {
        throw InvalidInput(
            fmt::format("{} is being written by another restitution run ({}, lock file '{}'): "
                        "wait until it ends, or write elsewhere",
                        what, holder_of(path_), path_.string()));
      }
      if (error == EINTR) continue;
      return;  // a file system without locks (ENOLCK): work unlocked, as before locks existed
    }
    if (same_file(fd_, path_)) break;
    ::close(fd_);
    fd_ = -1;
  }
  if (fd_ < 0) return;
  const std::string pid = fmt::format("{}\n", ::getpid());
  // The id is for messages only: the lock holds without it.
  if (::ftruncate(fd_, 0) != 0 || ::write(fd_, pid.data(), pid.size()) < 0) return;
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still locked: a process that opened it meanwhile retries on the name
  ::close(fd_);
}

FolderLock::FolderLock(const fs::path& folder, const std::string& what) {
  const fs::path lock_file = folder_lock_path(folder);
  parent_ = lock_file.parent_path();
  for (fs::path p = parent_; !p.empty() && !fs::exists(p) && p.has_relative_path(); p = p.parent_path())
    created_ = p;
  std::error_code error;
  fs::create_directories(parent_, error);
  if (error) {
    throw IoError(
        fmt::format("{}: cannot create the folder '{}': {}", what, parent_.string(), error.message()));
  }
  try {
    lock_.emplace(lock_file, what);
  } catch (...) {
    if (!created_.empty()) remove_empty_folders(parent_, created_);  // never another run's files
    throw;
  }
}

FolderLock::~FolderLock() {
  lock_.reset();
  if (!created_.empty()) remove_empty_folders(parent_, created_);
}

// Both beside the place the name resolves to: two names of one folder or file (a symlink to it, a link to a
// folder above it) take one lock.
fs::path folder_lock_path(const fs::path& folder) {
  fs::path path = resolved_path(folder);
  if (!path.has_filename()) path = path.parent_path();  // "out/" and "out/." name "out"
  if (path == path.root_path()) return path / ".restitution.lock";
  return path.string() + ".lock";
}

fs::path sweep_lock_path(const fs::path& file) {
  return resolved_path(file).string() + ".lock";
}

}  // namespace restitution::files
