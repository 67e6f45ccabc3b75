/* guard.h — the guards of a process that runs untrusted files: a wall-clock
 * cap, a cap on the memory the arithmetic (FLINT, arb, MPFR, GMP) holds,
 * FLINT's aborts turned into a clean failure, and SIGINT, SIGTERM and SIGHUP
 * handled; in every case the temporary files of output being written
 * (support/file.h) are removed, so that no partial output is left.
 *
 * A cap that is reached, an arithmetic operation FLINT gives up on, or the
 * arithmetic running out of memory ends the process at once: one line on
 * standard error naming the cap and the option of the vigen command that
 * raises it (--max-seconds, --max-memory), exit status 3 (a resource
 * failure, as VIGEN_E_LIMIT), nothing more on standard output (what is still
 * buffered there is discarded).  SIGINT, SIGTERM and SIGHUP remove the
 * temporary files, print one line and end the process by the same signal (a
 * shell sees status 128 + signal, and a make or a shell loop sees that it
 * was interrupted rather than a failure).  While output files are being
 * renamed into place these signals wait (vigen_write_files_atomic), so that
 * a pair of files is never left half replaced. */
#ifndef VIGEN_SUPPORT_GUARD_H
#define VIGEN_SUPPORT_GUARD_H

#include <signal.h>
#include <stddef.h>

typedef struct {
    const char *program;       /* prefix of the messages, e.g. "vigen generate" (copied; NULL: "vigen") */
    unsigned long max_seconds; /* wall-clock cap counted from this call; 0: none */
    size_t max_arith_bytes;    /* cap on the bytes FLINT, arb, MPFR and GMP hold at once; 0: none */
} vigen_guard_caps;

/* Installs the guards: counting memory functions for FLINT and GMP, FLINT's
 * abort handler, the signal handlers.  Call once, first thing in main,
 * before any arithmetic (memory allocated before is not counted). */
void vigen_guard_install(void);

/* Sets the caps (and the message prefix); the timer starts now. */
void vigen_guard_set_caps(const vigen_guard_caps *caps);

/* The most bytes the arithmetic held at once since vigen_guard_install. */
size_t vigen_guard_arith_peak(void);

/* The registry of temporary output files that the guards remove when they
 * end the process, and the blocking of the signals they handle while files
 * are renamed into place. */

/* Blocks SIGINT, SIGTERM, SIGHUP and SIGALRM (the old mask into *old), and
 * restores the mask; a signal that came meanwhile is handled at the
 * restore. */
void vigen_guard_block(sigset_t *old);
void vigen_guard_unblock(const sigset_t *old);

/* Registers path (copied) as a temporary file to remove if the process is
 * ended by a guard; returns its slot, or -1 when the registry is full or the
 * path too long.  vigen_guard_temp_drop forgets it (slot < 0: nothing).  Call
 * both with the signals blocked. */
int vigen_guard_temp_add(const char *path);
void vigen_guard_temp_drop(int slot);

#endif
