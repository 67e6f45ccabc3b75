/* enclose_tree.c — a tight enclosure of one tree condition over the balls of
 * rounded entries: the mean-value form with the condition's gradient.
 *
 * r(t) = bhat . Phi(t) - 1/gamma(t) is a polynomial in the entries u of A, At,
 * b, bt (c does not occur).  Plain ball arithmetic lets every occurrence of an
 * entry vary on its own and adds |terms| where the terms of dr/du cancel, so
 * its ball can contain 0 when no tableau inside the balls satisfies the
 * condition.  Over the box mid_u +- rad_u,
 *   r in r(mid) +- ( sum_u |dr/du (mid)| rad_u + R2 ),
 *   R2 = P(|mid| + rad) - P(|mid|) - sum_u rad_u dP/du (|mid|),
 * P the same expression with every entry replaced by its absolute value: for a
 * monomial of n factors, |prod(m_i + d_i) - prod m_i - sum_i d_i prod_{j != i}
 * m_j| <= sum over subsets S, |S| >= 2, of prod_S r_i prod_{not S} |m_j|, and
 * the sums of products of the condition expand into such monomials with
 * coefficients +1.  Computed by direct recursion over the tree, O(|t| s^2):
 *   r(mid) in arb at the working precision, entries the exact midpoints;
 *   dr/du by reverse mode (adjoints from the root to the leaves) in arb at
 *   CHK_TREE_GRAD_PREC bits, then upper bounds of |dr/du| rad_u;
 *   R2 by truncated forward mode on |mid| + eps rad in mag_t (rounded up),
 *   each quantity as (order 0, order 1, orders >= 2 summed at eps = 1).
 */
#include <string.h>
#include "check/check_internal.h"

#define CHK_TREE_GRAD_PREC 64

/* One vertex of the tree being enclosed, in preorder (children after their
 * parent): its colour, its first child and next sibling (-1: none). */
typedef struct {
    int colour;
    int child, sibling;
} tvertex;

#define NV (VIGEN_TREE_MAX_ORDER + 1)

struct chk_tree_encl {
    slong s, prec;
    /* entry slots: 0 for A / b, 1 for At / bt when the tableau gives them apart */
    int mslot[2], bslot[2];
    arb_mat_t Mp[2], Mg[2];      /* midpoints, at prec and at CHK_TREE_GRAD_PREC */
    arb_ptr bp[2], bg[2];
    mag_struct *Mabs[2], *Mrad[2], *babs[2], *brad[2];
    arb_ptr gM[2], gb[2];        /* the gradient, per slot */
    tvertex v[NV];
    int nv;
    /* per vertex: Phi and w = M Phi at prec, at the gradient's precision, and
     * as triples on |entries|; the adjoint of Phi */
    arb_ptr phip[NV], wp[NV], phig[NV], wg[NV], phibar[NV];
    mag_struct *phia[NV][3], *wa[NV][3];
    arb_ptr wbar, tmp;
    mag_t m, t;
};

static void vertices_add(chk_tree_encl *te, const vigen_treeset *ts, int parent, int colour, const slong *ids, int k)
{
    int me = te->nv++;
    te->v[me].colour = colour;
    te->v[me].child = -1;
    te->v[me].sibling = -1;
    if (parent >= 0) {
        te->v[me].sibling = te->v[parent].child;
        te->v[parent].child = me;
    }
    for (int q = 0; q < k; q++) {
        const vigen_tree *u = ts->trees + ids[q];
        vertices_add(te, ts, me, u->colour, vigen_treeset_children(ts, ids[q]), u->nchildren);
    }
}

