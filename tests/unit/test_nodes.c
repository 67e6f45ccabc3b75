/* test_nodes.c — node families checked against independent truths: closed
 * forms, the defining polynomials evaluated here by other formulas, quadrature
 * exactness with weights built here from the Lagrange basis, symmetry, and
 * every error path.  No expected value is taken from nodes.c itself. */
#define _POSIX_C_SOURCE 200809L   /* clock_gettime */
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <arb.h>
#include <arb_poly.h>
#include <arb_fmpz_poly.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>

#include "method/nodes.h"
#include "testlib.h"
#include "support/strbuf.h"

#define NUM_FAMILIES 8

/* ---- helpers ------------------------------------------------------------- */

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e3 * (double)t.tv_sec + 1e-6 * (double)t.tv_nsec;
}

/* Computes the nodes; a failure is reported and leaves zeros. */
static arb_ptr nodes_get(const char *family, slong s, slong prec)
{
    vigen_error err;
    vigen_error_init(&err);
    arb_ptr c = _arb_vec_init(s);
    int status = vigen_nodes_family(c, family, s, prec, &err);
    CHECK_MSG(status == VIGEN_OK, "%s(%ld) at %ld bits: %s", family, (long)s, (long)prec,
              err.message ? err.message : "(no message)");
    vigen_error_clear(&err);
    return c;
}

/* exact in x rigorously: x is a ball around the true value computed at a much
 * higher precision, so arb_contains(node, x) proves that node holds the value. */
static void check_contains(arb_srcptr node, const arb_t x, const char *what)
{
    CHECK_MSG(arb_contains(node, x), "%s", what);
}

/* (a + b sqrt(r)) / d, at high precision. */
static void closed_sqrt(arb_t x, slong a, slong b, ulong r, ulong d, slong prec)
{
    arb_sqrt_ui(x, r, prec);
    arb_mul_si(x, x, b, prec);
    arb_add_si(x, x, a, prec);
    arb_div_ui(x, x, d, prec);
}

static int is_exact_value(arb_srcptr c, slong num, ulong den)
{
    fmpq_t q;
    fmpq_init(q);
    fmpq_set_si(q, num, den);
    int ok = arb_is_exact(c) && arb_contains_fmpq(c, q);
    fmpq_clear(q);
    return ok;
}

static void check_rational(arb_srcptr c, slong num, ulong den, const char *what)
{
    fmpq_t q;
    fmpq_init(q);
    fmpq_set_si(q, num, den);
    CHECK_MSG(arb_contains_fmpq(c, q), "%s: does not contain %ld/%lu", what, (long)num, den);
    fmpq_clear(q);
}

/* Strictly increasing, in [0, 1], relative accuracy >= prec. */
static void check_basic(arb_srcptr c, slong s, slong prec, const char *family)
{
    arb_t one;
    arb_init(one);
    arb_one(one);
    for (slong i = 0; i < s; i++) {
        CHECK_MSG(arb_is_nonnegative(c + i), "%s(%ld): node %ld < 0", family, (long)s, (long)i);
        CHECK_MSG(arb_le(c + i, one), "%s(%ld): node %ld > 1", family, (long)s, (long)i);
        if (i > 0) CHECK_MSG(arb_lt(c + i - 1, c + i), "%s(%ld): nodes %ld, %ld not increasing", family, (long)s, (long)i - 1, (long)i);
        CHECK_MSG(arb_rel_accuracy_bits(c + i) >= prec, "%s(%ld): node %ld has %ld bits < %ld", family,
                  (long)s, (long)i, (long)arb_rel_accuracy_bits(c + i), (long)prec);
    }
    arb_clear(one);
}

/* c_i + c_{s-1-i} contains 1. */
static void check_symmetric(arb_srcptr c, slong s, const char *family)
{
    arb_t t;
    arb_init(t);
    for (slong i = 0; i < s; i++) {
        arb_add(t, c + i, c + s - 1 - i, ARF_PREC_EXACT);
        CHECK_MSG(arb_contains_si(t, 1), "%s(%ld): not symmetric at %ld", family, (long)s, (long)i);
    }
    arb_clear(t);
}

/* ---- defining polynomials, evaluated here by formulas nodes.c does not use -- */

/* P_n(2c - 1) = sum_k C(n,k)^2 (c - 1)^(n-k) c^k, and its c-derivative
 * 2 P'_n(2c - 1); n = 0 gives 1, 0. */
