/* test_expr_exact.c — what expressions say exactly (expr.h): their LaTeX,
 * their exact value in Q or Q(sqrt d), and decimals read rounded, as the
 * entries of a tableau file are (the ball of half a unit in the last digit).
 *
 * Every expected value is worked out by hand or from the definition of the
 * rounding, not taken from the code. */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq.h>
#include "test_expr.h"

/* LaTeX of entries as a paper would typeset them. */
static void test_latex(void)
{
    static const char *const cases[][2] = {
        { "1/4 - sqrt(3)/6", "\\frac{1}{4} - \\frac{\\sqrt{3}}{6}" },
        { "1/2 + sqrt(15)/10", "\\frac{1}{2} + \\frac{\\sqrt{15}}{10}" },
        { "2*pi", "2 \\pi" },
        { "-(1 + 2)", "-\\left(1 + 2\\right)" },
        { "1 - (2 - 3)", "1 - \\left(2 - 3\\right)" },
        { "(1 - 2) - 3", "1 - 2 - 3" },
        { "1 - -2", "1 - \\left(-2\\right)" },
        { "2*(3 + t)", "2 \\cdot \\left(3 + t\\right)" },
        { "2^-1", "2^{-1}" },
        { "(1/2)^3", "\\left(\\frac{1}{2}\\right)^{3}" },
        { "2.5e-3", "2.5\\times 10^{-3}" },
        { "cos(pi/7)", "\\cos\\left(\\frac{\\pi}{7}\\right)" },
        { "exp(t)*sin(2*t)", "\\exp\\left(t\\right) \\cdot \\sin\\left(2 t\\right)" },
        { "1/(2 - 2^(1/3))", "\\frac{1}{2 - 2^{\\frac{1}{3}}}" },
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        vigen_expr *e = NULL;
        vigen_error err;
        vigen_error_init(&err);
        CHECK(vigen_expr_parse(&e, cases[k][0], 1, &err) == VIGEN_OK);
        char *l = e ? vigen_expr_latex(e) : NULL;
        CHECK_MSG(l && strcmp(l, cases[k][1]) == 0, "LaTeX of %s: %s, expected %s", cases[k][0], l ? l : "(none)", cases[k][1]);
        free(l);
        vigen_expr_free(e);
        vigen_error_clear(&err);
    }
}

/* Parses the constant text (checking that it parses) and converts it with
 * vigen_expr_to_quadratic (quadratic) or vigen_expr_to_fmpq; its result. */
static int exact_value(fmpq_t a, fmpq_t b, fmpz_t d, const char *text, int quadratic)
{
    vigen_expr *e = NULL;
    vigen_error err;
    vigen_error_init(&err);
    int rc = vigen_expr_parse(&e, text, 0, &err);
    CHECK_MSG(rc == VIGEN_OK, "parse \"%s\": %s", text, err.message ? err.message : "");
    int got = rc == VIGEN_OK && (quadratic ? vigen_expr_to_quadratic(a, b, d, e) : vigen_expr_to_fmpq(a, e));
    vigen_expr_free(e);
    vigen_error_clear(&err);
    return got;
}

/* Values in Q(sqrt d), each worked out by hand: rationalised denominators,
 * square factors pulled out of the radicand, conjugate products. */
