/* nodes.c — certified quadrature-node families on [0, 1].
 *
 * Families classically defined on [-1, 1] are computed there and mapped by
 * c = (1 + x)/2.  That map cancels near x = -1, where the smallest node is
 * about 1/s^2, so every family works at wp = prec + 2 log2(s) + NODES_GUARD
 * bits; nodes_certify then checks that every returned ball has relative
 * accuracy >= prec, lies in [0, 1], and that the balls increase strictly.
 *
 *   gauss_legendre        arb_hypgeom_legendre_p_ui_root (certified by Arb)
 *   gauss_lobatto, radau  sign alternation at points near the Gauss-Legendre
 *                         roots isolates every root; safeguarded Newton, then a
 *                         certified sign change over a ball of radius ~2^-wp
 *   chebyshev_quadrature  exact G_s (fmpq), an exact coefficient test that
 *                         refuses most s, then arb_fmpz_poly_complex_roots with
 *                         realness read off the exactly-zero imaginary parts
 *   chebyshev_*           closed forms via arb_cos_pi_fmpq
 *   equispaced            exact rationals
 *
 * Nodes that are mathematically 0, 1/2 or 1 are set as exact balls.
 */
#include <stdlib.h>
#include <string.h>

#include <arb.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include <arb_hypgeom.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>

#include "method/nodes.h"
#include "support/strbuf.h"

#define NODES_GUARD 16

typedef int (*nodes_fn)(arb_ptr nodes, slong s, slong wp, vigen_error *err);

#define X(name, min_s, fn, description) static int fn(arb_ptr nodes, slong s, slong wp, vigen_error *err);
#include "method/nodes.def"
#undef X

typedef struct {
    const char *name;
    slong min_s;
    nodes_fn fn;
} nodes_family;

/* lookup and dispatch table from nodes.def (the name list is families.c's) */
#define X(name, min_s, fn, description) { #name, min_s, fn },
static const nodes_family nodes_families[] = {
#include "method/nodes.def"
};
#undef X

#define NODES_NUM_FAMILIES ((slong)(sizeof(nodes_families) / sizeof(nodes_families[0])))

static const nodes_family *nodes_lookup(const char *name)
{
    if (name == NULL) return NULL;
    for (slong i = 0; i < NODES_NUM_FAMILIES; i++)
        if (strcmp(nodes_families[i].name, name) == 0) return &nodes_families[i];
    return NULL;
}

/* ---- helpers ------------------------------------------------------------- */

/* c = (1 + x)/2 */
static void nodes_map(arb_t c, const arb_t x, slong wp)
{
    arb_add_ui(c, x, 1, wp);
    arb_mul_2exp_si(c, c, -1);
}

/* c = 1/2, exactly. */
static void nodes_set_half(arb_t c)
{
    arb_one(c);
    arb_mul_2exp_si(c, c, -1);
}

/* c = cos(pi p / q)^2: the Chebyshev closed forms (1 - cos t)/2 rewritten
 * without cancellation near the end points. */
static void nodes_cos_pi_sqr(arb_t c, slong p, slong q, slong wp)
{
    fmpq_t a;
    fmpq_init(a);
    fmpq_set_si(a, p, (ulong)q);
    arb_cos_pi_fmpq(c, a, wp);
    arb_sqr(c, c, wp);
    fmpq_clear(a);
}

/* Certified check of a result: nodes in [0, 1], strictly increasing, relative
 * accuracy >= prec.  Returns VIGEN_OK or VIGEN_E_PRECISION. */
static int nodes_certify(arb_srcptr nodes, slong s, const char *family, slong prec, vigen_error *err)
{
    int ok = 1;
    arb_t one;
    arb_init(one);
    arb_one(one);
    for (slong i = 0; i < s && ok; i++) {
        ok = arb_is_finite(nodes + i) && arb_is_nonnegative(nodes + i) && arb_le(nodes + i, one)
             && (i == 0 || arb_lt(nodes + i - 1, nodes + i))
             && (arb_is_zero(nodes + i) || arb_rel_accuracy_bits(nodes + i) >= prec);
    }
    arb_clear(one);
    if (ok) return VIGEN_OK;
    return vigen_error_set(err, VIGEN_E_PRECISION,
                           "%s(%ld): nodes could not be certified to %ld bits; retry with a higher precision",
                           family, (long)s, (long)prec);
}

