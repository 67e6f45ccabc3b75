/* test_expr_calculus.c — expressions as functions of t (expr.h): their
 * Taylor polynomials, their complex evaluation, and the integrals of the
 * Galerkin construction, numerical and in closed form.
 *
 * Every expected value comes from mathematics, not from the code: exact
 * polynomial coefficients worked out by hand, reference values computed
 * directly with arb and acb functions, closed-form integrals. */
#include <stdlib.h>
#include <string.h>
#include <acb_calc.h>
#include <flint/fmpq.h>
#include "test_expr.h"

/* ---- polynomials ------------------------------------------------------- */

static int poly_of(arb_poly_t p, const char *text, slong prec)
{
    vigen_expr *e;
    vigen_error err;
    vigen_error_init(&err);
    int ok = 0;
    if (vigen_expr_parse(&e, text, 1, &err) == VIGEN_OK) {
        ok = vigen_expr_to_arb_poly(p, e, prec);
        vigen_expr_free(e);
    } else {
        CHECK_MSG(0, "parse \"%s\": %s", text, err.message);
    }
    vigen_error_clear(&err);
    return ok;
}

static void check_coeff_q(const arb_poly_t p, slong i, slong num, ulong den, slong prec)
{
    arb_t c, r;
    arb_init(c); arb_init(r);
    arb_poly_get_coeff_arb(c, p, i);
    arb_set_si(r, num);
    arb_div_ui(r, r, den, prec);
    CHECK_MSG(arb_overlaps(c, r) && arb_rel_accuracy_bits(c) >= prec - 8,
              "coefficient %ld should be %ld/%lu", (long)i, (long)num, den);
    arb_clear(c); arb_clear(r);
}

static void test_poly(void)
{
    slong prec = 200;
    arb_poly_t p;
    arb_t c, r;
    arb_poly_init(p); arb_init(c); arb_init(r);

    CHECK(poly_of(p, "(t-1)^2", prec));
    CHECK(arb_poly_length(p) == 3);
    check_coeff_q(p, 0, 1, 1, prec);
    check_coeff_q(p, 1, -2, 1, prec);
    check_coeff_q(p, 2, 1, 1, prec);

    CHECK(poly_of(p, "t/3 + pi*t^2", prec));
    CHECK(arb_poly_length(p) == 3);
    check_coeff_q(p, 0, 0, 1, prec);
    check_coeff_q(p, 1, 1, 3, prec);
    arb_poly_get_coeff_arb(c, p, 2);
    arb_const_pi(r, prec);
    CHECK(arb_overlaps(c, r));
    CHECK_CLOSE(c, r, 55, prec);

    /* (t+1)(t-1) - t^2 = -1; (2t)^3/4 = 2t^3; t^(4/2) = t^2; a constant */
    CHECK(poly_of(p, "(t+1)*(t-1) - t^2", prec));
    check_coeff_q(p, 0, -1, 1, prec);
    check_coeff_q(p, 1, 0, 1, prec);
    check_coeff_q(p, 2, 0, 1, prec);
    CHECK(poly_of(p, "(2*t)^3/4", prec));
    CHECK(arb_poly_length(p) == 4);
    check_coeff_q(p, 3, 2, 1, prec);
    check_coeff_q(p, 0, 0, 1, prec);
    CHECK(poly_of(p, "-t^(4/2)", prec));
    CHECK(arb_poly_length(p) == 3);
    check_coeff_q(p, 2, -1, 1, prec);
    CHECK(poly_of(p, "sqrt(3)/6", prec));
    CHECK(arb_poly_length(p) == 1);
    arb_poly_get_coeff_arb(c, p, 0);
    arb_set_ui(r, 12);
    arb_rsqrt(r, r, prec);          /* sqrt(3)/6 = 1/sqrt(12) */
    CHECK(arb_overlaps(c, r));

    /* the polynomial agrees with direct evaluation at t = 3/10 */
    const char *text = "(t - 1/2)^3*sqrt(2) - t*(t+1)/7 + exp(1)";
    CHECK(poly_of(p, text, prec));
    CHECK(arb_poly_length(p) == 4);
    arb_t t, v;
    arb_init(t); arb_init(v);
    arb_set_ui(t, 3); arb_div_ui(t, t, 10, prec);
    arb_poly_evaluate(c, p, t, prec);
    if (eval_text(v, text, t, prec) == VIGEN_OK) CHECK(arb_overlaps(c, v));
    arb_clear(t); arb_clear(v);

    /* refusals: not polynomials in t */
    const char *refused[] = { "cos(pi*t)", "1/t", "t^(1/2)", "exp(t)", "t^-1", "2^t", "t^t",
                              "1/(t-t)", "sqrt(t^2)", "log(1+t)", "t/(1-1)" };
    for (size_t i = 0; i < sizeof(refused) / sizeof(refused[0]); i++) {
        arb_poly_one(p);
        CHECK_MSG(poly_of(p, refused[i], prec) == 0, "\"%s\" is not a polynomial", refused[i]);
        CHECK(arb_poly_length(p) == 0);
    }
    arb_poly_clear(p); arb_clear(c); arb_clear(r);
}

