/* file.c — input files read whole, and output files written atomically (a
 * temporary file next to the target, then rename), so that a failed write
 * never leaves a truncated file, with the target's permissions kept. */
#define _DEFAULT_SOURCE /* mkstemp, realpath, fchmod, lstat */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "core/file.h"

/* What the user can do about a file that cannot be opened or read. */
static const char *read_hint(int errnum)
{
    switch (errnum) {
    case EACCES:
    case EPERM: return "check its permissions";
    case EISDIR: return "give a file, not a directory";
    case ENOENT:
    case ENOTDIR:
    case ENAMETOOLONG:
    case ELOOP: return "check the path";
    default: return "check the file";
    }
}

int vigen_read_file(char **data, size_t *len, const char *path, size_t max_len, vigen_error *err)
{
    *data = NULL;
    *len = 0;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return vigen_error_set(err, VIGEN_E_IO, "%s: cannot open: %s; %s", path, strerror(errno), read_hint(errno));
    size_t n = 0, cap = 1 << 16;
    char *buf = malloc(cap);
    int code = buf ? VIGEN_OK : vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", path);
    while (code == VIGEN_OK) {
        if (cap - n < 2) {
            char *p = realloc(buf, cap * 2);
            if (p == NULL) { code = vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", path); break; }
            buf = p;
            cap *= 2;
        }
        size_t got = fread(buf + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0) {
            if (ferror(f))
                code = vigen_error_set(err, VIGEN_E_IO, "%s: cannot read: %s; %s", path, strerror(errno), read_hint(errno));
            break;
        }
        if (n > max_len)
            code = vigen_error_set(err, VIGEN_E_LIMIT, "%s: the file is larger than %zu bytes", path, max_len);
    }
    fclose(f);
    if (code != VIGEN_OK) {
        free(buf);
        return code;
    }
    buf[n] = '\0';
    *data = buf;
    *len = n;
    return VIGEN_OK;
}

/* Writes everything or fails (no partial output left behind). */
static int write_all(int fd, const char *text, size_t n)
{
    while (n > 0) {
        ssize_t k = write(fd, text, n);
        if (k < 0) {
            if (errno == EINTR) continue;
            return 0;
        }
        text += k;
        n -= (size_t)k;
    }
    return 1;
}

int vigen_write_file_atomic(const char *path, const char *text, vigen_error *err)
{
    size_t n = strlen(text);
    if (strcmp(path, "-") == 0) {
        if (fwrite(text, 1, n, stdout) != n || fflush(stdout) != 0)
            return vigen_error_set(err, VIGEN_E_WRITE, "cannot write to standard output: %s", strerror(errno));
        return VIGEN_OK;
    }
    /* A symbolic link is followed: the file it points to is replaced, the
     * link stays.  A device or FIFO (/dev/null, a pipe) is written directly:
     * renaming over it would replace the device with a regular file. */
    char *target = NULL;
    struct stat st;
    int exists = 0;
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        target = realpath(path, NULL);
        if (target == NULL) {
            /* /dev/stdout -> /proc/self/fd/1 -> "pipe:[...]": no path, but a
             * device or pipe that can be written in place */
            if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) target = vigen_strdup(path);
            else return vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: it is a symbolic link to a missing file",
                                        path);
        }
    } else target = vigen_strdup(path);
    if (stat(target, &st) == 0) {
        exists = 1;
        if (!S_ISREG(st.st_mode)) {
            int code = VIGEN_OK;
            FILE *f = fopen(target, "wb");
            if (f == NULL || fwrite(text, 1, n, f) != n || fclose(f) != 0)
                code = vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", path, strerror(errno));
            free(target);
            return code;
        }
    }
    /* A fresh, unpredictable temporary in the same directory (mkstemp creates
     * it exclusively, so nobody can plant a link there), then rename. */
    char *tmp = vigen_strdup_printf("%s.tmp.XXXXXX", target);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        int code = vigen_error_set(err, VIGEN_E_WRITE, "cannot create a temporary file next to %s: %s", path,
                                   strerror(errno));
        free(tmp);
        free(target);
        return code;
    }
    /* the new file gets the old one's permissions, or the usual 0666 & ~umask */
    mode_t mode;
    if (exists) mode = st.st_mode & 07777;
    else {
        mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    int ok = fchmod(fd, mode) == 0 && write_all(fd, text, n);
    ok = (close(fd) == 0) && ok;
    if (!ok || rename(tmp, target) != 0) {
        int code = vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", path, strerror(errno));
        remove(tmp);
        free(tmp);
        free(target);
        return code;
    }
    free(tmp);
    free(target);
    return VIGEN_OK;
}