/* ---- Gauss-Legendre ------------------------------------------------------ */

/* arb_hypgeom_legendre_p_ui_root gives the roots of P_s in decreasing order
 * (k = 0 closest to 1); only the positive ones are computed, x and -x give
 * the nodes (1 + x)/2 and (1 - x)/2. */
static int nodes_gauss_legendre(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    (void)err;
    arb_t x;
    arb_init(x);
    for (slong k = 0; k < s / 2; k++) {
        arb_hypgeom_legendre_p_ui_root(x, NULL, (ulong)s, (ulong)k, wp);
        nodes_map(nodes + s - 1 - k, x, wp);
        arb_neg(x, x);
        nodes_map(nodes + k, x, wp);
    }
    if (s % 2) nodes_set_half(nodes + s / 2);   /* P_s is odd: x = 0 is a root */
    arb_clear(x);
    return VIGEN_OK;
}

/* ---- Lobatto and Radau: bracketing by sign alternation ---------------------
 *
 * f is P'_n (Lobatto, n = s - 1) or P_n + sigma P_{n-1} (Radau, n = s).  The
 * roots of P'_n interlace with those of P_n, and so do the roots of the
 * quasi-orthogonal P_n + sigma P_{n-1} (besides its root x = -sigma).  So at
 * points -1 < t_1 < ... < t_n < 1 close to the roots of P_n, f alternates in
 * sign.  Certified signs give n - 1 disjoint intervals (t_j, t_{j+1}) each
 * holding at least one root; f has degree n - 1 (Lobatto) or n with the root
 * -sigma outside [t_1, t_n] (Radau), so each interval holds exactly one simple
 * root.  The certificate uses only the certified signs and the degree, not the
 * interlacing theorem, which merely says where to look.  Each root is then
 * located by safeguarded Newton at doubling precision and certified by a sign
 * change over [x - eps, x + eps] inside its interval.
 *
 * P_n, P'_n, P''_n come from the three-term recurrence, which is numerically
 * stable on [-1, 1] but whose ball radii grow like (1 + sqrt 2)^n: evaluations
 * use about 1.3 n extra bits. */

typedef struct {
    int lobatto;   /* 1: f = P'_n; 0: f = P_n + sigma P_{n-1} */
    int sigma;
    slong n;
} nodes_lfun;

/* f(x) and, if df != NULL, f'(x). */
static void nodes_lfun_eval(arb_t f, arb_t df, const nodes_lfun *F, const arb_t x, slong prec)
{
    /* p = P_k, d = P'_k, e = P''_k; suffix m for k - 1. */
    arb_t p, pm, d, dm, e, em, t;
    arb_init(p); arb_init(pm); arb_init(d); arb_init(dm); arb_init(e); arb_init(em); arb_init(t);
    arb_one(pm);
    arb_set(p, x);
    arb_zero(dm);
    arb_one(d);
    arb_zero(em);
    arb_zero(e);
    for (slong k = 1; k < F->n; k++) {
        /* P''_{k+1} = P''_{k-1} + (2k+1) P'_k;  P'_{k+1} = P'_{k-1} + (2k+1) P_k */
        arb_addmul_ui(em, d, (ulong)(2 * k + 1), prec);
        arb_swap(em, e);
        arb_addmul_ui(dm, p, (ulong)(2 * k + 1), prec);
        arb_swap(dm, d);
        /* (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1} */
        arb_mul(t, x, p, prec);
        arb_mul_ui(t, t, (ulong)(2 * k + 1), prec);
        arb_submul_ui(t, pm, (ulong)k, prec);
        arb_div_ui(t, t, (ulong)(k + 1), prec);
        arb_swap(pm, p);
        arb_swap(p, t);
    }
    if (F->lobatto) {
        arb_set(f, d);
        if (df) arb_set(df, e);
    } else {
        if (F->sigma > 0) arb_add(f, p, pm, prec);
        else arb_sub(f, p, pm, prec);
        if (df) {
            if (F->sigma > 0) arb_add(df, d, dm, prec);
            else arb_sub(df, d, dm, prec);
        }
    }
    arb_clear(p); arb_clear(pm); arb_clear(d); arb_clear(dm); arb_clear(e); arb_clear(em); arb_clear(t);
}