/* ---- complex evaluation and integration -------------------------------- */

static int eval_acb_text(acb_t res, const char *text, const acb_t t, int analytic, slong prec)
{
    vigen_expr *e;
    vigen_error err;
    vigen_error_init(&err);
    int rc = vigen_expr_parse(&e, text, 1, &err);
    CHECK_MSG(rc == VIGEN_OK, "parse \"%s\"", text);
    if (rc == VIGEN_OK) {
        rc = vigen_expr_eval_acb(res, e, t, analytic, prec);
        vigen_expr_free(e);
    }
    vigen_error_clear(&err);
    return rc;
}

static void test_acb(void)
{
    slong prec = 128;
    acb_t t, x, r;
    acb_init(t); acb_init(x); acb_init(r);

    /* t = -1 + [+/- 0.1] i straddles the negative real axis (the branch cut) */
    acb_set_si(t, -1);
    mag_set_ui_2exp_si(arb_radref(acb_imagref(t)), 1, -3);
    const char *cut[] = { "sqrt(t)", "log(t)", "t^(1/2)", "2 + sqrt(t)*0" };
    for (size_t i = 0; i < sizeof(cut) / sizeof(cut[0]); i++) {
        CHECK(eval_acb_text(x, cut[i], t, 1, prec) == VIGEN_OK);
        CHECK_MSG(!acb_is_finite(x), "%s should be indeterminate on the branch cut", cut[i]);
    }
    /* holomorphic there: entire functions and integer powers */
    const char *entire[] = { "exp(t)*t^3", "sin(t) + cos(t)", "t^-2", "(t-1)^(4/2)" };
    for (size_t i = 0; i < sizeof(entire) / sizeof(entire[0]); i++) {
        CHECK(eval_acb_text(x, entire[i], t, 1, prec) == VIGEN_OK);
        CHECK_MSG(acb_is_finite(x), "%s should be finite", entire[i]);
    }
    /* a pole of 1/t inside the ball */
    acb_zero(t);
    mag_set_ui_2exp_si(arb_radref(acb_realref(t)), 1, -3);
    CHECK(eval_acb_text(x, "1/t", t, 1, prec) == VIGEN_OK);
    CHECK(!acb_is_finite(x));

    /* away from cuts: sqrt(-4) = 2i without analyticity; sqrt(4i) = sqrt(2)(1+i) */
    acb_set_si(t, -4);
    CHECK(eval_acb_text(x, "sqrt(t)", t, 0, prec) == VIGEN_OK);
    acb_onei(r); acb_mul_ui(r, r, 2, prec);
    CHECK(acb_overlaps(x, r));
    acb_onei(t); acb_mul_ui(t, t, 4, prec);
    CHECK(eval_acb_text(x, "sqrt(t)", t, 1, prec) == VIGEN_OK);
    arb_sqrt_ui(acb_realref(r), 2, prec);
    arb_sqrt_ui(acb_imagref(r), 2, prec);
    CHECK(acb_overlaps(x, r));
    CHECK(acb_rel_accuracy_bits(x) >= prec - 10);

    /* the real and complex evaluators agree on the real axis */
    acb_set_si(t, 3);
    acb_div_ui(t, t, 7, prec);
    CHECK(eval_acb_text(x, "tan(t) + exp(-t)*log(2+t)/sqrt(t) + t^(1/3) - pi", t, 1, prec) == VIGEN_OK);
    arb_t xr;
    arb_init(xr);
    if (eval_text(xr, "tan(t) + exp(-t)*log(2+t)/sqrt(t) + t^(1/3) - pi", acb_realref(t), prec) == VIGEN_OK) {
        CHECK(arb_overlaps(acb_realref(x), xr));
        CHECK(arb_contains_zero(acb_imagref(x)));
    }
    arb_clear(xr);

    /* t missing */
    CHECK(eval_acb_text(x, "t", NULL, 1, prec) == VIGEN_E_DOMAIN);
    CHECK(!acb_is_finite(x));

    acb_clear(t); acb_clear(x); acb_clear(r);
}

