/* guard.c — the guards of a vigen process (support/guard.h): the registry of
 * temporary output files, the handlers that remove them (SIGINT, SIGTERM,
 * SIGHUP, the wall-clock timer's SIGALRM), the counting memory functions of
 * FLINT and GMP with their cap, and FLINT's abort handler.
 *
 * Everything a handler does is async-signal-safe: it reads the registry
 * (filled only while the signals are blocked), calls unlink, write, and
 * _exit or raise.  The messages are formatted beforehand, when the caps are
 * set.  The memory functions and the abort handler run in ordinary context
 * but end the process the same way (no stdio: the arithmetic may have run
 * out of memory, and what is buffered for standard output is discarded). */
#define _DEFAULT_SOURCE /* malloc_usable_size, setitimer */
#include <errno.h>
#include <gmp.h>
#include <flint/flint.h>
#include <malloc.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

#include "support/guard.h"

/* ---- the registry of temporary files ------------------------------------ */

enum { NSLOTS = 16, SLOT_LEN = 4096 };
static char temp_path[NSLOTS][SLOT_LEN];
static volatile sig_atomic_t temp_used[NSLOTS];

int vigen_guard_temp_add(const char *path)
{
    size_t n = strlen(path);
    if (n >= SLOT_LEN) return -1;
    for (int k = 0; k < NSLOTS; k++)
        if (!temp_used[k]) {
            memcpy(temp_path[k], path, n + 1);
            temp_used[k] = 1;
            return k;
        }
    return -1;
}

void vigen_guard_temp_drop(int slot)
{
    if (slot >= 0 && slot < NSLOTS) temp_used[slot] = 0;
}

static void remove_temps(void)
{
    for (int k = 0; k < NSLOTS; k++)
        if (temp_used[k]) {
            unlink(temp_path[k]);
            temp_used[k] = 0;
        }
}

static const int handled[] = { SIGINT, SIGTERM, SIGHUP, SIGALRM };
enum { NHANDLED = sizeof handled / sizeof handled[0] };

void vigen_guard_block(sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    for (int k = 0; k < NHANDLED; k++) sigaddset(&set, handled[k]);
    sigprocmask(SIG_BLOCK, &set, old);
}

void vigen_guard_unblock(const sigset_t *old)
{
    sigprocmask(SIG_SETMASK, old, NULL);
}

/* ---- the messages, formatted when the caps are set ---------------------- */

enum { MSG_LEN = 320 };
static char msg_time[MSG_LEN], msg_memory[MSG_LEN], msg_oom[MSG_LEN], msg_abort[MSG_LEN];
static char msg_signal[3][MSG_LEN]; /* SIGINT, SIGTERM, SIGHUP */
static size_t arith_cap;            /* bytes; 0: none */

static void format_messages(const char *program, unsigned long seconds, size_t cap)
{
    snprintf(msg_time, MSG_LEN, "%s: the time cap of %lu s was reached; raise it with --max-seconds\n", program,
             seconds);
    snprintf(msg_memory, MSG_LEN,
             "%s: the memory cap of the arithmetic (%zu MiB for FLINT, arb and GMP) was reached; raise it with "
             "--max-memory\n", program, cap >> 20);
    snprintf(msg_oom, MSG_LEN, "%s: out of memory in the arithmetic (FLINT, arb, GMP)\n", program);
    snprintf(msg_abort, MSG_LEN,
             "%s: the arithmetic library (FLINT) gave up on an operation, a number or size beyond its range; "
             "check the file's numbers\n", program);
    static const char *names[3] = { "SIGINT", "SIGTERM", "SIGHUP" };
    for (int k = 0; k < 3; k++)
        snprintf(msg_signal[k], MSG_LEN, "%s: interrupted (%s); no output file was written\n", program, names[k]);
}

/* Ends the process: temporary files removed, one line, exit status 3. */
static _Noreturn void die(const char *msg)
{
    remove_temps();
    ssize_t ignored = write(STDERR_FILENO, msg, strlen(msg));
    (void)ignored;
    _exit(3);
}

/* ---- signals ------------------------------------------------------------ */

