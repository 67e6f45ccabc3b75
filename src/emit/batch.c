/* batch.c — the batched stepper of the PRK variant (`vigen emit --batch`,
 * templates/prk/batch.h.in and batch.c.in): the C lines of one explicit step
 * of W trajectories side by side, in structure-of-arrays layout (component
 * k of trajectory j at x[k W + j]).  The operations are those of the scalar
 * explicit step (step_plan.c), in the same order and with the same expressions
 * per element, so that every trajectory gets the bits of the scalar
 * stepper; what changes is that the loops run over n W elements, that times
 * are arrays of W (t0[j], t1[j], ts[j]), that batched gradients or forces
 * are called once for all trajectories, that finiteness is tracked per
 * trajectory (nfl[j]), and that the first-same-as-last gradient is cached
 * per trajectory.  A tableau without an explicit step gets the fixed-point
 * iteration of the Nystrom form for mechanical problems instead, with a
 * convergence test per trajectory (the stage lines are the scalar
 * stepper's, nystrom.c). */
#include <stdlib.h>
#include <string.h>
#include "emit/batch.h"
#include "support/strbuf.h"

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
        vigen_slot_line(L, "        %s_lanes", N);
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
                vigen_slot_line(L, "%s_lanes", N);
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
            vigen_slot_line(L, "%s_lanes", N);
            vigen_slot_line(L, "for (size_t k = 0; k < nw; k++) X%ld[k] = %s[k] + %s;", op->dst, q0, ht);
            break;
        case XOP_STAGE_P:
            vigen_slot_line(L, "%s_lanes", N);
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

/* The blocks of the batched implicit step of a mechanical problem (a
 * tableau without an explicit step): pointers to the stage positions Q_i,
 * forces f_i, the previous step's fo_i and the fresh evaluations ft_i; the
 * forces of a sweep into ft_i (stage times per trajectory); the fresh forces
 * taken by the trajectories still iterating (a trajectory that has
 * converged keeps the forces of its last sweep, as the scalar stepper
 * does); the starting forces copied from ft1 or from fo_i; and the previous
 * step's forces put back for a trajectory that failed. */
static void implicit_blocks(vigen_slots *S, const prk_coefs *K, const char *N)
{
    const slong s = K->s;
    vigen_slot *ptr = vigen_slots_lines(S, "BATCH_IMPL_POINTERS");
    vigen_slot *fc = vigen_slots_lines(S, "BATCH_IMPL_FORCES");
    vigen_slot *bl = vigen_slots_lines(S, "BATCH_IMPL_BLEND");
    vigen_slot *st = vigen_slots_lines(S, "BATCH_IMPL_START");
    vigen_slot *cp = vigen_slots_lines(S, "BATCH_IMPL_COPY");
    vigen_slot *rs = vigen_slots_lines(S, "BATCH_IMPL_RESTORE");
    vigen_slot *ff = vigen_slots_lines(S, "BATCH_IMPL_FIRST");
    vigen_slots_textf(S, "BATCH_IMPL_END", "%s_bforce(b, b->t1, qn, f%ld);", N, (long)s);
    if (K->X.mode != EMIT_EXPLICIT_NONE) {
        vigen_slots_text(S, "BATCH_SWEEP_NFORCE", "0");
        return;
    }
    /* first same as last (vigen_emit_nys_fsal): the first stage's force is
     * not swept (the previous step's last, or evaluated once at Q1), nor
     * the last one's (evaluated once at the new q) */
    const int fsal = vigen_emit_nys_fsal(K);
    vigen_slots_textf(S, "BATCH_SWEEP_NFORCE", "%ld", (long)(fsal ? s - 2 : s));
    if (fsal) {
        vigen_slot_line(ff, "if (nf1) %s_bforce(b, t0, Q1, ft1);", N);
        vigen_slot_line(ff, "for (size_t c = 0; c < n; c++)");
        vigen_slot_line(ff, "    %s_lanes", N);
        vigen_slot_line(ff, "    for (size_t j = 0; j < W; j++) {");
        vigen_slot_line(ff, "        const size_t k = c * W + j;");
        vigen_slot_line(ff, "        f1[k] = cached[j] ? fo%ld[k] : ft1[k];", (long)s);
        vigen_slot_line(ff, "    }");
    }
    for (slong i = 1; i <= s; i++) {
        const long z = (long)(i - 1);
        vigen_slot_line(ptr, "double *const Q%ld = b->Q[%ld], *const f%ld = b->G[%ld], *const ft%ld = b->FT[%ld];", (long)i,
                        z, (long)i, z, (long)i, z);
        vigen_slot_line(ptr, "const double *const fo%ld = b->Go[%ld];", (long)i, z);
        vigen_slot_line(ptr, "(void)Q%ld; (void)f%ld; (void)ft%ld; (void)fo%ld;", (long)i, (long)i, (long)i, (long)i);
        if (!(fsal && (i == 1 || i == s))) {
            char *ch = vigen_emit_times(K->c[i - 1], "h");
            if (ch) {
                vigen_slot_line(fc, "for (size_t j = 0; j < W; j++) ts[j] = t0[j] + %s;", ch);
                vigen_slot_line(fc, "%s_bforce(b, ts, Q%ld, ft%ld);", N, (long)i, (long)i);
            } else {
                vigen_slot_line(fc, "%s_bforce(b, t0, Q%ld, ft%ld);", N, (long)i, (long)i);
            }
            free(ch);
            vigen_slot_line(bl, "f%ld[k] = done[j] ? f%ld[k] : ft%ld[k];", (long)i, (long)i, (long)i);
        }
        vigen_slot_line(st, "f%ld[k] = ft1[k];", (long)i);
        vigen_slot_line(cp, "f%ld[k] = fo%ld[k];", (long)i, (long)i);
        vigen_slot_line(rs, "b->G[%ld][k] = b->Go[%ld][k];", z, z);
    }
}

void vigen_emit_batch_code(vigen_slots *S, const prk_coefs *K, const char *name)
{
    const emit_explicit *X = &K->X;
    /* arrays of n W doubles: cq, cp, cqn, cpn, qs, ps, imw, ft, and the work
     * arrays of the explicit step or, for the implicit one, Q, G, Go, FT per
     * stage and v; 3 for the substeps of a splitting */
    vigen_slots_textf(S, "BATCH_NARRAYS", "%ld",
                      8 + (X->mode != EMIT_EXPLICIT_NONE ? X->nx : 4 * (long)K->s + 1) + (K->U.m > 0 ? 3 : 0));
    implicit_blocks(S, K, name);
    vigen_emit_sub_batch(S, K, name);
    vigen_slot *xp = vigen_slots_lines(S, "BATCH_X_POINTERS");
    vigen_slot *sw = vigen_slots_lines(S, "BATCH_FSAL_SWAPS");
    vigen_slot *ops = vigen_slots_lines(S, "BATCH_OPS"), *mops = vigen_slots_lines(S, "BATCH_MECH_OPS");
    if (X->mode == EMIT_EXPLICIT_NONE) return;
    for (long x = 0; x < X->nx; x++) vigen_slot_line(xp, "double *restrict const X%ld = b->x[%ld];", x, x);
    for (int k = 0; k < X->nswaps; k++) {
        vigen_slot_line(sw, "b->x[%ld] = X%ld;", X->swaps[k][0], X->swaps[k][1]);
        vigen_slot_line(sw, "b->x[%ld] = X%ld;", X->swaps[k][1], X->swaps[k][0]);
    }
    batch_ops(ops, X, name, 0);
    batch_ops(mops, X, name, 1);
}