static int integrand(acb_ptr out, const acb_t inp, void *param, slong order, slong prec)
{
    if (order > 1) flint_abort();   /* only f and its analyticity are requested */
    vigen_expr_eval_acb(out, (const vigen_expr *)param, inp, order != 0, prec);
    return 0;
}

/* Integral of text over [a, b] (rationals) to `digits` digits, against ref. */
static void check_integral(const char *text, slong an, ulong ad, slong bn, ulong bd,
                           const arb_t ref, slong digits, slong prec)
{
    vigen_expr *e;
    vigen_error err;
    acb_t a, b, res;
    mag_t tol;
    vigen_error_init(&err);
    acb_init(a); acb_init(b); acb_init(res); mag_init(tol);
    if (vigen_expr_parse(&e, text, 1, &err) == VIGEN_OK) {
        acb_set_si(a, an); acb_div_ui(a, a, ad, prec);
        acb_set_si(b, bn); acb_div_ui(b, b, bd, prec);
        mag_set_ui_2exp_si(tol, 1, -prec);
        acb_calc_integrate(res, integrand, e, a, b, prec, tol, NULL, prec);
        CHECK_MSG(arb_overlaps(acb_realref(res), ref), "integral of %s does not contain the exact value", text);
        CHECK_MSG(arb_contains_zero(acb_imagref(res)), "integral of %s: imaginary part", text);
        CHECK_CLOSE(acb_realref(res), ref, digits, prec);
        vigen_expr_free(e);
    } else {
        CHECK_MSG(0, "parse %s: %s", text, err.message);
    }
    vigen_error_clear(&err);
    acb_clear(a); acb_clear(b); acb_clear(res); mag_clear(tol);
}

static void test_integrals(void)
{
    slong prec = 200;
    arb_t ref, u;
    arb_init(ref); arb_init(u);

    /* int_0^1 exp(t/2) dt = 2 (e^(1/2) - 1) */
    arb_set_ui(u, 1); arb_mul_2exp_si(u, u, -1);
    arb_exp(ref, u, prec);
    arb_sub_ui(ref, ref, 1, prec);
    arb_mul_ui(ref, ref, 2, prec);
    check_integral("exp(t/2)", 0, 1, 1, 1, ref, 50, prec);

    /* int_0^(1/3) cos(pi t) dt = sin(pi/3)/pi = sqrt(3)/(2 pi) */
    arb_sqrt_ui(ref, 3, prec);
    arb_const_pi(u, prec);
    arb_div(ref, ref, u, prec);
    arb_mul_2exp_si(ref, ref, -1);
    check_integral("cos(pi*t)", 0, 1, 1, 3, ref, 50, prec);

    /* a polynomial: int_0^1 (t-1)^2 dt = 1/3 */
    arb_set_ui(ref, 1); arb_div_ui(ref, ref, 3, prec);
    check_integral("(t-1)^2", 0, 1, 1, 1, ref, 50, prec);

    /* the branch point at the endpoint: int_0^1 sqrt(t) dt = 2/3 */
    arb_set_ui(ref, 2); arb_div_ui(ref, ref, 3, prec);
    check_integral("sqrt(t)", 0, 1, 1, 1, ref, 20, 96);

    /* int_1^2 1/t dt = log 2 */
    arb_const_log2(ref, prec);
    check_integral("1/t", 1, 1, 2, 1, ref, 50, prec);

    arb_clear(ref); arb_clear(u);
}

/* The closed-form antiderivative against rigorous quadrature (an independent
 * route), for expressions in its class, and its refusal outside it. */
