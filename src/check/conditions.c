/* conditions.c — entries of the tableau (with At, bt, ct standing for A, b,
 * c when absent) and the row-sum and symplecticity conditions over them:
 * value, scale of the terms, entries involved, decision.
 */
#include <stdlib.h>
#include "check/check_internal.h"
#include "support/strbuf.h"

const char *const chk_matrix_names[6] = {"A", "At", "b", "bt", "c", "ct"};

static entry canon(const ctx_t *cx, entry e)
{
    if (e.mat == M_AT && !cx->has_At) e.mat = M_A;
    if (e.mat == M_BT && !cx->has_bt) e.mat = M_B;
    if (e.mat == M_CT && !cx->has_At) e.mat = M_C;
    return e;
}

int chk_entry_eq(entry x, entry y) { return x.mat == y.mat && x.i == y.i && x.j == y.j; }

static int entry_exact(const ctx_t *cx, entry e)
{
    slong s = cx->s;
    switch (e.mat) {
    case M_A: return cx->ex->A[e.i * s + e.j];
    case M_AT: return cx->ex->At[e.i * s + e.j];
    case M_B: return cx->ex->b[e.i];
    case M_BT: return cx->ex->bt[e.i];
    case M_C: return cx->ex->c[e.i];
    default: return cx->ex->ct[e.i];
    }
}

/* The text of a canonical entry as the file gives it, or NULL. */
const char *chk_entry_text(const ctx_t *cx, entry e)
{
    const vigen_tableau *t = cx->t;
    slong s = cx->s;
    char **texts;
    slong k = e.i;
    switch (e.mat) {
    case M_A: texts = t->A_text; k = e.i * s + e.j; break;
    case M_AT: texts = t->At_text; k = e.i * s + e.j; break;
    case M_B: texts = t->b_text; break;
    case M_BT: texts = t->bt_text; break;
    case M_C: texts = t->c_text; break;
    default: texts = cx->has_ct ? t->ct_text : NULL; break;
    }
    return texts ? texts[k] : NULL;
}

override chk_ov1(entry e, arb_srcptr v)
{
    override o;
    o.n = 1;
    o.e[0] = e;
    o.value[0] = v;
    o.e[1] = e;
    o.value[1] = v;
    return o;
}

arb_srcptr chk_get(const ctx_t *cx, int mat, slong i, slong j, const override *ov)
{
    entry e = {mat, i, (mat == M_A || mat == M_AT) ? j : 0};
    e = canon(cx, e);
    if (ov)
        for (int k = 0; k < ov->n; k++)
            if (chk_entry_eq(e, ov->e[k])) return ov->value[k];
    switch (e.mat) {
    case M_A: return arb_mat_entry(cx->A, i, j);
    case M_AT: return arb_mat_entry(cx->At, i, j);
    case M_B: return cx->b + i;
    case M_BT: return cx->bt + i;
    case M_C: return cx->c + i;
    default: return cx->ct + i;
    }
}

int chk_cond_is_rowsum(const cond *c) { return c->type <= C_SUM_BT; }

void chk_add_cond(cond *conds, slong *n, int type, slong i, slong j)
{
    cond *c = conds + (*n)++;
    c->type = type;
    c->i = i;
    c->j = j;
    c->status = HOLDS;
    c->too_short = 0;
    arb_init(c->r);
}

/* r = value - expected of the condition, with one entry possibly overridden. */
void chk_cond_parts(arb_t value, arb_t expected, const ctx_t *cx, const cond *c, const override *ov)
{
    slong s = cx->s, prec = cx->prec, i = c->i, j = c->j;
    arb_zero(value);
    switch (c->type) {
    case C_ROWSUM_A:
    case C_ROWSUM_AT: {
        int m = c->type == C_ROWSUM_A ? M_A : M_AT;
        for (slong k = 0; k < s; k++) arb_add(value, value, chk_get(cx, m, i, k, ov), prec);
        arb_set(expected, chk_get(cx, m == M_A ? M_C : M_CT, i, 0, ov));
        break;
    }
    case C_SUM_B:
    case C_SUM_BT:
        for (slong k = 0; k < s; k++) arb_add(value, value, chk_get(cx, c->type == C_SUM_B ? M_B : M_BT, k, 0, ov), prec);
        arb_one(expected);
        break;
    case C_BT_EQ_B:
        arb_set(value, chk_get(cx, M_BT, i, 0, ov));
        arb_set(expected, chk_get(cx, M_B, i, 0, ov));
        break;
    default: { /* b_i at_ij + bt_j a_ji - b_i bt_j (GNI Thm VI.4.6; with bt = b the usual condition) */
        arb_srcptr bi = chk_get(cx, M_B, i, 0, ov), bj = chk_get(cx, M_BT, j, 0, ov);
        arb_mul(value, bi, chk_get(cx, M_AT, i, j, ov), prec);
        arb_addmul(value, bj, chk_get(cx, M_A, j, i, ov), prec);
        arb_submul(value, bi, bj, prec);
        arb_zero(expected);
        break;
    }
    }
}

void chk_cond_eval(arb_t r, const ctx_t *cx, const cond *c, const override *ov)
{
    arb_t e;
    arb_init(e);
    chk_cond_parts(r, e, cx, c, ov);
    arb_sub(r, r, e, cx->prec);
    arb_clear(e);
}

/* An upper bound of the size of the terms of the condition (the scale of
 * its tightness test). */
