// SPDX-License-Identifier: BSD-3-Clause
#include "files/temporary_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/random.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <system_error>

#include "restitution/errors.hpp"

namespace restitution::files {

std::string random_name_part() {
  std::array<std::uint8_t, 6> bytes{};
  std::size_t filled = 0;
  while (filled < bytes.size()) {
    const ssize_t got = ::getrandom(bytes.data() + filled, bytes.size() - filled, 0);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;  // no kernel source (never on Linux >= 3.17): fall back below
    filled += static_cast<std::size_t>(got);
  }
  std::string out;
  for (const std::uint8_t b : bytes) out += fmt::format("{:02x}", b);
  if (filled < bytes.size()) out += fmt::format("{:x}", ::getpid());  // still exclusive, just guessable
  return out;
}

int create_exclusively(const std::filesystem::path& path) {
  return ::open(
      path.c_str(),
      O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,  // NOLINT(cppcoreguidelines-pro-type-vararg)
      0666);
}

TemporaryFile create_temporary_beside(const std::filesystem::path& target) {
  // A name taken by chance (or planted) is skipped for another; a folder that refuses files fails at once.
  constexpr int kAttempts = 16;
  int error = EEXIST;
  for (int attempt = 0; attempt < kAttempts && error == EEXIST; ++attempt) {
    std::filesystem::path path = target;
    path += fmt::format(".{}.tmp", random_name_part());
    const int fd = create_exclusively(path);
    if (fd >= 0) return {std::move(path), fd};
    error = errno;
  }
  throw IoError(fmt::format("cannot write '{}': cannot create a temporary file beside it: {}",
                            target.string(), std::strerror(error)));
}

std::filesystem::path write_temporary_beside(const std::filesystem::path& target, std::string_view content) {
  const TemporaryFile temporary = create_temporary_beside(target);
  const int written = write_all(temporary.fd, content.data(), content.size());
  const int closed = ::close(temporary.fd) == 0 ? 0 : errno;
  if (written != 0 || closed != 0) {
    ::unlink(temporary.path.c_str());  // a half-written temporary must not outlive the command
    throw IoError(fmt::format("cannot write '{}': {}", target.string(),
                              std::strerror(written != 0 ? written : closed)));
  }
  return temporary.path;
}

void rename_onto(const std::filesystem::path& temporary, const std::filesystem::path& target) {
  std::error_code error;
  std::filesystem::rename(temporary, target, error);
  if (!error) return;
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
  throw IoError(fmt::format("cannot write '{}': {}", target.string(), error.message()));
}

int write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) return errno;
    if (written == 0) return ENOSPC;
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return 0;
}

}  // namespace restitution::files
