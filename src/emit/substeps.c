/* substeps.c — the PRK variant's explicit step of a mechanical problem for
 * a tableau that comes from a splitting or composition file: the substeps
 * applied in place, in order.
 *
 * The tableau keeps its substeps (vigen_tableau.substep_*): drifts
 * q <- q + a h M^-1 p and kicks p <- p + b h f(t, q).  Consecutive substeps
 * of one kind are merged (their coefficients added in ball arithmetic, as
 * src/method/splitting.c does before it builds the tableau), substeps with
 * an exact zero coefficient dropped, and each remaining coefficient emitted
 * as a correctly rounded literal, multiplied by h once per step.  A kick's
 * force is evaluated at t0 + (sum of the drifts before it) h, the stage time
 * c_i of the tableau.  Each kick's loop also does the drift that follows it
 * (both are per component), so a step is one pass over q and p per force,
 * O(substeps dim) work against O(s^2 dim) for the stage sums of the general
 * explicit step.  A step that starts and ends with a kick at t0 and t1
 * reuses the last force of one step as the first of the next.
 *
 * Compensation: each component of q and p is updated with the runtime's
 * vigen_twosum_next, its compensation carried through the substeps and
 * from step to step (the first write of a step reads the workspace's
 * compensation, the others the step's own, which the step's end takes over
 * when the new state is finite).  Finiteness is checked on the last write
 * of each component only: a non-finite value in q or p is never made finite
 * again by later substeps (x + d stays NaN or infinite), and a non-finite
 * force makes p so at its kick.
 *
 * The same lines are written for the scalar stepper (loops over n) and for
 * the batched one (loops over n components times W trajectories, the same
 * expression per element): the batch gets the scalar stepper's bits. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emit/prk.h"

void vigen_emit_sub_clear(sub_coefs *U)
{
    for (slong k = 0; k < U->m; k++) {
        free(U->coef[k]);
        free(U->stamp[k]);
    }
    free(U->coef);
    free(U->stamp);
    free(U->drift);
    free(U->time);
    memset(U, 0, sizeof *U);
}

int vigen_emit_sub_round(sub_coefs *U, emit_ctx *E)
{
    memset(U, 0, sizeof *U);
    const vigen_tableau *t = E->t;
    const slong N = t->nsubsteps;
    if (N < 2) return VIGEN_OK;
    arb_ptr v = _arb_vec_init(N);
    int *kind = calloc((size_t)N, sizeof *kind);
    if (kind == NULL) abort();
    int rc = VIGEN_OK;
    /* merge in balls until no two neighbours are of one kind and no
     * coefficient is an exact zero */
    slong m = 0;
    for (slong k = 0; k < N && rc == VIGEN_OK; k++) {
        arb_t x;
        arb_init(x);
        rc = vigen_tableau_entry_eval(x, t->substep_coef[k], E->prec, E->err);
        if (rc == VIGEN_OK && !vigen_emit_tiny_zero(E, x)) {
            if (m > 0 && kind[m - 1] == t->substep_drift[k]) {
                arb_add(v + m - 1, v + m - 1, x, E->prec);
                if (vigen_emit_tiny_zero(E, v + m - 1)) m--;
            } else {
                kind[m] = t->substep_drift[k];
                arb_set(v + m++, x);
            }
            /* a dropped substep may leave two of one kind side by side */
            while (m >= 2 && kind[m - 2] == kind[m - 1]) {
                arb_add(v + m - 2, v + m - 2, v + m - 1, E->prec);
                m--;
                if (vigen_emit_tiny_zero(E, v + m - 1)) m--;
            }
        }
        arb_clear(x);
    }
    int kicks = 0, drifts = 0;
    for (slong k = 0; k < m; k++) {
        kicks += !kind[k];
        drifts += kind[k];
    }
    if (rc == VIGEN_OK && kicks > 0 && drifts > 0) {
        /* a kick after no drift is at t0, one after drifts adding up to 1
         * (within the rounding of the literals) at t1, which the next step
         * starts from */
        arb_t one;
        arb_init(one);
        U->m = m;
        U->drift = calloc((size_t)m, sizeof *U->drift);
        U->time = calloc((size_t)m, sizeof *U->time);
        U->coef = calloc((size_t)m, sizeof *U->coef);
        U->stamp = calloc((size_t)m, sizeof *U->stamp);
        if (!U->drift || !U->time || !U->coef || !U->stamp) abort();
        arb_t stamp;
        arb_init(stamp);
        for (slong k = 0; k < m && rc == VIGEN_OK; k++) {
            U->drift[k] = kind[k];
            rc = vigen_emit_literal(U->coef + k, E, v + k, -1, kind[k] ? "drift coefficient" : "kick coefficient");
            if (rc != VIGEN_OK) break;
            if (kind[k]) {
                arb_add(stamp, stamp, v + k, E->prec);
                continue;
            }
            U->nforce++;
            arb_sub_ui(one, stamp, 1, E->prec);
            U->time[k] = vigen_emit_tiny_zero(E, stamp) ? XTIME_T0 : vigen_emit_tiny_zero(E, one) ? XTIME_T1 : XTIME_C;
            if (U->time[k] == XTIME_C) rc = vigen_emit_literal(U->stamp + k, E, stamp, -1, "time of a kick");
        }
        arb_clear(stamp);
        arb_clear(one);
        U->fsal = rc == VIGEN_OK && !kind[0] && !kind[m - 1] && U->time[m - 1] == XTIME_T1;
        U->nforce -= U->fsal;
    }
    _arb_vec_clear(v, N);
    free(kind);
    return rc;
}

