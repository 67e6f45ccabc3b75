/* theorem.c — the order of a PRK method from its simplifying assumptions, and
 * the bushy-tree conditions that bound it from above (check.h,
 * vigen_check_theorem).  These decide claims of orders whose trees are too
 * many or too high to enumerate (Gauss s = 6: order 12 exactly, from B(12),
 * C(6), D(6) and the failing bushy tree of order 13).
 *
 * The statement used (Butcher 1964; Hairer, Norsett, Wanner I, Thm II.7.4):
 * if an RK method satisfies B(p), C(eta), D(zeta) with p <= eta + zeta + 1
 * and p <= 2 eta + 2, it has order p.  For a PRK method with c = ct = A 1 =
 * At 1 and b = bt, every reduction of that proof (C(k) of the child's part
 * turns a child with k - 1 leaves into c_i^k / k; D(k) of the child's part
 * moves the root to the child, with weights b = bt) gives the same result
 * whatever the colours, so the statement holds for the PRK method with p,
 * eta, zeta the smallest over the two parts.
 */
#include "check/check_internal.h"

static int imin(int a, int b) { return a < b ? a : b; }

/* Decides x_i = y_i for every i (b = bt, c = ct); HOLDS, FAILS or UNDECIDED,
 * and *data when some hold is within the precision of the data. */
int chk_decide_equal(ctx_t *cx, arb_srcptr x, arb_srcptr y, const unsigned char *ex, const unsigned char *ey,
                     slong id, int *data)
{
    int st = HOLDS;
    arb_t r;
    arb_init(r);
    for (slong i = 0; i < cx->s; i++) {
        arb_sub(r, x + i, y + i, cx->prec);
        chk_ctx_shape(cx, 1, 1, id, i, 0);
        int v = chk_decide2(cx, r, ex[i] && ey[i], x + i, y + i);
        if (v == HOLDS) *data |= cx->last_within;
        if (v == FAILS) st = FAILS;
        else if (v == UNDECIDED && st == HOLDS) st = UNDECIDED;
    }
    arb_clear(r);
    return st;
}

int chk_bushy(ctx_t *cx, int from, int Q, int fail[2], int *all)
{
    slong s = cx->s, prec = cx->prec;
    const arb_mat_struct *M[2] = {cx->A, cx->At};
    arb_srcptr bh[2] = {cx->b, cx->bt};
    arb_ptr rs = _arb_vec_init(2 * s), pw = _arb_vec_init(2 * s);
    arb_t v, q, r;
    mag_t m, t;
    arb_init(v);
    arb_init(q);
    arb_init(r);
    mag_init(m);
    mag_init(t);
    for (int l = 0; l < 2; l++)
        for (slong i = 0; i < s; i++) {
            arb_zero(rs + l * s + i);
            for (slong j = 0; j < s; j++) arb_add(rs + l * s + i, rs + l * s + i, arb_mat_entry(M[l], i, j), prec);
            arb_one(pw + l * s + i);
        }
    /* from the first order asked: (M 1)^(from - 1) at once */
    if (from > 1)
        for (slong k = 0; k < 2 * s; k++) arb_pow_ui(pw + k, rs + k, (ulong)(from - 1), prec);
    fail[0] = fail[1] = 0;
    int to = from - 1;
    *all = 0;
    for (int n = from; n <= Q; n++) {
        if (n > from)
            for (slong k = 0; k < 2 * s; k++) arb_mul(pw + k, pw + k, rs + k, prec);
        arb_one(q);
        arb_div_ui(q, q, (ulong)n, prec);
        int nfail = 0;
        for (int root = 0; root < 2; root++)
            for (int leaf = 0; leaf < 2; leaf++) {
                arb_dot(v, NULL, 0, bh[root], 1, pw + leaf * s, 1, s, prec);
                arb_sub(r, v, q, prec);
                /* the size of the terms: sum |bhat_i| |(M 1)_i|^(q-1) + 1/q */
                mag_zero(m);
                for (slong i = 0; i < s; i++) {
                    mag_t u;
                    mag_init(u);
                    chk_mid_mag(t, bh[root] + i);
                    chk_mid_mag(u, pw + leaf * s + i);
                    mag_addmul(m, t, u);
                    mag_clear(u);
                }
                arf_get_mag(t, arb_midref(q));
                mag_add(m, m, t);
                int exact = cx->ex->part[root] && cx->ex->part[leaf];
                chk_ctx_shape(cx, n, (ulong)n, 100 + n, root, leaf);
                int st = chk_decide(cx, r, exact, m);
                nfail += st == FAILS;
                if (st != FAILS) continue;
                /* leaves of the root's colour: a monochromatic tree (general H);
                 * of the other colour (or a single vertex): alternating, separable H too */
                if (!fail[0]) fail[0] = n;
                if ((leaf != root || n == 1) && !fail[1]) fail[1] = n;
            }
        to = n;
        if (nfail == 4 && !*all) *all = n;
        if (fail[0] && fail[1]) break;
    }
    _arb_vec_clear(rs, 2 * s);
    _arb_vec_clear(pw, 2 * s);
    arb_clear(v);
    arb_clear(q);
    arb_clear(r);
    mag_clear(m);
    mag_clear(t);
    return to;
}

