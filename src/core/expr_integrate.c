/* expr_integrate.c — expressions as polynomials in t, and closed-form
 * integrals int_0^x of polynomials and of the table's functions with an
 * antiderivative (sin, cos, exp) at linear arguments: exact and cheap where
 * rigorous quadrature at thousands of digits is slow. */
#include <arb_poly.h>
#include "core/expr_internal.h"

/* to_arb_poly refuses polynomials of higher degree. */
/* Expanding a power of a polynomial costs its degree squared: past this
 * degree an expression is integrated as a general function instead (under the
 * caps of time and precision).  4 x the stage bound leaves room for every
 * basis a spec of at most 256 functions can reasonably write. */
#define EXPR_MAX_POLY_DEGREE 1024

/* ------------------------------------------------------------------------ */
/* Polynomials in t                                                           */

static int poly_node(arb_poly_t res, const node *n, slong prec)
{
    int ok = 0;
    arb_poly_t q;

    if (!n->has_t) {
        arb_t v;
        arb_init(v);
        ok = expr_eval_constant(v, n, prec);
        if (ok) arb_poly_set_arb(res, v);
        arb_clear(v);
        return ok;
    }

    switch (n->kind) {
    case N_T:
        arb_poly_zero(res);
        arb_poly_set_coeff_si(res, 1, 1);
        return 1;
    case N_NEG:
        if (!poly_node(res, n->a, prec)) return 0;
        arb_poly_neg(res, res);
        return 1;
    case N_ADD: case N_SUB: case N_MUL:
        if (!poly_node(res, n->a, prec)) return 0;
        arb_poly_init(q);
        ok = poly_node(q, n->b, prec);
        if (ok) {
            if (n->kind == N_ADD) arb_poly_add(res, res, q, prec);
            else if (n->kind == N_SUB) arb_poly_sub(res, res, q, prec);
            else if (arb_poly_degree(res) + arb_poly_degree(q) > EXPR_MAX_POLY_DEGREE) ok = 0;
            else arb_poly_mul(res, res, q, prec);
        }
        arb_poly_clear(q);
        return ok;
    case N_DIV:
        if (n->b->has_t) return 0;
        if (!poly_node(res, n->a, prec)) return 0;
        {
            arb_t v;
            arb_init(v);
            ok = expr_eval_constant(v, n->b, prec) && !arb_contains_zero(v);
            if (ok) arb_poly_scalar_div(res, res, v, prec);
            arb_clear(v);
        }
        return ok;
    case N_POW:
        if (!n->int_exp || fmpz_sgn(n->k) < 0) return 0;
        if (!poly_node(res, n->a, prec)) return 0;
        {
            slong d = arb_poly_degree(res);
            if (d > 0 && fmpz_cmp_si(n->k, EXPR_MAX_POLY_DEGREE / d) > 0) return 0;
            arb_poly_pow_ui(res, res, fmpz_get_ui(n->k), prec);
        }
        return 1;
    default:
        return 0;    /* functions of t, and t in an exponent or a divisor */
    }
}

int vigen_expr_to_arb_poly(arb_poly_t res, const vigen_expr *e, slong prec)
{
    int ok = poly_node(res, e->root, prec);
    if (!ok) arb_poly_zero(res);
    return ok;
}

/* ------------------------------------------------------------------------ */
/* Closed-form integrals                                                      */

/* n = lambda (a t + b)^k with a linear polynomial a t + b (a != 0) in p
 * and a constant k (integer when *integer, then k >= 0): a power of a
 * linear polynomial, the polynomial itself (k = 1), or a product of two
 * such of proportional bases (c (a t + b) = c^k2 times the power; the
 * proportionality is checked exactly).  0 otherwise. */
