/* orders.c — the check of order conditions: every bicoloured tree up to order
 * P (general H, separable H, each part alone), walked over the forests of
 * trees.h with memoised vectors; for a symplectic tableau one or two trees
 * per class of reduction.c, the others inferred.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check/check_internal.h"
#include "support/strbuf.h"

/* the highest order whose conditions get the mean-value enclosure */
enum { CHK_MEANVALUE_MAX_ORDER = 8 };

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
    memset(o->inferred, 0, sizeof(o->inferred));
}

/* data: for a hold, it holds within the precision of the data; for an
 * undecided condition, the data are too short to decide it.  pos is the
 * tree's place in the enumeration of order n and first[2] the places of the
 * family's first failing and first undecided tree of order n (-1: none yet):
 * a tree decided in a second walk over the order (orders_complete) replaces
 * the one recorded when it comes first in the enumeration. */
static void orders_record(vigen_check_orders *o, int n, int status, int data, const vigen_treeset *ts, int colour,
                          const slong *ids, int k, const arb_t value, const arb_t expected, slong first[2], slong pos)
{
    o->count[n]++;
    if (status == HOLDS) {
        o->hold[n]++;
        o->hold_data[n] += data != 0;
        return;
    }
    int fails = status == FAILS;
    if (fails) o->fail[n]++;
    else {
        o->undecided[n]++;
        o->undecided_short[n] += data != 0;
    }
    int *order = fails ? &o->fail_order : &o->undecided_order;
    if (*order && !(*order == n && pos < first[!fails])) return;
    char **tree = fails ? &o->fail_tree : &o->undecided_tree;
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    chk_forest_tree_append(&sb, ts, colour, ids, k);
    free(*tree);
    *tree = sb.data;
    *order = n;
    first[!fails] = pos;
    arb_set(fails ? o->fail_value : o->undecided_value, value);
    arb_set(fails ? o->fail_expected : o->undecided_expected, expected);
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

/* What one walk over the conditions of an order needs: the tree table, the
 * memoised vectors, the sizes of terms, and which trees the reduction by
 * symplecticity (reduction.c) skips. */
typedef struct {
    vigen_check_report *rep;
    ctx_t *cx;
    int P;
    slong s, prec;
    vigen_treeset ts;
    const arb_mat_struct *M[2];
    arb_srcptr bh[2];
    slong nstore;
    arb_ptr *W;                  /* per stored tree u of order <= P - 2: w(u) = M_u Phi(u), or NULL
                                    until needed (orders_w) */
    double *Wa;                  /* the same on |entries|, once W[u] is set */
    arb_ptr prod, ones, y, phi, wphi;
    double *proda, *ya, *phia, *wphia, *Ma[2], *bha[2];
    ulong *sigma;                /* per stored tree: its symmetry */
    unsigned char *nys;          /* per stored tree: a Nystrom tree */
    arb_t val[2], r, inv, e;
    int need_ec;                 /* an error constant may need this order */
    chk_reduction red;
    int meanvalue;               /* tighten conditions on rounded data (enclose_tree.c) */
    chk_tree_encl *te;           /* created at the first such condition */
    arb_t tight;
    int clean[VIGEN_CHECK_FAMILIES];         /* no failing or undecided condition below this order */
    slong skipped[VIGEN_CHECK_FAMILIES];     /* conditions of this order not evaluated */
    slong bad_pos[VIGEN_CHECK_FAMILIES][2];  /* positions of the first failing, undecided tree of this order */
} orders_state;

enum { PASS_ALL, PASS_REPRESENTATIVES, PASS_REST };

/* Sets w(id) = M_c ph, ph = Phi of its forest, and its size from pha (NULL:
 * the empty forest). */
static void orders_w_set(orders_state *st, slong id, int c, arb_srcptr ph, const double *pha)
{
    slong s = st->s;
    st->W[id] = _arb_vec_init(s);
    for (slong i = 0; i < s; i++) {
        arb_dot(st->W[id] + i, NULL, 0, arb_mat_entry(st->M[c], i, 0), 1, ph, 1, s, st->prec);
        st->Wa[id * s + i] = 0;
        for (slong j = 0; j < s; j++) st->Wa[id * s + i] += st->Ma[c][i * s + j] * (pha ? pha[j] : 1);
    }
}

/* w(u), computed from its children when the walk over its order did not
 * (a tree whose conditions were all skipped); scratch row by order. */
static arb_srcptr orders_w(orders_state *st, slong u)
{
    if (st->W[u] != NULL) return st->W[u];
    slong s = st->s;
    const vigen_tree *t = st->ts.trees + u;
    const slong *ch = vigen_treeset_children(&st->ts, u);
    arb_ptr ph = st->wphi + t->order * s;
    double *pha = st->wphia + t->order * s;
    _arb_vec_set(ph, st->ones, s);
    for (slong i = 0; i < s; i++) pha[i] = 1;
    for (int q = 0; q < t->nchildren; q++) {
        arb_srcptr w = orders_w(st, ch[q]);
        for (slong i = 0; i < s; i++) {
            arb_mul(ph + i, ph + i, w + i, st->prec);
            pha[i] *= st->Wa[ch[q] * s + i];
        }
    }
    orders_w_set(st, u, t->colour, ph, pha);
    return st->W[u];
}

/* The smallest family that holds a tree: the lower-order conditions its
 * rerootings rest on are those of this family. */
static int tree_family(int colour, int flags)
{
    if (flags & VIGEN_TREE_MONO) return colour == VIGEN_TREE_BLACK ? VIGEN_CHECK_A_ALONE : VIGEN_CHECK_AT_ALONE;
    return (flags & VIGEN_TREE_SEPARABLE) ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_GENERAL;
}

/* Decides the condition of the tree (colour c, forest ids) of order n, its
 * value st->val[c] and the size of its terms vabs, and files it in every
 * family it belongs to; pos is its place in the enumeration. */
static void orders_condition(orders_state *st, int n, int c, const slong *ids, int k, ulong gamma, ulong sg,
                             int flags, int ny, double vabs, slong pos)
{
    vigen_check_report *rep = st->rep;
    ctx_t *cx = st->cx;
    slong prec = st->prec;
    arb_sub(st->r, st->val[c], st->inv, prec);
    /* a monochromatic tree involves one part only */
    int exact = (flags & VIGEN_TREE_MONO) ? cx->ex->part[c] : cx->ex->part[0] && cx->ex->part[1];
    /* the scale: sum of |terms| + 1/gamma, rounded up generously */
    mag_t sc;
    mag_init(sc);
    mag_set_d(sc, (vabs + 1.0 / (double)gamma) * (1 + 1e-9));
    /* a ball containing 0 on rounded data: plain ball arithmetic may
     * overestimate the range; both enclosures hold, so their intersection.
     * When the plain ball already holds within the data, only an enclosure
     * that may exclude 0 can change the verdict. */
    /* up to the default --max-order: beyond it the conditions are millions
     * (order 12: 10^7 trees) and each enclosure walks its tree */
    if (!exact && st->meanvalue && n <= CHK_MEANVALUE_MAX_ORDER && arb_is_finite(st->r) && arb_contains_zero(st->r)) {
        if (st->te == NULL) st->te = chk_tree_encl_new(cx);
        mag_t thr;
        mag_init(thr);
        mag_mul_2exp_si(thr, sc, -VIGEN_CHECK_DATA_BITS);
        int tight = mag_cmp(arb_radref(st->r), thr) <= 0;
        mag_clear(thr);
        if (chk_tree_enclose(st->tight, st->te, &st->ts, c, ids, k, st->inv, tight) && arb_is_finite(st->tight) &&
            arb_intersection(st->r, st->r, st->tight, prec))
            arb_add(st->val[c], st->r, st->inv, prec);
    }
    /* the principal error coefficient (Phi - 1/gamma)/sigma, squared */
    if (st->need_ec) {
        arb_div_ui(st->e, st->r, sg, prec);
        arb_sqr(st->e, st->e, prec);
        arb_add(rep->error_constant[VIGEN_CHECK_EC_GENERAL].sumsq[n], rep->error_constant[VIGEN_CHECK_EC_GENERAL].sumsq[n],
                st->e, prec);
        if (flags & VIGEN_TREE_SEPARABLE)
            arb_add(rep->error_constant[VIGEN_CHECK_EC_SEPARABLE].sumsq[n],
                    rep->error_constant[VIGEN_CHECK_EC_SEPARABLE].sumsq[n], st->e, prec);
        if (ny)
            arb_add(rep->error_constant[VIGEN_CHECK_EC_NYSTROM].sumsq[n],
                    rep->error_constant[VIGEN_CHECK_EC_NYSTROM].sumsq[n], st->e, prec);
    }
    chk_ctx_shape(cx, n, gamma, n, pos / 2, c);   /* b Phi has n factors; 1/gamma */
    int v = chk_decide(cx, st->r, exact, sc);
    mag_clear(sc);
    int data = v == HOLDS ? cx->last_within : cx->last_short;
    int fam[4], nf = 0;
    fam[nf++] = VIGEN_CHECK_GENERAL;
    if (flags & VIGEN_TREE_SEPARABLE) fam[nf++] = VIGEN_CHECK_SEPARABLE;
    if (flags & VIGEN_TREE_MONO) fam[nf++] = c == VIGEN_TREE_BLACK ? VIGEN_CHECK_A_ALONE : VIGEN_CHECK_AT_ALONE;
    if (ny) fam[nf++] = VIGEN_CHECK_NYSTROM;
    for (int q = 0; q < nf; q++)
        orders_record(&st->rep->orders[fam[q]], n, v, data, &st->ts, c, ids, k, st->val[c], st->inv,
                      st->bad_pos[fam[q]], pos);
}

/* One walk over the trees of order n (the forests of order n - 1, each with
 * a black and a white root): PASS_ALL decides every condition;
 * PASS_REPRESENTATIVES those the reduction keeps, counting the others into
 * st->skipped; PASS_REST those it skipped.  The vectors w of the trees of
 * order n whose forest product is computed are kept; the others are computed
 * when needed. */
static void orders_walk(orders_state *st, int n, int pass)
{
    slong s = st->s, prec = st->prec;
    const vigen_treeset *ts = &st->ts;
    int P = st->P;
    slong valid = 0;             /* st->prod holds the partial products of positions 0 .. valid-1 */
    vigen_forest_iter it;
    vigen_forest_iter_init(&it, ts, n - 1);
    while (vigen_forest_iter_next(&it)) {
        int k = it.k;
        const slong *ids = it.ids;
        if (it.changed < valid) valid = it.changed;
        int flags[2], ny[2], eval[2];
        for (int c = 0; c < 2; c++) {
            flags[c] = vigen_forest_tree_flags(ts, c, ids, k);
            ny[c] = forest_nystrom(ts, st->nys, c, ids, k);
            int skip = 0;
            if (pass != PASS_ALL && !ny[c] && chk_reduction_skips(&st->red, ts, n, c, ids, k))
                skip = st->clean[tree_family(c, flags[c])];
            eval[c] = pass == PASS_ALL || (pass == PASS_REPRESENTATIVES ? !skip : skip);
            if (pass == PASS_REPRESENTATIVES && skip) {
                st->skipped[VIGEN_CHECK_GENERAL]++;
                if (flags[c] & VIGEN_TREE_SEPARABLE) st->skipped[VIGEN_CHECK_SEPARABLE]++;
                if (flags[c] & VIGEN_TREE_MONO)
                    st->skipped[c == VIGEN_TREE_BLACK ? VIGEN_CHECK_A_ALONE : VIGEN_CHECK_AT_ALONE]++;
            }
        }
        if (!eval[0] && !eval[1]) continue;
        double vabs[2] = {0, 0};
        if (k == 1 && ts->trees[ids[0]].order > P - 2) {
            /* a single child u of order P - 1: y . Phi(u), y = bhat^T M_u */
            slong u = ids[0];
            const vigen_tree *tu = ts->trees + u;
            const slong *ch = vigen_treeset_children(ts, u);
            _arb_vec_set(st->phi, st->ones, s);
            for (int q = 0; q < tu->nchildren; q++) {
                arb_srcptr w = orders_w(st, ch[q]);
                for (slong i = 0; i < s; i++) arb_mul(st->phi + i, st->phi + i, w + i, prec);
            }
            for (int c = 0; c < 2; c++)
                if (eval[c]) arb_dot(st->val[c], NULL, 0, st->y + (2 * c + tu->colour) * s, 1, st->phi, 1, s, prec);
            for (slong i = 0; i < s; i++) {
                st->phia[i] = 1;
                for (int q = 0; q < tu->nchildren; q++) st->phia[i] *= st->Wa[ch[q] * s + i];
                for (int c = 0; c < 2; c++) vabs[c] += st->ya[(2 * c + tu->colour) * s + i] * st->phia[i];
            }
        } else {
            for (int d = valid; d < k; d++) {
                arb_srcptr wd = orders_w(st, ids[d]);
                if (d == 0) _arb_vec_set(st->prod, wd, s);
                else
                    for (slong i = 0; i < s; i++) arb_mul(st->prod + d * s + i, st->prod + (d - 1) * s + i, wd + i, prec);
                for (slong i = 0; i < s; i++)
                    st->proda[d * s + i] = (d ? st->proda[(d - 1) * s + i] : 1) * st->Wa[ids[d] * s + i];
            }
            valid = k;
            arb_srcptr ph = k ? st->prod + (k - 1) * s : st->ones;
            const double *pha = k ? st->proda + (k - 1) * s : NULL;
            for (int c = 0; c < 2; c++)
                if (eval[c]) arb_dot(st->val[c], NULL, 0, st->bh[c], 1, ph, 1, s, prec);
            for (slong i = 0; i < s; i++)
                for (int c = 0; c < 2; c++) vabs[c] += st->bha[c][i] * (pha ? pha[i] : 1);
            if (n <= P - 2)
                for (int c = 0; c < 2; c++) {
                    slong id = ts->start[n] + 2 * it.index + c;
                    if (st->W[id] == NULL) orders_w_set(st, id, c, ph, pha);
                }
        }
        ulong gamma = vigen_forest_tree_gamma(ts, ids, k);
        arb_one(st->inv);
        arb_div_ui(st->inv, st->inv, gamma, prec);
        ulong sg = forest_sigma(st->sigma, ids, k);
        for (int c = 0; c < 2; c++)
            if (eval[c]) orders_condition(st, n, c, ids, k, gamma, sg, flags[c], ny[c], vabs[c], 2 * it.index + c);
    }
    vigen_forest_iter_clear(&it);
}

/* After the representatives of order n: when a family that held below n
 * fails or is undecided at n and some of its conditions were skipped, the
 * skipped ones are decided too (the counts, the first bad tree and the error
 * constants need every condition of that order); otherwise they hold, as the
 * evaluated ones of their class do, and are counted as inferred. */
static void orders_complete(orders_state *st, int n)
{
    vigen_check_report *rep = st->rep;
    int rest = 0;
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        const vigen_check_orders *o = &rep->orders[f];
        rest |= st->skipped[f] > 0 && st->clean[f] && (o->fail[n] > 0 || o->undecided[n] > 0);
    }
    if (rest) {
        orders_walk(st, n, PASS_REST);
        return;
    }
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        vigen_check_orders *o = &rep->orders[f];
        o->count[n] += st->skipped[f];
        o->hold[n] += st->skipped[f];
        o->inferred[n] += st->skipped[f];
        if (st->red.within_data) o->hold_data[n] += st->skipped[f];
    }
}

