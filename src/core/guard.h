/* guard.h — the registry of temporary output files that the guards of
 * vigen/guard.h remove when they end the process, and the blocking of the
 * signals they handle while files are renamed into place. */
#ifndef VIGEN_GUARD_H
#define VIGEN_GUARD_H

#include <signal.h>
#include "vigen/guard.h"

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
