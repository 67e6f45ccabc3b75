/* progress.h — a progress line on standard error for long commands
 * (generation, `vigen try`, work-precision runs): shown only when standard
 * error is a terminal and once the work has lasted a second, refreshed
 * several times a second with the elapsed time, and erased at the end, so
 * that short runs, pipes and logs never see it.
 *
 *     vigen_progress_begin("vigen try");
 *     vigen_progress_set("gauss_2: compiling");
 *     ...
 *     vigen_progress_end();
 */
#ifndef VIGEN_SUPPORT_PROGRESS_H
#define VIGEN_SUPPORT_PROGRESS_H

/* Starts the clock (and, on a terminal, the thread that draws the line);
 * prefix starts the line. */
void vigen_progress_begin(const char *prefix);
/* What is being done now (printf-style; cut to the terminal's width). */
void vigen_progress_set(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* Erases the line and stops; a call without begin does nothing. */
void vigen_progress_end(void);

#endif
