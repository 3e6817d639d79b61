/* LD_PRELOAD for tests/fault_injection.sh where no small file system can be mounted: write(2),
 * pwrite(2), pwrite64 and writev(2) to files under $ENOSPC_DIR fail with ENOSPC once
 * $ENOSPC_BYTES bytes have been written there by this process (a full disk, as HDF5 and the
 * sweep's journals see it). Other files (stdout, stderr, sockets) are untouched. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static long long written = 0;

static int Limited(int fd, size_t n)
{
  const char *dir = getenv("ENOSPC_DIR"), *bytes = getenv("ENOSPC_BYTES");
  char        link[64], path[4096];
  if (!dir || !bytes) return 0;
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t len = readlink(link, path, sizeof path - 1);
  if (len <= 0) return 0;
  path[len] = 0;
  if (strncmp(path, dir, strlen(dir)) != 0) return 0;
  if (written + (long long)n > atoll(bytes)) return 1;
  written += (long long)n;
  return 0;
}

ssize_t write(int fd, const void *buf, size_t n)
{
  static ssize_t (*real)(int, const void *, size_t);
  if (!real) real = (ssize_t(*)(int, const void *, size_t))dlsym(RTLD_NEXT, "write");
  if (Limited(fd, n)) {
    errno = ENOSPC;
    return -1;
  }
  return real(fd, buf, n);
}

ssize_t pwrite(int fd, const void *buf, size_t n, off_t off)
{
  static ssize_t (*real)(int, const void *, size_t, off_t);
  if (!real) real = (ssize_t(*)(int, const void *, size_t, off_t))dlsym(RTLD_NEXT, "pwrite");
  if (Limited(fd, n)) {
    errno = ENOSPC;
    return -1;
  }
  return real(fd, buf, n, off);
}

ssize_t pwrite64(int fd, const void *buf, size_t n, off_t off)
{
  static ssize_t (*real)(int, const void *, size_t, off_t);
  if (!real) real = (ssize_t(*)(int, const void *, size_t, off_t))dlsym(RTLD_NEXT, "pwrite64");
  if (Limited(fd, n)) {
    errno = ENOSPC;
    return -1;
  }
  return real(fd, buf, n, off);
}

ssize_t writev(int fd, const struct iovec *iov, int count)
{
  static ssize_t (*real)(int, const struct iovec *, int);
  size_t         n = 0;
  if (!real) real = (ssize_t(*)(int, const struct iovec *, int))dlsym(RTLD_NEXT, "writev");
  for (int i = 0; i < count; ++i) n += iov[i].iov_len;
  if (Limited(fd, n)) {
    errno = ENOSPC;
    return -1;
  }
  return real(fd, iov, count);
}
