/* progress.c — the progress line of support/progress.h: a thread that wakes
 * every 100 ms and, once a second has passed, redraws "prefix: text (Ns)"
 * with a carriage return.  The thread blocks every signal, so that the
 * process's handlers (the guards, the working directory's cleanup) run in
 * the main thread. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "support/progress.h"

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_t ticker;
static int running, stop, drawn;
static char prefix_text[64], text[160];
static struct timespec started;

static double elapsed(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - started.tv_sec) + 1e-9 * (double)(now.tv_nsec - started.tv_nsec);
}

static void *tick(void *arg)
{
    (void)arg;
    struct timespec pause = { 0, 100000000L };
    for (;;) {
        nanosleep(&pause, NULL);
        pthread_mutex_lock(&lock);
        if (stop) {
            pthread_mutex_unlock(&lock);
            return NULL;
        }
        double s = elapsed();
        if (s >= 1.0) {
            /* 79 columns at most: no wrap on an 80-column terminal */
            fprintf(stderr, "\r\033[K%.20s: %.48s (%.0f s)", prefix_text, text, s);
            fflush(stderr);
            drawn = 1;
        }
        pthread_mutex_unlock(&lock);
    }
}

void vigen_progress_begin(const char *prefix)
{
    if (running || !isatty(2)) return;
    snprintf(prefix_text, sizeof prefix_text, "%s", prefix ? prefix : "vigen");
    text[0] = '\0';
    clock_gettime(CLOCK_MONOTONIC, &started);
    stop = drawn = 0;
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    running = pthread_create(&ticker, NULL, tick, NULL) == 0;
    pthread_sigmask(SIG_SETMASK, &old, NULL);
}

void vigen_progress_set(const char *fmt, ...)
{
    if (!running) return;
    pthread_mutex_lock(&lock);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    pthread_mutex_unlock(&lock);
}

void vigen_progress_end(void)
{
    if (!running) return;
    pthread_mutex_lock(&lock);
    stop = 1;
    pthread_mutex_unlock(&lock);
    pthread_join(ticker, NULL);
    running = 0;
    if (drawn) {
        fputs("\r\033[K", stderr);
        fflush(stderr);
    }
}
