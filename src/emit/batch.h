/* batch.h — the batched stepper of the PRK variant (batch.c; `vigen emit
 * --batch`, templates/prk/batch.*.in): W trajectories in one call. */
#ifndef VIGEN_EMIT_BATCH_H
#define VIGEN_EMIT_BATCH_H

#include "emit/prk.h"

/* The slots of the batched step (BATCH_*): the explicit step's blocks from
 * the explicit plan of K, or for a tableau without one the blocks of the
 * mechanical fixed-point iteration (the other blocks then empty). */
void vigen_emit_batch_code(vigen_slots *S, const prk_coefs *K, const char *name);

#endif