static void test_closed_form_integrals(void)
{
    static const char *const in_class[] = {
        "cos(pi*t)", "sin(2*pi*t)", "exp(t/2)", "1 + cos(pi*t)/2", "3*sin(2*pi*t + 1/5) - exp(-t)/7 + t^2",
        "-(cos(3*pi*t - 1) * 2)", "sin(pi*(t - 1/2))", "exp(2*t + log(3))",
        "(t/3 - 1)^2000", "2*(1/2 + 5*t)^1500",      /* powers too high to expand into polynomials */
        "(t + 1)^(1/3)", "3*(2*t + 1/2)^(5/2)", "(1 + t)^(-2)",   /* real powers of a positive base */
        "t^1500*t", "t^700*(-t)^3", "(2*t + 1)^(5/2)*(4*t + 2)", "(t + 1)^(1/3)*(t + 1)^2",   /* products of powers of one base */
    };
    static const char *const outside[] = {"(t - 1)^(1/2)", "(t - 1/5)^(1/3)", "t^(-1)", "t^(-3/2)", "t*cos(pi*t)", "t*(t + 1)^(1/2)", "(t + 1)^(1/2)*(t - 1)^(1/2)", "cos(t^2)", "sin(pi*t)^2", "1/(1 + t)", "cos(0*t + 1) * t * exp(t)"};
    slong prec = 256;
    arb_t x, closed;
    acb_t a, b, quad;
    mag_t tol;
    arb_init(x); arb_init(closed);
    acb_init(a); acb_init(b); acb_init(quad); mag_init(tol);
    arb_set_ui(x, 3);
    arb_div_ui(x, x, 7, prec);                  /* integrate over [0, 3/7] */
    acb_set_arb(b, x);
    mag_set_ui_2exp_si(tol, 1, -prec);
    for (size_t k = 0; k < sizeof in_class / sizeof in_class[0]; k++) {
        vigen_expr *e = NULL;
        vigen_error err;
        vigen_error_init(&err);
        CHECK(vigen_expr_parse(&e, in_class[k], 1, &err) == VIGEN_OK);
        if (e == NULL) continue;
        CHECK_MSG(vigen_expr_integral_closed_form(closed, e, x, prec), "%s: no closed form", in_class[k]);
        acb_calc_integrate(quad, integrand, e, a, b, prec, tol, NULL, prec);
        CHECK_MSG(arb_overlaps(closed, acb_realref(quad)), "%s: closed form and quadrature disagree", in_class[k]);
        CHECK_CLOSE(closed, acb_realref(quad), 60, prec);
        vigen_expr_free(e);
    }
    for (size_t k = 0; k < sizeof outside / sizeof outside[0]; k++) {
        vigen_expr *e = NULL;
        vigen_error err;
        vigen_error_init(&err);
        CHECK(vigen_expr_parse(&e, outside[k], 1, &err) == VIGEN_OK);
        if (e == NULL) continue;
        CHECK_MSG(!vigen_expr_integral_closed_form(closed, e, x, prec), "%s: claims a closed form", outside[k]);
        vigen_expr_free(e);
    }
    /* t^k for k far beyond quadrature (the integrand is below 2^-10^8 on
     * most of [0, 3/7]): int_0^x t^k = x^(k+1) / (k+1) */
    {
        vigen_expr *e = NULL;
        vigen_error err;
        vigen_error_init(&err);
        CHECK(vigen_expr_parse(&e, "t^100000000", 1, &err) == VIGEN_OK);
        if (e != NULL) {
            arb_t ref;
            arb_init(ref);
            arb_pow_ui(ref, x, 100000001, prec);
            arb_div_ui(ref, ref, 100000001, prec);
            CHECK_MSG(vigen_expr_integral_closed_form(closed, e, x, prec), "t^100000000: no closed form");
            CHECK(arb_overlaps(closed, ref));
            CHECK_CLOSE(closed, ref, 60, prec);
            arb_clear(ref);
            vigen_expr_free(e);
        }
    }
    /* t^k, k = 111783.5 (found by the spec fuzz harness): x^(k+1) / (k+1) */
    {
        vigen_expr *e = NULL;
        vigen_error err;
        vigen_error_init(&err);
        CHECK(vigen_expr_parse(&e, "t^111783.5", 1, &err) == VIGEN_OK);
        if (e != NULL) {
            arb_t ref, k1;
            arb_init(ref);
            arb_init(k1);
            arb_set_ui(k1, 223569);
            arb_mul_2exp_si(k1, k1, -1);               /* k + 1 = 111784.5 */
            arb_pow(ref, x, k1, prec);
            arb_div(ref, ref, k1, prec);
            CHECK_MSG(vigen_expr_integral_closed_form(closed, e, x, prec), "t^111783.5: no closed form");
            CHECK(arb_overlaps(closed, ref));
            CHECK_CLOSE(closed, ref, 60, prec);
            arb_clear(ref);
            arb_clear(k1);
            vigen_expr_free(e);
        }
    }
    arb_clear(x); arb_clear(closed);
    acb_clear(a); acb_clear(b); acb_clear(quad); mag_clear(tol);
}

int main(void)
{
    test_closed_form_integrals();
    test_poly();
    test_acb();
    test_integrals();
    TEST_MAIN_END();
}
