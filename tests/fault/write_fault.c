/* A write-fault shim for tests, loaded with LD_PRELOAD: after DPDRNG_FAULT_AFTER bytes have gone to regular files,
 * every further write to a regular file fails with DPDRNG_FAULT_ERRNO (ENOSPC, the default, or EIO), the way a
 * disk that fills up part-way fails. The write that crosses the limit is cut short, as a real one would be.
 * Standard error, pipes, terminals and /dev/null pass untouched, so the process's messages still arrive.
 *
 * glibc's stdio writes its buffers through an internal write that a preloaded library cannot replace, so the
 * stdio calls the tool uses (fwrite, fputs, putc, fputc, the printf family) are counted here as well; a refused
 * stdio write sets the stream's error indicator, as a failed flush would. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/sendfile.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

#undef putc
#undef putchar
#undef fputc

static atomic_llong budget = -1; /* bytes still allowed; -1 until read from the environment */
static int fault_errno = ENOSPC;

static void init_budget(void) {
  if (atomic_load(&budget) >= 0) return;
  const char* after = getenv("DPDRNG_FAULT_AFTER");
  const char* err = getenv("DPDRNG_FAULT_ERRNO");
  if (err && strcmp(err, "EIO") == 0) fault_errno = EIO;
  long long n = after ? atoll(after) : 0;
  if (n < 0) n = 0;
  long long unset = -1;
  atomic_compare_exchange_strong(&budget, &unset, n);
}

static int is_regular(int fd) {
  struct stat st;
  return fd >= 0 && fd != STDERR_FILENO && fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
}

/* How many of `want` bytes to a regular file may be written; 0 means the write fails. */
static size_t allow(size_t want) {
  init_budget();
  for (;;) {
    long long left = atomic_load(&budget);
    const long long take = (long long)want < left ? (long long)want : left;
    if (atomic_compare_exchange_weak(&budget, &left, left - take)) return (size_t)take;
  }
}

#define REAL(name) \
  static __typeof__(&name) real_##name; \
  if (!real_##name) real_##name = (__typeof__(&name))dlsym(RTLD_NEXT, #name)

ssize_t write(int fd, const void* buf, size_t count) {
  REAL(write);
  if (count == 0 || !is_regular(fd)) return real_write(fd, buf, count);
  const size_t n = allow(count);
  if (n == 0) {
    errno = fault_errno;
    return -1;
  }
  return real_write(fd, buf, n);
}

ssize_t pwrite(int fd, const void* buf, size_t count, off_t offset) {
  REAL(pwrite);
  if (count == 0 || !is_regular(fd)) return real_pwrite(fd, buf, count, offset);
  const size_t n = allow(count);
  if (n == 0) {
    errno = fault_errno;
    return -1;
  }
  return real_pwrite(fd, buf, n, offset);
}

ssize_t pwrite64(int fd, const void* buf, size_t count, off_t offset) { return pwrite(fd, buf, count, offset); }

ssize_t writev(int fd, const struct iovec* iov, int iovcnt) {
  REAL(writev);
  if (!is_regular(fd)) return real_writev(fd, iov, iovcnt);
  /* One buffer at a time through write(): a short write ends the call, as the kernel's would. */
  ssize_t total = 0;
  for (int k = 0; k < iovcnt; ++k) {
    const ssize_t w = write(fd, iov[k].iov_base, iov[k].iov_len);
    if (w < 0) return total > 0 ? total : -1;
    total += w;
    if ((size_t)w < iov[k].iov_len) break;
  }
  return total;
}

ssize_t sendfile(int out_fd, int in_fd, off_t* offset, size_t count) {
  REAL(sendfile);
  if (count == 0 || !is_regular(out_fd)) return real_sendfile(out_fd, in_fd, offset, count);
  const size_t n = allow(count);
  if (n == 0) {
    errno = fault_errno;
    return -1;
  }
  return real_sendfile(out_fd, in_fd, offset, n);
}

ssize_t sendfile64(int out_fd, int in_fd, off_t* offset, size_t count) {
  return sendfile(out_fd, in_fd, offset, count);
}

ssize_t copy_file_range(int fd_in, off_t* off_in, int fd_out, off_t* off_out, size_t len, unsigned flags) {
  REAL(copy_file_range);
  if (len == 0 || !is_regular(fd_out)) return real_copy_file_range(fd_in, off_in, fd_out, off_out, len, flags);
  const size_t n = allow(len);
  if (n == 0) {
    errno = fault_errno;
    return -1;
  }
  return real_copy_file_range(fd_in, off_in, fd_out, off_out, n, flags);
}

/* stdio: the bytes a call would add to a stream on a regular file are counted when the call is made. */
static size_t stdio_allow(FILE* f, size_t want) {
  if (want == 0 || !is_regular(fileno(f))) return want;
  const size_t n = allow(want);
  if (n < want) {
    f->_flags |= _IO_ERR_SEEN;
    errno = fault_errno;
  }
  return n;
}

size_t fwrite(const void* ptr, size_t size, size_t nmemb, FILE* f) {
  REAL(fwrite);
  if (size == 0 || nmemb == 0) return real_fwrite(ptr, size, nmemb, f);
  const size_t items = stdio_allow(f, size * nmemb) / size;
  if (items == 0) return 0;
  const size_t w = real_fwrite(ptr, size, items, f);
  if (items < nmemb) {
    f->_flags |= _IO_ERR_SEEN;
    errno = fault_errno;
  }
  return w;
}

int fputs(const char* s, FILE* f) {
  const size_t len = strlen(s);
  return fwrite(s, 1, len, f) == len ? 1 : EOF;
}

int fputc(int c, FILE* f) {
  const unsigned char b = (unsigned char)c;
  return fwrite(&b, 1, 1, f) == 1 ? b : EOF;
}

int putc(int c, FILE* f) { return fputc(c, f); }
int _IO_putc(int c, FILE* f) { return fputc(c, f); }
int putchar(int c) { return fputc(c, stdout); }
int puts(const char* s) { return fputs(s, stdout) == EOF || fputc('\n', stdout) == EOF ? EOF : 1; }

int vfprintf(FILE* f, const char* fmt, va_list ap) {
  va_list copy;
  va_copy(copy, ap);
  const int len = vsnprintf(NULL, 0, fmt, copy);
  va_end(copy);
  if (len < 0) return len;
  char* text = malloc((size_t)len + 1);
  if (!text) return -1;
  vsnprintf(text, (size_t)len + 1, fmt, ap);
  const size_t w = fwrite(text, 1, (size_t)len, f);
  free(text);
  return w == (size_t)len ? len : -1;
}

int fprintf(FILE* f, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const int r = vfprintf(f, fmt, ap);
  va_end(ap);
  return r;
}

int vprintf(const char* fmt, va_list ap) { return vfprintf(stdout, fmt, ap); }

int printf(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const int r = vfprintf(stdout, fmt, ap);
  va_end(ap);
  return r;
}
