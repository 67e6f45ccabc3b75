/* certify_theorem.c — the orders and symplecticity of a generated tableau
 * decided on the generator's balls by Butcher's theorem (theorem.c), without
 * walking the trees.
 *
 * The generator's balls contain the exact coefficients, so a condition
 * whose ball excludes 0 fails for the exact method, and a hold is decided
 * by the rule of exact entries (decide.c): a ball containing 0 with a radius
 * of at most 2^-(prec/2) of its terms, at 1024 bits (refine.c confirms
 * such holds there).  The precision is the lowest that decides: that of the
 * certified digits (what `vigen check` reads the written file at) while
 * below 1024 bits, since below it a difference in the last digit would hide
 * in the rounding; 1024 bits above it (more digits: an exact difference
 * below about 2^-1000 of the terms is not seen, as for exact entries).
 * Plain ball arithmetic on balls this narrow needs no mean-value enclosure
 * (enclose_tree.c is for rounded data).
 *
 * The row sums and symplecticity (rowsums.c), c = ct, b = bt, B, C, D of
 * both parts (simplifying.c) and the bushy trees (theorem.c) are the
 * checker's own conditions on those balls.  The theorem gives order p when
 * B holds to p and C, D far enough; the order is exactly p when every
 * bushy tree of order p + 1 fails: the monochromatic ones (general H), the
 * alternating ones (separable H), among them the one with a white root and
 * black leaves (Nystrom H).  The tree walk says the same then: every
 * condition up to p holds by the theorem and a bushy one of order p + 1
 * fails.  The failure of order p + 1 must also show on the written digits
 * (the balls widened by a unit of the last digit), or `vigen check` of the
 * file could not confirm "order p" (Gauss s = 16 at 16 digits: B(33) fails
 * by 8e-20, below what 16 digits show).  B holding to order 64, where the
 * checker stops, leaves the order "at least 64" and undecided, as the check
 * does; a failing symplecticity condition must show on the written digits
 * too.  When any of this is undecided, or C and D give less than B (the
 * Lobatto IIIA-IIIB pair: 2s - 3 < 2s - 2), the caller walks the trees
 * (certify.c).
 */
#include <math.h>
#include <string.h>
#include "check/check_internal.h"

/* The precision at which the refinement loop confirms the holds of exact
 * entries (refine.c, min_confirm). */
enum { CHK_CERTIFY_CONFIRM_PREC = 1024 };

/* The highest order of B and of the bushy trees the checker decides
 * (simplifying.c, theorem.c): an order p = 64 by the theorem is "at least
 * 64" there, its claim left out. */
enum { CHK_THEOREM_MAX_ORDER = 64 };

/* The precision of `digits` certified digits: the precision the checker
 * reads a decimal of that length at (notes.c, chk_adequate_prec). */
static slong digits_prec(const vigen_tableau *t)
{
    if (t->digits <= 0) return t->prec;
    slong p = (slong)ceil((double)t->digits * 3.3219280948873623) + 64;
    if (p < 128) p = 128;
    return p < t->prec ? p : t->prec;
}

/* u: the balls of t rounded to prec (each still contains the exact value),
 * no texts. */
static void rounded_copy(vigen_tableau *u, const vigen_tableau *t, slong prec)
{
    slong s = t->s;
    vigen_tableau_init(u, s);
    u->has_At = t->has_At;
    u->has_ct = t->has_ct;
    u->has_bt = t->has_bt;
    u->prec = prec;
    for (slong i = 0; i < s; i++) {
        arb_set_round(u->c + i, t->c + i, prec);
        arb_set_round(u->b + i, t->b + i, prec);
        arb_set_round(u->ct + i, t->ct + i, prec);
        arb_set_round(u->bt + i, t->bt + i, prec);
        for (slong j = 0; j < s; j++) {
            arb_set_round(arb_mat_entry(u->A, i, j), arb_mat_entry(t->A, i, j), prec);
            arb_set_round(arb_mat_entry(u->At, i, j), arb_mat_entry(t->At, i, j), prec);
        }
    }
}

/* Every entry exact (no proof by denominators: den = qd = 0). */
static void all_exact(exactness *x, const vigen_tableau *u)
{
    chk_exactness_init(x, u);
    slong s = u->s;
    memset(x->A, 1, (size_t)(s * s));
    memset(x->At, 1, (size_t)(s * s));
    memset(x->b, 1, (size_t)s);
    memset(x->bt, 1, (size_t)s);
    memset(x->c, 1, (size_t)s);
    memset(x->ct, 1, (size_t)s);
    x->part[0] = x->part[1] = x->part_c[0] = x->part_c[1] = 1;
    x->any_exact = 1;
    x->any_rounded = 0;
}

