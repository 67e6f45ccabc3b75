/* batch.h — the batched stepper of the PRK variant (batch.c; `vigen emit
 * --batch`, templates/prk/batch.*.in): W trajectories in one call. */
#ifndef VIGEN_EMIT_BATCH_H
#define VIGEN_EMIT_BATCH_H

#include "emit/prk.h"

/* The blocks of the batched explicit step (BATCH_X_POINTERS, BATCH_OPS,
 * BATCH_MECH_OPS, BATCH_FSAL_SWAPS) from the explicit plan of K.
 * VIGEN_E_USAGE (message in E->err) when the tableau has no explicit
 * step. */
int vigen_emit_batch_code(vigen_slots *S, const prk_coefs *K, const char *name, emit_ctx *E);

#endif