static void orders_state_clear(orders_state *st)
{
    for (slong u = 0; u < st->nstore; u++)
        if (st->W[u] != NULL) _arb_vec_clear(st->W[u], st->s);
    flint_free(st->W);
    flint_free(st->Wa);
    flint_free(st->wphia);
    _arb_vec_clear(st->wphi, (st->P + 1) * st->s);
    flint_free(st->proda);
    flint_free(st->ya);
    flint_free(st->phia);
    for (int c = 0; c < 2; c++) {
        flint_free(st->Ma[c]);
        flint_free(st->bha[c]);
        arb_clear(st->val[c]);
    }
    flint_free(st->sigma);
    flint_free(st->nys);
    arb_clear(st->r);
    arb_clear(st->inv);
    arb_clear(st->e);
    _arb_vec_clear(st->prod, st->P * st->s);
    _arb_vec_clear(st->ones, st->s);
    _arb_vec_clear(st->y, 4 * st->s);
    _arb_vec_clear(st->phi, st->s);
    arb_clear(st->tight);
    chk_tree_encl_free(st->te);
    vigen_treeset_clear(&st->ts);
}

/* The vectors and tables of the walk; the tree table up to order P - 1. */
static int orders_state_init(orders_state *st, chk_round *rd, vigen_error *err)
{
    memset(st, 0, sizeof(*st));
    int rc = vigen_treeset_init(&st->ts, rd->P - 1, err);
    if (rc != VIGEN_OK) return rc;
    ctx_t *cx = rd->cx;
    slong s = cx->s, P = rd->P;
    st->rep = rd->rep;
    st->cx = cx;
    st->P = rd->P;
    st->s = s;
    st->prec = cx->prec;
    st->M[0] = cx->A;
    st->M[1] = cx->At;
    st->bh[0] = cx->b;
    st->bh[1] = cx->bt;
    st->nstore = P >= 3 ? st->ts.start[P - 1] : 0;
    slong nw = (st->nstore > 0 ? st->nstore : 1) * s;
    st->W = flint_calloc((size_t)(st->nstore > 0 ? st->nstore : 1), sizeof(arb_ptr));
    st->wphi = _arb_vec_init((P + 1) * s);
    st->wphia = flint_calloc((size_t)((P + 1) * s), sizeof(double));
    st->prod = _arb_vec_init(P * s);
    st->ones = _arb_vec_init(s);
    st->y = _arb_vec_init(4 * s);
    st->phi = _arb_vec_init(s);
    /* the same recursion on |entries| (midpoints, doubles): the size of the
     * terms of each condition, its scale, as sum |terms| + |constant| like
     * every other condition of the checker */
    st->Wa = flint_calloc((size_t)nw, sizeof(double));
    st->proda = flint_calloc((size_t)(P * s), sizeof(double));
    st->ya = flint_calloc((size_t)(4 * s), sizeof(double));
    st->phia = flint_calloc((size_t)s, sizeof(double));
    for (int c = 0; c < 2; c++) {
        st->Ma[c] = flint_malloc(sizeof(double) * (size_t)(s * s));
        st->bha[c] = flint_malloc(sizeof(double) * (size_t)s);
        arb_init(st->val[c]);
        for (slong i = 0; i < s; i++) {
            st->bha[c][i] = fabs(arf_get_d(arb_midref(st->bh[c] + i), ARF_RND_UP));
            for (slong j = 0; j < s; j++)
                st->Ma[c][i * s + j] = fabs(arf_get_d(arb_midref(arb_mat_entry(st->M[c], i, j)), ARF_RND_UP));
        }
    }
    for (int c = 0; c < 2; c++)
        for (int col = 0; col < 2; col++)
            for (slong j = 0; j < s; j++) {
                arb_ptr yj = st->y + (2 * c + col) * s + j;
                arb_zero(yj);
                for (slong i = 0; i < s; i++) {
                    arb_addmul(yj, st->bh[c] + i, arb_mat_entry(st->M[col], i, j), st->prec);
                    st->ya[(2 * c + col) * s + j] += st->bha[c][i] * st->Ma[col][i * s + j];
                }
            }
    arb_init(st->r);
    arb_init(st->inv);
    arb_init(st->e);
    for (slong i = 0; i < s; i++) arb_one(st->ones + i);
    slong nst = st->ts.n > 0 ? st->ts.n : 1;
    st->sigma = flint_malloc(sizeof(ulong) * (size_t)nst);
    st->nys = flint_malloc((size_t)nst);
    for (slong u = 0; u < st->ts.n; u++) {
        const vigen_tree *tu = st->ts.trees + u;
        st->sigma[u] = forest_sigma(st->sigma, vigen_treeset_children(&st->ts, u), tu->nchildren);
        st->nys[u] = forest_nystrom(&st->ts, st->nys, tu->colour, vigen_treeset_children(&st->ts, u), tu->nchildren);
    }
    chk_reduction_init(&st->red, rd->rep, cx);
    arb_init(st->tight);
    /* plain ball arithmetic only: for comparing verdicts with and without */
    const char *off = getenv("VIGEN_CHECK_NO_MEANVALUE");
    st->meanvalue = off == NULL || *off == '\0' || *off == '0';
    return VIGEN_OK;
}