/* The target of the lines: the scalar stepper or the batched one. */
typedef struct {
    int batch;
    const char *N, *R, *SFX;
} sub_target;

static void loop_open(vigen_slot *L, const sub_target *T)
{
    if (T->batch) {
        vigen_slot_line(L, "for (size_t c = 0; c < n; c++)");
        vigen_slot_line(L, "    for (size_t j = 0; j < W; j++) {");
        vigen_slot_line(L, "        const size_t k = c * W + j;");
    } else {
        vigen_slot_line(L, "for (size_t k = 0; k < n; k++) {");
    }
}

static void loop_close(vigen_slot *L, const sub_target *T) { vigen_slot_line(L, T->batch ? "    }" : "}"); }

/* One substep on component k of x ("q" or "p") by d: compensated or not,
 * the start value kept in xs on its first write, finiteness folded in on
 * its last. */
static void update(vigen_slot *L, const sub_target *T, const char *x, const char *d, int first, int last)
{
    const char *in = T->batch ? "        " : "    ";
    if (first) {
        vigen_slot_line(L, "%s{", in);
        vigen_slot_line(L, "%s    const %s x = %s[k];", in, T->R, x);
        vigen_slot_line(L, "%s    %ss[k] = x;", in, x);
        vigen_slot_line(L, "%s    %s[k] = kahan ? vigen_twosum_next%s(x, %s, c%s0[k], &c%s[k]) : x + %s;", in, x, T->SFX, d,
                        x, x, d);
        vigen_slot_line(L, "%s}", in);
    } else {
        vigen_slot_line(L, "%s%s[k] = kahan ? vigen_twosum_next%s(%s[k], %s, c%s[k], &c%s[k]) : %s[k] + %s;", in, x,
                        T->SFX, x, d, x, x, x, d);
    }
    if (last && T->batch) vigen_slot_line(L, "%snfl[j] = %s_nf_add(nfl[j], %s[k]);", in, T->N, x);
    else if (last) vigen_slot_line(L, "%snf = %s_nf_add(nf, %s[k]);", in, T->N, x);
}

/* The force of the kick at substep k into dst. */
static void force(vigen_slot *L, const sub_target *T, const sub_coefs *U, slong k, const char *dst, const char *ind)
{
    const char *tm = U->time[k] == XTIME_T0 ? "t0" : U->time[k] == XTIME_T1 ? "t1" : NULL;
    char *tc = NULL;
    if (tm == NULL && T->batch) {
        vigen_slot_line(L, "%sfor (size_t j = 0; j < W; j++) ts[j] = t0[j] + %s * h;", ind, U->stamp[k]);
        tm = "ts";
    } else if (tm == NULL) {
        tc = vigen_strdup_printf("t0 + %s * h", U->stamp[k]);
        tm = tc;
    }
    if (T->batch) {
        vigen_slot_line(L, "%s%s_bforce(b, %s, q, %s);", ind, T->N, tm, dst);
        vigen_slot_line(L, "%sb->stats.dHdq_evals += W;", ind);
    } else {
        vigen_slot_line(L, "%s%s_force(w, %s, q, %s);", ind, T->N, tm, dst);
        vigen_slot_line(L, "%sw->stats.dHdq_evals++;", ind);
    }
    free(tc);
}

