/* simplifying.c — the check of the simplifying assumptions B(p), C(p), D(p)
 * and the stage order of each part.
 */
#include <stdlib.h>
#include "check/check_internal.h"

static int worst_status(int a, int b)
{
    if (a == FAILS || b == FAILS) return FAILS;
    if (a == UNDECIDED || b == UNDECIDED) return UNDECIDED;
    return HOLDS;
}

/* m += |x| |y| |z| (z may be NULL) */
static void mag_addmul3(mag_t m, const arb_t x, const arb_t y, const arb_t z)
{
    mag_t t, u;
    mag_init(t);
    mag_init(u);
    chk_mid_mag(t, x);
    chk_mid_mag(u, y);
    mag_mul(t, t, u);
    if (z) {
        chk_mid_mag(u, z);
        mag_mul(t, t, u);
    }
    mag_add(m, m, t);
    mag_clear(t);
    mag_clear(u);
}

static void mag_add_arb(mag_t m, const arb_t x)
{
    mag_t t;
    mag_init(t);
    chk_mid_mag(t, x);
    mag_add(m, m, t);
    mag_clear(t);
}

/* B(k): sum_i b_i c_i^(k-1) = 1/k */
int chk_assumption_B(chk_part *p, int k)
{
    slong s = p->cx->s, prec = p->cx->prec;
    arb_t r, q;
    mag_t m;
    arb_init(r);
    arb_init(q);
    mag_init(m);
    arb_dot(r, NULL, 0, p->b, 1, p->cp + (k - 1) * s, 1, s, prec);
    arb_one(q);
    arb_div_ui(q, q, (ulong)k, prec);
    arb_sub(r, r, q, prec);
    for (slong i = 0; i < s; i++) mag_addmul3(m, p->b + i, p->cp + (k - 1) * s + i, NULL);
    mag_add_arb(m, q);
    chk_ctx_shape(p->cx, k, (ulong)k, 3 * p->part, k, 0);
    int st = chk_decide(p->cx, r, p->exact_B, m);
    arb_clear(r);
    arb_clear(q);
    mag_clear(m);
    return st;
}

/* C(k): sum_j a_ij c_j^(k-1) = c_i^k / k for every i */
int chk_assumption_C(chk_part *p, int k)
{
    slong s = p->cx->s, prec = p->cx->prec;
    int st = HOLDS;
    arb_t r, q;
    mag_t m;
    arb_init(r);
    arb_init(q);
    mag_init(m);
    for (slong i = 0; i < s; i++) {
        arb_dot(r, NULL, 0, arb_mat_entry(p->A, i, 0), 1, p->cp + (k - 1) * s, 1, s, prec);
        arb_div_ui(q, p->cp + k * s + i, (ulong)k, prec);
        arb_sub(r, r, q, prec);
        mag_zero(m);
        for (slong j = 0; j < s; j++) mag_addmul3(m, arb_mat_entry(p->A, i, j), p->cp + (k - 1) * s + j, NULL);
        mag_add_arb(m, q);
        chk_ctx_shape(p->cx, k, (ulong)k, 3 * p->part + 1, k, i);
        st = worst_status(st, chk_decide(p->cx, r, p->exact_C, m));
    }
    arb_clear(r);
    arb_clear(q);
    mag_clear(m);
    return st;
}

/* D(k): sum_i b_i c_i^(k-1) a_ij = b_j (1 - c_j^k) / k for every j */
int chk_assumption_D(chk_part *p, int k)
{
    slong s = p->cx->s, prec = p->cx->prec;
    int st = HOLDS;
    arb_t r, q, u;
    mag_t m;
    arb_init(r);
    arb_init(q);
    arb_init(u);
    mag_init(m);
    /* b_i c_i^(k-1), the same for every j */
    arb_ptr bc = _arb_vec_init(s);
    for (slong i = 0; i < s; i++) arb_mul(bc + i, p->b + i, p->cp + (k - 1) * s + i, prec);
    for (slong j = 0; j < s; j++) {
        arb_zero(r);
        mag_zero(m);
        for (slong i = 0; i < s; i++) {
            arb_addmul(r, bc + i, arb_mat_entry(p->A, i, j), prec);
            mag_addmul3(m, p->b + i, p->cp + (k - 1) * s + i, arb_mat_entry(p->A, i, j));
        }
        /* b_j (1 + |c_j|^k) / k bounds the right side's terms */
        arb_sub_ui(q, p->cp + k * s + j, 1, prec);
        arb_neg(q, q);
        arb_mul(q, q, p->b + j, prec);
        arb_div_ui(q, q, (ulong)k, prec);
        arb_sub(r, r, q, prec);
        arb_abs(u, p->cp + k * s + j);
        arb_add_ui(u, u, 1, prec);
        arb_mul(u, u, p->b + j, prec);
        arb_div_ui(u, u, (ulong)k, prec);
        mag_add_arb(m, u);
        chk_ctx_shape(p->cx, k + 1, (ulong)k, 3 * p->part + 2, k, j);   /* b_j/k has fewer factors: D^1 | D^(k+1) */
        st = worst_status(st, chk_decide(p->cx, r, p->exact, m));
    }
    _arb_vec_clear(bc, s);
    arb_clear(r);
    arb_clear(q);
    arb_clear(u);
    mag_clear(m);
    return st;
}

