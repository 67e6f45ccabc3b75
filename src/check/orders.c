/* orders.c — the check of order conditions: every bicoloured tree up to order
 * P (general H, separable H, each part alone), walked over the forests of
 * trees.h with memoised vectors.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check/check_internal.h"

static void orders_reset(vigen_check_orders *o)
{
    free(o->fail_tree);
    free(o->undecided_tree);
    o->fail_tree = o->undecided_tree = NULL;
    o->fail_order = o->undecided_order = 0;
    o->evaluated_to = 0;
    memset(&o->level, 0, sizeof(o->level));
    memset(o->count, 0, sizeof(o->count));
    memset(o->hold, 0, sizeof(o->hold));
    memset(o->fail, 0, sizeof(o->fail));
    memset(o->undecided, 0, sizeof(o->undecided));
    memset(o->hold_data, 0, sizeof(o->hold_data));
    memset(o->undecided_short, 0, sizeof(o->undecided_short));
}

/* data: for a hold, it holds within the precision of the data; for an
 * undecided condition, the data are too short to decide it. */
static void orders_record(vigen_check_orders *o, int n, int status, int data, const vigen_treeset *ts, int colour,
                          const slong *ids, int k, const arb_t value, const arb_t expected)
{
    o->count[n]++;
    if (status == HOLDS) {
        o->hold[n]++;
        o->hold_data[n] += data != 0;
        return;
    }
    vigen_strbuf sb;
    if (status == FAILS) {
        o->fail[n]++;
        if (o->fail_order) return;
        o->fail_order = n;
        vigen_strbuf_init(&sb);
        vigen_forest_tree_append(&sb, ts, colour, ids, k);
        o->fail_tree = sb.data;
        arb_set(o->fail_value, value);
        arb_set(o->fail_expected, expected);
    } else {
        o->undecided[n]++;
        o->undecided_short[n] += data != 0;
        if (o->undecided_order) return;
        o->undecided_order = n;
        vigen_strbuf_init(&sb);
        vigen_forest_tree_append(&sb, ts, colour, ids, k);
        o->undecided_tree = sb.data;
        arb_set(o->undecided_value, value);
        arb_set(o->undecided_expected, expected);
    }
}

static void orders_finish(vigen_check_orders *o, int P)
{
    int bad = 0;
    if (o->fail_order) bad = o->fail_order;
    if (o->undecided_order && (!bad || o->undecided_order < bad)) bad = o->undecided_order;
    if (!bad) {
        o->level.value = P;
        o->level.capped = 1;
        o->level.undecided = 0;
    } else {
        o->level.value = bad - 1;
        o->level.capped = 0;
        o->level.undecided = o->fail_order != bad;
    }
    /* the level rests on every condition up to it */
    o->level.within_data = 0;
    for (int n = 1; n <= o->level.value && n <= VIGEN_TREE_MAX_ORDER; n++) o->level.within_data |= o->hold_data[n] > 0;
    o->level.too_short = o->level.undecided && o->undecided[bad] > 0 && o->undecided_short[bad] == o->undecided[bad];
}

/* sigma of a tree whose children are ids[0..k-1] (nonincreasing): the order
 * of its symmetry group, prod over distinct children u of m_u! sigma(u)^m_u
 * (HLW GNI sec. III.1.2); at most (n - 1)! for order n <= 12. */
static ulong forest_sigma(const ulong *sigma, const slong *ids, int k)
{
    ulong g = 1;
    for (int d = 0; d < k;) {
        int m = 1;
        while (d + m < k && ids[d + m] == ids[d]) m++;
        for (int q = 1; q <= m; q++) g *= (ulong)q * sigma[ids[d]];
        d += m;
    }
    return g;
}

/* A Nystrom tree (H = p^T M^-1 p / 2 + V(q)): alternating, and a black vertex
 * (dH/dp, linear in p: its second and higher derivatives vanish) has at most
 * one child, white; a white vertex (-dV/dq, a function of q only) has black
 * children only.  The elementary differentials of the other trees vanish. */