chk_tree_encl *chk_tree_encl_new(const ctx_t *cx)
{
    chk_tree_encl *te = flint_calloc(1, sizeof(*te));
    slong s = cx->s;
    te->s = s;
    te->prec = cx->prec;
    const arb_mat_struct *M[2] = {cx->A, cx->At};
    arb_srcptr b[2] = {cx->b, cx->bt};
    te->mslot[0] = te->bslot[0] = 0;
    te->mslot[1] = cx->At != cx->A;
    te->bslot[1] = cx->bt != cx->b;
    for (int c = 0; c < 2; c++) {
        arb_mat_init(te->Mp[c], s, s);
        arb_mat_init(te->Mg[c], s, s);
        te->bp[c] = _arb_vec_init(s);
        te->bg[c] = _arb_vec_init(s);
        te->Mabs[c] = _mag_vec_init(s * s);
        te->Mrad[c] = _mag_vec_init(s * s);
        te->babs[c] = _mag_vec_init(s);
        te->brad[c] = _mag_vec_init(s);
        te->gM[c] = _arb_vec_init(s * s);
        te->gb[c] = _arb_vec_init(s);
        for (slong i = 0; i < s; i++) {
            for (slong j = 0; j < s; j++) {
                const arb_struct *x = arb_mat_entry(M[c], i, j);
                arb_set_arf(arb_mat_entry(te->Mp[c], i, j), arb_midref(x));
                arb_set_round(arb_mat_entry(te->Mg[c], i, j), arb_mat_entry(te->Mp[c], i, j), CHK_TREE_GRAD_PREC);
                arf_get_mag(te->Mabs[c] + i * s + j, arb_midref(x));
                mag_set(te->Mrad[c] + i * s + j, arb_radref(x));
            }
            arb_set_arf(te->bp[c] + i, arb_midref(b[c] + i));
            arb_set_round(te->bg[c] + i, te->bp[c] + i, CHK_TREE_GRAD_PREC);
            arf_get_mag(te->babs[c] + i, arb_midref(b[c] + i));
            mag_set(te->brad[c] + i, arb_radref(b[c] + i));
        }
    }
    for (int v = 0; v < NV; v++) {
        te->phip[v] = _arb_vec_init(s);
        te->wp[v] = _arb_vec_init(s);
        te->phig[v] = _arb_vec_init(s);
        te->wg[v] = _arb_vec_init(s);
        te->phibar[v] = _arb_vec_init(s);
        for (int o = 0; o < 3; o++) {
            te->phia[v][o] = _mag_vec_init(s);
            te->wa[v][o] = _mag_vec_init(s);
        }
    }
    te->wbar = _arb_vec_init(s);
    te->tmp = _arb_vec_init(s);
    mag_init(te->m);
    mag_init(te->t);
    return te;
}

void chk_tree_encl_free(chk_tree_encl *te)
{
    if (te == NULL) return;
    slong s = te->s;
    for (int c = 0; c < 2; c++) {
        arb_mat_clear(te->Mp[c]);
        arb_mat_clear(te->Mg[c]);
        _arb_vec_clear(te->bp[c], s);
        _arb_vec_clear(te->bg[c], s);
        _mag_vec_clear(te->Mabs[c], s * s);
        _mag_vec_clear(te->Mrad[c], s * s);
        _mag_vec_clear(te->babs[c], s);
        _mag_vec_clear(te->brad[c], s);
        _arb_vec_clear(te->gM[c], s * s);
        _arb_vec_clear(te->gb[c], s);
    }
    for (int v = 0; v < NV; v++) {
        _arb_vec_clear(te->phip[v], s);
        _arb_vec_clear(te->wp[v], s);
        _arb_vec_clear(te->phig[v], s);
        _arb_vec_clear(te->wg[v], s);
        _arb_vec_clear(te->phibar[v], s);
        for (int o = 0; o < 3; o++) {
            _mag_vec_clear(te->phia[v][o], s);
            _mag_vec_clear(te->wa[v][o], s);
        }
    }
    _arb_vec_clear(te->wbar, s);
    _arb_vec_clear(te->tmp, s);
    mag_clear(te->m);
    mag_clear(te->t);
    flint_free(te);
}

/* z += x y for triples (x0, x1, x2+): z0 += x0 y0, z1 += x0 y1 + x1 y0,
 * z2 += x0 y2 + x2 y0 + (x1 + x2)(y1 + y2). */
static void triple_addmul(chk_tree_encl *te, mag_ptr z[3], slong kz, const mag_struct *x0, const mag_struct *x1,
                          const mag_struct *x2, const mag_struct *y0, const mag_struct *y1, const mag_struct *y2)
{
    mag_ptr m = te->m, t = te->t;
    mag_addmul(z[0] + kz, x0, y0);
    mag_addmul(z[1] + kz, x0, y1);
    mag_addmul(z[1] + kz, x1, y0);
    mag_addmul(z[2] + kz, x0, y2);
    mag_addmul(z[2] + kz, x2, y0);
    mag_add(m, x1, x2);
    mag_add(t, y1, y2);
    mag_addmul(z[2] + kz, m, t);
}

