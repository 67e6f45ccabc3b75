/* rowsums.c — the checks of consistency (row sums, sum b = 1) and of
 * symplecticity (bt = b and the pair conditions), as lists of conditions kept
 * in the round, so that the diagnosis (diagnose.c) can trace their failures
 * back to one entry.
 */
#include "check/check_internal.h"

/* Room for every row-sum and symplecticity condition of the round, and the
 * tableau at its midpoints: for the enclosures of conditions on rounded
 * entries and for the typo diagnosis. */
static void round_conds_start(chk_round *r)
{
    if (r->conds != NULL) return;
    slong s = r->cx->s;
    r->alloc_conds = 2 + 3 * s + s * s;
    r->conds = flint_malloc(sizeof(cond) * (size_t)r->alloc_conds);
    r->nconds = 0;
    chk_midpoints_init(&r->mid, r->cx);
    r->have_mid = 1;
}

/* Evaluates and decides the conditions from..nconds-1, counting them into
 * the report's totals of their section. */
static void decide_conds(chk_round *r, slong from)
{
    vigen_check_report *rep = r->rep;
    ctx_t *cx = r->cx;
    const ctx_t *mx = &r->mid.cx;
    cond *conds = r->conds;
    arb_t lin;
    arb_init(lin);
    for (slong k = from; k < r->nconds; k++) {
        chk_cond_eval(conds[k].r, cx, conds + k, NULL);
        if (!chk_cond_exact(cx, conds + k)) {
            /* an entry that occurs twice (b_i in b_i a_ii + b_i a_ii - b_i b_i)
             * varies once: intersect with the second-order enclosure */
            chk_cond_enclose(lin, cx, mx, conds + k, NULL, NULL);
            if (arb_is_finite(lin) && arb_is_finite(conds[k].r)) arb_intersection(conds[k].r, conds[k].r, lin, cx->prec);
        }
        cx->section = chk_cond_is_rowsum(conds + k) ? VIGEN_CHECK_SECT_ROWSUM : VIGEN_CHECK_SECT_SYMPLECTIC;
        conds[k].status = chk_cond_decide(cx, conds + k);
        conds[k].too_short = cx->last_short;
        slong *fail = chk_cond_is_rowsum(conds + k) ? &rep->row_fail : &rep->sym_fail;
        slong *und = chk_cond_is_rowsum(conds + k) ? &rep->row_undecided : &rep->sym_undecided;
        slong *tot = chk_cond_is_rowsum(conds + k) ? &rep->row_total : &rep->sym_total;
        (*tot)++;
        if (conds[k].status == FAILS) (*fail)++;
        if (conds[k].status == UNDECIDED) (*und)++;
    }
    arb_clear(lin);
}

int chk_consistency(chk_round *r, vigen_error *err)
{
    (void)err;
    round_conds_start(r);
    ctx_t *cx = r->cx;
    vigen_check_report *rep = r->rep;
    slong s = cx->s, from = r->nconds;
    for (slong i = 0; i < s; i++) chk_add_cond(r->conds, &r->nconds, C_ROWSUM_A, i, 0);
    if (cx->has_ct)
        for (slong i = 0; i < s; i++) chk_add_cond(r->conds, &r->nconds, C_ROWSUM_AT, i, 0);
    chk_add_cond(r->conds, &r->nconds, C_SUM_B, 0, 0);
    if (cx->has_bt) chk_add_cond(r->conds, &r->nconds, C_SUM_BT, 0, 0);
    rep->row_fail = rep->row_undecided = rep->row_total = 0;
    decide_conds(r, from);
    rep->consistent = chk_tri_of(rep->row_fail, rep->row_undecided);
    rep->consistent_within_data = rep->consistent == VIGEN_CHECK_YES && rep->holds[VIGEN_CHECK_SECT_ROWSUM].data > 0;
    return VIGEN_OK;
}

int chk_symplecticity(chk_round *r, vigen_error *err)
{
    (void)err;
    round_conds_start(r);
    ctx_t *cx = r->cx;
    vigen_check_report *rep = r->rep;
    slong s = cx->s, from = r->nconds;
    if (cx->has_bt)
        for (slong i = 0; i < s; i++) chk_add_cond(r->conds, &r->nconds, C_BT_EQ_B, i, 0);
    /* with At = A the pair (i, j) and the pair (j, i) are one condition */
    for (slong i = 0; i < s; i++)
        for (slong j = cx->has_At ? 0 : i; j < s; j++) chk_add_cond(r->conds, &r->nconds, C_SYMP, i, j);
    rep->sym_fail = rep->sym_undecided = rep->sym_total = 0;
    decide_conds(r, from);
    rep->symplectic = chk_tri_of(rep->sym_fail, rep->sym_undecided);
    /* for separable H the pair conditions suffice: bt may differ from b */
    slong pair_fail = 0, pair_undecided = 0;
    for (slong k = from; k < r->nconds; k++)
        if (r->conds[k].type == C_SYMP) {
            pair_fail += r->conds[k].status == FAILS;
            pair_undecided += r->conds[k].status == UNDECIDED;
        }
    rep->symplectic_separable = chk_tri_of(pair_fail, pair_undecided);
    rep->symplectic_within_data = (rep->symplectic == VIGEN_CHECK_YES || rep->symplectic_separable == VIGEN_CHECK_YES) &&
                                  rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].data > 0;
    return VIGEN_OK;
}