static void legendre_in_c(arb_t p, arb_t dp, slong n, const arb_t c, slong prec)
{
    arb_t u, a, b, t;
    fmpz_t bin;
    arb_init(u); arb_init(a); arb_init(b); arb_init(t);
    fmpz_init(bin);
    arb_sub_ui(u, c, 1, prec);
    arb_zero(p);
    arb_zero(dp);
    for (slong k = 0; k <= n; k++) {
        fmpz_bin_uiui(bin, (ulong)n, (ulong)k);
        fmpz_mul(bin, bin, bin);
        arb_pow_ui(a, u, (ulong)(n - k), prec);
        arb_pow_ui(b, c, (ulong)k, prec);
        arb_mul(t, a, b, prec);
        arb_addmul_fmpz(p, t, bin, prec);
        if (n - k > 0) {   /* (n-k) (c-1)^(n-k-1) c^k */
            arb_pow_ui(a, u, (ulong)(n - k - 1), prec);
            arb_mul(t, a, b, prec);
            arb_mul_ui(t, t, (ulong)(n - k), prec);
            arb_addmul_fmpz(dp, t, bin, prec);
        }
        if (k > 0) {       /* k (c-1)^(n-k) c^(k-1) */
            arb_pow_ui(a, u, (ulong)(n - k), prec);
            arb_pow_ui(b, c, (ulong)(k - 1), prec);
            arb_mul(t, a, b, prec);
            arb_mul_ui(t, t, (ulong)k, prec);
            arb_addmul_fmpz(dp, t, bin, prec);
        }
    }
    arb_clear(u); arb_clear(a); arb_clear(b); arb_clear(t);
    fmpz_clear(bin);
}

enum { POLY_GAUSS, POLY_LOBATTO, POLY_RADAU_LEFT, POLY_RADAU_RIGHT, POLY_CHEB_T, POLY_CHEB_U };

/* The defining polynomial of a family at c (in the c variable). */
static void defining_poly(arb_t res, int kind, slong n, const arb_t c, slong prec)
{
    arb_t p, dp, q, dq, x, t0, t1, t2;
    arb_init(p); arb_init(dp); arb_init(q); arb_init(dq);
    arb_init(x); arb_init(t0); arb_init(t1); arb_init(t2);
    switch (kind) {
    case POLY_GAUSS:
        legendre_in_c(res, dp, n, c, prec);
        break;
    case POLY_LOBATTO:   /* P'_n */
        legendre_in_c(p, res, n, c, prec);
        break;
    case POLY_RADAU_LEFT:
    case POLY_RADAU_RIGHT:
        legendre_in_c(p, dp, n, c, prec);
        legendre_in_c(q, dq, n - 1, c, prec);
        if (kind == POLY_RADAU_LEFT) arb_add(res, p, q, prec);
        else arb_sub(res, p, q, prec);
        break;
    case POLY_CHEB_T:    /* T_n(x) and U_n(x) by their recurrences, x = 2c - 1 */
    case POLY_CHEB_U:
        arb_mul_2exp_si(x, c, 1);
        arb_sub_ui(x, x, 1, prec);
        arb_one(t0);
        if (kind == POLY_CHEB_T) arb_set(t1, x);
        else arb_mul_2exp_si(t1, x, 1);
        if (n == 0) arb_set(t1, t0);
        for (slong k = 1; k < n; k++) {
            arb_mul(t2, x, t1, prec);
            arb_mul_2exp_si(t2, t2, 1);
            arb_sub(t2, t2, t0, prec);
            arb_swap(t0, t1);
            arb_swap(t1, t2);
        }
        arb_set(res, t1);
        break;
    }
    arb_clear(p); arb_clear(dp); arb_clear(q); arb_clear(dq);
    arb_clear(x); arb_clear(t0); arb_clear(t1); arb_clear(t2);
}

/* Chebyshev's G_s computed here as sum_j e_j x^(s-2j) with e = exp(f) by the
 * recurrence j e_j = sum_{k=1}^j k f_k e_{j-k}, f_k = -s / (2k(2k+1))
 * (not by fmpq_poly_exp_series as in nodes.c).
 * coeffs[j] is the coefficient of x^(s-2j), j = 0..s/2. */
static fmpq *chebyshev_g_coeffs(slong s)
{
    slong m = s / 2;
    fmpq *e = _fmpq_vec_init(m + 1);
    fmpq_t f, t;
    fmpq_init(f);
    fmpq_init(t);
    fmpq_one(e + 0);
    for (slong j = 1; j <= m; j++) {
        for (slong k = 1; k <= j; k++) {
            fmpq_set_si(f, -s * k, (ulong)(2 * k * (2 * k + 1)));
            fmpq_mul(t, f, e + j - k);
            fmpq_add(e + j, e + j, t);
        }
        fmpq_set_si(t, 1, (ulong)j);
        fmpq_mul(e + j, e + j, t);
    }
    fmpq_clear(f);
    fmpq_clear(t);
    return e;
}

static void chebyshev_g_eval(arb_t res, const fmpq *e, slong s, const arb_t c, slong prec)
{
    arb_t x, xp, t;
    arb_init(x); arb_init(xp); arb_init(t);
    arb_mul_2exp_si(x, c, 1);
    arb_sub_ui(x, x, 1, prec);
    arb_zero(res);
    for (slong j = 0; j <= s / 2; j++) {
        arb_pow_ui(xp, x, (ulong)(s - 2 * j), prec);
        arb_set_fmpq(t, e + j, prec);
        arb_addmul(res, t, xp, prec);
    }
    arb_clear(x); arb_clear(xp); arb_clear(t);
}

/* The ball of the polynomial over each node contains 0 (certified), and at the
 * node's midpoint it is below 2^(slack - prec) (tight). */