static void on_signal(int sig)
{
    if (sig == SIGALRM) die(msg_time);
    remove_temps();
    const char *msg = msg_signal[sig == SIGINT ? 0 : sig == SIGTERM ? 1 : 2];
    ssize_t ignored = write(STDERR_FILENO, msg, strlen(msg));
    (void)ignored;
    /* end by the same signal, so that the parent sees an interruption */
    signal(sig, SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, sig);
    sigprocmask(SIG_UNBLOCK, &set, NULL);
    raise(sig);
    _exit(128 + sig);
}

/* ---- the arithmetic's memory -------------------------------------------- */

static long long live, peak; /* bytes, updated atomically */

static void account(void *p, long long before, size_t asked)
{
    if (p == NULL) {
        if (asked != 0) die(msg_oom);
        return;
    }
    long long now = __atomic_add_fetch(&live, (long long)malloc_usable_size(p) - before, __ATOMIC_RELAXED);
    long long high = __atomic_load_n(&peak, __ATOMIC_RELAXED);
    while (now > high && !__atomic_compare_exchange_n(&peak, &high, now, 1, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {}
}

/* Refuses an allocation that would take the live bytes past the cap. */
static void check_cap(size_t more)
{
    if (arith_cap == 0) return;
    long long now = __atomic_load_n(&live, __ATOMIC_RELAXED);
    if (more > arith_cap || (unsigned long long)now + more > arith_cap) die(msg_memory);
}

static void *g_malloc(size_t n)
{
    check_cap(n);
    void *p = malloc(n);
    account(p, 0, n);
    return p;
}

static void *g_calloc(size_t n, size_t m)
{
    if (m != 0 && n > (size_t)-1 / m) die(msg_memory);
    check_cap(n * m);
    void *p = calloc(n, m);
    account(p, 0, n * m);
    return p;
}

static void *g_realloc(void *q, size_t n)
{
    long long before = q ? (long long)malloc_usable_size(q) : 0;
    if ((long long)n > before) check_cap(n - (size_t)before);
    void *p = realloc(q, n);
    account(p, before, n);
    return p;
}

static void g_free(void *q)
{
    if (q == NULL) return;
    __atomic_sub_fetch(&live, (long long)malloc_usable_size(q), __ATOMIC_RELAXED);
    free(q);
}

static void *gmp_realloc(void *q, size_t old, size_t n)
{
    (void)old;
    return g_realloc(q, n);
}

static void gmp_free(void *q, size_t n)
{
    (void)n;
    g_free(q);
}

static FLINT_NORETURN void on_flint_abort(void)
{
    die(msg_abort);
}

/* ---- installing --------------------------------------------------------- */

void vigen_guard_install(void)
{
    format_messages("vigen", 0, 0);
    __flint_set_memory_functions(g_malloc, g_calloc, g_realloc, g_free);
    mp_set_memory_functions(g_malloc, gmp_realloc, gmp_free);
    flint_set_abort(on_flint_abort);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (int k = 0; k < NHANDLED; k++) sigaddset(&sa.sa_mask, handled[k]);
    for (int k = 0; k < NHANDLED; k++) {
        struct sigaction prev;
        /* a signal ignored by the parent (nohup, a background job) stays ignored */
        if (handled[k] != SIGALRM && sigaction(handled[k], NULL, &prev) == 0 && prev.sa_handler == SIG_IGN)
            continue;
        sigaction(handled[k], &sa, NULL);
    }
}

void vigen_guard_set_caps(const vigen_guard_caps *caps)
{
    sigset_t old;
    vigen_guard_block(&old);
    format_messages(caps->program ? caps->program : "vigen", caps->max_seconds, caps->max_arith_bytes);
    arith_cap = caps->max_arith_bytes;
    struct itimerval t;
    memset(&t, 0, sizeof t);
    t.it_value.tv_sec = (time_t)caps->max_seconds;
    setitimer(ITIMER_REAL, &t, NULL);
    vigen_guard_unblock(&old);
}

size_t vigen_guard_arith_peak(void)
{
    long long p = __atomic_load_n(&peak, __ATOMIC_RELAXED);
    return p > 0 ? (size_t)p : 0;
}
