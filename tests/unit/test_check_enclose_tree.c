/* test_check_enclose_tree.c — the mean-value enclosure of tree conditions
 * over the balls of the entries (src/check/enclose_tree.c).
 *
 * Independent source: the definition of the elementary weights, Phi(t)_i =
 * prod over the children u of the root of (M_u Phi(u))_i and r = bhat .
 * Phi(t) - 1/gamma(t), evaluated here in exact rationals (fmpq) at points of
 * the box of the entries: its corners (where a polynomial that is
 * multilinear in no entry still takes large values) and random points.  Every
 * value must lie in the enclosure, for every bicoloured tree up to order 5, on
 * random 3-stage tableaux with wide balls (radius 2^-6, so that the
 * second-order remainder matters), with At, bt apart and with At = A, bt = b
 * (one entry feeding both colours).  With zero radii the enclosure is r at
 * the midpoints to the working precision.
 */
#include <string.h>
#include <flint/fmpq.h>
#include "check/check_internal.h"
#include "testlib.h"

#define S 3
#define MAXN 5

typedef struct {
    fmpq M[2][S * S];
    fmpq b[2][S];
} qtab;

/* Phi of the stored tree u (entries q), into out[S]. */
static void phi_stored(fmpq *out, const vigen_treeset *ts, slong u, const qtab *q, int alias)
{
    const vigen_tree *t = ts->trees + u;
    const slong *ch = vigen_treeset_children(ts, u);
    for (slong i = 0; i < S; i++) fmpq_one(out + i);
    fmpq sub[S], w;
    for (slong i = 0; i < S; i++) fmpq_init(sub + i);
    fmpq_init(&w);
    for (int d = 0; d < t->nchildren; d++) {
        phi_stored(sub, ts, ch[d], q, alias);
        int c = alias ? 0 : ts->trees[ch[d]].colour;
        for (slong i = 0; i < S; i++) {
            fmpq_zero(&w);
            for (slong j = 0; j < S; j++) fmpq_addmul(&w, q->M[c] + i * S + j, sub + j);
            fmpq_mul(out + i, out + i, &w);
        }
    }
    for (slong i = 0; i < S; i++) fmpq_clear(sub + i);
    fmpq_clear(&w);
}

/* r of the tree (colour, forest ids) at the entries q. */
static void r_exact(fmpq_t r, const vigen_treeset *ts, int colour, const slong *ids, int k, const qtab *q, int alias)
{
    fmpq ph[S], sub[S], w;
    for (slong i = 0; i < S; i++) {
        fmpq_init(ph + i);
        fmpq_init(sub + i);
        fmpq_one(ph + i);
    }
    fmpq_init(&w);
    for (int d = 0; d < k; d++) {
        phi_stored(sub, ts, ids[d], q, alias);
        int c = alias ? 0 : ts->trees[ids[d]].colour;
        for (slong i = 0; i < S; i++) {
            fmpq_zero(&w);
            for (slong j = 0; j < S; j++) fmpq_addmul(&w, q->M[c] + i * S + j, sub + j);
            fmpq_mul(ph + i, ph + i, &w);
        }
    }
    int cb = alias ? 0 : colour;
    fmpq_zero(r);
    for (slong i = 0; i < S; i++) fmpq_addmul(r, q->b[cb] + i, ph + i);
    fmpq_set_si(&w, 1, vigen_forest_tree_gamma(ts, ids, k));
    fmpq_sub(r, r, &w);
    for (slong i = 0; i < S; i++) {
        fmpq_clear(ph + i);
        fmpq_clear(sub + i);
    }
    fmpq_clear(&w);
}

static void qtab_init(qtab *q)
{
    for (int c = 0; c < 2; c++) {
        for (int k = 0; k < S * S; k++) fmpq_init(q->M[c] + k);
        for (int k = 0; k < S; k++) fmpq_init(q->b[c] + k);
    }
}

static void qtab_clear(qtab *q)
{
    for (int c = 0; c < 2; c++) {
        for (int k = 0; k < S * S; k++) fmpq_clear(q->M[c] + k);
        for (int k = 0; k < S; k++) fmpq_clear(q->b[c] + k);
    }
}

/* x = mid + t rad, t = -1, 1 (corner) or a random multiple of 1/64 in [-1, 1] */
static void point(fmpq_t x, const fmpq_t mid, const fmpq_t rad, int corner, flint_rand_t st)
{
    fmpq_t t;
    fmpq_init(t);
    if (corner) fmpq_set_si(t, (n_randint(st, 2) ? 1 : -1), 1);
    else fmpq_set_si(t, (slong)n_randint(st, 129) - 64, 64);
    fmpq_mul(t, t, rad);
    fmpq_add(x, mid, t);
    fmpq_clear(t);
}