/* Certified sign of f at the exact point x: -1, 1, or 0 if undetermined. */
static int nodes_lfun_sign(const nodes_lfun *F, const arf_t x, slong prec)
{
    arb_t xb, f;
    arb_init(xb);
    arb_init(f);
    arb_set_arf(xb, x);
    nodes_lfun_eval(f, NULL, F, xb, prec);
    int sgn = arb_is_positive(f) ? 1 : arb_is_negative(f) ? -1 : 0;
    arb_clear(xb);
    arb_clear(f);
    return sgn;
}

/* One Newton step x <- x - f(x)/f'(x) on midpoints at precision prec, kept
 * inside (lo, hi) (bisection otherwise); tightens (lo, hi) by the sign of f(x)
 * when certified.  Returns 1 when converged at this precision: the sign of
 * f(x) is undetermined or the step is below 2^(12 - prec). */
static int nodes_newton_step(arf_t x, arf_t lo, arf_t hi, int sign_lo, const nodes_lfun *F,
                             slong prec, slong extra)
{
    arb_t xb, f, df;
    arf_t xn;
    int converged = 1;
    arb_init(xb); arb_init(f); arb_init(df);
    arf_init(xn);
    arb_set_arf(xb, x);
    nodes_lfun_eval(f, df, F, xb, prec + extra);
    int sgn = arb_is_positive(f) ? 1 : arb_is_negative(f) ? -1 : 0;
    if (sgn != 0) {
        if (sgn == sign_lo) arf_set(lo, x);
        else arf_set(hi, x);
    }
    if (arb_contains_zero(df)) {
        arf_add(xn, lo, hi, ARF_PREC_EXACT, ARF_RND_DOWN);
        arf_mul_2exp_si(xn, xn, -1);
    } else {
        arb_div(f, f, df, prec + extra);
        arf_sub(xn, x, arb_midref(f), prec, ARF_RND_NEAR);
        if (arf_cmp(xn, lo) <= 0 || arf_cmp(xn, hi) >= 0) {
            if (arf_cmpabs_2exp_si(arb_midref(f), 4 - prec) < 0) {
                arf_set(xn, x);   /* a rounding-size step: converged */
            } else {              /* Newton left the bracket: bisect */
                arf_add(xn, lo, hi, ARF_PREC_EXACT, ARF_RND_DOWN);
                arf_mul_2exp_si(xn, xn, -1);
            }
        }
    }
    if (sgn != 0) {
        arf_sub(arb_midref(f), xn, x, MAG_BITS, ARF_RND_UP);
        converged = arf_cmpabs_2exp_si(arb_midref(f), 12 - prec) < 0;
    }
    arf_set(x, xn);
    arb_clear(xb); arb_clear(f); arb_clear(df);
    arf_clear(xn);
    return converged;
}

/* The unique root of f in (lo, hi), f(lo) having sign sign_lo and f(hi) the
 * opposite sign (both certified).  Writes a ball of radius about 2^eps_exp
 * (at most 2^-wp + a few bits); returns 0 if the sign change cannot be certified. */