static void check_roots_of(arb_srcptr c, slong s, slong first, slong last, int kind, slong n,
                           const fmpq *g, slong prec, const char *family)
{
    slong ep = prec + 3 * n + 64;   /* the sums above cancel by up to ~4^n */
    slong slack = 4 * FLINT_BIT_COUNT((ulong)n + 1) + 16;
    arb_t v, mid;
    arb_init(v);
    arb_init(mid);
    for (slong i = first; i <= last; i++) {
        if (g) chebyshev_g_eval(v, g, n, c + i, ep);
        else defining_poly(v, kind, n, c + i, ep);
        CHECK_MSG(arb_contains_zero(v), "%s(%ld): node %ld is not a root", family, (long)s, (long)i);
        arb_set_arf(mid, arb_midref(c + i));
        if (g) chebyshev_g_eval(v, g, n, mid, ep);
        else defining_poly(v, kind, n, mid, ep);
        arb_abs(v, v);
        CHECK_MSG(arb_is_finite(v) && arf_cmpabs_2exp_si(arb_midref(v), slack - prec) < 0
                  && mag_cmp_2exp_si(arb_radref(v), slack - prec) < 0,
                  "%s(%ld): residual at node %ld not below 2^(%ld)", family, (long)s, (long)i, (long)(slack - prec));
    }
    arb_clear(v);
    arb_clear(mid);
}

/* ---- quadrature checks ----------------------------------------------------- */

/* w_i = int_0^1 l_i, l_i the Lagrange basis polynomial of the nodes. */
static void lagrange_weights(arb_ptr w, arb_srcptr c, slong s, slong prec)
{
    arb_ptr others = _arb_vec_init(s);
    arb_poly_t l;
    arb_t den, t;
    arb_poly_init(l);
    arb_init(den);
    arb_init(t);
    for (slong i = 0; i < s; i++) {
        slong n = 0;
        arb_one(den);
        for (slong j = 0; j < s; j++) {
            if (j == i) continue;
            arb_set(others + n++, c + j);
            arb_sub(t, c + i, c + j, prec);
            arb_mul(den, den, t, prec);
        }
        arb_poly_product_roots(l, others, n, prec);
        arb_zero(w + i);
        for (slong k = 0; k < arb_poly_length(l); k++) {
            arb_div_ui(t, arb_poly_get_coeff_ptr(l, k), (ulong)(k + 1), prec);
            arb_add(w + i, w + i, t, prec);
        }
        arb_div(w + i, w + i, den, prec);
    }
    _arb_vec_clear(others, s);
    arb_poly_clear(l);
    arb_clear(den);
    arb_clear(t);
}

/* sum_i w_i c_i^k contains 1/(k+1) for k <= degree and certainly misses it
 * at k = degree + 1; the weights are positive.  prec: that of the nodes. */
static void check_exactness(arb_srcptr c, slong s, slong degree, slong node_prec, const char *family)
{
    slong prec = 2 * node_prec + 64;
    arb_ptr w = _arb_vec_init(s);
    arb_t sum, t;
    fmpq_t q;
    arb_init(sum);
    arb_init(t);
    fmpq_init(q);
    lagrange_weights(w, c, s, prec);
    for (slong i = 0; i < s; i++)
        CHECK_MSG(arb_is_positive(w + i), "%s(%ld): weight %ld not positive", family, (long)s, (long)i);
    for (slong k = 0; k <= degree + 1; k++) {
        arb_zero(sum);
        for (slong i = 0; i < s; i++) {
            arb_pow_ui(t, c + i, (ulong)k, prec);
            arb_addmul(sum, w + i, t, prec);
        }
        fmpq_set_si(q, 1, (ulong)(k + 1));
        if (k <= degree) {
            CHECK_MSG(arb_contains_fmpq(sum, q) && arb_rel_accuracy_bits(sum) > node_prec / 2,
                      "%s(%ld): not exact for t^%ld", family, (long)s, (long)k);
        } else {
            CHECK_MSG(!arb_contains_fmpq(sum, q), "%s(%ld): exact beyond degree %ld", family, (long)s, (long)degree);
        }
    }
    _arb_vec_clear(w, s);
    arb_clear(sum);
    arb_clear(t);
    fmpq_clear(q);
}

/* (1/s) sum_i c_i^k contains 1/(k+1) for k = 0..s, tightly. */
static void check_equal_weight(arb_srcptr c, slong s, slong prec)
{
    arb_t sum, t;
    fmpq_t q;
    arb_init(sum);
    arb_init(t);
    fmpq_init(q);
    for (slong k = 0; k <= s; k++) {
        arb_zero(sum);
        for (slong i = 0; i < s; i++) {
            arb_pow_ui(t, c + i, (ulong)k, prec);
            arb_add(sum, sum, t, prec);
        }
        arb_div_si(sum, sum, s, prec);
        fmpq_set_si(q, 1, (ulong)(k + 1));
        CHECK_MSG(arb_contains_fmpq(sum, q) && arb_rel_accuracy_bits(sum) > prec - 16,
                  "chebyshev_quadrature(%ld): equal weights not exact for t^%ld", (long)s, (long)k);
    }
    arb_clear(sum);
    arb_clear(t);
    fmpq_clear(q);
}