/* x += |x| 10^(1 - digits) in radius: at least one unit of the last of
 * `digits` significant digits, so the ball holds the written decimal and
 * the ball `vigen check` reads it as (that decimal +- half a unit). */
static void widen_to_digits(arb_t x, slong digits)
{
    mag_t m, u;
    mag_init(m);
    mag_init(u);
    arf_get_mag(m, arb_midref(x));
    mag_set_ui(u, 10);
    mag_pow_ui(u, u, (ulong)(digits - 1));
    mag_div(m, m, u);
    mag_add(arb_radref(x), arb_radref(x), m);
    mag_clear(m);
    mag_clear(u);
}

/* One part (c, A, b) of the tableau (0: A, 1: At), every entry exact, with
 * the powers of its c up to kmax. */
static void part_init(chk_part *p, ctx_t *cx, int part, int kmax)
{
    slong s = cx->s;
    p->cx = cx;
    p->part = part;
    p->exact = p->exact_B = p->exact_C = 1;
    p->A = part ? cx->At : cx->A;
    p->b = part ? cx->bt : cx->b;
    p->c = part ? cx->ct : cx->c;
    p->cp = _arb_vec_init((kmax + 1) * s);
    for (slong i = 0; i < s; i++) arb_one(p->cp + i);
    for (int k = 1; k <= kmax; k++)
        for (slong i = 0; i < s; i++) arb_mul(p->cp + k * s + i, p->cp + (k - 1) * s + i, p->c + i, cx->prec);
}

/* The highest k <= cap with test(1..k) holding in every part; -1 when the
 * first that does not hold is undecided. */
static int level(chk_part *parts, int nparts, int (*test)(chk_part *, int), int cap)
{
    for (int k = 1; k <= cap; k++)
        for (int q = 0; q < nparts; q++) {
            int st = test(parts + q, k);
            if (st == UNDECIDED) return -1;
            if (st == FAILS) return k - 1;
        }
    return cap;
}

/* The order p of the theorem when B holds up to p and fails at p + 1 (or p
 * is 64, the checker's cap) and C and D reach what the theorem needs for that
 * p (C up to min(p - 1, s): more never helps; D only as far as p <= eta +
 * zeta + 1 asks); 0 when something is undecided, or c != ct, b != bt, or C
 * and D give less than B. */
static int theorem_order(ctx_t *cx)
{
    slong s = cx->s;
    int n = cx->has_At ? 2 : 1, data = 0;   /* one part: At, bt, ct are A, b, c */
    const exactness *x = cx->ex;
    if (cx->has_At && chk_decide_equal(cx, cx->c, cx->ct, x->c, x->ct, 91, &data) != HOLDS) return 0;
    if (cx->has_bt && chk_decide_equal(cx, cx->b, cx->bt, x->b, x->bt, 90, &data) != HOLDS) return 0;
    /* an s-stage method has at most B(2s); the checker looks no further than
     * order 64 (simplifying.c, theorem.c) */
    int cap = (int)(2 * s + 1);
    if (cap > CHK_THEOREM_MAX_ORDER) cap = CHK_THEOREM_MAX_ORDER;
    chk_part parts[2];
    for (int q = 0; q < n; q++) part_init(parts + q, cx, q, cap);
    int p = 0;
    int pb = level(parts, n, chk_assumption_B, cap);
    if (pb >= 1 && (pb < cap || cap == CHK_THEOREM_MAX_ORDER)) {
        /* C(s) fixes A for distinct nodes: C(s + 1) is not looked for */
        int eta = level(parts, n, chk_assumption_C, pb - 1 < (int)s ? pb - 1 : (int)s);
        int need = pb - 1 - eta;
        if (eta >= 0 && 2 * eta + 2 >= pb && (need <= 0 || level(parts, n, chk_assumption_D, need) == need)) p = pb;
    }
    for (int q = 0; q < n; q++) _arb_vec_clear(parts[q].cp, (cap + 1) * s);
    return p;
}

/* The checker's state for conditions on the balls of t at prec, every
 * entry exact; widened: the balls of A, At, b, bt widened to the written
 * digits (widen_to_digits), what `vigen check` of the written file sees. */
typedef struct {
    vigen_tableau u;
    exactness ex;
    vigen_check_report rep;
    ctx_t cx;
    chk_round rd;
} certify_round;

