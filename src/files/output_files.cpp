// SPDX-License-Identifier: BSD-3-Clause
#include "files/output_files.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <system_error>

#include "files/printable_name.hpp"
#include "files/temporary_file.hpp"
#include "restitution/errors.hpp"

namespace restitution::files {
namespace fs = std::filesystem;

namespace {

// `file` (empty for a folder output) names what is to be written there, so that the message says which output
// failed; the system's reason comes last, in brackets, since for /proc it reads "No such file or directory".
void check_writable_folder(const fs::path& folder, const fs::path& file) {
  std::error_code error;
  const fs::path start = folder.empty() ? fs::path(".") : folder;
  fs::path existing = start;
  while (!fs::exists(fs::symlink_status(existing, error)) && existing.has_parent_path() &&
         existing.parent_path() != existing) {
    existing = existing.parent_path();
  }
  if (!fs::exists(existing)) existing = ".";  // a relative path none of whose parts exists yet
  const std::string what =
      existing != start ? fmt::format("cannot create output folder '{}'", folder.string())
      : file.empty()    ? fmt::format("cannot write into output folder '{}'", folder.string())
                        : fmt::format("cannot write '{}'", file.string());
  if (!fs::is_directory(existing)) {
    throw IoError(fmt::format("{}: '{}' is not a folder", what, existing.string()));
  }
  // access(W_OK) says yes to root everywhere, /proc included: probe with a file that is removed at once.
  std::string probe = (existing / ".restitution-probe-XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0) {
    throw IoError(
        fmt::format("{}: the folder '{}' does not let this program create files in it (the system "
                    "says: {})",
                    what, existing.string(), std::strerror(errno)));
  }
  close(fd);
  unlink(probe.c_str());
}

}  // namespace

void check_output_folder(const fs::path& folder) {
  check_writable_folder(folder, {});
}

void check_output_file(const fs::path& path) {
  const OutputTarget target = output_target(path);
  if (target.in_place) return;
  std::error_code error;
  const fs::path folder = target.path.has_parent_path() ? target.path.parent_path() : fs::path(".");
  if (fs::is_symlink(fs::symlink_status(path, error)) && !fs::is_directory(folder, error)) {
    throw InvalidInput(fmt::format(
        "'{}' is a link to '{}', whose folder does not exist: writing would create folders where the link "
        "points; create the folder, or name another file",
        printable_name(path.string()), printable_name(target.path.string())));
  }
  check_writable_folder(target.path.parent_path(), path);
}

void check_figure_file(const fs::path& path, const std::string& option) {
  if (output_target(path).in_place) {
    throw InvalidInput(
        fmt::format("{} '{}' is a device, a pipe or a stream, not a file: a figure is written as a "
                    "new file and renamed into place; name a file",
                    option, printable_name(path.string())));
  }
  check_output_file(path);
}

OutputTarget output_target(const fs::path& path) {
  std::error_code error;
  const fs::file_status followed = fs::status(path, error);
  if (fs::is_directory(followed)) {
    throw InvalidInput(fmt::format("'{}' is a folder, not a file", path.string()));
  }
  if (fs::exists(followed) && !fs::is_regular_file(followed)) return {path, true};  // device, FIFO, socket
  fs::path at = path;
  for (int hops = 0; fs::is_symlink(fs::symlink_status(at, error)); ++hops) {
    if (hops == 40) throw InvalidInput(fmt::format("'{}': too many levels of symbolic links", path.string()));
    const fs::path link = fs::read_symlink(at, error);
    if (error) throw InvalidInput(fmt::format("cannot read the link '{}': {}", at.string(), error.message()));
    at = link.is_absolute() ? link : at.parent_path() / link;
    // /dev/stdout -> /proc/self/fd/1: an open stream, whatever file it happens to be.
    if (at.lexically_normal().string().rfind("/proc/", 0) == 0) return {path, true};
  }
  return {at.lexically_normal(), false};
}

void write_in_place(const fs::path& path, const std::string& content) {
  const int fd =
      ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);  // NOLINT(cppcoreguidelines-pro-type-vararg)
  const int written = fd < 0 ? errno : write_all(fd, content.data(), content.size());
  const int closed = fd < 0 || ::close(fd) == 0 ? 0 : errno;
  if (written != 0 || closed != 0) {
    throw IoError(fmt::format("cannot write '{}': {}", printable_name(path.string()),
                              std::strerror(written != 0 ? written : closed)));
  }
}

void create_folder_of(const fs::path& file) {
  std::error_code error;
  if (file.has_parent_path()) fs::create_directories(file.parent_path(), error);
  if (error)
    throw IoError(fmt::format("cannot create the folder of '{}': {}", file.string(), error.message()));
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  const OutputTarget target = output_target(path);
  if (target.in_place) {
    write_in_place(path, content);
    return;
  }
  create_folder_of(target.path);
  rename_onto(write_temporary_beside(target.path, content), target.path);
}

}  // namespace restitution::files