/* ---- tests ----------------------------------------------------------------- */

static void test_closed_forms(void)
{
    const slong prec = 200, hp = 1000;
    arb_ptr c;
    arb_t x;
    arb_init(x);

    c = nodes_get("gauss_legendre", 1, prec);
    CHECK(is_exact_value(c + 0, 1, 2));
    _arb_vec_clear(c, 1);

    c = nodes_get("gauss_legendre", 2, prec);
    closed_sqrt(x, 3, -1, 3, 6, hp); check_contains(c + 0, x, "GL2 node 1 = 1/2 - sqrt(3)/6");
    closed_sqrt(x, 3, 1, 3, 6, hp);  check_contains(c + 1, x, "GL2 node 2 = 1/2 + sqrt(3)/6");
    _arb_vec_clear(c, 2);

    c = nodes_get("gauss_legendre", 3, prec);
    closed_sqrt(x, 5, -1, 15, 10, hp); check_contains(c + 0, x, "GL3 node 1 = 1/2 - sqrt(15)/10");
    CHECK(is_exact_value(c + 1, 1, 2));
    closed_sqrt(x, 5, 1, 15, 10, hp);  check_contains(c + 2, x, "GL3 node 3 = 1/2 + sqrt(15)/10");
    _arb_vec_clear(c, 3);

    c = nodes_get("gauss_lobatto", 2, prec);
    CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + 1, 1, 1));
    _arb_vec_clear(c, 2);

    c = nodes_get("gauss_lobatto", 3, prec);
    CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + 1, 1, 2) && is_exact_value(c + 2, 1, 1));
    _arb_vec_clear(c, 3);

    c = nodes_get("gauss_lobatto", 4, prec);
    CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + 3, 1, 1));
    closed_sqrt(x, 5, -1, 5, 10, hp); check_contains(c + 1, x, "Lobatto4 node 2 = 1/2 - sqrt(5)/10");
    closed_sqrt(x, 5, 1, 5, 10, hp);  check_contains(c + 2, x, "Lobatto4 node 3 = 1/2 + sqrt(5)/10");
    _arb_vec_clear(c, 4);

    c = nodes_get("radau_right", 1, prec);
    CHECK(is_exact_value(c + 0, 1, 1));
    _arb_vec_clear(c, 1);

    c = nodes_get("radau_right", 2, prec);
    check_rational(c + 0, 1, 3, "RadauIIA2 node 1 = 1/3");
    CHECK(is_exact_value(c + 1, 1, 1));
    _arb_vec_clear(c, 2);

    c = nodes_get("radau_right", 3, prec);
    closed_sqrt(x, 4, -1, 6, 10, hp); check_contains(c + 0, x, "RadauIIA3 node 1 = (4 - sqrt 6)/10");
    closed_sqrt(x, 4, 1, 6, 10, hp);  check_contains(c + 1, x, "RadauIIA3 node 2 = (4 + sqrt 6)/10");
    CHECK(is_exact_value(c + 2, 1, 1));
    _arb_vec_clear(c, 3);

    c = nodes_get("radau_left", 1, prec);
    CHECK(is_exact_value(c + 0, 0, 1));
    _arb_vec_clear(c, 1);

    c = nodes_get("radau_left", 2, prec);
    CHECK(is_exact_value(c + 0, 0, 1));
    check_rational(c + 1, 2, 3, "RadauIA2 node 2 = 2/3");
    _arb_vec_clear(c, 2);

    c = nodes_get("radau_left", 3, prec);
    CHECK(is_exact_value(c + 0, 0, 1));
    closed_sqrt(x, 6, -1, 6, 10, hp); check_contains(c + 1, x, "RadauIA3 node 2 = (6 - sqrt 6)/10");
    closed_sqrt(x, 6, 1, 6, 10, hp);  check_contains(c + 2, x, "RadauIA3 node 3 = (6 + sqrt 6)/10");
    _arb_vec_clear(c, 3);

    c = nodes_get("chebyshev_quadrature", 1, prec);
    CHECK(is_exact_value(c + 0, 1, 2));
    _arb_vec_clear(c, 1);

    c = nodes_get("chebyshev_quadrature", 2, prec);
    closed_sqrt(x, 3, -1, 3, 6, hp); check_contains(c + 0, x, "ChebQ2 node 1 = 1/2 - sqrt(3)/6");
    closed_sqrt(x, 3, 1, 3, 6, hp);  check_contains(c + 1, x, "ChebQ2 node 2 = 1/2 + sqrt(3)/6");
    _arb_vec_clear(c, 2);

    c = nodes_get("chebyshev_quadrature", 3, prec);
    closed_sqrt(x, 2, -1, 2, 4, hp); check_contains(c + 0, x, "ChebQ3 node 1 = 1/2 - sqrt(2)/4");
    CHECK(is_exact_value(c + 1, 1, 2));
    closed_sqrt(x, 2, 1, 2, 4, hp);  check_contains(c + 2, x, "ChebQ3 node 3 = 1/2 + sqrt(2)/4");
    _arb_vec_clear(c, 3);

    /* Chebyshev-Gauss: (1 - cos((2i-1) pi / (2s)))/2. */
    c = nodes_get("chebyshev_gauss", 1, prec);
    CHECK(is_exact_value(c + 0, 1, 2));
    _arb_vec_clear(c, 1);
    c = nodes_get("chebyshev_gauss", 2, prec);   /* cos(pi/4) = sqrt(2)/2 */
    closed_sqrt(x, 2, -1, 2, 4, hp); check_contains(c + 0, x, "ChebGauss2 node 1 = 1/2 - sqrt(2)/4");
    closed_sqrt(x, 2, 1, 2, 4, hp);  check_contains(c + 1, x, "ChebGauss2 node 2 = 1/2 + sqrt(2)/4");
    _arb_vec_clear(c, 2);
    c = nodes_get("chebyshev_gauss", 3, prec);   /* cos(pi/6) = sqrt(3)/2 */
    closed_sqrt(x, 2, -1, 3, 4, hp); check_contains(c + 0, x, "ChebGauss3 node 1 = 1/2 - sqrt(3)/4");
    CHECK(is_exact_value(c + 1, 1, 2));
    closed_sqrt(x, 2, 1, 3, 4, hp);  check_contains(c + 2, x, "ChebGauss3 node 3 = 1/2 + sqrt(3)/4");
    _arb_vec_clear(c, 3);

    /* Chebyshev-Lobatto: (1 - cos(k pi / (s-1)))/2. */
    c = nodes_get("chebyshev_lobatto", 3, prec);
    CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + 1, 1, 2) && is_exact_value(c + 2, 1, 1));
    _arb_vec_clear(c, 3);
    c = nodes_get("chebyshev_lobatto", 4, prec);   /* cos(pi/3) = 1/2 */
    CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + 3, 1, 1));
    check_rational(c + 1, 1, 4, "ChebLobatto4 node 2 = 1/4");
    check_rational(c + 2, 3, 4, "ChebLobatto4 node 3 = 3/4");
    _arb_vec_clear(c, 4);
    c = nodes_get("chebyshev_lobatto", 5, prec);
    closed_sqrt(x, 2, -1, 2, 4, hp); check_contains(c + 1, x, "ChebLobatto5 node 2 = 1/2 - sqrt(2)/4");
    CHECK(is_exact_value(c + 2, 1, 2));
    closed_sqrt(x, 2, 1, 2, 4, hp);  check_contains(c + 3, x, "ChebLobatto5 node 4 = 1/2 + sqrt(2)/4");
    _arb_vec_clear(c, 5);

    /* Equispaced: k/(s-1), exact when dyadic. */
    c = nodes_get("equispaced", 2, prec);
    CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + 1, 1, 1));
    _arb_vec_clear(c, 2);
    c = nodes_get("equispaced", 4, prec);
    CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + 3, 1, 1));
    check_rational(c + 1, 1, 3, "equispaced4 node 2 = 1/3");
    check_rational(c + 2, 2, 3, "equispaced4 node 3 = 2/3");
    _arb_vec_clear(c, 4);
    c = nodes_get("equispaced", 5, prec);
    for (slong i = 0; i < 5; i++) CHECK_MSG(is_exact_value(c + i, i, 4), "equispaced5 node %ld = %ld/4 exactly", (long)i, (long)i);
    _arb_vec_clear(c, 5);

    arb_clear(x);
}