/* Phi(v) = prod over children w of w(w), and for a vertex below the root
 * w(v) = M_colour Phi(v), at the midpoints at prec (children have larger
 * numbers: walked from the last vertex). */
static void forward_mid(chk_tree_encl *te)
{
    slong s = te->s;
    for (int v = te->nv - 1; v >= 0; v--) {
        for (slong i = 0; i < s; i++) arb_one(te->phip[v] + i);
        for (int w = te->v[v].child; w >= 0; w = te->v[w].sibling)
            for (slong i = 0; i < s; i++) arb_mul(te->phip[v] + i, te->phip[v] + i, te->wp[w] + i, te->prec);
        if (v == 0) break;
        int c = te->v[v].colour;
        for (slong i = 0; i < s; i++)
            arb_dot(te->wp[v] + i, NULL, 0, arb_mat_entry(te->Mp[c], i, 0), 1, te->phip[v], 1, s, te->prec);
    }
}

/* The same at the gradient's precision (rounded from forward_mid) and as
 * triples on |mid| + eps rad. */
static void forward_abs(chk_tree_encl *te)
{
    slong s = te->s;
    mag_t p0, p1, p2;
    mag_ptr p12 = _mag_vec_init(s);
    mag_init(p0);
    mag_init(p1);
    mag_init(p2);
    for (int v = te->nv - 1; v >= 0; v--) {
        for (slong i = 0; i < s; i++) {
            mag_one(te->phia[v][0] + i);
            mag_zero(te->phia[v][1] + i);
            mag_zero(te->phia[v][2] + i);
            arb_set_round(te->phig[v] + i, te->phip[v] + i, CHK_TREE_GRAD_PREC);
        }
        mag_ptr z[3];
        for (int o = 0; o < 3; o++) z[o] = te->phia[v][o];
        for (int w = te->v[v].child; w >= 0; w = te->v[w].sibling) {
            for (slong i = 0; i < s; i++) {
                /* product of triples: (p0, p1, p2) * (w0, w1, w2) */
                mag_set(p0, z[0] + i);
                mag_set(p1, z[1] + i);
                mag_set(p2, z[2] + i);
                mag_zero(z[0] + i);
                mag_zero(z[1] + i);
                mag_zero(z[2] + i);
                triple_addmul(te, z, i, p0, p1, p2, te->wa[w][0] + i, te->wa[w][1] + i, te->wa[w][2] + i);
            }
        }
        if (v == 0) break;
        int c = te->v[v].colour;
        mag_ptr y[3];
        for (int o = 0; o < 3; o++) {
            y[o] = te->wa[v][o];
            for (slong i = 0; i < s; i++) mag_zero(y[o] + i);
        }
        for (slong j = 0; j < s; j++) mag_add(p12 + j, z[1] + j, z[2] + j);
        for (slong i = 0; i < s; i++) {
            arb_set_round(te->wg[v] + i, te->wp[v] + i, CHK_TREE_GRAD_PREC);
            /* (|m|, r, 0) * (p0, p1, p2): |m| p0, |m| p1 + r p0, |m| p2 + r (p1 + p2) */
            for (slong j = 0; j < s; j++) {
                const mag_struct *m = te->Mabs[c] + i * s + j, *r = te->Mrad[c] + i * s + j;
                mag_addmul(y[0] + i, m, z[0] + j);
                mag_addmul(y[1] + i, m, z[1] + j);
                mag_addmul(y[1] + i, r, z[0] + j);
                mag_addmul(y[2] + i, m, z[2] + j);
                mag_addmul(y[2] + i, r, p12 + j);
            }
        }
    }
    _mag_vec_clear(p12, s);
    mag_clear(p0);
    mag_clear(p1);
    mag_clear(p2);
}

/* The adjoints: dr/dPhi(root) = bhat; for a child w of v, dr/dw(w)_i =
 * dr/dPhi(v)_i prod_{other children w'} w(w')_i; w(w) = M Phi(w) gives
 * dr/dM_ij += dr/dw(w)_i Phi(w)_j and dr/dPhi(w) = M^T dr/dw(w). */