static int nodes_lfun_root(arb_t root, const nodes_lfun *F, const arf_t lo_in, const arf_t hi_in,
                           int sign_lo, slong wp, slong extra, slong eps_exp)
{
    const slong p0 = 64;
    int ok = 0;
    arf_t lo, hi, x, a, b;
    arf_init(lo); arf_init(hi); arf_init(x); arf_init(a); arf_init(b);
    arf_set(lo, lo_in);
    arf_set(hi, hi_in);
    arf_add(x, lo, hi, ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_mul_2exp_si(x, x, -1);

    /* Safeguarded Newton at low precision until the step is tiny. */
    for (int it = 0; it < 4 * FLINT_BITS; it++)
        if (nodes_newton_step(x, lo, hi, sign_lo, F, p0, extra)) break;
    /* Doubling precision: one quadratically convergent step per level. */
    slong target = wp + 16, levels[FLINT_BITS];
    slong nlev = 0;
    for (slong p = target; p > p0 && nlev < FLINT_BITS; p = (p + 1) / 2) levels[nlev++] = p;
    for (slong i = nlev - 1; i >= 0; i--) nodes_newton_step(x, lo, hi, sign_lo, F, levels[i], extra);
    nodes_newton_step(x, lo, hi, sign_lo, F, target, extra);

    /* Certify: sign change over [a, b] = [x - eps, x + eps], clipped to (lo_in, hi_in). */
    arf_one(a);
    arf_mul_2exp_si(a, a, eps_exp);
    arf_add(b, x, a, ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_sub(a, x, a, ARF_PREC_EXACT, ARF_RND_DOWN);
    if (arf_cmp(a, lo_in) < 0) arf_set(a, lo_in);
    if (arf_cmp(b, hi_in) > 0) arf_set(b, hi_in);
    if (nodes_lfun_sign(F, a, target + extra) == sign_lo && nodes_lfun_sign(F, b, target + extra) == -sign_lo) {
        arb_set_interval_arf(root, a, b, target);
        ok = 1;
    }
    arf_clear(lo); arf_clear(hi); arf_clear(x); arf_clear(a); arf_clear(b);
    return ok;
}

/* Writes the n - 1 roots of f inside (t_1, t_n) to x, increasing.  With
 * symmetric set (f even or odd), only the roots > 0 are refined, the others
 * mirrored, and a middle root is exactly 0.  Returns VIGEN_OK or
 * VIGEN_E_PRECISION. */
static int nodes_lfun_roots(arb_ptr x, const nodes_lfun *F, int symmetric, slong wp)
{
    slong m = F->n, nr = m - 1;
    int status = VIGEN_OK;
    slong extra = (4 * F->n) / 3 + 2 * FLINT_BIT_COUNT((ulong)F->n) + 32;
    arb_t g;
    arb_init(g);
    arf_struct *t = flint_malloc((size_t)m * sizeof(arf_struct));
    int *sg = flint_malloc((size_t)m * sizeof(int));
    for (slong j = 0; j < m; j++) arf_init(t + j);

    /* Bracketing points near the roots of P_m, increasing, and their signs. */
    for (slong j = 0; j < m; j++) {
        arb_hypgeom_legendre_p_ui_root(g, NULL, (ulong)m, (ulong)(m - 1 - j), 64);
        arf_set(t + j, arb_midref(g));
    }
    if (arf_cmp_si(t + 0, -1) <= 0 || arf_cmp_si(t + m - 1, 1) >= 0) status = VIGEN_E_PRECISION;
    for (slong j = 0; j < m && status == VIGEN_OK; j++) {
        sg[j] = nodes_lfun_sign(F, t + j, 64 + extra);
        if (sg[j] == 0 || (j > 0 && (arf_cmp(t + j - 1, t + j) >= 0 || sg[j] != -sg[j - 1])))
            status = VIGEN_E_PRECISION;
    }
    for (slong j = 0; j < nr && status == VIGEN_OK; j++) {
        if (symmetric && 2 * j + 1 == nr) {   /* middle root of an odd f */
            arb_zero(x + j);
            continue;
        }
        if (symmetric && 2 * j + 1 < nr) continue;   /* mirrored below */
        int ok = 0;
        for (int attempt = 0; attempt < 3 && !ok; attempt++)
            ok = nodes_lfun_root(x + j, F, t + j, t + j + 1, sg[j], wp, extra << attempt, attempt - wp);
        if (!ok) status = VIGEN_E_PRECISION;
    }
    if (symmetric && status == VIGEN_OK)
        for (slong j = 0; 2 * j + 1 < nr; j++) arb_neg(x + j, x + nr - 1 - j);

    for (slong j = 0; j < m; j++) arf_clear(t + j);
    flint_free(t);
    flint_free(sg);
    arb_clear(g);
    return status;
}

static int nodes_gauss_lobatto(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    nodes_lfun F = { 1, 0, s - 1 };
    arb_zero(nodes);
    arb_one(nodes + s - 1);
    if (s == 2) return VIGEN_OK;
    arb_ptr x = _arb_vec_init(s - 2);
    int status = nodes_lfun_roots(x, &F, 1, wp);
    if (status == VIGEN_OK)
        for (slong i = 0; i < s - 2; i++) {
            if (arb_is_zero(x + i)) nodes_set_half(nodes + i + 1);
            else nodes_map(nodes + i + 1, x + i, wp);
        }
    _arb_vec_clear(x, s - 2);
    if (status != VIGEN_OK)
        vigen_error_set(err, status, "gauss_lobatto(%ld): nodes could not be isolated at %ld bits; retry with a higher precision",
                        (long)s, (long)wp);
    return status;
}

/* sigma = +1: P_s + P_{s-1}, root -1 (left); sigma = -1: P_s - P_{s-1}, root +1 (right). */
static int nodes_radau(arb_ptr nodes, slong s, slong wp, int sigma, const char *family, vigen_error *err)
{
    nodes_lfun F = { 0, sigma, s };
    slong off = sigma > 0 ? 1 : 0;
    if (sigma > 0) arb_zero(nodes);
    else arb_one(nodes + s - 1);
    if (s == 1) return VIGEN_OK;
    arb_ptr x = _arb_vec_init(s - 1);
    int status = nodes_lfun_roots(x, &F, 0, wp);
    if (status == VIGEN_OK)
        for (slong i = 0; i < s - 1; i++) nodes_map(nodes + off + i, x + i, wp);
    _arb_vec_clear(x, s - 1);
    if (status != VIGEN_OK)
        vigen_error_set(err, status, "%s(%ld): nodes could not be isolated at %ld bits; retry with a higher precision",
                        family, (long)s, (long)wp);
    return status;
}

static int nodes_radau_left(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    return nodes_radau(nodes, s, wp, +1, "radau_left", err);
}

static int nodes_radau_right(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    return nodes_radau(nodes, s, wp, -1, "radau_right", err);
}

/* ---- Chebyshev's equal-weight quadrature ---------------------------------
 *
 * G_s(x) = polynomial part of x^s exp(-s sum_{k>=1} x^-2k / (2k(2k+1))), i.e.
 * G_s(x) = x^(s mod 2) q(x^2) with q(y) = sum_j a_j y^(m-j), m = floor(s/2),
 * where sum_j a_j u^j = exp(-s sum_k u^k / (2k(2k+1))) truncated at degree m.
 */

/* q(y) as above. */
static void nodes_chebyshev_q(fmpq_poly_t q, slong s)
{
    slong m = s / 2;
    fmpq_poly_t f;
    fmpq_t c;
    fmpq_poly_init(f);
    fmpq_init(c);
    for (slong k = 1; k <= m; k++) {
        fmpq_set_si(c, -s, (ulong)(2 * k * (2 * k + 1)));
        fmpq_poly_set_coeff_fmpq(f, k, c);
    }
    fmpq_poly_exp_series(f, f, m + 1);
    fmpq_poly_zero(q);
    for (slong j = 0; j <= m; j++) {
        fmpq_poly_get_coeff_fmpq(c, f, j);
        fmpq_poly_set_coeff_fmpq(q, m - j, c);
    }
    fmpq_poly_clear(f);
    fmpq_clear(c);
}

/* Exact necessary condition for G_s to have s distinct real roots: then the
 * roots of q are x_i^2 > 0 (x = 0 is not a double root), so q's coefficients
 * b_0..b_m alternate strictly in sign, and q, being real-rooted, satisfies
 * Newton's inequalities b_k^2 C(m,k-1) C(m,k+1) >= b_{k-1} b_{k+1} C(m,k)^2.
 * Returns 0 when either fails, a proof that G_s has a non-real (or repeated)
 * root; this refuses s = 8 and 10 <= s <= 256 without any root finding. */
static int nodes_may_be_real_rooted(const fmpq_poly_t q)
{
    slong m = fmpq_poly_degree(q);
    int ok = 1;
    fmpq_t a, b, c, l, r;
    fmpz_t t;
    fmpq_init(a); fmpq_init(b); fmpq_init(c); fmpq_init(l); fmpq_init(r);
    fmpz_init(t);
    for (slong k = 0; k <= m && ok; k++) {
        fmpq_poly_get_coeff_fmpq(b, q, k);
        ok = !fmpq_is_zero(b) && (k == 0 || fmpq_sgn(a) != fmpq_sgn(b));
        fmpq_swap(a, b);
    }
    for (slong k = 1; k < m && ok; k++) {
        fmpq_poly_get_coeff_fmpq(a, q, k - 1);
        fmpq_poly_get_coeff_fmpq(b, q, k);
        fmpq_poly_get_coeff_fmpq(c, q, k + 1);
        fmpq_mul(l, b, b);
        fmpz_bin_uiui(t, (ulong)m, (ulong)(k - 1));
        fmpq_mul_fmpz(l, l, t);
        fmpz_bin_uiui(t, (ulong)m, (ulong)(k + 1));
        fmpq_mul_fmpz(l, l, t);
        fmpq_mul(r, a, c);
        fmpz_bin_uiui(t, (ulong)m, (ulong)k);
        fmpz_mul(t, t, t);
        fmpq_mul_fmpz(r, r, t);
        ok = fmpq_cmp(l, r) >= 0;
    }
    fmpq_clear(a); fmpq_clear(b); fmpq_clear(c); fmpq_clear(l); fmpq_clear(r);
    fmpz_clear(t);
    return ok;
}

static int nodes_chebyshev_refuse(slong s, vigen_error *err)
{
    return vigen_error_set(err, VIGEN_E_MATH,
                           "chebyshev_quadrature(%ld): Chebyshev's equal-weight quadrature has complex nodes "
                           "for s = 8 and s >= 10 (Bernstein); use s <= 7 or s = 9", (long)s);
}

/* The nodes from the roots of G_s, once the coefficient test has passed. */
static int nodes_chebyshev_roots(arb_ptr nodes, const fmpq_poly_t q, slong s, slong wp, vigen_error *err)
{
    slong m = s / 2, d = 2 * m;
    int status = VIGEN_OK;
    if (s % 2) nodes_set_half(nodes + m);   /* G_s is odd: x = 0 */
    if (d == 0) return status;

    /* G_s(x) / x^(s mod 2) = q(x^2), cleared to integer coefficients. */
    fmpq_poly_t g;
    fmpz_poly_t p;
    fmpq_t c;
    fmpq_poly_init(g);
    fmpz_poly_init(p);
    fmpq_init(c);
    for (slong k = 0; k <= m; k++) {
        fmpq_poly_get_coeff_fmpq(c, q, k);
        fmpq_poly_set_coeff_fmpq(g, 2 * k, c);
    }
    fmpq_poly_get_numerator(p, g);
    if (!fmpz_poly_is_squarefree(p)) {   /* arb_fmpz_poly_complex_roots requires it */
        status = vigen_error_set(err, VIGEN_E_MATH, "chebyshev_quadrature(%ld): G_%ld has a repeated root",
                                 (long)s, (long)s);
    } else {
        /* Real roots come first, ascending, with imaginary part exactly 0;
         * every other root is isolated away from the real axis. */
        acb_ptr r = _acb_vec_init(d);
        arb_fmpz_poly_complex_roots(r, p, 0, wp);
        int all_real = 1;
        for (slong i = 0; i < d; i++) all_real = all_real && arb_is_zero(acb_imagref(r + i));
        if (all_real) {
            /* q(0) != 0, so m roots are negative and m positive. */
            for (slong i = 0; i < m; i++) nodes_map(nodes + i, acb_realref(r + i), wp);
            for (slong i = m; i < d; i++) nodes_map(nodes + i + s % 2, acb_realref(r + i), wp);
        } else {
            status = nodes_chebyshev_refuse(s, err);
        }
        _acb_vec_clear(r, d);
    }
    fmpq_poly_clear(g);
    fmpz_poly_clear(p);
    fmpq_clear(c);
    return status;
}

static int nodes_chebyshev_quadrature(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    fmpq_poly_t q;
    fmpq_poly_init(q);
    nodes_chebyshev_q(q, s);
    int status = nodes_may_be_real_rooted(q) ? nodes_chebyshev_roots(nodes, q, s, wp, err)
                                             : nodes_chebyshev_refuse(s, err);
    fmpq_poly_clear(q);
    return status;
}

/* ---- closed forms --------------------------------------------------------- */

/* Roots of T_s, increasing: c_i = (1 - cos((2i+1) pi / (2s)))/2 = cos^2((2s-2i-1) pi / (4s)). */
static int nodes_chebyshev_gauss(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    (void)err;
    for (slong i = 0; i < s; i++) {
        if (2 * i + 1 == s) nodes_set_half(nodes + i);
        else nodes_cos_pi_sqr(nodes + i, 2 * s - 2 * i - 1, 4 * s, wp);
    }
    return VIGEN_OK;
}

/* c_i = (1 - cos(i pi / (s-1)))/2 = cos^2((s-1-i) pi / (2(s-1))), i = 0..s-1. */
static int nodes_chebyshev_lobatto(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    (void)err;
    for (slong i = 0; i < s; i++) {
        if (i == 0) arb_zero(nodes + i);
        else if (i == s - 1) arb_one(nodes + i);
        else if (2 * i == s - 1) nodes_set_half(nodes + i);
        else nodes_cos_pi_sqr(nodes + i, s - 1 - i, 2 * (s - 1), wp);
    }
    return VIGEN_OK;
}

/* k/(s-1), exact whenever it is dyadic. */
static int nodes_equispaced(arb_ptr nodes, slong s, slong wp, vigen_error *err)
{
    (void)err;
    fmpq_t q;
    fmpq_init(q);
    for (slong i = 0; i < s; i++) {
        fmpq_set_si(q, i, (ulong)(s - 1));
        arb_set_fmpq(nodes + i, q, wp);
    }
    fmpq_clear(q);
    return VIGEN_OK;
}

/* ---- entry point --------------------------------------------------------- */

int vigen_nodes_family(arb_ptr nodes, const char *family, slong s, slong prec, vigen_error *err)
{
    const nodes_family *f = nodes_lookup(family);
    if (f == NULL) {
        vigen_strbuf known;
        vigen_strbuf_init(&known);
        for (slong i = 0; vigen_nodes_family_names[i] != NULL; i++) {
            if (i > 0) vigen_strbuf_append(&known, ", ");
            vigen_strbuf_append(&known, vigen_nodes_family_names[i]);
        }
        int code;
        if (family == NULL)
            code = vigen_error_set(err, VIGEN_E_SPEC, "missing node family name; known families: %s",
                                   known.data);
        else
            code = vigen_error_set(err, VIGEN_E_SPEC, "unknown node family '%s'; known families: %s",
                                   family, known.data);
        vigen_strbuf_clear(&known);
        return code;
    }
    if (s < f->min_s || s > VIGEN_NODES_MAX_S)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s(%ld): the number of nodes s must be in %ld..%d",
                               f->name, (long)s, (long)f->min_s, VIGEN_NODES_MAX_S);
    if (prec < 2) prec = 2;
    slong wp = prec + 2 * FLINT_BIT_COUNT((ulong)s) + NODES_GUARD;
    int status = f->fn(nodes, s, wp, err);
    if (status != VIGEN_OK) return status;
    return nodes_certify(nodes, s, f->name, prec, err);
}