/* G_1..G_3 of the paper, from this file's own series computation. */
static void test_chebyshev_g(void)
{
    fmpq_t q;
    fmpq_init(q);
    fmpq *g = chebyshev_g_coeffs(1);   /* x */
    CHECK(fmpq_is_one(g + 0));
    _fmpq_vec_clear(g, 1);
    g = chebyshev_g_coeffs(2);          /* (3x^2 - 1)/3 */
    fmpq_set_si(q, -1, 3);
    CHECK(fmpq_is_one(g + 0) && fmpq_equal(g + 1, q));
    _fmpq_vec_clear(g, 2);
    g = chebyshev_g_coeffs(3);          /* (2x^3 - x)/2 */
    fmpq_set_si(q, -1, 2);
    CHECK(fmpq_is_one(g + 0) && fmpq_equal(g + 1, q));
    _fmpq_vec_clear(g, 2);
    fmpq_clear(q);
}

static void test_roots_and_exactness(void)
{
    const slong prec = 256;
    static const slong sizes[] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 12, 16, 17 };
    for (size_t k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
        slong s = sizes[k];
        arb_ptr c;

        c = nodes_get("gauss_legendre", s, prec);
        check_basic(c, s, prec, "gauss_legendre");
        check_symmetric(c, s, "gauss_legendre");
        check_roots_of(c, s, 0, s - 1, POLY_GAUSS, s, NULL, prec, "gauss_legendre");
        check_exactness(c, s, 2 * s - 1, prec, "gauss_legendre");
        _arb_vec_clear(c, s);

        if (s >= 2) {
            c = nodes_get("gauss_lobatto", s, prec);
            check_basic(c, s, prec, "gauss_lobatto");
            check_symmetric(c, s, "gauss_lobatto");
            CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + s - 1, 1, 1));
            if (s % 2) CHECK(is_exact_value(c + s / 2, 1, 2));
            check_roots_of(c, s, 1, s - 2, POLY_LOBATTO, s - 1, NULL, prec, "gauss_lobatto");
            check_exactness(c, s, 2 * s - 3, prec, "gauss_lobatto");
            _arb_vec_clear(c, s);
        }

        arb_ptr r = nodes_get("radau_right", s, prec);
        check_basic(r, s, prec, "radau_right");
        CHECK(is_exact_value(r + s - 1, 1, 1));
        check_roots_of(r, s, 0, s - 2, POLY_RADAU_RIGHT, s, NULL, prec, "radau_right");
        check_exactness(r, s, 2 * s - 2, prec, "radau_right");

        arb_ptr l = nodes_get("radau_left", s, prec);
        check_basic(l, s, prec, "radau_left");
        CHECK(is_exact_value(l + 0, 0, 1));
        check_roots_of(l, s, 1, s - 1, POLY_RADAU_LEFT, s, NULL, prec, "radau_left");
        check_exactness(l, s, 2 * s - 2, prec, "radau_left");
        /* Radau IA nodes are the mirror image of Radau IIA nodes. */
        arb_t t;
        arb_init(t);
        for (slong i = 0; i < s; i++) {
            arb_add(t, l + i, r + s - 1 - i, ARF_PREC_EXACT);
            CHECK_MSG(arb_contains_si(t, 1), "radau(%ld): left node %ld is not 1 - right node", (long)s, (long)i);
        }
        arb_clear(t);
        _arb_vec_clear(r, s);
        _arb_vec_clear(l, s);

        c = nodes_get("chebyshev_gauss", s, prec);
        check_basic(c, s, prec, "chebyshev_gauss");
        check_symmetric(c, s, "chebyshev_gauss");
        check_roots_of(c, s, 0, s - 1, POLY_CHEB_T, s, NULL, prec, "chebyshev_gauss");
        check_exactness(c, s, s - 1 + (s % 2), prec, "chebyshev_gauss");
        _arb_vec_clear(c, s);

        if (s >= 2) {
            c = nodes_get("chebyshev_lobatto", s, prec);
            check_basic(c, s, prec, "chebyshev_lobatto");
            check_symmetric(c, s, "chebyshev_lobatto");
            CHECK(is_exact_value(c + 0, 0, 1) && is_exact_value(c + s - 1, 1, 1));
            check_roots_of(c, s, 1, s - 2, POLY_CHEB_U, s - 2, NULL, prec, "chebyshev_lobatto");
            _arb_vec_clear(c, s);

            c = nodes_get("equispaced", s, prec);
            check_basic(c, s, prec, "equispaced");
            check_symmetric(c, s, "equispaced");
            for (slong i = 0; i < s; i++) check_rational(c + i, i, (ulong)(s - 1), "equispaced k/(s-1)");
            _arb_vec_clear(c, s);
        }
    }

    /* Chebyshev's equal-weight quadrature: s = 1..7 and 9. */
    for (slong s = 1; s <= 9; s++) {
        if (s == 8) continue;
        arb_ptr c = nodes_get("chebyshev_quadrature", s, prec);
        fmpq *g = chebyshev_g_coeffs(s);
        check_basic(c, s, prec, "chebyshev_quadrature");
        check_symmetric(c, s, "chebyshev_quadrature");
        check_roots_of(c, s, 0, s - 1, 0, s, g, prec, "chebyshev_quadrature");
        check_equal_weight(c, s, prec);
        if (s % 2) CHECK(is_exact_value(c + s / 2, 1, 2));
        _fmpq_vec_clear(g, s / 2 + 1);
        _arb_vec_clear(c, s);
    }
}

