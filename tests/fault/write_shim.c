// SPDX-License-Identifier: BSD-3-Clause
// Writes that fail once, and a SIGKILL at a chosen rename, for fault-injection tests without root
// (LD_PRELOAD=libwrite_shim.so).
//
// A full disk: the first write to a targeted file that reaches byte $RESTITUTION_FAULT_OFFSET of the file is
// cut short there, the next write to it fails with ENOSPC, and every later write goes through: a full disk on
// which space is freed after the failure (the case where a late write follows a cut-off line). A file is
// targeted when its path ends in $RESTITUTION_FAULT_SUFFIX and, if $RESTITUTION_FAULT_NAME_PREFIX is set, its
// name (the last part of the path) begins with it: temporaries have random names (NAME.<random>.tmp), so the
// prefix picks one file of a set. Every way a program writes is wrapped: write, writev (libstdc++'s streams
// write large blocks with it), pwrite, and C stdio's fwrite, fputs and fputc (glibc's stdio calls its own
// internal write, which no preload reaches, so the stream functions themselves fail).
//
// A kill: with $RESTITUTION_KILL_AT_RENAME = N, the process sends itself SIGKILL in place of its Nth rename
// (rename, renameat, renameat2; std::filesystem::rename calls rename): the state a power cut or a kill -9
// between two renames leaves.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

enum { kArmed, kCutShort, kSpent };

static pthread_mutex_t mutex = PTHREAD_MUTEX_INITIALIZER;
static int state = kArmed;
static int renames = 0;

#define NEXT(name) ((__typeof__(&name))dlsym(RTLD_NEXT, #name))

static int targeted(int fd) {
  const char* suffix = getenv("RESTITUTION_FAULT_SUFFIX");
  if (suffix == NULL || *suffix == '\0' || fd < 0) return 0;
  char link[64];
  char path[PATH_MAX];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, path, sizeof path - 1);
  if (n <= 0) return 0;
  path[n] = '\0';
  const size_t length = strlen(suffix);
  if ((size_t)n < length || strcmp(path + n - length, suffix) != 0) return 0;
  const char* prefix = getenv("RESTITUTION_FAULT_NAME_PREFIX");
  const char* name = strrchr(path, '/');
  name = name != NULL ? name + 1 : path;
  return prefix == NULL || strncmp(name, prefix, strlen(prefix)) == 0;
}

// Where a write(2) lands: the end of the file in append mode, else the file offset.
static off_t position(int fd) {
  const int flags = fcntl(fd, F_GETFL);
  if (flags >= 0 && (flags & O_APPEND) != 0) {
    struct stat s;
    return fstat(fd, &s) == 0 ? s.st_size : 0;
  }
  const off_t at = lseek(fd, 0, SEEK_CUR);
  return at < 0 ? 0 : at;
}

// Called with the mutex held, for a write of `size` bytes at byte `at` of a file: how many of them go
// through (all, or fewer when the write is cut short), or -1 when it fails with ENOSPC.
static ssize_t allowance(int fd, off_t at, size_t size) {
  if (state == kSpent || !targeted(fd)) return (ssize_t)size;
  if (state == kCutShort) {
    state = kSpent;
    return -1;
  }
  const char* text = getenv("RESTITUTION_FAULT_OFFSET");
  const off_t offset = text != NULL ? (off_t)strtoll(text, NULL, 10) : 0;
  if (at + (off_t)size <= offset) return (ssize_t)size;
  if (at >= offset) {  // nothing fits: the failure comes at once
    state = kSpent;
    return -1;
  }
  state = kCutShort;
  return (ssize_t)(offset - at);
}

// The allowance of a write through a file descriptor (the mutex is taken here).
static ssize_t fd_allowance(int fd, off_t at_or_minus_one, size_t size) {
  pthread_mutex_lock(&mutex);
  const ssize_t allowed = allowance(fd, at_or_minus_one < 0 ? position(fd) : at_or_minus_one, size);
  pthread_mutex_unlock(&mutex);
  return allowed;
}

