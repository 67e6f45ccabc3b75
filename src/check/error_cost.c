/* error_cost.c — the figures by which methods are compared: the error constants
 * (from the principal error coefficients that orders.c sums per order) and
 * the cost of a step (stages, force and velocity evaluations, explicit or
 * implicit).  The stability interval is stability.c's.
 */
#include <string.h>
#include "check/check_internal.h"

/* The error constant of each family at its order p: sqrt of the sum over its
 * trees t of order p + 1 of ((Phi(t) - 1/gamma(t)) / sigma(t))^2. */
static void error_constants(vigen_check_report *rep, slong prec)
{
    static const int family[VIGEN_CHECK_EC_FAMILIES] = {VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE,
                                                        VIGEN_CHECK_NYSTROM};
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        vigen_check_error_constant *e = &rep->error_constant[f];
        const vigen_check_orders *o = &rep->orders[family[f]];
        int p = o->level.value;
        e->order = p;
        e->available = !o->level.capped && !o->level.undecided && p + 1 <= o->evaluated_to;
        e->ntrees = e->available ? o->count[p + 1] : 0;
        if (e->available) arb_sqrtpos(e->value, e->sumsq[p + 1], prec);   /* a sum of squares of balls may reach below 0 */
        else arb_indeterminate(e->value);
    }
}

/* Row i of m (or the vector v when i < 0) is exactly zero. */
static int row_zero(const arb_mat_struct *m, slong i, slong s)
{
    for (slong j = 0; j < s; j++)
        if (!arb_is_zero(arb_mat_entry(m, i, j))) return 0;
    return 1;
}

static int row_equal(const arb_mat_struct *m, slong i, slong k, slong s)
{
    for (slong j = 0; j < s; j++)
        if (!arb_equal(arb_mat_entry(m, i, j), arb_mat_entry(m, k, j))) return 0;
    return 1;
}

static int row_is(const arb_mat_struct *m, slong i, arb_srcptr v, slong s)
{
    for (slong j = 0; j < s; j++)
        if (!arb_equal(arb_mat_entry(m, i, j), v + j)) return 0;
    return 1;
}

/* Stage j's evaluation of the function whose increments go through (U, w) is
 * used when column j of U or w_j is not exactly 0; its argument is given by
 * row j of V (the other matrix), so stages with equal rows of V share it.
 * Counts the distinct arguments used, less one when one of them is the start
 * of the step (a zero row) and another its end (the row equals w of the
 * other part): the end's evaluation is the next step's first. */
static slong evaluations(const arb_mat_struct *U, arb_srcptr w, const arb_mat_struct *V, arb_srcptr wv, slong s,
                         int *fsal)
{
    slong n = 0;
    int start = 0, end = 0;
    for (slong j = 0; j < s; j++) {
        int used = !arb_is_zero(w + j);
        for (slong i = 0; i < s && !used; i++) used = !arb_is_zero(arb_mat_entry(U, i, j));
        if (!used) continue;
        int seen = 0;
        for (slong k = 0; k < j && !seen; k++) {
            int used_k = !arb_is_zero(w + k);
            for (slong i = 0; i < s && !used_k; i++) used_k = !arb_is_zero(arb_mat_entry(U, i, k));
            seen = used_k && row_equal(V, j, k, s);
        }
        if (seen) continue;
        n++;
        start |= row_zero(V, j, s);
        end |= row_is(V, j, wv, s);
    }
    *fsal = start && end && n > 1;
    return n - *fsal;
}

/* The stages can be computed one after another: the graph of "needs" has no
 * cycle (Kahn's algorithm).  Separable H: node j < s is Q_j, which needs
 * P_k where a_jk != 0; node s + j is P_j, which needs Q_k where at_jk != 0.
 * General H: node j is stage j, which needs stage k where a_jk or at_jk != 0. */
static int acyclic(const arb_mat_struct *A, const arb_mat_struct *At, slong s, int separable)
{
    slong n = separable ? 2 * s : s;
    slong *indeg = flint_calloc((size_t)n, sizeof(slong));
    unsigned char *done = flint_calloc((size_t)n, 1);
#define NEEDS(u, v) (separable ? ((u) < s ? ((v) >= s && !arb_is_zero(arb_mat_entry(A, u, (v) - s))) \
                                          : ((v) < s && !arb_is_zero(arb_mat_entry(At, (u) - s, v)))) \
                               : (!arb_is_zero(arb_mat_entry(A, u, v)) || !arb_is_zero(arb_mat_entry(At, u, v))))
    for (slong u = 0; u < n; u++)
        for (slong v = 0; v < n; v++) indeg[u] += NEEDS(u, v);
    slong removed = 0;
    for (int progress = 1; progress;) {
        progress = 0;
        for (slong u = 0; u < n; u++) {
            if (done[u] || indeg[u]) continue;
            done[u] = 1;
            removed++;
            progress = 1;
            for (slong w = 0; w < n; w++)
                if (!done[w] && NEEDS(w, u)) indeg[w]--;
        }
    }
#undef NEEDS
    flint_free(indeg);
    flint_free(done);
    return removed == n;
}

int chk_figures(chk_round *rd, vigen_error *err)
{
    vigen_check_report *rep = rd->rep;
    const ctx_t *cx = rd->cx;
    slong s = cx->s;
    error_constants(rep, cx->prec);
    vigen_check_cost *c = &rep->cost;
    memset(c, 0, sizeof(*c));
    c->stages = s;
    int f1, f2;
    /* forces -dV/dq(Q_j): increments through (At, bt), arguments rows of A */
    c->force = evaluations(cx->At, cx->bt, cx->A, cx->b, s, &f1);
    /* velocities dT/dp(P_j): increments through (A, b), arguments rows of At */
    c->velocity = evaluations(cx->A, cx->b, cx->At, cx->bt, s, &f2);
    c->fsal = f1;
    c->explicit_separable = acyclic(cx->A, cx->At, s, 1);
    c->explicit_general = acyclic(cx->A, cx->At, s, 0);
    /* a splitting's principal error as the splitting literature writes it */
    const vigen_check_level *lv = &rep->orders[VIGEN_CHECK_SEPARABLE].level;
    int p = !lv->capped && !lv->undecided ? lv->value : 0;
    return chk_lie_error(&rep->lie_error, rd->t, p, cx->prec, err);
}