/* The step: h times each coefficient, then the passes. */
static void sub_lines(vigen_slot *L, const sub_target *T, const sub_coefs *U)
{
    const slong m = U->m;
    slong firstq = -1, lastq = -1, firstp = -1, lastp = -1;
    for (slong k = 0; k < m; k++) {
        char *ch = vigen_emit_times(U->coef[k], "h");
        vigen_slot_line(L, "const %s h%ld = %s;", T->R, (long)k + 1, ch);
        free(ch);
        if (U->drift[k]) {
            if (firstq < 0) firstq = k;
            lastq = k;
        } else {
            if (firstp < 0) firstp = k;
            lastp = k;
        }
    }
    const char *im = T->batch ? "imw[k] * p[k]" : "(unit ? p[k] : im[k] * p[k])";
    for (slong k = 0; k < m; k++) {
        char d[64];
        if (U->drift[k]) {
            /* a leading drift has a pass of its own; the others join the
             * pass of the kick before them */
            if (k > 0) continue;
            snprintf(d, sizeof d, "h%ld * %s", (long)k + 1, im);
            loop_open(L, T);
            update(L, T, "q", d, k == firstq, k == lastq);
            loop_close(L, T);
            continue;
        }
        /* the force: the cached one of the last step (first same as last),
         * or a fresh one; with first same as last every later kick uses F1 */
        const char *f = U->fsal && k > 0 ? "F1" : "F0";
        if (U->fsal && k == 0 && T->batch) {
            vigen_slot_line(L, "if (b->nstale == 0) {");
            vigen_slot_line(L, "    b->stats.fsal_reuses += W;");
            vigen_slot_line(L, "} else {");
            vigen_slot_line(L, "    double *const fx = b->nstale < W ? b->ft : F0;");
            force(L, T, U, k, "fx", "    ");
            vigen_slot_line(L, "    if (fx != F0) %s_batch_merge(b, fx, F0);", T->N);
            vigen_slot_line(L, "}");
        } else if (U->fsal && k == 0) {
            vigen_slot_line(L, "if (w->fsal) {");
            vigen_slot_line(L, "    w->stats.fsal_reuses++;");
            vigen_slot_line(L, "} else {");
            force(L, T, U, k, "F0", "    ");
            vigen_slot_line(L, "}");
        } else {
            force(L, T, U, k, f, "");
        }
        snprintf(d, sizeof d, "h%ld * %s[k]", (long)k + 1, f);
        loop_open(L, T);
        update(L, T, "p", d, k == firstp, k == lastp);
        if (k + 1 < m) {
            snprintf(d, sizeof d, "h%ld * %s", (long)k + 2, im);
            update(L, T, "q", d, k + 1 == firstq, k + 1 == lastq);
        }
        loop_close(L, T);
    }
}

void vigen_emit_sub_code(vigen_slots *S, const prk_coefs *K, const char *name, int real)
{
    const sub_coefs *U = &K->U;
    const sub_target T = { 0, name, vigen_emit_reals[real].ctype, vigen_emit_reals[real].suffix };
    vigen_slots_flag(S, "SUBSTEPS", U->m > 0);
    vigen_slots_flag(S, "SUB_FSAL", U->fsal);
    vigen_slots_flag(S, "SAVE_X", U->fsal || K->X.fsal);
    vigen_slots_textf(S, "SUB_COUNT", "%ld", (long)U->m);
    vigen_slots_textf(S, "SUB_FORCES", "%ld", U->nforce);
    vigen_slot *L = vigen_slots_lines(S, "SUB_OPS");
    if (U->m > 0) sub_lines(L, &T, U);
}

void vigen_emit_sub_batch(vigen_slots *S, const prk_coefs *K, const char *name)
{
    const sub_coefs *U = &K->U;
    const sub_target T = { 1, name, "double", "" };
    vigen_slot *L = vigen_slots_lines(S, "BATCH_SUB_OPS");
    if (U->m > 0) sub_lines(L, &T, U);
}
