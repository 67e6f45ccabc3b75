/* prk.h — the PRK variant's slot builder (variants.def row "prk"), in two
 * halves: prk_data.c rounds the coefficients and writes the texts,
 * prk_code.c writes the C lines of the blocks (docs/templates.md lists the
 * slots). */
#ifndef VIGEN_EMIT_PRK_H
#define VIGEN_EMIT_PRK_H

#include "emit/step_plan.h"
#include "emit/variant.h"

/* The rounded coefficients of one pass: literals, NULL for an exact zero
 * (c: "0"); inv[j * s + m] = 1/(c_j - c_m) when lagrange. */
/* The Nystrom coefficients of the tableau (nystrom.c), for mechanical
 * problems: row sums of A, A At, sum b and b^T At, rounded from balls (NULL
 * for an exact zero). */
typedef struct {
    char **ca, **aat, *sb, **bat;
    char **inv1;     /* 1/(c_j - 1) when the nodes are distinct and none is 1 (else NULL):
                        the force at the step's start joins the extrapolation */
} nys_coefs;

/* The substeps of a splitting or composition tableau (substeps.c), merged
 * and rounded: m = 0 when the tableau has none (or only one kind). */
typedef struct {
    slong m;
    int *drift;      /* 1 drift q += coef h M^-1 p, 0 kick p += coef h f */
    char **coef;     /* literals, never an exact zero */
    int *time;       /* kicks: XTIME_T0, XTIME_T1 or XTIME_C at stamp */
    char **stamp;    /* kicks at XTIME_C: the literal c of t0 + c h */
    int fsal;        /* starts and ends with a kick, at t0 and t1 */
    long nforce;     /* force evaluations per step */
} sub_coefs;

typedef struct {
    slong s;
    char **c, **b, **bt, **a, **at, **inv;
    int lagrange;
    emit_explicit X;
    nys_coefs Y;
    sub_coefs U;
} prk_coefs;

int vigen_emit_prk_round(prk_coefs *K, emit_ctx *E);
void vigen_emit_prk_clear(prk_coefs *K);
void vigen_emit_prk_texts(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident);
void vigen_emit_prk_code(vigen_slots *S, const prk_coefs *K, const char *name, int real);
/* nystrom.c: rounds K->Y (after the PRK coefficients), clears it, and
 * writes the mechanical implicit step's blocks. */
int vigen_emit_nys_round(nys_coefs *Y, emit_ctx *E);
void vigen_emit_nys_clear(nys_coefs *Y, slong s);
void vigen_emit_nys_code(vigen_slots *S, const prk_coefs *K, const char *name, int real);
/* First same as last: is the first stage q at t0 (no term, c_1 = 0) and the
 * last one q1 at t0 + h (the rounded coefficients of its position those of
 * q1, c_s = 1), with the last stage's force in no stage and not in q1?
 * Then that force is evaluated once, at the new q, and is the next step's
 * first (Lobatto IIIA-IIIB). */
int vigen_emit_nys_fsal(const prk_coefs *K);
/* The slot the batched stepper's sweep uses besides those of the scalar one
 * (MECH_SWEEP_STORE: the increments of MECH_STAGES' new stage positions and
 * their stores), for an emission with --batch. */
void vigen_emit_nys_batch_code(vigen_slots *S, const prk_coefs *K, const char *name);
/* substeps.c: rounds K->U (after the explicit plan), clears it, writes the
 * scalar step's slots (SUBSTEPS, SUB_*) and the batched one's
 * (BATCH_SUB_OPS). */
int vigen_emit_sub_round(sub_coefs *U, emit_ctx *E);
void vigen_emit_sub_clear(sub_coefs *U);
void vigen_emit_sub_code(vigen_slots *S, const prk_coefs *K, const char *name, int real);
void vigen_emit_sub_batch(vigen_slots *S, const prk_coefs *K, const char *name);
/* prk_code.c helpers shared with nystrom.c */
char *vigen_emit_times(const char *coef, const char *x);
char *vigen_emit_lin(char *const *coefs, slong n, const char *pre, const char *post);
char *vigen_emit_at_time(const char *c);
char *vigen_emit_hsum_op(const emit_xop *op);
/* Whether column j of the s x s literals m has a nonzero entry. */
int vigen_emit_colused(char *const *m, slong s, slong j);

#endif
