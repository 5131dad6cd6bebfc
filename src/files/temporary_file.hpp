// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The temporary files every output is written into before it is renamed onto its name (the command line, the
// scene run, the sweep library and Python alike). A fixed name such as FILE.tmp can be planted in advance as
// a link to a victim, which the write would then fill and the rename would leave behind as FILE; two
// processes writing one FILE would also share it. So a temporary is NAME.<random>.tmp (or .tmp.<extension>),
// created with O_CREAT|O_EXCL|O_NOFOLLOW: never a file that existed before, never through a link.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace restitution::files {

// 12 hexadecimal digits from the kernel's random source: a name nobody can guess in advance.
std::string random_name_part();

// Creates `path` exclusively (O_CREAT|O_EXCL|O_NOFOLLOW, mode 0666 less the umask) and returns its open
// descriptor for writing, or -1 with errno set (EEXIST: something, a link included, already has that name).
int create_exclusively(const std::filesystem::path& path);

// An exclusively created temporary file beside `target`: TARGET.<random>.tmp in the same folder, so that the
// rename onto the target stays within one file system.
struct TemporaryFile {
  std::filesystem::path path;
  int fd = -1;
};
// Throws IoError naming the target when no temporary can be created in its folder.
TemporaryFile create_temporary_beside(const std::filesystem::path& target);

// Writes `content` into a new temporary beside `target` and closes it; returns its name. On failure the
// temporary is removed and IoError names the target and the system's reason (ENOSPC: "No space left").
std::filesystem::path write_temporary_beside(const std::filesystem::path& target, std::string_view content);

// Renames a finished temporary onto `target` (replacing it in one step). On failure the temporary is removed
// and IoError names the target and the system's reason.
void rename_onto(const std::filesystem::path& temporary, const std::filesystem::path& target);

// Writes all the bytes, continuing after a short write; returns 0, or the errno of the write(2) that failed
// (ENOSPC when the file takes no byte more). Raw write(2) rather than stdio: stdio writes what its buffer
// holds again when the file is closed, after a failure too.
int write_all(int fd, const char* data, std::size_t size);

}  // namespace restitution::files
