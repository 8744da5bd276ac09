/* A disk that fills up, for the fault tests (tests/fault/full_disk.py):
 * preloaded into anvil (LD_PRELOAD), it lets the process write
 * ANVIL_TEST_DISK_BYTES bytes to regular files in all, then fails every
 * further write with ENOSPC, as a full disk does. Pipes and terminals
 * (stdout, stderr) are not counted. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static long long budget = -1; /* bytes left; -1: not read yet */

static int counted(int fd) {
  struct stat s;
  return fstat(fd, &s) == 0 && S_ISREG(s.st_mode);
}

/* How many of `size` bytes may be written to `fd` now (0: the disk is full). */
static size_t allowed(int fd, size_t size) {
  if (budget < 0) {
    const char* text = getenv("ANVIL_TEST_DISK_BYTES");
    budget = text ? atoll(text) : (1LL << 62);
  }
  if (!counted(fd)) return size;
  if ((long long)size > budget) size = (size_t)budget;
  budget -= (long long)size;
  return size;
}

typedef ssize_t (*write_fn)(int, const void*, size_t);
typedef ssize_t (*pwrite_fn)(int, const void*, size_t, off_t);
typedef ssize_t (*writev_fn)(int, const struct iovec*, int);

ssize_t write(int fd, const void* data, size_t size) {
  static write_fn next = 0;
  if (!next) next = (write_fn)dlsym(RTLD_NEXT, "write");
  const size_t n = allowed(fd, size);
  if (n == 0 && size > 0) {
    errno = ENOSPC;
    return -1;
  }
  return next(fd, data, n);
}

ssize_t pwrite(int fd, const void* data, size_t size, off_t offset) {
  static pwrite_fn next = 0;
  if (!next) next = (pwrite_fn)dlsym(RTLD_NEXT, "pwrite");
  const size_t n = allowed(fd, size);
  if (n == 0 && size > 0) {
    errno = ENOSPC;
    return -1;
  }
  return next(fd, data, n, offset);
}

/* The large-file name of the same call. */
ssize_t pwrite64(int fd, const void* data, size_t size, off_t offset) __attribute__((alias("pwrite")));

ssize_t writev(int fd, const struct iovec* parts, int count) {
  static writev_fn next = 0;
  if (!next) next = (writev_fn)dlsym(RTLD_NEXT, "writev");
  size_t size = 0;
  for (int i = 0; i < count; ++i) size += parts[i].iov_len;
  /* All or nothing per call: a partial writev is rare enough not to model. */
  if (size > 0 && counted(fd) && allowed(fd, size) < size) {
    errno = ENOSPC;
    return -1;
  }
  return next(fd, parts, count);
}