static int forest_nystrom(const vigen_treeset *ts, const unsigned char *nys, int colour, const slong *ids, int k)
{
    if (colour == VIGEN_TREE_BLACK && k > 1) return 0;
    for (int d = 0; d < k; d++)
        if (!nys[ids[d]] || ts->trees[ids[d]].colour == colour) return 0;
    return 1;
}

/* Every order condition of order 1..P.  Phi(F) of a forest F is the
 * componentwise product over its trees u of w(u) = M_u Phi(u) (M = A for a
 * black u, At for a white one); the condition of (colour, F) is
 * bhat . Phi(F) = 1/gamma.  w is stored for trees of order <= P - 2 (the
 * children of every tree of order <= P); for a tree u of order P - 1, which
 * occurs only as the single child of a tree of order P, the condition is
 * y . Phi(u) with the precomputed row vector y = bhat^T M_u. */
int chk_orders(chk_round *rd, vigen_error *err)
{
    vigen_check_report *rep = rd->rep;
    ctx_t *cx = rd->cx;
    int P = rd->P;
    vigen_treeset ts;
    int rc = vigen_treeset_init(&ts, P - 1, err);
    if (rc != VIGEN_OK) return rc;
    slong s = cx->s, prec = cx->prec;
    const arb_mat_struct *M[2] = {cx->A, cx->At};
    arb_srcptr bh[2] = {cx->b, cx->bt};
    slong nstore = P >= 3 ? ts.start[P - 1] : 0;
    arb_ptr W = _arb_vec_init((nstore > 0 ? nstore : 1) * s);
    arb_ptr prod = _arb_vec_init(P * s);
    arb_ptr ones = _arb_vec_init(s);
    arb_ptr y = _arb_vec_init(4 * s);
    arb_ptr phi = _arb_vec_init(s);
    /* the same recursion on |entries| (midpoints, doubles): the size of the
     * terms of each condition, its scale, as sum |terms| + |constant| like
     * every other condition of the checker */
    double *Wa = flint_calloc((size_t)((nstore > 0 ? nstore : 1) * s), sizeof(double));
    double *proda = flint_calloc((size_t)(P * s), sizeof(double));
    double *ya = flint_calloc((size_t)(4 * s), sizeof(double));
    double *phia = flint_calloc((size_t)s, sizeof(double));
    double *Ma[2], *bha[2];
    for (int c = 0; c < 2; c++) {
        Ma[c] = flint_malloc(sizeof(double) * (size_t)(s * s));
        bha[c] = flint_malloc(sizeof(double) * (size_t)s);
        for (slong i = 0; i < s; i++) {
            bha[c][i] = fabs(arf_get_d(arb_midref(bh[c] + i), ARF_RND_UP));
            for (slong j = 0; j < s; j++)
                Ma[c][i * s + j] = fabs(arf_get_d(arb_midref(arb_mat_entry(M[c], i, j)), ARF_RND_UP));
        }
    }
    for (int c = 0; c < 2; c++)
        for (int col = 0; col < 2; col++)
            for (slong j = 0; j < s; j++)
                for (slong i = 0; i < s; i++) ya[(2 * c + col) * s + j] += bha[c][i] * Ma[col][i * s + j];
    arb_t v, r, inv;
    arb_init(v);
    arb_init(r);
    arb_init(inv);
    for (slong i = 0; i < s; i++) arb_one(ones + i);
    for (int c = 0; c < 2; c++)
        for (int col = 0; col < 2; col++)
            for (slong j = 0; j < s; j++) {
                arb_ptr yj = y + (2 * c + col) * s + j;
                arb_zero(yj);
                for (slong i = 0; i < s; i++) arb_addmul(yj, bh[c] + i, arb_mat_entry(M[col], i, j), prec);
            }

    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) orders_reset(&rep->orders[f]);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++)
        for (int n = 0; n <= VIGEN_TREE_MAX_ORDER; n++) arb_zero(rep->error_constant[f].sumsq[n]);
    /* per stored tree: sigma (its symmetry) and whether it is a Nystrom tree */
    slong nst = ts.n > 0 ? ts.n : 1;
    ulong *sigma = flint_malloc(sizeof(ulong) * (size_t)nst);
    unsigned char *nys = flint_malloc((size_t)nst);
    for (slong u = 0; u < ts.n; u++) {
        const vigen_tree *tu = ts.trees + u;
        sigma[u] = forest_sigma(sigma, vigen_treeset_children(&ts, u), tu->nchildren);
        nys[u] = forest_nystrom(&ts, nys, tu->colour, vigen_treeset_children(&ts, u), tu->nchildren);
    }
    arb_t e;
    arb_init(e);
    cx->section = VIGEN_CHECK_SECT_ORDER;

    static const int ec_family[VIGEN_CHECK_EC_FAMILIES] = {VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE,
                                                           VIGEN_CHECK_NYSTROM};
    for (int n = 1; n <= P; n++) {
        /* the error constant of a family is needed at order p + 1 only: not
         * above an order where the family already fails or is undecided */
        int need_ec = 0;
        for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
            const vigen_check_orders *o = &rep->orders[ec_family[f]];
            need_ec |= o->fail_order == 0 && o->undecided_order == 0;
        }
        vigen_forest_iter it;
        vigen_forest_iter_init(&it, &ts, n - 1);
        while (vigen_forest_iter_next(&it)) {
            int k = it.k;
            const slong *ids = it.ids;
            arb_t val[2];
            double vabs[2] = {0, 0};
            arb_init(val[0]);
            arb_init(val[1]);
            if (k == 1 && ts.trees[ids[0]].order > P - 2) {
                slong u = ids[0];
                const vigen_tree *tu = ts.trees + u;
                const slong *ch = vigen_treeset_children(&ts, u);
                _arb_vec_set(phi, ones, s);
                for (int q = 0; q < tu->nchildren; q++)
                    for (slong i = 0; i < s; i++) arb_mul(phi + i, phi + i, W + ch[q] * s + i, prec);
                for (int c = 0; c < 2; c++)
                    arb_dot(val[c], NULL, 0, y + (2 * c + tu->colour) * s, 1, phi, 1, s, prec);
                for (slong i = 0; i < s; i++) {
                    phia[i] = 1;
                    for (int q = 0; q < tu->nchildren; q++) phia[i] *= Wa[ch[q] * s + i];
                    for (int c = 0; c < 2; c++) vabs[c] += ya[(2 * c + tu->colour) * s + i] * phia[i];
                }
            } else {
                for (int d = it.changed; d < k; d++) {
                    arb_srcptr wd = W + ids[d] * s;
                    if (d == 0) _arb_vec_set(prod, wd, s);
                    else
                        for (slong i = 0; i < s; i++) arb_mul(prod + d * s + i, prod + (d - 1) * s + i, wd + i, prec);
                    for (slong i = 0; i < s; i++)
                        proda[d * s + i] = (d ? proda[(d - 1) * s + i] : 1) * Wa[ids[d] * s + i];
                }
                arb_srcptr ph = k ? prod + (k - 1) * s : ones;
                for (int c = 0; c < 2; c++) arb_dot(val[c], NULL, 0, bh[c], 1, ph, 1, s, prec);
                for (slong i = 0; i < s; i++)
                    for (int c = 0; c < 2; c++) vabs[c] += bha[c][i] * (k ? proda[(k - 1) * s + i] : 1);
                if (n <= P - 2)
                    for (int c = 0; c < 2; c++) {
                        slong id = ts.start[n] + 2 * it.index + c;
                        for (slong i = 0; i < s; i++) {
                            arb_dot(W + id * s + i, NULL, 0, arb_mat_entry(M[c], i, 0), 1, ph, 1, s, prec);
                            Wa[id * s + i] = 0;
                            for (slong j = 0; j < s; j++)
                                Wa[id * s + i] += Ma[c][i * s + j] * (k ? proda[(k - 1) * s + j] : 1);
                        }
                    }
            }
            ulong gamma = vigen_forest_tree_gamma(&ts, ids, k);
            arb_one(inv);
            arb_div_ui(inv, inv, gamma, prec);
            ulong sg = forest_sigma(sigma, ids, k);
            for (int c = 0; c < 2; c++) {
                arb_sub(r, val[c], inv, prec);
                int flags = vigen_forest_tree_flags(&ts, c, ids, k);
                int ny = forest_nystrom(&ts, nys, c, ids, k);
                /* the principal error coefficient (Phi - 1/gamma)/sigma, squared */
                if (need_ec) {
                    arb_div_ui(e, r, sg, prec);
                    arb_sqr(e, e, prec);
                    arb_add(rep->error_constant[VIGEN_CHECK_EC_GENERAL].sumsq[n],
                            rep->error_constant[VIGEN_CHECK_EC_GENERAL].sumsq[n], e, prec);
                    if (flags & VIGEN_TREE_SEPARABLE)
                        arb_add(rep->error_constant[VIGEN_CHECK_EC_SEPARABLE].sumsq[n],
                                rep->error_constant[VIGEN_CHECK_EC_SEPARABLE].sumsq[n], e, prec);
                    if (ny)
                        arb_add(rep->error_constant[VIGEN_CHECK_EC_NYSTROM].sumsq[n],
                                rep->error_constant[VIGEN_CHECK_EC_NYSTROM].sumsq[n], e, prec);
                }
                /* a monochromatic tree involves one part only */
                int exact = (flags & VIGEN_TREE_MONO) ? cx->ex->part[c] : cx->ex->part[0] && cx->ex->part[1];
                chk_ctx_shape(cx, n, gamma, n, it.index, c);   /* b Phi has n factors; 1/gamma */
                /* the scale: sum of |terms| + 1/gamma, rounded up generously */
                mag_t sc;
                mag_init(sc);
                mag_set_d(sc, (vabs[c] + 1.0 / (double)gamma) * (1 + 1e-9));
                int st = chk_decide(cx, r, exact, sc);
                mag_clear(sc);
                int data = st == HOLDS ? cx->last_within : cx->last_short;
                orders_record(&rep->orders[VIGEN_CHECK_GENERAL], n, st, data, &ts, c, ids, k, val[c], inv);
                if (flags & VIGEN_TREE_SEPARABLE)
                    orders_record(&rep->orders[VIGEN_CHECK_SEPARABLE], n, st, data, &ts, c, ids, k, val[c], inv);
                if (flags & VIGEN_TREE_MONO)
                    orders_record(&rep->orders[c == VIGEN_TREE_BLACK ? VIGEN_CHECK_A_ALONE : VIGEN_CHECK_AT_ALONE],
                                  n, st, data, &ts, c, ids, k, val[c], inv);
                if (ny) orders_record(&rep->orders[VIGEN_CHECK_NYSTROM], n, st, data, &ts, c, ids, k, val[c], inv);
            }
            arb_clear(val[0]);
            arb_clear(val[1]);
        }
        vigen_forest_iter_clear(&it);
        int all_failed = 1;
        for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
            rep->orders[f].evaluated_to = n;
            all_failed &= rep->orders[f].fail_order != 0;
        }
        if (all_failed) break;   /* nothing above can change any order */
    }
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) orders_finish(&rep->orders[f], P);

    arb_clear(e);
    flint_free(Wa);
    flint_free(proda);
    flint_free(ya);
    flint_free(phia);
    for (int c = 0; c < 2; c++) {
        flint_free(Ma[c]);
        flint_free(bha[c]);
    }
    flint_free(sigma);
    flint_free(nys);
    arb_clear(v);
    arb_clear(r);
    arb_clear(inv);
    _arb_vec_clear(W, (nstore > 0 ? nstore : 1) * s);
    _arb_vec_clear(prod, P * s);
    _arb_vec_clear(ones, s);
    _arb_vec_clear(y, 4 * s);
    _arb_vec_clear(phi, s);
    vigen_treeset_clear(&ts);
    return VIGEN_OK;
}