static void cond_scale(mag_t m, const ctx_t *cx, const cond *c)
{
    slong s = cx->s, i = c->i, j = c->j;
    mag_t t, u;
    mag_init(t);
    mag_init(u);
    mag_zero(m);
    switch (c->type) {
    case C_ROWSUM_A:
    case C_ROWSUM_AT: {
        int mt = c->type == C_ROWSUM_A ? M_A : M_AT;
        for (slong k = 0; k < s; k++) {
            chk_mid_mag(t, chk_get(cx, mt, i, k, NULL));
            mag_add(m, m, t);
        }
        chk_mid_mag(t, chk_get(cx, mt == M_A ? M_C : M_CT, i, 0, NULL));
        mag_add(m, m, t);
        break;
    }
    case C_SUM_B:
    case C_SUM_BT:
        for (slong k = 0; k < s; k++) {
            chk_mid_mag(t, chk_get(cx, c->type == C_SUM_B ? M_B : M_BT, k, 0, NULL));
            mag_add(m, m, t);
        }
        mag_one(t);
        mag_add(m, m, t);
        break;
    case C_BT_EQ_B:
        chk_mid_mag(m, chk_get(cx, M_BT, i, 0, NULL));
        chk_mid_mag(t, chk_get(cx, M_B, i, 0, NULL));
        mag_add(m, m, t);
        break;
    default: {
        mag_t bi, bj;
        mag_init(bi);
        mag_init(bj);
        chk_mid_mag(bi, chk_get(cx, M_B, i, 0, NULL));
        chk_mid_mag(bj, chk_get(cx, M_BT, j, 0, NULL));
        chk_mid_mag(t, chk_get(cx, M_AT, i, j, NULL));
        mag_mul(m, bi, t);
        chk_mid_mag(t, chk_get(cx, M_A, j, i, NULL));
        mag_mul(u, bj, t);
        mag_add(m, m, u);
        mag_mul(u, bi, bj);
        mag_add(m, m, u);
        mag_clear(bi);
        mag_clear(bj);
        break;
    }
    }
    mag_clear(t);
    mag_clear(u);
}

/* The canonical entries a condition involves (at most s + 1 or 4). */
slong chk_cond_entries(entry *out, const ctx_t *cx, const cond *c)
{
    slong n = 0, s = cx->s;
    switch (c->type) {
    case C_ROWSUM_A:
    case C_ROWSUM_AT: {
        int m = c->type == C_ROWSUM_A ? M_A : M_AT;
        for (slong k = 0; k < s; k++) out[n++] = canon(cx, (entry){m, c->i, k});
        out[n++] = canon(cx, (entry){m == M_A ? M_C : M_CT, c->i, 0});
        break;
    }
    case C_SUM_B:
    case C_SUM_BT:
        for (slong k = 0; k < s; k++) out[n++] = canon(cx, (entry){c->type == C_SUM_B ? M_B : M_BT, k, 0});
        break;
    case C_BT_EQ_B:
        out[n++] = canon(cx, (entry){M_BT, c->i, 0});
        out[n++] = canon(cx, (entry){M_B, c->i, 0});
        break;
    default:
        out[n++] = canon(cx, (entry){M_B, c->i, 0});
        out[n++] = canon(cx, (entry){M_BT, c->j, 0});
        out[n++] = canon(cx, (entry){M_AT, c->i, c->j});
        out[n++] = canon(cx, (entry){M_A, c->j, c->i});
        break;
    }
    return n;
}

int chk_cond_involves(const ctx_t *cx, const cond *c, entry e)
{
    entry buf[4];
    entry *list = chk_cond_is_rowsum(c) ? flint_malloc(sizeof(entry) * (size_t)(cx->s + 1)) : buf;
    slong n = chk_cond_entries(list, cx, c);
    int hit = 0;
    for (slong k = 0; k < n && !hit; k++) hit = chk_entry_eq(list[k], e);
    if (list != buf) flint_free(list);
    return hit;
}

/* Every entry the condition involves is exact. */
int chk_cond_exact(const ctx_t *cx, const cond *c)
{
    entry buf[4];
    entry *list = chk_cond_is_rowsum(c) ? flint_malloc(sizeof(entry) * (size_t)(cx->s + 1)) : buf;
    slong n = chk_cond_entries(list, cx, c);
    int all = 1;
    for (slong k = 0; k < n && all; k++) all = entry_exact(cx, list[k]);
    if (list != buf) flint_free(list);
    return all;
}

int chk_cond_decide(ctx_t *cx, const cond *c)
{
    mag_t m;
    mag_init(m);
    cond_scale(m, cx, c);
    chk_ctx_shape(cx, chk_cond_is_rowsum(c) || c->type == C_BT_EQ_B ? 1 : 2, 1, c->type, c->i, c->j);
    int v = chk_decide(cx, c->r, chk_cond_exact(cx, c), m);
    mag_clear(m);
    return v;
}

const char *chk_cond_kind_words(int type)
{
    switch (type) {
    case C_ROWSUM_A: case C_ROWSUM_AT: return "the row sum";
    case C_SUM_B: case C_SUM_BT: return "sum b = 1";
    case C_BT_EQ_B: return "bt = b";
    default: return "symplecticity";
    }
}

arb_srcptr chk_entry_value(const ctx_t *cx, entry e) { return chk_get(cx, e.mat, e.i, e.j, NULL); }

char *chk_entry_name(entry e)
{
    if (e.mat == M_A || e.mat == M_AT)
        return vigen_strdup_printf("%s[%ld][%ld]", chk_matrix_names[e.mat], (long)(e.i + 1), (long)(e.j + 1));
    return vigen_strdup_printf("%s[%ld]", chk_matrix_names[e.mat], (long)(e.i + 1));
}