static void test_quadratic(void)
{
    static const char *const ok[][4] = {
        /* text, a, b, d */
        { "1/(2 - sqrt(3))", "2", "1", "3" },                 /* (2 + sqrt 3)/(4 - 3) */
        { "sqrt(12)", "0", "2", "3" },
        { "(1 + sqrt(5))^2/4", "3/2", "1/2", "5" },           /* (6 + 2 sqrt 5)/4 */
        { "sqrt(3/4)", "0", "1/2", "3" },
        { "sqrt(2/3)", "0", "1/3", "6" },                     /* sqrt(6)/3 */
        { "1/sqrt(2)", "0", "1/2", "2" },
        { "(1 + sqrt(2))^-3", "-7", "5", "2" },               /* (sqrt 2 - 1)^3 */
        { "sqrt(7)^3", "0", "7", "7" },
        { "-sqrt(10)/-5", "0", "1/5", "10" },
        { "5/36 - sqrt(15)/30", "5/36", "-1/30", "15" },      /* Gauss-3, a_13 */
        { "2.5e-3*sqrt(5)", "0", "1/400", "5" },
        { "sqrt(2/10^60)", "0", "1/1000000000000000000000000000000", "2" },   /* 1/(2^59 5^60) */
        { "sqrt(3*2^65)", "0", "4294967296", "6" },
        { "sqrt(5*(2^61 - 1)^2)", "0", "2305843009213693951", "5" },          /* a large square cofactor */
        /* rational values: d = 1, b = 0 */
        { "sqrt(2)^2", "2", "0", "1" },
        { "sqrt(8) - 2*sqrt(2)", "0", "0", "1" },
        { "(2 + sqrt(3))*(2 - sqrt(3))", "1", "0", "1" },
        { "sqrt(4)", "2", "0", "1" },
        { "sqrt(1/10^60)", "1/1000000000000000000000000000000", "0", "1" },
        { "0.5 + sqrt(0)", "1/2", "0", "1" },
        /* one field after all: sqrt(2)^2 is rational */
        { "sqrt(2)*sqrt(2) + sqrt(3)", "2", "1", "3" },
    };
    static const char *const refused[] = {
        "sqrt(2)*sqrt(3)",          /* = sqrt(6), but from two fields */
        "sqrt(6)/sqrt(2)",
        "sqrt(2) + sqrt(3)",        /* of degree 4 */
        "sqrt(-3)", "pi", "exp(1)", "sqrt(sqrt(2))", "sqrt(1 + sqrt(2))", "2^(1/2)",
        "1/(sqrt(3) - sqrt(3))", "0^-1",
        "(1 + sqrt(2))^5000",       /* beyond the exponent limit */
        "sqrt((2^61 - 1)*(2^31 - 1))",   /* two primes > 4096: a non-square cofactor of 92 bits */
    };
    fmpq_t a, b, wa, wb;
    fmpz_t d, wd;
    arb_t x, y, r;
    fmpq_init(a); fmpq_init(b); fmpq_init(wa); fmpq_init(wb);
    fmpz_init(d); fmpz_init(wd);
    arb_init(x); arb_init(y); arb_init(r);
    for (size_t k = 0; k < sizeof ok / sizeof ok[0]; k++) {
        fmpq_set_str(wa, ok[k][1], 10);
        fmpq_set_str(wb, ok[k][2], 10);
        fmpz_set_str(wd, ok[k][3], 10);
        int got = exact_value(a, b, d, ok[k][0], 1);
        CHECK_MSG(got && fmpq_equal(a, wa) && fmpq_equal(b, wb) && fmpz_equal(d, wd), "%s as a + b sqrt(d)", ok[k][0]);
        /* and a + b sqrt(d) is the value the expression evaluates to */
        if (got) {
            arb_sqrt_fmpz(r, d, 256);
            arb_mul_fmpz(r, r, fmpq_numref(b), 256);
            arb_div_fmpz(r, r, fmpq_denref(b), 256);
            arb_set_fmpq(y, a, 256);
            arb_add(y, y, r, 256);
            CHECK(eval_text(x, ok[k][0], NULL, 256) == VIGEN_OK);
            CHECK_MSG(arb_overlaps(x, y), "%s", ok[k][0]);
        }
    }
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; k++)
        CHECK_MSG(!exact_value(a, b, d, refused[k], 1), "%s is not in one Q(sqrt d)", refused[k]);
    /* vigen_expr_to_fmpq takes no square roots, even of squares */
    static const char *const rat[][2] = { { "1/3 + 2^-2", "7/12" }, { "(1/2)^-3", "8" }, { "-0.125e1", "-5/4" } };
    for (size_t k = 0; k < sizeof rat / sizeof rat[0]; k++) {
        fmpq_set_str(wa, rat[k][1], 10);
        CHECK_MSG(exact_value(a, NULL, NULL, rat[k][0], 0) && fmpq_equal(a, wa), "%s = %s", rat[k][0], rat[k][1]);
    }
    static const char *const not_rat[] = { "sqrt(4)", "sqrt(3)", "pi", "1/0" };
    for (size_t k = 0; k < sizeof not_rat / sizeof not_rat[0]; k++)
        CHECK_MSG(!exact_value(a, NULL, NULL, not_rat[k], 0), "%s is not taken as rational", not_rat[k]);
    fmpq_clear(a); fmpq_clear(b); fmpq_clear(wa); fmpq_clear(wb);
    fmpz_clear(d); fmpz_clear(wd);
    arb_clear(x); arb_clear(y); arb_clear(r);
}

/* ---- decimals read rounded (tableau entries) ---------------------------- */

/* Parses text, reads its decimals rounded, evaluates at prec. */
static int rounded_eval(arb_t res, const char *text, slong prec, int *ndec)
{
    vigen_error err;
    vigen_expr *e = NULL;
    vigen_error_init(&err);
    int rc = vigen_expr_parse(&e, text, 0, &err);
    if (rc == VIGEN_OK) {
        *ndec = vigen_expr_round_decimals(e);
        rc = vigen_expr_eval_arb(res, e, NULL, prec, &err);
    }
    vigen_expr_free(e);
    vigen_error_clear(&err);
    return rc;
}

/* 1 when the ball res contains lo and hi and is at most widen times as wide
 * as hi - lo: the interval of the rounded value, and not much more */
static int encloses_interval(const arb_t res, const arb_t lo, const arb_t hi, double widen)
{
    arb_t span;
    arb_init(span);
    arb_sub(span, hi, lo, 256);
    arb_t w;
    arb_init(w);
    arb_set_d(w, widen);
    arb_mul(span, span, w, 256);
    arb_clear(w);
    arf_t width;
    arf_init(width);
    arf_set_mag(width, arb_radref(res));
    arf_mul_2exp_si(width, width, 1);
    int ok = arb_contains(res, lo) && arb_contains(res, hi) && arf_cmp(width, arb_midref(span)) <= 0;
    arf_clear(width);
    arb_clear(span);
    return ok;
}

