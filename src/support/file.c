/* file.c — input files read whole, and output files written atomically, one
 * file or a set replaced as a unit (temporary files next to the targets, then
 * renames that are undone on failure), so that a failed or interrupted write
 * never leaves a truncated file, a temporary file or a set half replaced;
 * the targets' permissions are kept. */
#define _DEFAULT_SOURCE /* mkstemp, realpath, fchmod, lstat */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "support/file.h"
#include "support/guard.h"
#include "support/strbuf.h"

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


/* ---- output -------------------------------------------------------------
 *
 * A set of output files (one, or the .h/.c pair of vigen emit) is replaced as
 * a unit: after a failure at any step the files are all old, and after
 * success all new; no temporary file is left.
 *   1. Each new text goes to a temporary file created by mkstemp next to its
 *      target (TARGET.tmp.XXXXXX: unique, so two processes writing the same
 *      file never share one), registered with the guards (support/guard.h),
 *      which remove it if a signal or a cap ends the process; written,
 *      fsync'ed and closed, each step checked.  A failure here removes the
 *      temporary files: the targets were never touched.
 *   2. With SIGINT, SIGTERM, SIGHUP and SIGALRM held back: each existing
 *      target is linked to a backup name (the temporary name + ".old"; where
 *      the file system has no hard links, the target is renamed there
 *      instead); each temporary file is renamed onto its target; the
 *      directories are fsync'ed.  A failure at any of these steps renames
 *      every backup back over its target (and removes the new targets that
 *      had no old file), so the set is old again.  Only when all succeeded
 *      are the backups removed.
 * A reader after any single failure thus sees the old set, and after success
 * the new set.  (A reader running at the same moment as a successful commit
 * may see one file new and the other old for the microseconds between the
 * renames: build systems run vigen emit before compiling its output, never
 * while.)  A signal that comes during step 2 is handled after it, so it
 * cannot stop the set half renamed. */

typedef struct {
    const char *path, *text; /* as given; path names the file in messages */
    char *target;            /* the file replaced: path, or what a link points to */
    int special;             /* "-" or not a regular file: written in place */
    int exists;
    mode_t mode;
    char *tmp, *bak;         /* temporary file (NULL once renamed or removed), backup (NULL: none) */
    int slot;                /* the temporary file's slot in the guards' registry */
    int renamed;             /* the new text is at target */
} out_file;

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

/* fsync, where the file system offers it (EINVAL: it does not). */
static int sync_fd(int fd)
{
    return fsync(fd) == 0 || errno == EINVAL || errno == ENOTSUP;
}

/* Finds what path names: a symbolic link is followed (the file it points to
 * is replaced, the link stays); a device or FIFO (/dev/null, a pipe) is
 * written in place, as renaming over it would replace it with a regular
 * file. */
static int resolve(out_file *f, vigen_error *err)
{
    struct stat st;
    if (strcmp(f->path, "-") == 0) {
        f->special = 1;
        return VIGEN_OK;
    }
    if (lstat(f->path, &st) == 0 && S_ISLNK(st.st_mode)) {
        f->target = realpath(f->path, NULL);
        if (f->target == NULL) {
            /* /dev/stdout -> /proc/self/fd/1 -> "pipe:[...]": no path, but a
             * device or pipe that can be written in place */
            if (stat(f->path, &st) == 0 && !S_ISREG(st.st_mode)) f->target = vigen_strdup(f->path);
            else return vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: it is a symbolic link to a missing file",
                                        f->path);
        }
    } else f->target = vigen_strdup(f->path);
    if (stat(f->target, &st) == 0) {
        f->exists = 1;
        f->special = !S_ISREG(st.st_mode);
        f->mode = st.st_mode & 07777;
    } else {
        /* the usual 0666 & ~umask */
        mode_t mask = umask(0);
        umask(mask);
        f->mode = 0666 & ~mask;
    }
    return VIGEN_OK;
}

static int write_special(const out_file *f, vigen_error *err)
{
    size_t n = strlen(f->text);
    if (f->target == NULL) {
        if (fwrite(f->text, 1, n, stdout) != n || fflush(stdout) != 0)
            return vigen_error_set(err, VIGEN_E_WRITE, "cannot write to standard output: %s", strerror(errno));
        return VIGEN_OK;
    }
    FILE *out = fopen(f->target, "wb");
    int ok = out != NULL && fwrite(f->text, 1, n, out) == n;
    if (out != NULL && fclose(out) != 0) ok = 0;
    if (!ok) return vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", f->path, strerror(errno));
    return VIGEN_OK;
}

static void remove_temp(out_file *f)
{
    if (f->tmp == NULL) return;
    sigset_t old;
    vigen_guard_block(&old);
    unlink(f->tmp);
    vigen_guard_temp_drop(f->slot);
    vigen_guard_unblock(&old);
    free(f->tmp);
    f->tmp = NULL;
}