/* Bits 0 .. k-1 of a mask of levels (bit k-1 is level k). */
static unsigned long long levels_upto(int k)
{
    return k >= 64 ? ~0ULL : k <= 0 ? 0ULL : (1ULL << k) - 1;
}

/* The level of one assumption; *data: bit k-1 set when level k holds with
 * some condition within the precision of the data (cap <= 64). */
static vigen_check_level level_of(chk_part *p, int (*fn)(chk_part *, int), int cap, unsigned long long *data)
{
    vigen_check_level L = {cap, 1, 0, 0, 0};
    const vigen_check_holds *h = p->cx->holds + p->cx->section;
    *data = 0;
    for (int k = 1; k <= cap; k++) {
        slong d0 = h->data, u0 = p->cx->n_undecided, s0 = p->cx->n_undecided_short;
        int st = fn(p, k);
        if (st == HOLDS) {
            if (h->data > d0) *data |= 1ULL << (k - 1);
            continue;
        }
        L.value = k - 1;
        L.capped = 0;
        L.undecided = st == UNDECIDED;
        slong u = p->cx->n_undecided - u0, sh = p->cx->n_undecided_short - s0;
        L.too_short = L.undecided && u > 0 && sh == u;
        break;
    }
    L.within_data = (*data & levels_upto(L.value)) != 0;
    return L;
}

int chk_simplifying(chk_round *rd, vigen_error *err)
{
    (void)err;
    vigen_check_report *rep = rd->rep;
    ctx_t *cx = rd->cx;
    slong s = cx->s;
    int cap = (int)(2 * s + 1);
    if (cap < rep->max_order) cap = rep->max_order;
    if (cap > 64) cap = 64;
    rep->simplifying_cap = cap;
    cx->section = VIGEN_CHECK_SECT_SIMPLIFYING;
    for (int part = 0; part < 2; part++) {
        chk_part p;
        p.cx = cx;
        p.part = part;
        p.exact = cx->ex->part_c[part];
        /* B(k) involves (c, b) only and C(k) (c, A) only: exact when those are */
        {
            const exactness *x = cx->ex;
            const unsigned char *M = part ? x->At : x->A, *w = part ? x->bt : x->b, *cc = part ? x->ct : x->c;
            int ec = 1, eb = 1, eA = 1;
            for (slong i = 0; i < s; i++) {
                ec &= cc[i];
                eb &= w[i];
            }
            for (slong k = 0; k < s * s; k++) eA &= M[k];
            p.exact_B = ec && eb;
            p.exact_C = ec && eA;
        }
        p.A = part ? cx->At : cx->A;
        p.b = part ? cx->bt : cx->b;
        p.c = part ? cx->ct : cx->c;
        p.cp = _arb_vec_init((cap + 1) * s);
        for (slong i = 0; i < s; i++) arb_one(p.cp + i);
        for (int k = 1; k <= cap; k++)
            for (slong i = 0; i < s; i++) arb_mul(p.cp + k * s + i, p.cp + (k - 1) * s + i, p.c + i, cx->prec);
        unsigned long long dB, dC, dD;
        rep->B[part] = level_of(&p, chk_assumption_B, cap, &dB);
        rep->C[part] = level_of(&p, chk_assumption_C, cap, &dC);
        rep->D[part] = level_of(&p, chk_assumption_D, cap, &dD);
        /* stage order: C(q) and B(q) */
        vigen_check_level B = rep->B[part], C = rep->C[part], S;
        S.value = B.value < C.value ? B.value : C.value;
        S.capped = B.capped && C.capped;
        int fails_next = (B.value == S.value && !B.undecided && !B.capped) ||
                         (C.value == S.value && !C.undecided && !C.capped);
        S.undecided = !S.capped && !fails_next;
        S.within_data = ((dB | dC) & levels_upto(S.value)) != 0;
        /* undecided above: every assumption undecided at S.value + 1 is so for short data */
        S.too_short = S.undecided && (B.value != S.value || !B.undecided || B.too_short) &&
                      (C.value != S.value || !C.undecided || C.too_short);
        rep->stage_order[part] = S;
        _arb_vec_clear(p.cp, (cap + 1) * s);
    }
    return VIGEN_OK;
}
