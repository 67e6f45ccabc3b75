/* batch.c — the batched stepper of the PRK variant (`vigen emit --batch`,
 * templates/prk/batch.h.in and batch.c.in): the C lines of one explicit step
 * of W trajectories side by side, in structure-of-arrays layout (component
 * k of trajectory j at x[k W + j]).  The operations are those of the scalar
 * explicit step (plan.c), in the same order and with the same expressions
 * per element, so that every trajectory gets the bits of the scalar
 * stepper; what changes is that the loops run over n W elements, that times
 * are arrays of W (t0[j], t1[j], ts[j]), that batched gradients or forces
 * are called once for all trajectories, that finiteness is tracked per
 * trajectory (nfl[j]), and that the first-same-as-last gradient is cached
 * per trajectory. */
#include <stdlib.h>
#include <string.h>
#include "emit/batch.h"

/* The time array of an evaluation: t0, t1, or ts filled with t0[j] + c h
 * (the scalar stepper's expression per trajectory). */
static const char *eval_time(vigen_slot *L, const emit_xop *op, const char *ind)
{
    if (op->time == XTIME_T0) return "t0";
    if (op->time == XTIME_T1) return "t1";
    char *ch = vigen_emit_times(op->tc, "h");
    if (ch == NULL) return "t0";
    vigen_slot_line(L, "%sfor (size_t j = 0; j < W; j++) ts[j] = t0[j] + %s;", ind, ch);
    free(ch);
    return "ts";
}

/* The update of q (+) or p (psign) in place, per element as in the scalar
 * step, the old value kept in qs (ps), finiteness folded per trajectory. */
static void update_lines(vigen_slot *L, const char *N, const char *x, char sign, const char *ht)
{
    char *arg = sign == '+' ? vigen_strdup(ht) : vigen_strdup_printf("-(%s)", ht);
    for (int kahan = 1; kahan >= 0; kahan--) {
        vigen_slot_line(L, kahan ? "if (kahan) {" : "} else {");
        vigen_slot_line(L, "    for (size_t c = 0; c < n; c++)");
        vigen_slot_line(L, "        for (size_t j = 0; j < W; j++) {");
        vigen_slot_line(L, "            const size_t k = c * W + j;");
        vigen_slot_line(L, "            const double x = %s[k];", x);
        vigen_slot_line(L, "            %ss[k] = x;", x);
        if (kahan) vigen_slot_line(L, "            %s[k] = vigen_twosum_next(x, %s, c%s0[k], &c%s[k]);", x, arg, x, x);
        else vigen_slot_line(L, "            %s[k] = x %c %s;", x, sign, ht);
        vigen_slot_line(L, "            nfl[j] = %s_nf_add(nfl[j], %s[k]);", N, x);
        vigen_slot_line(L, "        }");
    }
    vigen_slot_line(L, "}");
    free(arg);
}

static void batch_ops(vigen_slot *L, const emit_explicit *X, const char *N, int mech)
{
    const char *q0 = "q", *p0 = "p";
    const char psign = mech ? '+' : '-';
    for (slong k = 0; k < X->nops; k++) {
        const emit_xop *op = X->ops + k;
        if (op->op == XOP_EVAL_F || op->op == XOP_EVAL_G) {
            const int isf = op->op == XOP_EVAL_F;
            const char *qa = strcmp(op->q, "q0") == 0 ? q0 : op->q, *pa = strcmp(op->p, "p0") == 0 ? p0 : op->p;
            if (mech && isf) {
                vigen_slot_line(L, "for (size_t k = 0; k < nw; k++) X%ld[k] = imw[k] * %s[k];", op->dst, pa);
                continue;
            }
            /* with a first-same-as-last gradient: evaluated only when some
             * active trajectory has none cached, into ft when others do */
            const char *ind = op->fsal ? "    " : "";
            if (op->fsal) {
                vigen_slot_line(L, "if (b->nstale == 0) {");
                vigen_slot_line(L, "    b->stats.fsal_reuses += W;");
                vigen_slot_line(L, "} else {");
                vigen_slot_line(L, "    double *const fx = b->nstale < W ? b->ft : X%ld;", op->dst);
            }
            const char *tm = eval_time(L, op, ind);
            const char *dst = op->fsal ? "fx" : NULL;
            char xd[32];
            snprintf(xd, sizeof xd, "X%ld", op->dst);
            if (dst == NULL) dst = xd;
            if (mech) vigen_slot_line(L, "%s%s_bforce(b, %s, %s, %s);", ind, N, tm, qa, dst);
            else vigen_slot_line(L, "%s%s_b%s(b, %s, %s, %s, %s);", ind, N, isf ? "dHdp" : "dHdq", tm, qa, pa, dst);
            vigen_slot_line(L, "%sb->stats.%s_evals += W;", ind, isf ? "dHdp" : "dHdq");
            if (op->fsal) {
                vigen_slot_line(L, "    if (fx != X%ld) %s_batch_merge(b, fx, X%ld);", op->dst, N, op->dst);
                vigen_slot_line(L, "}");
            }
            continue;
        }
        char *ht = vigen_emit_hsum_op(op);
        switch (op->op) {
        case XOP_STAGE_Q:
            vigen_slot_line(L, "for (size_t k = 0; k < nw; k++) X%ld[k] = %s[k] + %s;", op->dst, q0, ht);
            break;
        case XOP_STAGE_P:
            vigen_slot_line(L, "for (size_t k = 0; k < nw; k++) X%ld[k] = %s[k] %c %s;", op->dst, p0, psign, ht);
            break;
        default: {
            const int isq = op->op == XOP_UPDATE_Q;
            update_lines(L, N, isq ? "q" : "p", isq ? '+' : psign, ht);
            if (isq) q0 = "qs";
            else p0 = "ps";
            break;
        }
        }
        free(ht);
    }
}

int vigen_emit_batch_code(vigen_slots *S, const prk_coefs *K, const char *name, emit_ctx *E)
{
    const emit_explicit *X = &K->X;
    if (X->mode == EMIT_EXPLICIT_NONE)
        return vigen_error_set(E->err, VIGEN_E_USAGE,
                               "--batch needs a tableau with an explicit step (Stormer-Verlet, a composition); "
                               "this one is implicit: emit it without --batch and run the ensemble with "
                               "vigen_integrate_ensemble");
    vigen_slot *xp = vigen_slots_lines(S, "BATCH_X_POINTERS");
    for (long x = 0; x < X->nx; x++) vigen_slot_line(xp, "double *restrict const X%ld = b->x[%ld];", x, x);
    vigen_slot *sw = vigen_slots_lines(S, "BATCH_FSAL_SWAPS");
    for (int k = 0; k < X->nswaps; k++) {
        vigen_slot_line(sw, "b->x[%ld] = X%ld;", X->swaps[k][0], X->swaps[k][1]);
        vigen_slot_line(sw, "b->x[%ld] = X%ld;", X->swaps[k][1], X->swaps[k][0]);
    }
    batch_ops(vigen_slots_lines(S, "BATCH_OPS"), X, name, 0);
    batch_ops(vigen_slots_lines(S, "BATCH_MECH_OPS"), X, name, 1);
    return VIGEN_OK;
}