/* Step 1: the new text in a complete, synced temporary file. */
static int write_temp(out_file *f, vigen_error *err)
{
    f->tmp = vigen_strdup_printf("%s.tmp.XXXXXX", f->target);
    sigset_t old;
    vigen_guard_block(&old);
    int fd = mkstemp(f->tmp);
    if (fd >= 0 && (f->slot = vigen_guard_temp_add(f->tmp)) < 0) {
        unlink(f->tmp);
        close(fd);
        fd = -1;
        errno = ENAMETOOLONG;
    }
    vigen_guard_unblock(&old);
    if (fd < 0) {
        int code = vigen_error_set(err, VIGEN_E_WRITE, "cannot create a temporary file next to %s: %s", f->path,
                                   strerror(errno));
        free(f->tmp);
        f->tmp = NULL;
        return code;
    }
    int ok = fchmod(fd, f->mode) == 0 && write_all(fd, f->text, strlen(f->text)) && sync_fd(fd);
    int saved = errno;
    if (close(fd) != 0 && ok) {
        ok = 0;
        saved = errno;
    }
    if (ok) return VIGEN_OK;
    remove_temp(f);
    return vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", f->path, strerror(saved));
}

/* fsync of the directory holding path, so that the renames last. */
static int sync_dir(const char *path)
{
    const char *slash = strrchr(path, '/');
    char *dir = slash == NULL ? vigen_strdup(".") : slash == path ? vigen_strdup("/")
                                                  : vigen_strdup_printf("%.*s", (int)(slash - path), path);
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    free(dir);
    if (fd < 0) return 1; /* a directory we may write but not read: nothing to sync through */
    int ok = sync_fd(fd);
    int saved = errno;
    close(fd);
    errno = saved;
    return ok;
}

/* Step 2, with the signals held back; on failure the old set is restored. */
static int commit(out_file *f, size_t n, vigen_error *err)
{
    size_t k;
    int code = VIGEN_OK;
    for (k = 0; k < n && code == VIGEN_OK; k++) {
        if (f[k].special || !f[k].exists) continue;
        f[k].bak = vigen_strdup_printf("%s.old", f[k].tmp);
        int done = link(f[k].target, f[k].bak) == 0;
        if (!done && (errno == EPERM || errno == ENOTSUP || errno == EMLINK || errno == ENOSYS))
            done = rename(f[k].target, f[k].bak) == 0;
        if (!done) {
            code = vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: cannot keep the old file aside: %s",
                                   f[k].path, strerror(errno));
            free(f[k].bak);
            f[k].bak = NULL;
        }
    }
    for (k = 0; k < n && code == VIGEN_OK; k++) {
        if (f[k].special) continue;
        if (rename(f[k].tmp, f[k].target) != 0) {
            code = vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", f[k].path, strerror(errno));
            break;
        }
        f[k].renamed = 1;
        vigen_guard_temp_drop(f[k].slot);
        free(f[k].tmp);
        f[k].tmp = NULL;
    }
    for (k = 0; k < n && code == VIGEN_OK; k++)
        if (!f[k].special && !sync_dir(f[k].target))
            code = vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", f[k].path, strerror(errno));
    for (k = 0; k < n; k++) {
        if (code != VIGEN_OK && f[k].renamed && f[k].bak == NULL && unlink(f[k].target) != 0)
            vigen_error_prefix(err, "%s is new and could not be removed: ", f[k].path);
        if (f[k].bak == NULL) continue;
        if (code != VIGEN_OK && (f[k].renamed || access(f[k].target, F_OK) != 0) &&
            rename(f[k].bak, f[k].target) != 0) {
            vigen_error_prefix(err, "the old %s could not be put back (it is %s): ", f[k].path, f[k].bak);
        } else unlink(f[k].bak);
        free(f[k].bak);
        f[k].bak = NULL;
    }
    return code;
}

int vigen_write_files_atomic(size_t n, const char *const *paths, const char *const *texts, vigen_error *err)
{
    out_file *f = calloc(n ? n : 1, sizeof *f);
    if (f == NULL) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory writing %s", n ? paths[0] : "");
    int code = VIGEN_OK;
    size_t k;
    for (k = 0; k < n; k++) {
        f[k].path = paths[k];
        f[k].text = texts[k];
        f[k].slot = -1;
    }
    for (k = 0; k < n && code == VIGEN_OK; k++) code = resolve(f + k, err);
    for (k = 0; k < n && code == VIGEN_OK; k++)
        code = f[k].special ? write_special(f + k, err) : write_temp(f + k, err);
    if (code == VIGEN_OK) {
        sigset_t old;
        vigen_guard_block(&old);
        code = commit(f, n, err);
        vigen_guard_unblock(&old);
    }
    for (k = 0; k < n; k++) {
        remove_temp(f + k);
        free(f[k].target);
    }
    free(f);
    return code;
}

int vigen_write_file_atomic(const char *path, const char *text, vigen_error *err)
{
    return vigen_write_files_atomic(1, &path, &text, err);
}
