// SPDX-License-Identifier: BSD-3-Clause
// A write(2) that fails once, for fault-injection tests without root (LD_PRELOAD=libwrite_shim.so). The first
// write to a file whose path ends in $RESTITUTION_FAULT_SUFFIX that reaches byte $RESTITUTION_FAULT_OFFSET of
// the file is cut short there, the next write to it fails with ENOSPC, and every later write goes through: a
// full disk on which space is freed after the failure (the case where a late write follows a cut-off line).
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { kArmed, kCutShort, kSpent };

static pthread_mutex_t mutex = PTHREAD_MUTEX_INITIALIZER;
static int state = kArmed;

static ssize_t real_write(int fd, const void* data, size_t size) {
  static ssize_t (*next)(int, const void*, size_t) = NULL;
  if (next == NULL) next = (ssize_t(*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
  return next(fd, data, size);
}

static int targeted(int fd) {
  const char* suffix = getenv("RESTITUTION_FAULT_SUFFIX");
  if (suffix == NULL || *suffix == '\0') return 0;
  char link[64];
  char path[PATH_MAX];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, path, sizeof path - 1);
  if (n <= 0) return 0;
  path[n] = '\0';
  const size_t length = strlen(suffix);
  return (size_t)n >= length && strcmp(path + n - length, suffix) == 0;
}

// Where the write lands: the end of the file in append mode, else the file offset.
static off_t position(int fd) {
  const int flags = fcntl(fd, F_GETFL);
  if (flags >= 0 && (flags & O_APPEND) != 0) {
    struct stat s;
    return fstat(fd, &s) == 0 ? s.st_size : 0;
  }
  const off_t at = lseek(fd, 0, SEEK_CUR);
  return at < 0 ? 0 : at;
}

ssize_t write(int fd, const void* data, size_t size) {
  pthread_mutex_lock(&mutex);
  if (state == kSpent || !targeted(fd)) {
    pthread_mutex_unlock(&mutex);
    return real_write(fd, data, size);
  }
  ssize_t result = -1;
  if (state == kCutShort) {
    state = kSpent;
    errno = ENOSPC;
  } else {
    const char* text = getenv("RESTITUTION_FAULT_OFFSET");
    const off_t offset = text != NULL ? (off_t)strtoll(text, NULL, 10) : 0;
    const off_t at = position(fd);
    if (at + (off_t)size <= offset) {
      result = real_write(fd, data, size);
    } else if (at >= offset) {  // nothing fits: the failure comes at once
      state = kSpent;
      errno = ENOSPC;
    } else {
      state = kCutShort;
      result = real_write(fd, data, (size_t)(offset - at));
    }
  }
  const int error = errno;
  pthread_mutex_unlock(&mutex);
  errno = error;
  return result;
}
