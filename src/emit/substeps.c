/* substeps.c — the PRK variant's explicit step of a mechanical problem for
 * a tableau that comes from a splitting or composition file: the substeps
 * applied in order.
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
 * Compensation: the increments of each component over the step are summed
 * in plain arithmetic (they are O(h), so their rounding is far below an
 * ulp of q or p) and added to q and p once, by the last substep of each
 * kind, with the runtime's vigen_twosum_next and the compensation carried
 * from step to step (read from the workspace's, written to the step's own,
 * which the step's end takes over when the new state is finite), as the
 * PRK paths add h sum b_i F_i.  Finiteness is checked at those writes
 * only: a non-finite force or position makes the increments non-finite for
 * good (d + x stays NaN or infinite).
 *
 * The same lines are written for the scalar stepper (loops over n) and for
 * the batched one (loops over n components times W trajectories, the same
 * expression per element): the batch gets the scalar stepper's bits. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emit/prk.h"
#include "support/strbuf.h"

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

/* The force of the kick at substep k, at the positions qa, into dst. */
static void force(vigen_slot *L, const sub_target *T, const sub_coefs *U, slong k, const char *qa, const char *dst,
                  const char *ind)
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
        vigen_slot_line(L, "%s%s_bforce(b, %s, %s, %s);", ind, T->N, tm, qa, dst);
        vigen_slot_line(L, "%sb->stats.dHdq_evals += W;", ind);
    } else {
        vigen_slot_line(L, "%s%s_force(w, %s, %s, %s);", ind, T->N, tm, qa, dst);
        vigen_slot_line(L, "%sw->stats.dHdq_evals++;", ind);
    }
    free(tc);
}

/* The final value of component k of x ("q" or "p"): its increment d over
 * the step added to the start value, compensated or not, the start value
 * kept in xs, finiteness folded in (the scalar stepper: by the sum of the
 * new compensations when compensated, see the template's NAME_nf_add). */
static void commit(vigen_slot *L, const sub_target *T, const char *in, const char *x, const char *d)
{
    vigen_slot_line(L, "%sconst %s x%s = %s[k];", in, T->R, x, x);
    vigen_slot_line(L, "%s%ss[k] = x%s;", in, x, x);
    if (T->batch) {
        vigen_slot_line(L, "%s%s[k] = kahan ? vigen_twosum_next%s(x%s, %s, c%s0[k], &c%s[k]) : x%s + %s;", in, x, T->SFX,
                        x, d, x, x, x, d);
        vigen_slot_line(L, "%snfl[j] = %s_nf_add(nfl[j], %s[k]);", in, T->N, x);
        return;
    }
    /* the new compensation through a local: a store through the pointer
     * argument of vigen_twosum_next would hide from the compiler that cq,
     * cp are apart from the other arrays (no vectorised loop) */
    vigen_slot_line(L, "%s%s c%sk = 0;", in, T->R, x);
    vigen_slot_line(L, "%sconst %s s%s = kahan ? vigen_twosum_next%s(x%s, %s, c%s0[k], &c%sk) : x%s + %s;", in, T->R, x,
                    T->SFX, x, d, x, x, x, d);
    vigen_slot_line(L, "%s%s[k] = s%s;", in, x, x);
    vigen_slot_line(L, "%sif (kahan) c%s[k] = c%sk;", in, x, x);
    vigen_slot_line(L, "%sif (kahan && !%s_nf_or) nfc += c%sk;", in, T->N, x);
    vigen_slot_line(L, "%selse nf = %s_nf_add(nf, kahan ? c%sk : s%s);", in, T->N, x, x);
}