/* Every order condition of order 1..P.  Phi(F) of a forest F is the
 * componentwise product over its trees u of w(u) = M_u Phi(u) (M = A for a
 * black u, At for a white one); the condition of (colour, F) is
 * bhat . Phi(F) = 1/gamma.  w is stored for trees of order <= P - 2 (the
 * children of every tree of order <= P); for a tree u of order P - 1, which
 * occurs only as the single child of a tree of order P, the condition is
 * y . Phi(u) with the precomputed row vector y = bhat^T M_u.  For a
 * symplectic tableau only representatives of the classes of reduction.c are
 * decided while every condition below holds. */
int chk_orders(chk_round *rd, vigen_error *err)
{
    vigen_check_report *rep = rd->rep;
    orders_state st;
    int rc = orders_state_init(&st, rd, err);
    if (rc != VIGEN_OK) return rc;
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) orders_reset(&rep->orders[f]);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++)
        for (int n = 0; n <= VIGEN_TREE_MAX_ORDER; n++) arb_zero(rep->error_constant[f].sumsq[n]);
    rd->cx->section = VIGEN_CHECK_SECT_ORDER;

    static const int ec_family[VIGEN_CHECK_EC_FAMILIES] = {VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE,
                                                           VIGEN_CHECK_NYSTROM};
    for (int n = 1; n <= rd->P; n++) {
        /* the error constant of a family is needed at order p + 1 only: not
         * above an order where the family already fails or is undecided */
        st.need_ec = 0;
        for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
            const vigen_check_orders *o = &rep->orders[ec_family[f]];
            st.need_ec |= o->fail_order == 0 && o->undecided_order == 0;
        }
        for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
            const vigen_check_orders *o = &rep->orders[f];
            st.clean[f] = o->fail_order == 0 && o->undecided_order == 0;
            st.skipped[f] = 0;
            st.bad_pos[f][0] = st.bad_pos[f][1] = -1;
        }
        if (st.red.on) {
            orders_walk(&st, n, PASS_REPRESENTATIVES);
            orders_complete(&st, n);
        } else
            orders_walk(&st, n, PASS_ALL);
        int all_failed = 1;
        for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
            rep->orders[f].evaluated_to = n;
            all_failed &= rep->orders[f].fail_order != 0;
        }
        if (all_failed) break;   /* nothing above can change any order */
    }
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) orders_finish(&rep->orders[f], rd->P);
    orders_state_clear(&st);
    return VIGEN_OK;
}
