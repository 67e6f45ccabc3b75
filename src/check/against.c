/* against.c — the check --against FILE2: every entry compared with FILE2's,
 * at the scale of its matrix or vector.
 */
#include <stdlib.h>
#include "check/check_internal.h"
#include "support/strbuf.h"

/* Largest |entry| of each matrix or vector, the scale of the comparisons. */
static void entries_scale(mag_t m, const arb_srcptr *vecs, slong nvec, slong len)
{
    mag_t t;
    mag_init(t);
    mag_zero(m);
    for (slong v = 0; v < nvec; v++)
        for (slong k = 0; k < len; k++) {
            chk_mid_mag(t, vecs[v] + k);
            mag_max(m, m, t);
        }
    mag_clear(t);
}

static void mat_scale(mag_t m, const arb_mat_struct *X, const arb_mat_struct *Y, slong s)
{
    mag_t t;
    mag_init(t);
    mag_zero(m);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            chk_mid_mag(t, arb_mat_entry(X, i, j));
            mag_max(m, m, t);
            chk_mid_mag(t, arb_mat_entry(Y, i, j));
            mag_max(m, m, t);
        }
    mag_clear(t);
}

static void compare_entry(vigen_check_report *rep, ctx_t *cx, const char *mat, slong i, slong j, const arb_t x,
                          const arb_t y, int exact, const mag_t scale)
{
    arb_t d;
    arb_init(d);
    arb_sub(d, x, y, cx->prec);
    chk_ctx_shape(cx, 0, 0, 0, i, j);   /* FILE2's denominators are not in cx: no proof by denominators */
    int st = chk_decide(cx, d, exact, scale);
    if (st == HOLDS) {
        arb_clear(d);
        return;
    }
    if (st == FAILS) rep->against_differences++;
    else rep->against_undecided++;
    vigen_check_failure *p = chk_failure_new(rep, VIGEN_CHECK_FAIL_AGAINST);
    p->undecided = st == UNDECIDED;
    p->matrix = mat;
    p->row = i + 1;
    p->col = j >= 0 ? j + 1 : 0;
    p->has_value = p->has_expected = 1;
    arb_set(p->value, x);
    arb_set(p->expected, y);
    slong digits = vigen_ball_digits_to_separate(x, y, cx->prec);
    /* a difference: digits enough that the two sides differ in the text */
    char *a = st == FAILS ? vigen_ball_str_apart(x, y, cx->prec) : vigen_ball_str(x, digits);
    char *b = st == FAILS ? vigen_ball_str_apart(y, x, cx->prec) : vigen_ball_str(y, digits);
    char *name = j >= 0 ? vigen_strdup_printf("%s[%ld][%ld]", mat, (long)(i + 1), (long)(j + 1))
                        : vigen_strdup_printf("%s[%ld]", mat, (long)(i + 1));
    if (st == FAILS) {
        char *ds = vigen_ball_str(d, 6);
        p->message = vigen_strdup_printf("%s = %s here but %s there (difference %s%s)", name, a, b,
                                         ds[0] == '[' ? "in " : "", ds);
        free(ds);
    }
    else p->message = vigen_strdup_printf("%s = %s here and %s there: undecided at this precision", name, a, b);
    free(name);
    free(a);
    free(b);
    arb_clear(d);
}

/* x: the checked tableau (its context makes the decisions), y: FILE2. */
static void compare_tableaux(vigen_check_report *rep, ctx_t *x, const ctx_t *y)
{
    rep->against_checked = 1;
    rep->against_differences = 0;
    rep->against_undecided = 0;
    if (x->s != y->s) {
        rep->against_differences = 1;
        rep->against_stages = y->s;
        vigen_check_failure *p = chk_failure_new(rep, VIGEN_CHECK_FAIL_AGAINST);
        p->value_json = vigen_strdup_printf("%ld", (long)x->s);
        p->expected_json = vigen_strdup_printf("%ld", (long)y->s);
        p->message = vigen_strdup_printf("the tableaux have %ld and %ld stages", (long)x->s, (long)y->s);
        return;
    }
    x->section = VIGEN_CHECK_SECT_AGAINST;
    slong s = x->s;
    int p_part = x->has_At || y->has_At;
    mag_t sc;
    mag_init(sc);
    /* the scale of a comparison: the largest entry of that matrix or vector in
     * either tableau (an entry that is 0 is compared at the scale of its
     * neighbours) */
#define VEC_SCALE(X, Y)                                                                                               \
    do {                                                                                                              \
        arb_srcptr v_[2] = {(X), (Y)};                                                                                \
        entries_scale(sc, v_, 2, s);                                                                                  \
    } while (0)
#define MAT_SCALE(X, Y) mat_scale(sc, (X), (Y), s)
    const exactness *ex = x->ex, *ey = y->ex;
    VEC_SCALE(x->c, y->c);
    for (slong i = 0; i < s; i++)
        compare_entry(rep, x, "c", i, -1, x->c + i, y->c + i, ex->c[i] && ey->c[i], sc);
    MAT_SCALE(x->A, y->A);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++)
            compare_entry(rep, x, "A", i, j, arb_mat_entry(x->A, i, j), arb_mat_entry(y->A, i, j),
                          ex->A[i * s + j] && ey->A[i * s + j], sc);
    VEC_SCALE(x->b, y->b);
    for (slong i = 0; i < s; i++)
        compare_entry(rep, x, "b", i, -1, x->b + i, y->b + i, ex->b[i] && ey->b[i], sc);
    if (p_part) {
        VEC_SCALE(x->ct, y->ct);
        for (slong i = 0; i < s; i++)
            compare_entry(rep, x, "ct", i, -1, x->ct + i, y->ct + i, ex->ct[i] && ey->ct[i], sc);
        MAT_SCALE(x->At, y->At);
        for (slong i = 0; i < s; i++)
            for (slong j = 0; j < s; j++)
                compare_entry(rep, x, "At", i, j, arb_mat_entry(x->At, i, j), arb_mat_entry(y->At, i, j),
                              ex->At[i * s + j] && ey->At[i * s + j], sc);
        VEC_SCALE(x->bt, y->bt);
        for (slong i = 0; i < s; i++)
            compare_entry(rep, x, "bt", i, -1, x->bt + i, y->bt + i, ex->bt[i] && ey->bt[i], sc);
    }
#undef VEC_SCALE
#undef MAT_SCALE
    mag_clear(sc);
}

/* --against: FILE2 read at the precision of the round; its decisions count
 * in the checked tableau's context. */
int chk_against(chk_round *rd, vigen_error *err)
{
    (void)err;
    if (rd->against == NULL) return VIGEN_OK;
    ctx_t cy;
    chk_ctx_init(&cy, rd->against, rd->ex_against, rd->rep->holds);
    cy.prec = rd->cx->prec;
    compare_tableaux(rd->rep, rd->cx, &cy);
    return VIGEN_OK;
}