int chk_theorem(chk_round *rd, vigen_error *err)
{
    (void)err;
    vigen_check_report *rep = rd->rep;
    ctx_t *cx = rd->cx;
    vigen_check_theorem *th = &rep->theorem;
    const exactness *x = cx->ex;
    cx->section = VIGEN_CHECK_SECT_SIMPLIFYING;
    th->applies = 0;
    th->order = 0;
    th->within_data = 0;
    th->B = imin(rep->B[0].value, rep->B[1].value);
    th->eta = imin(rep->C[0].value, rep->C[1].value);
    th->zeta = imin(rep->D[0].value, rep->D[1].value);
    /* b = bt and c = ct (aliases when the tableau does not give them) */
    int data = 0, eq = HOLDS;
    th->why_not = NULL;
    if (cx->has_bt) eq = chk_decide_equal(cx, cx->b, cx->bt, x->b, x->bt, 90, &data);
    if (eq != HOLDS) th->why_not = eq == FAILS ? "b != bt" : "b = bt is undecided";
    if (eq == HOLDS && cx->has_At) {
        eq = chk_decide_equal(cx, cx->c, cx->ct, x->c, x->ct, 91, &data);
        if (eq != HOLDS) th->why_not = eq == FAILS ? "c != ct" : "c = ct is undecided";
    }
    if (eq == HOLDS && rep->consistent != VIGEN_CHECK_YES) th->why_not = "the row sums do not all hold";
    if (eq == HOLDS && rep->consistent == VIGEN_CHECK_YES) {
        th->applies = 1;
        int p = th->B;
        p = imin(p, th->eta + th->zeta + 1);
        p = imin(p, 2 * th->eta + 2);
        th->order = p;
        /* the levels up to what is used, and the row sums */
        for (int part = 0; part < 2; part++)
            th->within_data |= rep->B[part].within_data || rep->C[part].within_data || rep->D[part].within_data;
        th->within_data |= data || rep->consistent_within_data;
    }
    /* the bushy trees up to two orders above what the assumptions reach (at
     * most 2s + 2: an s-point quadrature is exact at most to degree 2s - 1) */
    int Q = (int)(2 * cx->s + 2);
    if (Q < rd->P + 1) Q = rd->P + 1;
    if (rep->claim_order >= 0 && Q < rep->claim_order + 1) Q = rep->claim_order + 1;
    if (Q > 64) Q = 64;
    int all;
    th->bushy_to = chk_bushy(cx, 1, Q, th->bushy_fail, &all);
    return VIGEN_OK;
}