static void certify_round_init(certify_round *r, const vigen_tableau *t, slong prec, int widened)
{
    slong s = t->s;
    rounded_copy(&r->u, t, prec);
    if (widened && t->digits > 0)
        for (slong i = 0; i < s; i++) {
            widen_to_digits(r->u.b + i, t->digits);
            widen_to_digits(r->u.bt + i, t->digits);
            for (slong j = 0; j < s; j++) {
                widen_to_digits(arb_mat_entry(r->u.A, i, j), t->digits);
                widen_to_digits(arb_mat_entry(r->u.At, i, j), t->digits);
            }
        }
    all_exact(&r->ex, &r->u);
    vigen_check_report_init(&r->rep);
    r->rep.s = s;
    r->rep.has_At = t->has_At;
    r->rep.has_bt = t->has_At && t->has_bt;
    r->rep.has_ct = t->has_At && t->has_ct;
    chk_ctx_init(&r->cx, &r->u, &r->ex, r->rep.holds);
    r->cx.prec = prec;
    memset(&r->rd, 0, sizeof(r->rd));
    r->rd.rep = &r->rep;
    r->rd.cx = &r->cx;
    r->rd.t = &r->u;
}

static void certify_round_clear(certify_round *r)
{
    for (slong k = 0; k < r->rd.nconds; k++) arb_clear(r->rd.conds[k].r);
    flint_free(r->rd.conds);
    if (r->rd.have_mid) chk_midpoints_clear(&r->rd.mid);
    vigen_check_report_clear(&r->rep);
    chk_exactness_clear(&r->ex);
    vigen_tableau_clear(&r->u);
}

/* Every bushy tree of order n fails on the written digits: what the exact
 * balls show must show in the file, or `vigen check` of it could not
 * confirm the order. */
static int bushy_fail_on_digits(const vigen_tableau *t, slong prec, int n)
{
    certify_round r;
    certify_round_init(&r, t, prec, 1);
    int fail[2], all = 0;
    chk_bushy(&r.cx, n, n, fail, &all);
    certify_round_clear(&r);
    return all == n;
}

/* Symplecticity on the written digits (VIGEN_CHECK_YES, _NO, _UNDECIDED). */
static int symplectic_on_digits(const vigen_tableau *t, slong prec)
{
    certify_round r;
    certify_round_init(&r, t, prec, 1);
    vigen_error err;
    vigen_error_init(&err);
    int v = chk_symplecticity(&r.rd, &err) == VIGEN_OK ? r.rep.symplectic : VIGEN_CHECK_UNDECIDED;
    vigen_error_clear(&err);
    certify_round_clear(&r);
    return v;
}

/* One round at prec: 1 and *out when every verdict needed is decided. */
static int theorem_round(chk_theorem_verdict *out, const vigen_tableau *t, slong prec)
{
    certify_round r;
    certify_round_init(&r, t, prec, 0);
    ctx_t *cx = &r.cx;
    vigen_error err;
    vigen_error_init(&err);
    int rc = chk_consistency(&r.rd, &err);
    if (rc == VIGEN_OK) rc = chk_symplecticity(&r.rd, &err);
    int sympl = r.rep.symplectic;
    /* not symplectic on the exact balls: so in the file too, or undecided */
    if (rc == VIGEN_OK && sympl == VIGEN_CHECK_NO && symplectic_on_digits(t, prec) != VIGEN_CHECK_NO)
        sympl = VIGEN_CHECK_UNDECIDED;
    int p = 0;
    if (rc == VIGEN_OK && r.rep.consistent == VIGEN_CHECK_YES && sympl != VIGEN_CHECK_UNDECIDED)
        p = theorem_order(cx);
    /* every bushy tree of order p + 1 fails: the monochromatic ones (general
     * H), the alternating ones (separable H), among them the one with a white
     * root and black leaves (Nystrom H) */
    int fail[2], all = 0, at_least = p == CHK_THEOREM_MAX_ORDER;
    if (p >= 1 && !at_least && cx->n_undecided == 0 && (t->claim_order < 0 || t->claim_order == p))
        chk_bushy(cx, p + 1, p + 1, fail, &all);
    int decided = (all == p + 1 || (at_least && t->claim_order < 0)) && cx->n_undecided == 0;
    if (decided && !at_least) decided = bushy_fail_on_digits(t, prec, p + 1);
    if (decided) {
        out->order = at_least ? -1 : p;
        out->symplectic = sympl == VIGEN_CHECK_YES;
        out->prec = prec;
    }
    vigen_error_clear(&err);
    certify_round_clear(&r);
    return decided;
}

int chk_certify_theorem(chk_theorem_verdict *out, const vigen_tableau *t)
{
    if (t->prec <= 0) return 0;
    /* one round: a hold at 1024 bits (|condition| below about 2^-1000 of its
     * terms) holds at 512 as well, where the refinement loop would compare
     * it, and a failure is certain at any precision */
    slong prec = digits_prec(t);
    if (prec > CHK_CERTIFY_CONFIRM_PREC) prec = CHK_CERTIFY_CONFIRM_PREC;
    return theorem_round(out, t, prec);
}