ssize_t write(int fd, const void* data, size_t size) {
  const ssize_t allowed = fd_allowance(fd, -1, size);
  if (allowed < 0) {
    errno = ENOSPC;
    return -1;
  }
  return NEXT(write)(fd, data, (size_t)allowed);
}

ssize_t pwrite(int fd, const void* data, size_t size, off_t at) {
  const ssize_t allowed = fd_allowance(fd, at, size);
  if (allowed < 0) {
    errno = ENOSPC;
    return -1;
  }
  return NEXT(pwrite)(fd, data, (size_t)allowed, at);
}

ssize_t pwrite64(int fd, const void* data, size_t size, off_t at) {
  return pwrite(fd, data, size, at);
}

ssize_t writev(int fd, const struct iovec* parts, int count) {
  size_t total = 0;
  for (int i = 0; i < count; ++i) total += parts[i].iov_len;
  const ssize_t allowed = fd_allowance(fd, -1, total);
  if (allowed < 0) {
    errno = ENOSPC;
    return -1;
  }
  if ((size_t)allowed == total) return NEXT(writev)(fd, parts, count);
  // Cut short: the leading parts that fit, the last one shortened.
  struct iovec kept[IOV_MAX];
  int n = 0;
  size_t left = (size_t)allowed;
  for (int i = 0; i < count && left > 0 && n < IOV_MAX; ++i) {
    kept[n] = parts[i];
    if (kept[n].iov_len > left) kept[n].iov_len = left;
    left -= kept[n].iov_len;
    ++n;
  }
  return n == 0 ? 0 : NEXT(writev)(fd, kept, n);
}

// stdio: the stream's logical position (buffered bytes included) decides.
static ssize_t stream_allowance(FILE* stream, size_t size) {
  pthread_mutex_lock(&mutex);
  const int fd = fileno(stream);
  ssize_t allowed = (ssize_t)size;
  if (state != kSpent && targeted(fd)) {
    const long at = ftell(stream);
    allowed = allowance(fd, at < 0 ? 0 : (off_t)at, size);
  }
  pthread_mutex_unlock(&mutex);
  return allowed;
}

size_t fwrite(const void* data, size_t size, size_t count, FILE* stream) {
  if (size == 0) return NEXT(fwrite)(data, size, count, stream);
  const ssize_t allowed = stream_allowance(stream, size * count);
  if (allowed < 0) {
    errno = ENOSPC;
    return 0;
  }
  if ((size_t)allowed == size * count) return NEXT(fwrite)(data, size, count, stream);
  NEXT(fwrite)(data, 1, (size_t)allowed, stream);
  errno = ENOSPC;
  return (size_t)allowed / size;
}

int fputs(const char* text, FILE* stream) {
  const size_t size = strlen(text);
  const ssize_t allowed = stream_allowance(stream, size);
  if (allowed >= 0 && (size_t)allowed == size) return NEXT(fputs)(text, stream);
  if (allowed > 0) NEXT(fwrite)(text, 1, (size_t)allowed, stream);
  errno = ENOSPC;
  return EOF;
}

int fputc(int c, FILE* stream) {
  if (stream_allowance(stream, 1) == 1) return NEXT(fputc)(c, stream);
  errno = ENOSPC;
  return EOF;
}

static void count_rename(void) {
  const char* text = getenv("RESTITUTION_KILL_AT_RENAME");
  if (text == NULL) return;
  pthread_mutex_lock(&mutex);
  const int n = ++renames;
  pthread_mutex_unlock(&mutex);
  if (n == atoi(text)) raise(SIGKILL);
}

int rename(const char* from, const char* to) {
  count_rename();
  return NEXT(rename)(from, to);
}

int renameat(int from_folder, const char* from, int to_folder, const char* to) {
  count_rename();
  return NEXT(renameat)(from_folder, from, to_folder, to);
}

int renameat2(int from_folder, const char* from, int to_folder, const char* to, unsigned flags) {
  count_rename();
  return NEXT(renameat2)(from_folder, from, to_folder, to, flags);
}