static void test_box(int alias, int zero_rad, flint_rand_t st)
{
    slong prec = 256;
    vigen_error err;
    vigen_error_init(&err);
    vigen_treeset ts;
    CHECK(vigen_treeset_init(&ts, MAXN - 1, &err) == VIGEN_OK);
    qtab mid, x;
    qtab_init(&mid);
    qtab_init(&x);
    fmpq_t rad, r;
    fmpq_init(rad);
    fmpq_init(r);
    fmpq_set_si(rad, zero_rad ? 0 : 1, 64);
    arb_mat_t M[2];
    arb_ptr b[2];
    for (int c = 0; c < 2; c++) {
        arb_mat_init(M[c], S, S);
        b[c] = _arb_vec_init(S);
        for (int k = 0; k < S * S + S; k++) {
            fmpq *m = k < S * S ? mid.M[c] + k : mid.b[c] + (k - S * S);
            fmpq_set_si(m, (slong)n_randint(st, 257) - 128, 128);
            arb_ptr e = k < S * S ? arb_mat_entry(M[c], k / S, k % S) : b[c] + (k - S * S);
            arb_set_fmpq(e, m, prec);
            mag_set_ui_2exp_si(arb_radref(e), zero_rad ? 0 : 1, -6);
        }
    }
    ctx_t cx;
    memset(&cx, 0, sizeof(cx));
    cx.s = S;
    cx.prec = prec;
    cx.A = M[0];
    cx.At = alias ? M[0] : M[1];
    cx.b = b[0];
    cx.bt = alias ? b[0] : b[1];
    chk_tree_encl *te = chk_tree_encl_new(&cx);
    arb_t enc, inv;
    arb_init(enc);
    arb_init(inv);
    slong trees = 0, points = 0;
    for (int n = 1; n <= MAXN; n++) {
        vigen_forest_iter it;
        vigen_forest_iter_init(&it, &ts, n - 1);
        while (vigen_forest_iter_next(&it)) {
            for (int colour = 0; colour < 2; colour++) {
                arb_one(inv);
                arb_div_ui(inv, inv, vigen_forest_tree_gamma(&ts, it.ids, it.k), prec);
                CHECK(chk_tree_enclose(enc, te, &ts, colour, it.ids, it.k, inv, 0) == 1);
                CHECK(arb_is_finite(enc));
                trees++;
                if (zero_rad) {
                    /* no box: r at the midpoints, to the working precision */
                    r_exact(r, &ts, colour, it.ids, it.k, &mid, alias);
                    CHECK(arb_contains_fmpq(enc, r));
                    CHECK(mag_cmp_2exp_si(arb_radref(enc), -200) < 0);
                    continue;
                }
                for (int p = 0; p < 24; p++) {
                    for (int c = 0; c < 2; c++) {
                        for (int k = 0; k < S * S; k++) point(x.M[c] + k, mid.M[c] + k, rad, p < 12, st);
                        for (int k = 0; k < S; k++) point(x.b[c] + k, mid.b[c] + k, rad, p < 12, st);
                    }
                    r_exact(r, &ts, colour, it.ids, it.k, &x, alias);
                    CHECK_MSG(arb_contains_fmpq(enc, r), "order %d colour %d alias %d point %d", n, colour, alias, p);
                    points++;
                }
            }
        }
        vigen_forest_iter_clear(&it);
    }
    /* every bicoloured tree up to order 5 (OEIS A038055: 2, 4, 14, 52, 214) */
    CHECK(trees == 286);
    CHECK(zero_rad || points == 24 * 286);
    chk_tree_encl_free(te);
    arb_clear(enc);
    arb_clear(inv);
    for (int c = 0; c < 2; c++) {
        arb_mat_clear(M[c]);
        _arb_vec_clear(b[c], S);
    }
    fmpq_clear(rad);
    fmpq_clear(r);
    qtab_clear(&mid);
    qtab_clear(&x);
    vigen_treeset_clear(&ts);
    vigen_error_clear(&err);
}

int main(void)
{
    flint_rand_t st;
    flint_randinit(st);
    for (int rep = 0; rep < 3; rep++) {
        test_box(0, 0, st);
        test_box(1, 0, st);
    }
    test_box(0, 1, st);
    test_box(1, 1, st);
    flint_randclear(st);
    TEST_MAIN_END();
}