/* Larger s at a modest precision: strict increase, accuracy, residuals. */
static void test_large(void)
{
    const slong prec = 128;
    static const slong sizes[] = { 33, 64 };
    for (size_t k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
        slong s = sizes[k];
        for (slong f = 0; vigen_nodes_family_names[f] != NULL; f++) {
            const char *name = vigen_nodes_family_names[f];
            if (strcmp(name, "chebyshev_quadrature") == 0) continue;
            arb_ptr c = nodes_get(name, s, prec);
            check_basic(c, s, prec, name);
            _arb_vec_clear(c, s);
        }
        arb_ptr c = nodes_get("radau_right", s, prec);
        check_roots_of(c, s, 0, s - 2, POLY_RADAU_RIGHT, s, NULL, prec, "radau_right");
        _arb_vec_clear(c, s);
        c = nodes_get("gauss_lobatto", s, prec);
        check_roots_of(c, s, 1, s - 2, POLY_LOBATTO, s - 1, NULL, prec, "gauss_lobatto");
        _arb_vec_clear(c, s);
    }
    /* The largest s, every family that has it, at a low precision. */
    for (slong f = 0; vigen_nodes_family_names[f] != NULL; f++) {
        const char *name = vigen_nodes_family_names[f];
        if (strcmp(name, "chebyshev_quadrature") == 0) continue;
        double t0 = now_ms();
        arb_ptr c = nodes_get(name, VIGEN_NODES_MAX_S, 64);
        double t1 = now_ms();
        check_basic(c, VIGEN_NODES_MAX_S, 64, name);
        printf("  %-22s s = %d at 64 bits: %8.2f ms\n", name, VIGEN_NODES_MAX_S, t1 - t0);
        _arb_vec_clear(c, VIGEN_NODES_MAX_S);
    }
}

