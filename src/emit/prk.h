/* prk.h — the PRK variant's slot builder (variants.def row "prk"), in two
 * halves: prk_data.c rounds the coefficients and writes the texts,
 * prk_code.c writes the C lines of the blocks (docs/templates.md lists the
 * slots). */
#ifndef VIGEN_EMIT_PRK_H
#define VIGEN_EMIT_PRK_H

#include "emit/plan.h"
#include "emit/variant.h"

/* The rounded coefficients of one pass: literals, NULL for an exact zero
 * (c: "0"); inv[j * s + m] = 1/(c_j - c_m) when lagrange. */
typedef struct {
    slong s;
    char **c, **b, **bt, **a, **at, **inv;
    int lagrange;
    emit_explicit X;
} prk_coefs;

int vigen_emit_prk_round(prk_coefs *K, emit_ctx *E);
void vigen_emit_prk_clear(prk_coefs *K);
void vigen_emit_prk_texts(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident);
void vigen_emit_prk_code(vigen_slots *S, const prk_coefs *K, const char *name, int real);

#endif
