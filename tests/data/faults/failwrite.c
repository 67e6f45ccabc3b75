/* failwrite.c — an LD_PRELOAD shim for fault injection in the tests
 * (tests/cli/cli_atomic.sh compiles it with cc -shared -fPIC).  It counts the
 * calls of write, fsync, fdatasync and close on descriptors above 2 (not
 * standard input, output or error) and of rename and link, and makes one of
 * them fail, without doing it:
 *   FAULT_AT=k       the k-th counted call fails (absent or 0: none fails)
 *   FAULT_ERRNO=EIO  its errno (ENOSPC by default)
 *   FAULT_LOG=FILE   appends "k name" for the failed call to FILE, and
 *                    "total n" at exit (the number of counted calls)
 *   FAULT_SLEEP_MS=m sleeps m ms before every counted write (to widen the
 *                    window in which a test sends a signal)
 * A failed close still closes the descriptor (as Linux does). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static long counted, fail_at = -1;
static int fail_errno = ENOSPC, sleep_ms;
static const char *log_path;

static void write_log(const char *line)
{
    if (log_path == NULL) return;
    int fd = open(log_path, O_WRONLY | O_APPEND | O_CREAT, 0644);
    if (fd < 0) return;
    ssize_t (*real_write)(int, const void *, size_t) = dlsym(RTLD_NEXT, "write");
    real_write(fd, line, strlen(line));
    int (*real_close)(int) = dlsym(RTLD_NEXT, "close");
    real_close(fd);
}

static void at_end(void)
{
    char line[64];
    snprintf(line, sizeof line, "total %ld\n", counted);
    write_log(line);
}

__attribute__((constructor)) static void setup(void)
{
    const char *s = getenv("FAULT_AT");
    if (s && atol(s) > 0) fail_at = atol(s);
    s = getenv("FAULT_ERRNO");
    if (s && strcmp(s, "EIO") == 0) fail_errno = EIO;
    s = getenv("FAULT_SLEEP_MS");
    if (s) sleep_ms = atoi(s);
    log_path = getenv("FAULT_LOG");
    atexit(at_end);
}

/* 1 when this call is the one to fail (its errno set) */
static int should_fail(const char *name)
{
    counted++;
    if (counted != fail_at) return 0;
    char line[64];
    snprintf(line, sizeof line, "%ld %s\n", counted, name);
    write_log(line);
    errno = fail_errno;
    return 1;
}

ssize_t write(int fd, const void *buf, size_t n)
{
    static ssize_t (*real)(int, const void *, size_t);
    if (!real) real = dlsym(RTLD_NEXT, "write");
    if (fd > 2) {
        if (sleep_ms > 0) {
            struct timespec ts = { sleep_ms / 1000, (sleep_ms % 1000) * 1000000L };
            nanosleep(&ts, NULL);
        }
        if (should_fail("write")) return -1;
    }
    return real(fd, buf, n);
}

int fsync(int fd)
{
    static int (*real)(int);
    if (!real) real = dlsym(RTLD_NEXT, "fsync");
    if (fd > 2 && should_fail("fsync")) return -1;
    return real(fd);
}

int fdatasync(int fd)
{
    static int (*real)(int);
    if (!real) real = dlsym(RTLD_NEXT, "fdatasync");
    if (fd > 2 && should_fail("fdatasync")) return -1;
    return real(fd);
}

int close(int fd)
{
    static int (*real)(int);
    if (!real) real = dlsym(RTLD_NEXT, "close");
    if (fd > 2 && should_fail("close")) {
        int saved = errno;
        real(fd);
        errno = saved;
        return -1;
    }
    return real(fd);
}

int rename(const char *from, const char *to)
{
    static int (*real)(const char *, const char *);
    if (!real) real = dlsym(RTLD_NEXT, "rename");
    if (should_fail("rename")) return -1;
    return real(from, to);
}

int link(const char *from, const char *to)
{
    static int (*real)(const char *, const char *);
    if (!real) real = dlsym(RTLD_NEXT, "link");
    if (should_fail("link")) return -1;
    return real(from, to);
}
