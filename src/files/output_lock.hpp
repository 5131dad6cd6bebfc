// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An advisory lock on what a command writes (a sweep's FILE and FILE.partial, a `run` output folder), so that
// a second process never writes the same files at the same time: flock(2) on a lock file holding the owner's
// process id. The kernel releases the lock when its process ends, however it ends, so a lock file left by a
// killed process is stale and simply taken over.
#include <filesystem>
#include <optional>
#include <string>

namespace restitution::files {

class OutputLock {
 public:
  // Takes the lock on `lock_file` (created if missing) and writes this process's id into it. Throws
  // InvalidInput at once, naming `what` and the holder's process id, when another process holds it; IoError
  // when the lock file cannot be created.
  OutputLock(std::filesystem::path lock_file, const std::string& what);
  ~OutputLock();  // removes the lock file and releases the lock
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// The lock of an output folder: FOLDER.lock beside it (not inside: the folder itself is made only by the
// first file written into it, so a run that fails or is killed before that leaves no folder behind). Folders
// above it are created for the lock file if missing, and removed again at the end when still empty.
class FolderLock {
 public:
  FolderLock(const std::filesystem::path& folder, const std::string& what);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::filesystem::path parent_, created_;  // created_: the outermost folder made here, or empty
  std::optional<OutputLock> lock_;
};

// The lock file of an output folder: FOLDER.lock beside it (inside it for a file system's root), FOLDER being
// where the name resolves to after symbolic links (files/resolved_path.hpp).
std::filesystem::path folder_lock_path(const std::filesystem::path& folder);

// The lock file of a sweep's output FILE: FILE.lock beside where FILE resolves to.
std::filesystem::path sweep_lock_path(const std::filesystem::path& file);

}  // namespace restitution::files