/* Number of real roots of this file's G_s, by certified isolation. */
static slong chebyshev_g_num_real(slong s)
{
    fmpq *e = chebyshev_g_coeffs(s);
    fmpq_poly_t g;
    fmpz_poly_t p;
    fmpq_poly_init(g);
    fmpz_poly_init(p);
    for (slong j = 0; j <= s / 2; j++) fmpq_poly_set_coeff_fmpq(g, s - 2 * j, e + j);
    fmpq_poly_get_numerator(p, g);
    slong n = 0;
    CHECK_MSG(fmpz_poly_is_squarefree(p), "G_%ld is not squarefree", (long)s);
    if (fmpz_poly_is_squarefree(p)) {
        acb_ptr r = _acb_vec_init(s);
        arb_fmpz_poly_complex_roots(r, p, 0, 32);
        for (slong i = 0; i < s; i++) n += arb_is_zero(acb_imagref(r + i));
        _acb_vec_clear(r, s);
    }
    fmpq_poly_clear(g);
    fmpz_poly_clear(p);
    _fmpq_vec_clear(e, s / 2 + 1);
    return n;
}

/* Bernstein: complex nodes for s = 8 and s >= 10. */
static void test_chebyshev_refusal(void)
{
    /* The premise, checked here independently of nodes.c. */
    for (slong s = 1; s <= 11; s++) {
        slong n = chebyshev_g_num_real(s);
        if (s == 8 || s >= 10) CHECK_MSG(n < s, "G_%ld has %ld real roots", (long)s, (long)n);
        else CHECK_MSG(n == s, "G_%ld has %ld real roots", (long)s, (long)n);
    }

    static const slong bad[] = { 8, 10, 11, 12, 13, 20, 64, VIGEN_NODES_MAX_S };
    for (size_t k = 0; k < sizeof(bad) / sizeof(bad[0]); k++) {
        slong s = bad[k];
        vigen_error err;
        vigen_error_init(&err);
        arb_ptr c = _arb_vec_init(s);
        int status = vigen_nodes_family(c, "chebyshev_quadrature", s, 128, &err);
        CHECK_MSG(status == VIGEN_E_MATH && err.code == VIGEN_E_MATH, "chebyshev_quadrature(%ld): status %d", (long)s, status);
        CHECK(err.message != NULL && strstr(err.message, "chebyshev_quadrature") != NULL
              && strstr(err.message, "complex") != NULL && strstr(err.message, "s <= 7 or s = 9") != NULL);
        if (s == 8) CHECK(err.message != NULL && strstr(err.message, "chebyshev_quadrature(8)") != NULL);
        vigen_error_clear(&err);
        _arb_vec_clear(c, s);
    }
    /* s = 9 succeeds (checked above as well). */
    vigen_error err;
    vigen_error_init(&err);
    arb_ptr c = _arb_vec_init(9);
    CHECK(vigen_nodes_family(c, "chebyshev_quadrature", 9, 64, &err) == VIGEN_OK && err.message == NULL);
    _arb_vec_clear(c, 9);
    vigen_error_clear(&err);
}

static void expect_error(const char *family, slong s, int code, const char *needle1, const char *needle2)
{
    vigen_error err;
    vigen_error_init(&err);
    arb_ptr c = _arb_vec_init(4);
    int status = vigen_nodes_family(c, family, s, 64, &err);
    CHECK_MSG(status == code && err.code == code, "%s(%ld): status %d, expected %d", family ? family : "(null)",
              (long)s, status, code);
    CHECK_MSG(err.message != NULL && strstr(err.message, needle1) != NULL
              && (needle2 == NULL || strstr(err.message, needle2) != NULL),
              "%s(%ld): message '%s' lacks '%s'", family ? family : "(null)", (long)s,
              err.message ? err.message : "", needle1);
    vigen_error_clear(&err);
    _arb_vec_clear(c, 4);
}