static int linear_power(arb_poly_t p, arb_t k, int *integer, arb_t lambda, const node *n, slong prec)
{
    arb_one(lambda);
    if (n->kind == N_POW && !n->b->has_t && poly_node(p, n->a, prec) && arb_poly_degree(p) == 1 &&
        !arb_contains_zero(arb_poly_get_coeff_ptr(p, 1))) {
        *integer = n->int_exp && fmpz_sgn(n->k) >= 0;
        if (*integer) arb_set_fmpz(k, n->k);
        else if (!expr_eval_constant(k, n->b, prec)) return 0;
        return 1;
    }
    if (n->kind == N_MUL && n->a->has_t && n->b->has_t) {
        arb_poly_t q;
        arb_t k2, l2, r;
        arb_poly_init(q);
        arb_init(k2);
        arb_init(l2);
        arb_init(r);
        int i2 = 0;
        int ok = linear_power(p, k, integer, lambda, n->a, prec) && linear_power(q, k2, &i2, l2, n->b, prec);
        if (ok) {
            /* q = c p exactly: q0 p1 = p0 q1 with exact coefficients */
            arb_srcptr p0 = arb_poly_get_coeff_ptr(p, 0), p1 = arb_poly_get_coeff_ptr(p, 1);
            arb_srcptr q0 = arb_poly_get_coeff_ptr(q, 0), q1 = arb_poly_get_coeff_ptr(q, 1);
            arb_t a, b;
            arb_init(a);
            arb_init(b);
            if (q0) arb_mul(a, q0, p1, ARF_PREC_EXACT);
            if (p0) arb_mul(b, p0, q1, ARF_PREC_EXACT);
            ok = arb_is_exact(p1) && arb_is_exact(q1) && (!p0 || arb_is_exact(p0)) && (!q0 || arb_is_exact(q0)) &&
                 arb_equal(a, b);
            arb_clear(a);
            arb_clear(b);
        }
        if (ok) {
            arb_div(r, arb_poly_get_coeff_ptr(q, 1), arb_poly_get_coeff_ptr(p, 1), prec);   /* c */
            /* c^k2: any real k2 needs c > 0 */
            if (i2) arb_pow(r, r, k2, prec);
            else if (arb_is_positive(r)) arb_pow(r, r, k2, prec);
            else ok = 0;
        }
        if (ok) {
            arb_mul(lambda, lambda, l2, prec);
            arb_mul(lambda, lambda, r, prec);
            arb_add(k, k, k2, prec);
            *integer = *integer && i2;
        }
        arb_poly_clear(q);
        arb_clear(k2);
        arb_clear(l2);
        arb_clear(r);
        return ok;
    }
    if (n->has_t && poly_node(p, n, prec) && arb_poly_degree(p) == 1 &&
        !arb_contains_zero(arb_poly_get_coeff_ptr(p, 1))) {
        *integer = 1;
        arb_one(k);
        return 1;
    }
    return 0;
}

/* res = int_0^x (a t + b)^k dt = ((a x + b)^(k+1) - b^(k+1)) / (a (k+1)),
 * for an integer k >= 0, or a real constant k != -1 when a t + b >= 0 on
 * [0, x] (b > 0, or b = 0 and k > -1, so that the integral exists). */
static int power_integral(arb_t res, const arb_poly_t p, const arb_t k, int integer, const arb_t x, slong prec)
{
    arb_srcptr b = arb_poly_get_coeff_ptr(p, 0);
    arb_srcptr a = arb_poly_get_coeff_ptr(p, 1);
    arb_t k1, ax, u, v;
    arb_init(k1);
    arb_init(ax);
    arb_init(u);
    arb_init(v);
    arb_mul(ax, a, x, prec);
    if (b != NULL) arb_add(ax, ax, b, prec);                 /* a x + b */
    arb_add_ui(k1, k, 1, prec);
    int b_zero = b == NULL || arb_is_zero(b), ok = 1;
    if (!integer)
        ok = arb_is_nonnegative(ax) && (b_zero ? arb_is_positive(k1) : arb_is_positive(b) && !arb_contains_zero(k1));
    if (ok) {
        if (integer) {
            fmpz_t e;
            fmpz_init(e);
            ok = arb_get_unique_fmpz(e, k1);
            if (ok) {
                arb_pow_fmpz(u, ax, e, prec);
                if (!b_zero) arb_pow_fmpz(v, b, e, prec);
            }
            fmpz_clear(e);
        } else {
            arb_pow(u, ax, k1, prec);
            if (!b_zero) arb_pow(v, b, k1, prec);
        }
    }
    if (ok) {
        if (!b_zero) arb_sub(u, u, v, prec);
        arb_mul(v, a, k1, prec);
        arb_div(res, u, v, prec);
        ok = arb_is_finite(res);
    }
    arb_clear(k1);
    arb_clear(ax);
    arb_clear(u);
    arb_clear(v);
    return ok;
}

