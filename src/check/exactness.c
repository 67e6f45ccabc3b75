/* exactness.c — which entries are exact expressions, and whether every entry
 * lies in Q or in one real quadratic field Q(sqrt d), with a common
 * denominator: what makes a hold a proof (decide.c).
 */
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "core/expr.h"
#include "check/check_internal.h"
#include "support/strbuf.h"

static int text_exact(char **texts, slong k)
{
    return texts != NULL && texts[k] != NULL && !vigen_tableau_entry_is_rounded(texts[k]);
}

/* Entries in Q or in one Q(sqrt d) make holds provable (see proved_zero in decide.c).
 * With D a common denominator of every a and b of the entries a + b sqrt(d),
 * each condition value v (a sum of products of k entries, minus a constant
 * with denominator g) has v D^k g = m + n sqrt(d) with integers m, n.  Sets
 * x->den = D and x->qd = d (1 for rationals) when every given entry is such a
 * value, and for d > 1 the texts of the conjugate entries a - b sqrt(d); the
 * caller has checked that every entry is exact. */
static void algebraic_init(exactness *x, char **const lists[6], const slong lens[6])
{
    int ok = x->part_c[0] && x->part_c[1];
    fmpz_one(x->den);
    fmpz_one(x->qd);
    fmpq *qa[6] = {NULL}, *qb[6] = {NULL};
    fmpz_t d;
    fmpz_init(d);
    for (int l = 0; l < 6 && ok; l++) {
        if (lists[l] == NULL) continue;
        qa[l] = _fmpq_vec_init(lens[l]);
        qb[l] = _fmpq_vec_init(lens[l]);
        for (slong k = 0; k < lens[l] && ok; k++) {
            vigen_expr *e = NULL;
            vigen_error err;
            vigen_error_init(&err);
            ok = lists[l][k] != NULL && vigen_expr_parse(&e, lists[l][k], 0, &err) == VIGEN_OK &&
                 vigen_expr_to_quadratic(qa[l] + k, qb[l] + k, d, e);
            /* one field for the whole tableau */
            if (ok && !fmpz_is_one(d)) {
                if (fmpz_is_one(x->qd)) fmpz_set(x->qd, d);
                else ok = fmpz_equal(x->qd, d);
            }
            if (ok) {
                fmpz_lcm(x->den, x->den, fmpq_denref(qa[l] + k));
                fmpz_lcm(x->den, x->den, fmpq_denref(qb[l] + k));
            }
            vigen_expr_free(e);
            vigen_error_clear(&err);
        }
    }
    if (ok && !fmpz_is_one(x->qd)) {
        char *ds = fmpz_get_str(NULL, 10, x->qd);
        for (int l = 0; l < 6; l++) {
            if (lists[l] == NULL) continue;
            x->conj[l] = flint_calloc((size_t)lens[l], sizeof(char *));
            for (slong k = 0; k < lens[l]; k++) {
                char *a = fmpq_get_str(NULL, 10, qa[l] + k), *b = fmpq_get_str(NULL, 10, qb[l] + k);
                x->conj[l][k] = vigen_strdup_printf("(%s) - (%s)*sqrt(%s)", a, b, ds);
                flint_free(a);
                flint_free(b);
            }
        }
        flint_free(ds);
    }
    for (int l = 0; l < 6; l++)
        if (qa[l]) {
            _fmpq_vec_clear(qa[l], lens[l]);
            _fmpq_vec_clear(qb[l], lens[l]);
        }
    fmpz_clear(d);
    if (!ok) {
        fmpz_zero(x->den);
        fmpz_zero(x->qd);
    }
}

void chk_exactness_init(exactness *x, const vigen_tableau *t)
{
    slong s = t->s;
    x->s = s;
    x->A = flint_calloc((size_t)(s * s), 1);
    x->At = flint_calloc((size_t)(s * s), 1);
    x->b = flint_calloc((size_t)s, 1);
    x->bt = flint_calloc((size_t)s, 1);
    x->c = flint_calloc((size_t)s, 1);
    x->ct = flint_calloc((size_t)s, 1);
    int texts = t->c_text != NULL && t->A_text != NULL && t->b_text != NULL;
    x->any_exact = 0;
    x->any_rounded = !texts;
    fmpz_init(x->den);
    fmpz_init(x->qd);
    for (int l = 0; l < 6; l++) x->conj[l] = NULL;
    if (!texts) {
        x->part[0] = x->part[1] = x->part_c[0] = x->part_c[1] = 0;
        return;
    }
    int has_At = t->has_At, has_bt = t->has_At && t->has_bt, has_ct = t->has_At && t->has_ct;
    for (slong k = 0; k < s * s; k++) {
        x->A[k] = (unsigned char)text_exact(t->A_text, k);
        x->At[k] = has_At ? (unsigned char)text_exact(t->At_text, k) : x->A[k];
    }
    for (slong i = 0; i < s; i++) {
        x->b[i] = (unsigned char)text_exact(t->b_text, i);
        x->bt[i] = has_bt ? (unsigned char)text_exact(t->bt_text, i) : x->b[i];
        x->c[i] = (unsigned char)text_exact(t->c_text, i);
        if (!has_At) x->ct[i] = x->c[i];
        else if (has_ct) x->ct[i] = (unsigned char)text_exact(t->ct_text, i);
        else {   /* ct computed from the row sums of At */
            int all = 1;
            for (slong j = 0; j < s; j++) all &= x->At[i * s + j];
            x->ct[i] = (unsigned char)all;
        }
    }
    for (int part = 0; part < 2; part++) {
        const unsigned char *M = part ? x->At : x->A, *w = part ? x->bt : x->b, *c = part ? x->ct : x->c;
        int all = 1, allc = 1;
        for (slong k = 0; k < s * s; k++) all &= M[k];
        for (slong i = 0; i < s; i++) all &= w[i];
        for (slong i = 0; i < s; i++) allc &= c[i];
        x->part[part] = all;
        x->part_c[part] = all && allc;
    }
    /* what the file gives (texts present), exact or rounded */
    char **lists[6] = {t->c_text, t->b_text, has_ct ? t->ct_text : NULL, has_bt ? t->bt_text : NULL, t->A_text,
                       has_At ? t->At_text : NULL};
    slong lens[6] = {s, s, s, s, s * s, s * s};
    for (int l = 0; l < 6; l++)
        for (slong k = 0; lists[l] && k < lens[l]; k++) {
            if (lists[l][k] == NULL) continue;
            if (vigen_tableau_entry_is_rounded(lists[l][k])) x->any_rounded = 1;
            else x->any_exact = 1;
        }
    algebraic_init(x, lists, lens);
}

void chk_exactness_clear(exactness *x)
{
    slong lens[6] = {x->s, x->s, x->s, x->s, x->s * x->s, x->s * x->s};
    for (int l = 0; l < 6; l++) {
        for (slong k = 0; x->conj[l] && k < lens[l]; k++) free(x->conj[l][k]);
        flint_free(x->conj[l]);
    }
    fmpz_clear(x->den);
    fmpz_clear(x->qd);
    flint_free(x->A);
    flint_free(x->At);
    flint_free(x->b);
    flint_free(x->bt);
    flint_free(x->c);
    flint_free(x->ct);
}

int chk_has_texts(const vigen_tableau *t) { return t->c_text != NULL && t->A_text != NULL && t->b_text != NULL; }

