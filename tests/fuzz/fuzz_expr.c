/* fuzz_expr.c — libFuzzer harness for exact expressions (src/core/expr.h):
 * the input is parsed as a constant and as a function of t; what parses is
 * evaluated in balls at a modest precision, printed as LaTeX, converted
 * exactly (Q, Q(sqrt d)) and, as a function of t, turned into a polynomial
 * and integrated in closed form.  Properties checked: a text that parses
 * without t parses with t; an exact value found by the exact conversions
 * lies in the ball the evaluator returns. */
#include <arb.h>
#include <acb.h>
#include "core/expr.h"
#include "fuzz_common.h"

enum { PREC = 128 };

static void constant(vigen_expr *e)
{
    vigen_error err;
    vigen_error_init(&err);
    arb_t v;
    arb_init(v);
    int rc = vigen_expr_eval_arb(v, e, NULL, PREC, &err);
    FUZZ_ASSERT(rc == VIGEN_OK || err.message != NULL);

    fmpq_t q, a, b;
    fmpz_t d;
    fmpq_init(q);
    fmpq_init(a);
    fmpq_init(b);
    fmpz_init(d);
    if (vigen_expr_to_fmpq(q, e) && rc == VIGEN_OK) {
        /* an exact rational value is inside the certified ball */
        FUZZ_ASSERT(arb_contains_fmpq(v, q));
    }
    if (vigen_expr_to_quadratic(a, b, d, e) && rc == VIGEN_OK) {
        /* a + b sqrt(d) overlaps the certified ball */
        arb_t w, x;
        arb_init(w);
        arb_init(x);
        arb_sqrt_fmpz(w, d, PREC);
        arb_set_fmpq(x, b, PREC);
        arb_mul(w, w, x, PREC);
        arb_set_fmpq(x, a, PREC);
        arb_add(w, w, x, PREC);
        FUZZ_ASSERT(arb_overlaps(v, w));
        arb_clear(x);
        arb_clear(w);
    }
    (void)vigen_expr_magnitude_span_bits(e);
    fmpq_clear(q);
    fmpq_clear(a);
    fmpq_clear(b);
    fmpz_clear(d);
    arb_clear(v);
    vigen_error_clear(&err);
}

static void of_t(vigen_expr *e)
{
    vigen_error err;
    vigen_error_init(&err);
    arb_t t, v;
    arb_init(t);
    arb_init(v);
    arb_set_si(t, 1);
    arb_div_si(t, t, 3, PREC);
    (void)vigen_expr_eval_arb(v, e, t, PREC, &err);

    acb_t ct, cv;
    acb_init(ct);
    acb_init(cv);
    acb_set_arb(ct, t);
    (void)vigen_expr_eval_acb(cv, e, ct, 1, PREC);

    arb_poly_t p;
    arb_poly_init(p);
    if (vigen_expr_to_arb_poly(p, e, PREC) && arb_poly_degree(p) <= 64) {
        arb_t pv;
        arb_init(pv);
        arb_poly_evaluate(pv, p, t, PREC);
        /* the polynomial and the expression agree at t */
        if (vigen_expr_eval_arb(v, e, t, PREC, &err) == VIGEN_OK) FUZZ_ASSERT(arb_overlaps(pv, v));
        arb_clear(pv);
    }
    arb_set_si(t, 1);
    arb_mul_2exp_si(t, t, -1);
    (void)vigen_expr_integral_closed_form(v, e, t, PREC);
    arb_poly_clear(p);
    acb_clear(ct);
    acb_clear(cv);
    arb_clear(t);
    arb_clear(v);
    vigen_error_clear(&err);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_cstring(data, size);
    vigen_error err;
    vigen_error_init(&err);

    vigen_expr *c = NULL, *f = NULL;
    int rc_c = vigen_expr_parse(&c, text, 0, &err);
    FUZZ_ASSERT(rc_c == VIGEN_OK ? c != NULL : err.message != NULL);
    vigen_error_clear(&err);
    int rc_f = vigen_expr_parse(&f, text, 1, &err);
    FUZZ_ASSERT(rc_f == VIGEN_OK ? f != NULL : err.message != NULL);
    vigen_error_clear(&err);
    if (rc_c == VIGEN_OK) {
        FUZZ_ASSERT(rc_f == VIGEN_OK);
        FUZZ_ASSERT(!vigen_expr_depends_on_t(c));
        constant(c);
        char *latex = vigen_expr_latex(c);
        FUZZ_ASSERT(latex != NULL);
        free(latex);
    }
    if (rc_f == VIGEN_OK) {
        of_t(f);
        char *latex = vigen_expr_latex(f);
        FUZZ_ASSERT(latex != NULL);
        free(latex);
    }
    vigen_expr_free(c);
    vigen_expr_free(f);
    free(text);
    return 0;
}