/* res = int_0^x n(t) dt when n is built from polynomials in t, sin, cos and
 * exp of linear arguments a t + b (a != 0), sums, and constant factors or
 * divisors: then the antiderivative is exact and cheap, where rigorous
 * quadrature at thousands of digits is slow.  Returns 0 (res undefined) for
 * anything else. */
static int closed_integral(arb_t res, const node *n, const arb_t x, slong prec)
{
    if (!n->has_t) {
        if (!expr_eval_constant(res, n, prec)) return 0;
        arb_mul(res, res, x, prec);
        return 1;
    }
    arb_poly_t p;
    arb_poly_init(p);
    int ok = 0;
    if (poly_node(p, n, prec)) {
        arb_poly_integral(p, p, prec);
        arb_poly_evaluate(res, p, x, prec);
        arb_poly_clear(p);
        return 1;
    }
    arb_t u, v;
    arb_init(u);
    arb_init(v);
    switch (n->kind) {
    case N_NEG:
        ok = closed_integral(res, n->a, x, prec);
        if (ok) arb_neg(res, res);
        break;
    case N_ADD: case N_SUB:
        ok = closed_integral(u, n->a, x, prec) && closed_integral(v, n->b, x, prec);
        if (ok) {
            if (n->kind == N_ADD) arb_add(res, u, v, prec);
            else arb_sub(res, u, v, prec);
        }
        break;
    case N_DIV:
        if (n->b->has_t) break;
        ok = expr_eval_constant(u, n->b, prec) && !arb_contains_zero(u) && closed_integral(v, n->a, x, prec);
        if (ok) arb_div(res, v, u, prec);
        break;
    case N_POW:
    case N_MUL: {
        /* (a t + b)^k of any size (t^100000000 is no polynomial anyone
         * expands, and its integral is far below an absolute quadrature
         * tolerance), also written as a product of such powers of one base
         * (t^62652 * t, (2 t + 1)^3.5 * (4 t + 2)) */
        arb_t k, lambda;
        arb_init(k);
        arb_init(lambda);
        int integer;
        if (linear_power(p, k, &integer, lambda, n, prec)) {
            ok = power_integral(res, p, k, integer, x, prec);
            if (ok) arb_mul(res, res, lambda, prec);
            ok = ok && arb_is_finite(res);
        }
        arb_clear(k);
        arb_clear(lambda);
        if (ok || n->kind == N_POW) break;
        const node *kf = n->a->has_t ? n->b : n->a, *f = n->a->has_t ? n->a : n->b;
        if (kf->has_t) break;                      /* a product of two other functions of t */
        ok = expr_eval_constant(u, kf, prec) && closed_integral(v, f, x, prec);
        if (ok) arb_mul(res, u, v, prec);
        break;
    }
    case N_FUNC: {
        /* f(a t + b): int_0^x = (F(a x + b) - F(b)) / a with F' = f */
        expr_arb_plain_fn F = expr_functions[n->fn].antiderivative;
        if (F == NULL || !poly_node(p, n->a, prec) || arb_poly_degree(p) != 1) break;
        arb_srcptr b = arb_poly_get_coeff_ptr(p, 0);
        arb_srcptr a = arb_poly_get_coeff_ptr(p, 1);
        if (arb_contains_zero(a)) break;
        arb_t zero, fx, fb;
        arb_init(zero);
        arb_init(fx);
        arb_init(fb);
        if (b == NULL) b = zero;
        arb_mul(u, a, x, prec);
        arb_add(u, u, b, prec);                    /* a x + b */
        F(fx, u, prec);
        F(fb, b, prec);
        arb_sub(v, fx, fb, prec);
        arb_div(res, v, a, prec);
        ok = arb_is_finite(res);
        arb_clear(zero);
        arb_clear(fx);
        arb_clear(fb);
        break;
    }
    default:
        break;
    }
    arb_clear(u);
    arb_clear(v);
    arb_poly_clear(p);
    return ok;
}

int vigen_expr_integral_closed_form(arb_t res, const vigen_expr *e, const arb_t x, slong prec)
{
    return closed_integral(res, e->root, x, prec);
}

