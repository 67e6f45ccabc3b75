/* workdir.c — the private temporary directory of `vigen try`: created with
 * mkdtemp (mode 0700) under $TMPDIR or /tmp, every file in it registered
 * before it is made, and removed on return, on failure and when a signal
 * (SIGINT, SIGTERM, SIGHUP) or the time cap (SIGALRM) ends the process.
 *
 * The handlers run before those installed earlier (the guards of
 * support/guard.h), which they then call: they kill the child being waited for
 * (a compiler, a driver, gnuplot, which might otherwise write into the
 * directory after it is gone) and unlink the registered files and rmdir the
 * directory, all async-signal-safe calls on data filled before. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include "try/try_internal.h"
#include "support/strbuf.h"

enum { MAX_FILES = 512, NAME_LEN = 64, DIR_LEN = 3072 };

static char dir_path[DIR_LEN];
static char file_name[MAX_FILES][NAME_LEN];
static volatile sig_atomic_t nfiles, active;
static volatile sig_atomic_t child_pid;

static const int handled[] = { SIGINT, SIGTERM, SIGHUP, SIGALRM };
enum { NHANDLED = sizeof handled / sizeof handled[0] };
static struct sigaction previous[NHANDLED];
static int installed[NHANDLED];

/* dir_path + "/" + name into buf, without snprintf (not async-signal-safe). */
static void join(char *buf, size_t cap, const char *name)
{
    size_t n = 0;
    for (const char *s = dir_path; *s && n + 1 < cap; s++) buf[n++] = *s;
    if (n + 1 < cap) buf[n++] = '/';
    for (const char *s = name; *s && n + 1 < cap; s++) buf[n++] = *s;
    buf[n] = '\0';
}

static void remove_all(void)
{
    char path[DIR_LEN + NAME_LEN + 2];
    for (int k = 0; k < nfiles; k++) {
        join(path, sizeof path, file_name[k]);
        unlink(path);
    }
    rmdir(dir_path);
}

static void on_signal(int sig)
{
    if (active) {
        pid_t pid = (pid_t)child_pid;
        if (pid > 0) {
            kill(pid, SIGKILL);
            waitpid(pid, NULL, 0);
        }
        remove_all();
        active = 0;
    }
    for (int k = 0; k < NHANDLED; k++) {
        if (handled[k] != sig) continue;
        /* the handler before ours (the guards) ends the process its way */
        if (previous[k].sa_handler != SIG_DFL && previous[k].sa_handler != SIG_IGN &&
            !(previous[k].sa_flags & SA_SIGINFO)) {
            previous[k].sa_handler(sig);
            return;
        }
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

int try_workdir_create(vigen_error *err)
{
    const char *tmp = getenv("TMPDIR");
    if (tmp == NULL || *tmp == '\0') tmp = "/tmp";
    if (strlen(tmp) + 32 >= DIR_LEN)
        return vigen_error_set(err, VIGEN_E_WRITE, "TMPDIR is too long (%zu characters)", strlen(tmp));
    snprintf(dir_path, sizeof dir_path, "%s/vigen-try-XXXXXX", tmp);
    if (mkdtemp(dir_path) == NULL)
        return vigen_error_set(err, VIGEN_E_WRITE, "cannot create a temporary directory in %s: %s (set TMPDIR)",
                               tmp, strerror(errno));
    nfiles = 0;
    child_pid = 0;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (int k = 0; k < NHANDLED; k++) sigaddset(&sa.sa_mask, handled[k]);
    /* a signal the process ignores (SIGINT of a background job) stays ignored */
    for (int k = 0; k < NHANDLED; k++) {
        sigaction(handled[k], NULL, &previous[k]);
        installed[k] = previous[k].sa_handler != SIG_IGN;
        if (installed[k]) sigaction(handled[k], &sa, NULL);
    }
    active = 1;
    return VIGEN_OK;
}

char *try_workdir_file(const char *name)
{
    int k = nfiles, known = 0;
    for (int i = 0; i < k && !known; i++) known = strcmp(file_name[i], name) == 0;
    if (!known && k < MAX_FILES && strlen(name) < NAME_LEN) {
        memcpy(file_name[k], name, strlen(name) + 1);
        nfiles = k + 1;
    }
    return vigen_strdup_printf("%s/%s", dir_path, name);
}

void try_workdir_set_child(long pid) { child_pid = (sig_atomic_t)pid; }

void try_workdir_remove(void)
{
    if (!active) return;
    sigset_t block, old;
    sigemptyset(&block);
    for (int k = 0; k < NHANDLED; k++) sigaddset(&block, handled[k]);
    sigprocmask(SIG_BLOCK, &block, &old);
    remove_all();
    active = 0;
    nfiles = 0;
    for (int k = 0; k < NHANDLED; k++)
        if (installed[k]) sigaction(handled[k], &previous[k], NULL);
    sigprocmask(SIG_SETMASK, &old, NULL);
}

int try_workdir_write(char **path, const char *name, const char *text, vigen_error *err)
{
    *path = try_workdir_file(name);
    FILE *f = fopen(*path, "w");
    int ok = f != NULL && fputs(text, f) >= 0;
    if (f && fclose(f) != 0) ok = 0;
    if (!ok) return vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", *path, strerror(errno));
    return VIGEN_OK;
}