static void test_rounded_decimals(void)
{
    slong prec = 256;
    arb_t v, lo, hi, r3;
    arb_init(v);
    arb_init(lo);
    arb_init(hi);
    arb_init(r3);
    int nd = -1;
    /* "0.5*sqrt(3)": 0.5 stands for [0.45, 0.55], so the value for
     * [0.45 sqrt 3, 0.55 sqrt 3], and nothing much wider */
    CHECK(rounded_eval(v, "0.5*sqrt(3)", prec, &nd) == VIGEN_OK && nd == 1);
    arb_sqrt_ui(r3, 3, prec);
    arb_set_ui(lo, 45);
    arb_div_ui(lo, lo, 100, prec);
    arb_mul(lo, lo, r3, prec);
    arb_set_ui(hi, 55);
    arb_div_ui(hi, hi, 100, prec);
    arb_mul(hi, hi, r3, prec);
    CHECK_MSG(encloses_interval(v, lo, hi, 1.000001), "0.5*sqrt(3) rounded is not [0.45, 0.55] sqrt 3");
    /* the unit is that of the last digit written: "0.500" is 0.5 +/- 0.0005 */
    CHECK(rounded_eval(v, "1 - 0.500", prec, &nd) == VIGEN_OK && nd == 1);
    arb_set_str(lo, "0.4995", prec);
    arb_set_str(hi, "0.5005", prec);
    CHECK(encloses_interval(v, lo, hi, 1.000001));
    /* an exponent without a point is a decimal too: "25e-3" is 0.025 +/- 0.0005 */
    CHECK(rounded_eval(v, "25e-3 + 1/4", prec, &nd) == VIGEN_OK && nd == 1);
    arb_set_str(lo, "0.2745", prec);
    arb_set_str(hi, "0.2755", prec);
    CHECK(encloses_interval(v, lo, hi, 1.000001));
    /* a written zero keeps its unit: "0.000" is 0 +/- 0.0005 */
    CHECK(rounded_eval(v, "0.000 + 1", prec, &nd) == VIGEN_OK && nd == 1);
    arb_set_str(lo, "0.9995", prec);
    arb_set_str(hi, "1.0005", prec);
    CHECK(encloses_interval(v, lo, hi, 1.000001));
    /* integers and fractions stay exact */
    CHECK(rounded_eval(v, "1/4 - 3/2", prec, &nd) == VIGEN_OK && nd == 0);
    CHECK(arb_is_exact(v));
    arb_set_si(lo, -5);
    arb_div_ui(lo, lo, 4, prec);
    CHECK(arb_equal(v, lo));
    /* a decimal exponent is no longer an exact integer power: (-2)^2.0 needs
     * a positive base, where (-2)^2 is 4 */
    CHECK(rounded_eval(v, "(-2)^2.0", prec, &nd) != VIGEN_OK && nd == 1);
    CHECK(rounded_eval(v, "(-2)^2", prec, &nd) == VIGEN_OK && nd == 0 && arb_equal_si(v, 4));

    /* the exact conversions decline rounded decimals, and accept them unread */
    vigen_error err;
    vigen_error_init(&err);
    vigen_expr *e = NULL;
    fmpq_t a, b;
    fmpz_t d;
    fmpq_init(a);
    fmpq_init(b);
    fmpz_init(d);
    CHECK(vigen_expr_parse(&e, "0.25 + sqrt(12)/2", 0, &err) == VIGEN_OK);
    CHECK(vigen_expr_decimal_count(e) == 1);
    CHECK(vigen_expr_to_quadratic(a, b, d, e) == 1 && fmpz_equal_si(d, 3));   /* 1/4 + sqrt(3) */
    vigen_expr_round_decimals(e);
    CHECK(vigen_expr_to_quadratic(a, b, d, e) == 0);
    CHECK(vigen_expr_to_fmpq(a, e) == 0);
    vigen_expr_free(e);
    /* the shortest and the longest literal */
    CHECK(vigen_expr_parse(&e, "0.1234567891 * 2 - 0.50 + 1e-3", 0, &err) == VIGEN_OK);
    char *shortest = vigen_expr_shortest_decimal(e);
    CHECK(shortest != NULL && strcmp(shortest, "1e-3") == 0);
    free(shortest);
    CHECK(vigen_expr_longest_decimal_digits(e) == 10);
    vigen_expr_free(e);
    CHECK(vigen_expr_parse(&e, "sqrt(3)/6", 0, &err) == VIGEN_OK);
    CHECK(vigen_expr_shortest_decimal(e) == NULL && vigen_expr_longest_decimal_digits(e) == 0);
    vigen_expr_free(e);
    vigen_error_clear(&err);
    fmpq_clear(a);
    fmpq_clear(b);
    fmpz_clear(d);
    arb_clear(v);
    arb_clear(lo);
    arb_clear(hi);
    arb_clear(r3);
}

int main(void)
{
    test_rounded_decimals();
    test_quadratic();
    test_latex();
    TEST_MAIN_END();
}
