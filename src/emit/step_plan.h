/* step_plan.h — the structure of a PRK step the emitter finds in a tableau:
 * stages with equal rows share their values and gradients, zero coefficients
 * drop out, and when the dependency graph of stage values, gradients and
 * the updates of q and p is acyclic the step is explicit, written as an
 * ordered list of operations on work arrays X0, X1, ...; the gradient at the
 * end of a step is reused at the start of the next (first same as last)
 * when the graph allows it. */
#ifndef VIGEN_EMIT_STEP_PLAN_H
#define VIGEN_EMIT_STEP_PLAN_H

#include "emit/literals.h"

enum { EMIT_EXPLICIT_NONE, EMIT_EXPLICIT_SEPARABLE, EMIT_EXPLICIT_GENERAL };
enum { XOP_STAGE_Q, XOP_STAGE_P, XOP_EVAL_F, XOP_EVAL_G, XOP_UPDATE_Q, XOP_UPDATE_P };
enum { XTIME_T0, XTIME_T1, XTIME_C };

/* coef * X<src> */
typedef struct {
    char *coef;
    long src;
} emit_term;

/* One operation of the explicit step: a stage value (dst = q0 + h sum, or
 * p0 - h sum), a gradient evaluation at (time, q, p) into dst (fsal: the
 * cached one when valid), or the update of q or p. */
typedef struct {
    int op;              /* XOP_* */
    long dst;            /* X<dst> */
    char q[32], p[32];   /* arrays the gradient is evaluated at: "q", "q0", "X3", ... */
    int time;            /* XTIME_*: t0, t1 or t0 + c h */
    char *tc;            /* the literal c for XTIME_C ("0" for zero) */
    int fsal;
    emit_term *terms;
    slong nterms;
} emit_xop;

typedef struct {
    int mode;                 /* EMIT_EXPLICIT_*: general = for any H */
    long nx;                  /* work arrays (at least 1 when explicit) */
    int fsal;
    long nevals_f, nevals_g;  /* gradient evaluations per step */
    long swaps[2][2];         /* first-same-as-last array exchanges */
    int nswaps;
    emit_xop *ops;
    slong nops;
} emit_explicit;

/* Finds the explicit structure of E's tableau: for any H, else for
 * separable H, else none (mode EMIT_EXPLICIT_NONE).  Coefficients are
 * rounded with vigen_emit_literal (VIGEN_E_PRECISION: retry at a higher
 * precision).  X is filled on success; clear it with
 * vigen_emit_explicit_clear in every case. */
int vigen_emit_plan(emit_explicit *X, emit_ctx *E);
void vigen_emit_explicit_clear(emit_explicit *X);

#endif