/* The step.  Each component's increments over the step, dq and dp, are
 * summed in plain arithmetic (they are O(h)) in Dq and Dp between passes;
 * the positions a force needs before the last drift are q + dq in Qt.  The
 * last substep of each kind adds the whole increment to the start value,
 * compensated (the update of q and p that the compensation is for: small
 * increments into a large value, over many steps), and writes the user's
 * array: q and p are written once per step. */
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
    /* scratch arrays, only those this step uses */
    const int need_dq = firstq != lastq, need_dp = firstp != lastp;
    const char *scratch = T->batch ? "b->sub" : "S";
    const char *len = T->batch ? "nw" : "n";
    if (need_dq) vigen_slot_line(L, "%s *restrict const Dq = %s;", T->R, scratch);
    if (need_dp) vigen_slot_line(L, "%s *restrict const Dp = %s + %s;", T->R, scratch, len);
    if (need_dq) vigen_slot_line(L, "%s *restrict const Qt = %s + 2 * %s;", T->R, scratch, len);
    const char *in = T->batch ? "        " : "    ";
    for (slong k = 0; k < m; k++) {
        char d[96], v[64];
        if (U->drift[k] && k > 0) continue;   /* in the pass of the kick before it */
        const char *f = U->fsal && k > 0 ? "F1" : "F0";
        if (!U->drift[k]) {
            /* the force at the positions after the drifts before k: the
             * final q once the last drift is done, else Qt (or q itself
             * before any drift) */
            const char *qa = k == 0 || lastq < k ? "q" : "Qt";
            if (U->fsal && k == 0 && T->batch) {
                vigen_slot_line(L, "if (b->nstale == 0) {");
                vigen_slot_line(L, "    b->stats.fsal_reuses += W;");
                vigen_slot_line(L, "} else {");
                vigen_slot_line(L, "    double *const fx = b->nstale < W ? b->ft : F0;");
                force(L, T, U, k, qa, "fx", "    ");
                vigen_slot_line(L, "    if (fx != F0) %s_batch_merge(b, fx, F0);", T->N);
                vigen_slot_line(L, "}");
            } else if (U->fsal && k == 0) {
                vigen_slot_line(L, "if (w->fsal) {");
                vigen_slot_line(L, "    w->stats.fsal_reuses++;");
                vigen_slot_line(L, "} else {");
                force(L, T, U, k, qa, "F0", "    ");
                vigen_slot_line(L, "}");
            } else {
                force(L, T, U, k, qa, f, "");
            }
        }
        if (T->batch) {
            vigen_slot_line(L, "for (size_t c = 0; c < n; c++)");
            vigen_slot_line(L, "    %s_lanes", T->N);
            vigen_slot_line(L, "    for (size_t j = 0; j < W; j++) {");
            vigen_slot_line(L, "        const size_t k = c * W + j;");
        } else {
            vigen_slot_line(L, "for (size_t k = 0; k < n; k++) {");
        }
        const char *pv = "p[k]";   /* the momentum the drift uses */
        if (!U->drift[k]) {
            if (k == firstp) snprintf(d, sizeof d, "h%ld * %s[k]", (long)k + 1, f);
            else snprintf(d, sizeof d, "Dp[k] + h%ld * %s[k]", (long)k + 1, f);
            vigen_slot_line(L, "%sconst %s dp = %s;", in, T->R, d);
            if (k == lastp) {
                commit(L, T, in, "p", "dp");
            } else {
                vigen_slot_line(L, "%sDp[k] = dp;", in);
                if (k + 1 < m) vigen_slot_line(L, "%sconst %s pt = p[k] + dp;", in, T->R);
                pv = "pt";
            }
        }
        const slong j = U->drift[k] ? k : k + 1;   /* the drift of this pass */
        if (j < m) {
            if (T->batch) snprintf(v, sizeof v, "(imw[k] * %s)", pv);
            else snprintf(v, sizeof v, "(unit ? %s : im[k] * %s)", pv, pv);
            if (j == firstq) snprintf(d, sizeof d, "h%ld * %s", (long)j + 1, v);
            else snprintf(d, sizeof d, "Dq[k] + h%ld * %s", (long)j + 1, v);
            vigen_slot_line(L, "%sconst %s dq = %s;", in, T->R, d);
            if (j == lastq) {
                commit(L, T, in, "q", "dq");
            } else {
                vigen_slot_line(L, "%sDq[k] = dq;", in);
                vigen_slot_line(L, "%sQt[k] = q[k] + dq;", in);
            }
        }
        vigen_slot_line(L, T->batch ? "    }" : "}");
    }
}

void vigen_emit_sub_code(vigen_slots *S, const prk_coefs *K, const char *name, int real)
{
    const sub_coefs *U = &K->U;
    const sub_target T = { 0, name, vigen_emit_reals[real].ctype, vigen_emit_reals[real].suffix };
    vigen_slots_flag(S, "SUBSTEPS", U->m > 0);
    vigen_slots_flag(S, "SUB_FSAL", U->fsal);
    vigen_slots_text(S, "SUB_F1", U->fsal ? "w->x[1]" : "NULL");
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