static void backward(chk_tree_encl *te, int colour)
{
    slong s = te->s, pg = CHK_TREE_GRAD_PREC;
    for (int c = 0; c < 2; c++) {
        _arb_vec_zero(te->gM[c], s * s);
        _arb_vec_zero(te->gb[c], s);
    }
    _arb_vec_set(te->phibar[0], te->bg[colour], s);
    _arb_vec_add(te->gb[te->bslot[colour]], te->gb[te->bslot[colour]], te->phig[0], s, pg);
    for (int v = 0; v < te->nv; v++)
        for (int w = te->v[v].child; w >= 0; w = te->v[w].sibling) {
            _arb_vec_set(te->wbar, te->phibar[v], s);
            for (int x = te->v[v].child; x >= 0; x = te->v[x].sibling)
                if (x != w)
                    for (slong i = 0; i < s; i++) arb_mul(te->wbar + i, te->wbar + i, te->wg[x] + i, pg);
            int c = te->v[w].colour, sl = te->mslot[c];
            for (slong i = 0; i < s; i++)
                for (slong j = 0; j < s; j++) arb_addmul(te->gM[sl] + i * s + j, te->wbar + i, te->phig[w] + j, pg);
            for (slong j = 0; j < s; j++)
                arb_dot(te->phibar[w] + j, NULL, 0, te->wbar, 1, arb_mat_entry(te->Mg[c], 0, j), s, s, pg);
        }
}

/* sum over the entries of the slots of |g_u| rad_u, added to tol. */
static void first_order(chk_tree_encl *te, mag_t tol, arb_srcptr g, const mag_struct *rad, slong n)
{
    for (slong k = 0; k < n; k++) {
        if (mag_is_zero(rad + k)) continue;
        arb_get_mag(te->m, g + k);
        mag_addmul(tol, te->m, rad + k);
    }
}

/* 1 when |r(mid)| <= sum_i |Phi_i(mid)| rad(bhat_i), certainly: that sum is
 * the part of the first-order term that comes from bhat (dr/dbhat_i = Phi_i,
 * no cancellation with other entries), so the enclosure contains 0. */
static int contains_zero_surely(chk_tree_encl *te, const arb_t rmid, int colour)
{
    mag_t tb, lo;
    mag_init(tb);
    mag_init(lo);
    for (slong i = 0; i < te->s; i++) {
        arb_get_mag_lower(lo, te->phip[0] + i);
        mag_mul_lower(lo, lo, te->brad[colour] + i);
        mag_add_lower(tb, tb, lo);
    }
    arb_get_mag(lo, rmid);
    int surely = mag_cmp(lo, tb) <= 0;
    mag_clear(tb);
    mag_clear(lo);
    return surely;
}

int chk_tree_enclose(arb_t out, chk_tree_encl *te, const vigen_treeset *ts, int colour, const slong *ids, int k,
                     const arb_t inv, int exclusion_only)
{
    slong s = te->s;
    te->nv = 0;
    vertices_add(te, ts, -1, colour, ids, k);
    forward_mid(te);
    /* r(mid) = bhat . Phi - 1/gamma */
    arb_neg(te->tmp, inv);
    arb_dot(out, te->tmp, 0, te->bp[colour], 1, te->phip[0], 1, s, te->prec);
    if (exclusion_only && contains_zero_surely(te, out, colour)) return 0;
    forward_abs(te);
    backward(te, colour);
    mag_t tol;
    mag_init(tol);
    for (int sl = 0; sl < 2; sl++) {
        if (sl == 1 && !te->mslot[1]) break;
        first_order(te, tol, te->gM[sl], te->Mrad[sl], s * s);
    }
    for (int sl = 0; sl < 2; sl++) {
        if (sl == 1 && !te->bslot[1]) break;
        first_order(te, tol, te->gb[sl], te->brad[sl], s);
    }
    /* R2: the part of order >= 2 of bhat . Phi on |entries| */
    mag_ptr z[3] = {NULL, NULL, NULL};
    mag_struct acc[3];
    for (int o = 0; o < 3; o++) {
        mag_init(acc + o);
        z[o] = acc + o;
    }
    mag_t zero;
    mag_init(zero);
    for (slong i = 0; i < s; i++)
        triple_addmul(te, z, 0, te->babs[colour] + i, te->brad[colour] + i, zero, te->phia[0][0] + i,
                      te->phia[0][1] + i, te->phia[0][2] + i);
    mag_add(tol, tol, acc + 2);
    arb_add_error_mag(out, tol);
    for (int o = 0; o < 3; o++) mag_clear(acc + o);
    mag_clear(zero);
    mag_clear(tol);
    return 1;
}