static void test_errors(void)
{
    static const slong min_s[NUM_FAMILIES] = { 1, 2, 1, 1, 1, 1, 2, 2 };
    static const char *const names[NUM_FAMILIES] = {
        "gauss_legendre", "gauss_lobatto", "radau_left", "radau_right",
        "chebyshev_quadrature", "chebyshev_gauss", "chebyshev_lobatto", "equispaced"
    };
    slong n = 0;
    while (vigen_nodes_family_names[n] != NULL) n++;
    CHECK(n == NUM_FAMILIES);
    for (slong i = 0; i < NUM_FAMILIES; i++) {
        int listed = 0;
        for (slong j = 0; j < n; j++) listed += strcmp(vigen_nodes_family_names[j], names[i]) == 0;
        CHECK_MSG(listed == 1, "%s listed %d times", names[i], listed);
        CHECK(vigen_nodes_is_family(names[i]));

        char *range = vigen_strdup_printf("%ld..%d", (long)min_s[i], VIGEN_NODES_MAX_S);
        expect_error(names[i], 0, VIGEN_E_SPEC, names[i], range);
        expect_error(names[i], -3, VIGEN_E_SPEC, names[i], range);
        expect_error(names[i], min_s[i] - 1, VIGEN_E_SPEC, names[i], range);
        expect_error(names[i], VIGEN_NODES_MAX_S + 1, VIGEN_E_SPEC, names[i], range);
        free(range);
    }
    CHECK(!vigen_nodes_is_family("gauss"));
    CHECK(!vigen_nodes_is_family(""));
    CHECK(!vigen_nodes_is_family("Gauss_Legendre"));
    CHECK(!vigen_nodes_is_family(NULL));
    for (slong i = 0; i < NUM_FAMILIES; i++) {
        expect_error("gauss", 3, VIGEN_E_SPEC, "gauss", names[i]);
        expect_error(NULL, 3, VIGEN_E_SPEC, "family", names[i]);
    }
    expect_error("", 3, VIGEN_E_SPEC, "unknown", "gauss_legendre");
    /* A NULL error record is allowed (the code is still returned). */
    arb_ptr c = _arb_vec_init(2);
    CHECK(vigen_nodes_family(c, "nope", 2, 64, NULL) == VIGEN_E_SPEC);
    CHECK(vigen_nodes_family(c, "chebyshev_quadrature", 2, 64, NULL) == VIGEN_OK);
    _arb_vec_clear(c, 2);
}

/* Radius below 1e-1990 at 6700 bits (2^-6611 < 1e-1990), relative accuracy
 * >= prec at several precisions, identical output on a second call. */
static void test_precision(void)
{
    static const struct { const char *name; slong s; } cases[] = {
        { "gauss_legendre", 32 }, { "gauss_lobatto", 8 }, { "radau_right", 8 },
        { "radau_left", 8 }, { "chebyshev_quadrature", 9 }, { "chebyshev_gauss", 16 },
        { "chebyshev_lobatto", 16 }, { "gauss_lobatto", 32 }, { "radau_right", 32 },
    };
    for (size_t k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
        const char *name = cases[k].name;
        slong s = cases[k].s;
        double t0 = now_ms();
        arb_ptr c = nodes_get(name, s, 6700);
        double t1 = now_ms();
        printf("  %-22s s = %-3ld at 6700 bits: %8.2f ms\n", name, (long)s, t1 - t0);
        for (slong i = 0; i < s; i++)
            CHECK_MSG(mag_cmp_2exp_si(arb_radref(c + i), -6611) < 0, "%s(%ld): node %ld radius above 1e-1990",
                      name, (long)s, (long)i);
        check_basic(c, s, 6700, name);
        arb_ptr again = nodes_get(name, s, 6700);
        for (slong i = 0; i < s; i++)
            CHECK_MSG(arb_equal(c + i, again + i), "%s(%ld): node %ld not deterministic", name, (long)s, (long)i);
        _arb_vec_clear(again, s);
        _arb_vec_clear(c, s);

        static const slong precs[] = { 2, 10, 32, 53, 64, 100, 333, 1000 };
        for (size_t j = 0; j < sizeof(precs) / sizeof(precs[0]); j++) {
            c = nodes_get(name, s, precs[j]);
            check_basic(c, s, precs[j], name);
            _arb_vec_clear(c, s);
        }
    }
    /* Residuals at high precision: the radius really shrinks like 2^-prec. */
    arb_ptr c = nodes_get("gauss_legendre", 32, 6700);
    check_roots_of(c, 32, 0, 31, POLY_GAUSS, 32, NULL, 6700, "gauss_legendre");
    _arb_vec_clear(c, 32);
    c = nodes_get("gauss_lobatto", 8, 6700);
    check_roots_of(c, 8, 1, 6, POLY_LOBATTO, 7, NULL, 6700, "gauss_lobatto");
    _arb_vec_clear(c, 8);
    c = nodes_get("radau_right", 8, 6700);
    check_roots_of(c, 8, 0, 6, POLY_RADAU_RIGHT, 8, NULL, 6700, "radau_right");
    _arb_vec_clear(c, 8);
    c = nodes_get("chebyshev_quadrature", 9, 6700);
    fmpq *g = chebyshev_g_coeffs(9);
    check_roots_of(c, 9, 0, 8, 0, 9, g, 6700, "chebyshev_quadrature");
    check_equal_weight(c, 9, 6700);
    _fmpq_vec_clear(g, 5);
    _arb_vec_clear(c, 9);
}

int main(void)
{
    test_chebyshev_g();
    test_closed_forms();
    test_errors();
    test_chebyshev_refusal();
    test_roots_and_exactness();
    test_large();
    test_precision();
    TEST_MAIN_END();
}
