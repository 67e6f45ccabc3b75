/* test_expr.c — the expression parser and its ball evaluation (expr.h).
 *
 * Every expected value comes from mathematics, not from the code: identities
 * (sin(pi/6) = 1/2, exp(log 2) = 2), exact rationals written independently
 * with fmpq, reference values computed directly with arb functions, and
 * closed-form integrals. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <acb_calc.h>
#include <flint/fmpq.h>
#include "core/expr.h"
#include "testlib.h"
#include "support/strbuf.h"

/* ---- helpers ----------------------------------------------------------- */

/* Parses and evaluates text (t may be NULL); checks success. */
static int eval_text(arb_t res, const char *text, const arb_t t, slong prec)
{
    vigen_error err;
    vigen_expr *e = NULL;
    vigen_error_init(&err);
    int rc = vigen_expr_parse(&e, text, t != NULL, &err);
    CHECK_MSG(rc == VIGEN_OK, "parse \"%s\": %s", text, err.message ? err.message : "");
    if (rc == VIGEN_OK) {
        rc = vigen_expr_eval_arb(res, e, t, prec, &err);
        CHECK_MSG(rc == VIGEN_OK, "eval \"%s\": %s", text, err.message ? err.message : "");
    }
    vigen_expr_free(e);
    vigen_error_clear(&err);
    return rc;
}

/* text evaluates at prec to a ball that contains p/q and has at least
 * min_bits of relative accuracy (absolute when p = 0). */
static void check_rational(const char *text, slong p, ulong q, slong prec, slong min_bits)
{
    arb_t x, y;
    fmpq_t r;
    arb_init(x); arb_init(y); fmpq_init(r);
    fmpq_set_si(r, p, q);
    if (eval_text(x, text, NULL, prec) == VIGEN_OK) {
        arb_set_fmpq(y, r, prec + 64);
        CHECK_MSG(arb_contains(x, y), "\"%s\" at %ld bits does not contain %ld/%lu", text, (long)prec, (long)p, q);
        if (p != 0)
            CHECK_MSG(arb_rel_accuracy_bits(x) >= min_bits, "\"%s\" at %ld bits: only %ld accurate bits",
                      text, (long)prec, (long)arb_rel_accuracy_bits(x));
        else
            CHECK_MSG(mag_cmp_2exp_si(arb_radref(x), -min_bits) <= 0, "\"%s\": radius too large", text);
    }
    arb_clear(x); arb_clear(y); fmpq_clear(r);
}

/* text evaluates to exactly the integer v (a ball of radius 0). */
static void check_exact_int(const char *text, slong v)
{
    arb_t x;
    arb_init(x);
    if (eval_text(x, text, NULL, 64) == VIGEN_OK)
        CHECK_MSG(arb_is_exact(x) && arb_equal_si(x, v), "\"%s\" is not exactly %ld", text, (long)v);
    arb_clear(x);
}

/* text evaluates to a ball containing ref and within digits of it. */
static void check_value(const char *text, const arb_t t, const arb_t ref, slong digits, slong prec)
{
    arb_t x;
    arb_init(x);
    if (eval_text(x, text, t, prec) == VIGEN_OK) {
        CHECK_MSG(arb_overlaps(x, ref), "\"%s\" does not overlap the reference", text);
        CHECK_CLOSE(x, ref, digits, prec);
    }
    arb_clear(x);
}

static int contains(const char *haystack, const char *needle)
{
    return haystack != NULL && strstr(haystack, needle) != NULL;
}

/* Parsing text fails with a syntax error whose message contains each of the
 * given phrases (NULL-terminated) and quotes the text. */
static void check_syntax_error(const char *text, int allow_t, ...)
{
    vigen_error err;
    vigen_expr *e = (vigen_expr *)&err;    /* must be reset to NULL */
    vigen_error_init(&err);
    int rc = vigen_expr_parse(&e, text, allow_t, &err);
    CHECK_MSG(rc == VIGEN_E_SYNTAX && err.code == VIGEN_E_SYNTAX, "\"%s\" should be a syntax error (rc %d)", text, rc);
    CHECK_MSG(e == NULL, "\"%s\": *out not NULL after an error", text);
    if (rc == VIGEN_OK) vigen_expr_free(e);
    char *quoted = vigen_strdup_printf("\"%s\"", text);
    CHECK_MSG(contains(err.message, quoted), "\"%s\": message does not quote the text: %s", text,
              err.message ? err.message : "(none)");
    free(quoted);
    va_list ap;
    va_start(ap, allow_t);
    for (const char *phrase; (phrase = va_arg(ap, const char *)) != NULL; )
        CHECK_MSG(contains(err.message, phrase), "\"%s\": message lacks \"%s\": %s", text, phrase,
                  err.message ? err.message : "(none)");
    va_end(ap);
    vigen_error_clear(&err);
}

/* Evaluating text (with t, or NULL) fails with a domain error whose message
 * contains the phrase, quotes the text, and mentions "precision" exactly when
 * undecided is set. */
static void check_domain_error(const char *text, const arb_t t, slong prec, const char *phrase, int undecided)
{
    vigen_error err;
    vigen_expr *e = NULL;
    arb_t x;
    arb_init(x);
    vigen_error_init(&err);
    int rc = vigen_expr_parse(&e, text, 1, &err);
    CHECK_MSG(rc == VIGEN_OK, "parse \"%s\": %s", text, err.message ? err.message : "");
    if (rc == VIGEN_OK) {
        rc = vigen_expr_eval_arb(x, e, t, prec, &err);
        CHECK_MSG(rc == VIGEN_E_DOMAIN && err.code == VIGEN_E_DOMAIN, "\"%s\" should be a domain error (rc %d)", text, rc);
        CHECK_MSG(!arb_is_finite(x), "\"%s\": the result after a domain error should be indeterminate", text);
        char *quoted = vigen_strdup_printf("\"%s\"", text);
        CHECK_MSG(contains(err.message, quoted), "\"%s\": message does not quote the text: %s", text,
                  err.message ? err.message : "(none)");
        free(quoted);
        CHECK_MSG(contains(err.message, phrase), "\"%s\": message lacks \"%s\": %s", text, phrase,
                  err.message ? err.message : "(none)");
        CHECK_MSG(contains(err.message, "at this precision") == (undecided != 0),
                  "\"%s\": \"at this precision\" should%s be in: %s", text, undecided ? "" : " not",
                  err.message ? err.message : "(none)");
    }
    vigen_expr_free(e);
    vigen_error_clear(&err);
    arb_clear(x);
}

/* ---- identities -------------------------------------------------------- */

static void test_identities(void)
{
    slong prec = 360;   /* > 100 decimal digits */
    check_rational("sin(pi/6)", 1, 2, prec, 330);
    check_rational("cos(pi)^2 + sin(pi)^2", 1, 1, prec, 330);
    check_rational("exp(log(2))", 2, 1, prec, 330);
    check_rational("sqrt(2)^2", 2, 1, prec, 330);
    check_rational("tan(pi/4)", 1, 1, prec, 330);
    check_rational("cos(pi/3)", 1, 2, prec, 330);
    check_rational("log(2) + log(3) - log(6)", 0, 1, prec, 330);
    check_rational("exp(1)*exp(-1)", 1, 1, prec, 330);
    check_rational("2*sin(pi/12)*cos(pi/12)", 1, 2, prec, 330);

    /* references computed directly with arb */
    arb_t ref, u;
    arb_init(ref); arb_init(u);
    arb_const_e(ref, prec);
    check_value("exp(1)", NULL, ref, 100, prec);
    arb_const_pi(ref, prec);
    check_value("4*(pi/4)", NULL, ref, 100, prec);
    arb_set_ui(ref, 3); arb_sqrt(ref, ref, prec);
    check_value("sqrt(3)", NULL, ref, 100, prec);
    arb_set_ui(ref, 10); arb_log(ref, ref, prec);
    check_value("log(10)", NULL, ref, 100, prec);

    /* t as a variable: sin^2 + cos^2 = 1 at t = 7/10 */
    arb_set_ui(u, 7); arb_div_ui(u, u, 10, prec);
    arb_one(ref);
    check_value("sin(t)^2 + cos(t)^2", u, ref, 100, prec);
    arb_clear(ref); arb_clear(u);
}

/* ---- exact numbers ----------------------------------------------------- */

static void test_numbers(void)
{
    check_rational("0.1*10", 1, 1, 64, 60);
    check_rational("0.1", 1, 10, 64, 60);
    check_rational("2.5e-3", 1, 400, 3000, 2990);
    check_rational("2.5e-3*400", 1, 1, 3000, 2990);
    check_rational("0.3 - 0.1 - 0.2", 0, 1, 64, 60);
    check_rational(".5", 1, 2, 64, 64);
    check_rational("1.25E-1", 1, 8, 64, 64);
    check_rational("12.5e+0", 25, 2, 64, 64);
    check_rational("7e-1", 7, 10, 200, 195);
    check_exact_int("0e-40", 0);
    check_exact_int("0.000", 0);
    check_exact_int("1e3", 1000);
    check_exact_int("1E+2", 100);
    check_exact_int("00012.500*2", 25);
    check_exact_int("2.5e1", 25);
    check_exact_int("  1 +\t2 *\n3 ", 7);
    check_exact_int("10 - 2 - 3", 5);       /* left associative */
    check_exact_int("24 / 4 / 2", 3);
    check_exact_int("-3 + +4", 1);
    check_exact_int("2*-3", -6);
    check_exact_int("1--1", 2);

    /* a number wider than a machine word */
    check_rational("123456789012345678901234567890 - 123456789012345678901234567889", 1, 1, 200, 190);

    /* huge decimal exponents (rounded through a power of ten) */
    check_rational("1e-5000 * 10^5000", 1, 1, 256, 240);
    check_rational("3e5000 / 10^5000", 3, 1, 256, 240);
    arb_t x;
    arb_init(x);
    if (eval_text(x, "1e-5000", NULL, 64) == VIGEN_OK) CHECK(arb_is_positive(x));
    arb_clear(x);
}

/* ---- powers ------------------------------------------------------------ */

static void test_powers(void)
{
    check_exact_int("2^3^2", 512);            /* right associative: 2^9 */
    check_exact_int("(2^3)^2", 64);
    check_exact_int("(-2)^3", -8);
    check_exact_int("-2^2", -4);              /* unary minus binds looser than ^ */
    check_exact_int("2^(4/2)", 4);
    check_exact_int("(-3)^(4/2)", 9);         /* constant exponent that is an integer */
    check_exact_int("(-3)^(1+1)", 9);
    check_exact_int("(-2)^sqrt(4)", 4);       /* sqrt(4) is exactly 2 */
    check_exact_int("(-5)^0", 1);
    check_exact_int("(1-1)^2", 0);
    check_rational("2^-1", 1, 2, 64, 64);
    check_rational("(-2)^-3", -1, 8, 64, 64);
    check_rational("2^-2^2", 1, 16, 64, 64);  /* 2^(-(2^2)) */
    check_rational("(2/3)^-2", 9, 4, 128, 120);
    check_rational("8^(1/3)", 2, 1, 256, 240);
    check_rational("4^0.5", 2, 1, 256, 240);
    check_rational("27^(2/3)", 9, 1, 256, 240);
    check_rational("2^(1/2) * 2^(1/2)", 2, 1, 256, 240);

    /* a large exact integer power: 3^100 against fmpz */
    fmpz_t z;
    arb_t x, ref;
    fmpz_init(z); arb_init(x); arb_init(ref);
    fmpz_ui_pow_ui(z, 3, 100);
    arb_set_fmpz(ref, z);
    if (eval_text(x, "3^100", NULL, 256) == VIGEN_OK) CHECK(arb_is_exact(x) && arb_equal(x, ref));
    /* a non-integer power with t: t^t at t = 2 is 4 */
    arb_set_ui(ref, 2);
    if (eval_text(x, "t^t", ref, 128) == VIGEN_OK) {
        arb_set_ui(ref, 4);
        CHECK(arb_contains(x, ref));
        CHECK_CLOSE(x, ref, 30, 128);
    }
    fmpz_clear(z); arb_clear(x); arb_clear(ref);
}

/* ---- Gauss-Legendre node and precision ladder -------------------------- */

static void test_gauss_legendre(void)
{
    slong precs[] = { 64, 128, 333, 1000, 3000, 7000 };
    mag_t prev;
    mag_init(prev);
    mag_inf(prev);
    for (size_t i = 0; i < sizeof(precs) / sizeof(precs[0]); i++) {
        slong prec = precs[i];
        arb_t c, p, zero, half;
        arb_init(c); arb_init(p); arb_init(zero); arb_init(half);
        if (eval_text(c, "1/2 - sqrt(3)/6", NULL, prec) == VIGEN_OK) {
            /* 6c^2 - 6c + 1 = 0 (Legendre P2 shifted to [0,1]) */
            arb_mul(p, c, c, prec);
            arb_sub(p, p, c, prec);
            arb_mul_ui(p, p, 6, prec);
            arb_add_ui(p, p, 1, prec);
            CHECK(arb_contains(p, zero));
            CHECK_MSG(mag_cmp_2exp_si(arb_radref(p), -(prec - 8)) <= 0, "radius at %ld bits too large", (long)prec);
            CHECK(arb_rel_accuracy_bits(c) >= prec - 8);
            /* the radius shrinks as the precision grows */
            CHECK(mag_cmp(arb_radref(c), prev) < 0);
            mag_set(prev, arb_radref(c));
            /* c in (0, 1/2) */
            arb_set_si(half, 1); arb_mul_2exp_si(half, half, -1);
            CHECK(arb_is_positive(c) && arb_lt(c, half));
        }
        /* the same identity written as one expression */
        if (eval_text(p, "6*(1/2 - sqrt(3)/6)^2 - 6*(1/2 - sqrt(3)/6) + 1", NULL, prec) == VIGEN_OK) {
            CHECK(arb_contains(p, zero));
            CHECK(mag_cmp_2exp_si(arb_radref(p), -(prec - 8)) <= 0);
        }
        /* and sin(pi/6) at every precision */
        check_rational("sin(pi/6)", 1, 2, prec, prec - 8);
        arb_clear(c); arb_clear(p); arb_clear(zero); arb_clear(half);
    }
    mag_clear(prev);
}

/* ---- syntax errors ----------------------------------------------------- */

static void test_syntax_errors(void)
{
    check_syntax_error("1 +", 0, "unexpected end of expression", "column 4", NULL);
    check_syntax_error("cosh(t)", 1, "unknown name 'cosh'", "column 1",
                       "(known: pi, t, sqrt, exp, log, sin, cos, tan)", NULL);
    check_syntax_error("1+t", 0, "the variable t is not allowed here (constants only)", "column 3", NULL);
    check_syntax_error("(1+2", 0, "unbalanced parentheses", "missing ')'", "column 1", NULL);
    check_syntax_error("sqrt(2*(1+2)", 0, "unbalanced parentheses", "column 5", NULL);
    check_syntax_error("1+2)", 0, "unbalanced parentheses", "column 4", NULL);
    check_syntax_error("", 0, "empty expression", NULL);
    check_syntax_error("   ", 0, "empty expression", NULL);
    check_syntax_error("1.2.3", 0, "malformed number '1.2.3'", "column 1", NULL);
    check_syntax_error("2*1..5", 0, "malformed number", "column 3", NULL);
    check_syntax_error("1.", 0, "malformed number", "decimal point", NULL);
    check_syntax_error(".", 0, "malformed number", NULL);
    check_syntax_error("1e", 0, "malformed number '1e'", "exponent", NULL);
    check_syntax_error("1e+", 0, "malformed number", "exponent", NULL);
    check_syntax_error("2pi", 0, "missing operator", "column 2", "implicit multiplication", "2*pi", NULL);
    check_syntax_error("3 t", 1, "missing operator", "3*t", NULL);
    check_syntax_error("2(1+t)", 1, "missing operator", "implicit multiplication", NULL);
    check_syntax_error("(1+t)(1-t)", 1, "missing operator", "column 6", NULL);
    check_syntax_error("2exp(1)", 0, "missing operator", "2*exp", NULL);
    check_syntax_error("1 2", 0, "missing operator", "column 3", NULL);
    check_syntax_error("sqrt 2", 0, "expected '('", "sqrt", "column 6", NULL);
    check_syntax_error("sin", 0, "expected '('", NULL);
    check_syntax_error("()", 0, "unexpected ')'", "column 2", NULL);
    check_syntax_error("1 + * 2", 0, "unexpected '*'", "column 5", NULL);
    check_syntax_error("1 $", 0, "unexpected '$'", "column 3", NULL);
    check_syntax_error("1,5", 0, "unexpected ','", "column 2", NULL);
    check_syntax_error("(1 # 2)", 0, "expected ')'", "column 4", NULL);
    check_syntax_error("PI", 0, "unknown name 'PI'", "case-sensitive", NULL);
    check_syntax_error("e^2", 0, "unknown name 'e'", "exp(1)", NULL);
    check_syntax_error("x", 1, "unknown name 'x'", NULL);
    check_syntax_error("2^", 0, "unexpected end of expression", "column 3", NULL);
    check_syntax_error("sqrt(1", 0, "missing ')'", NULL);

    /* pathological nesting is refused, not a stack overflow */
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    for (int i = 0; i < 5000; i++) vigen_strbuf_append(&sb, "(");
    vigen_strbuf_append(&sb, "1");
    for (int i = 0; i < 5000; i++) vigen_strbuf_append(&sb, ")");
    check_syntax_error(sb.data, 0, "nested too deeply", NULL);
    vigen_strbuf_clear(&sb);
    for (int i = 0; i < 5000; i++) vigen_strbuf_append(&sb, "-");
    vigen_strbuf_append(&sb, "1");
    check_syntax_error(sb.data, 0, "nested too deeply", NULL);
    vigen_strbuf_clear(&sb);
    vigen_strbuf_append(&sb, "1");
    for (int i = 0; i < 5000; i++) vigen_strbuf_append(&sb, "+1");
    check_syntax_error(sb.data, 0, "nested too deeply", NULL);
    vigen_strbuf_clear(&sb);
    /* moderate nesting is fine: 100 parentheses */
    for (int i = 0; i < 100; i++) vigen_strbuf_append(&sb, "(");
    vigen_strbuf_append(&sb, "1");
    for (int i = 0; i < 100; i++) vigen_strbuf_append(&sb, ")");
    check_exact_int(sb.data, 1);
    vigen_strbuf_clear(&sb);

    /* the text and t-dependence are reported */
    vigen_expr *e;
    vigen_error err;
    vigen_error_init(&err);
    CHECK(vigen_expr_parse(&e, "t*pi + 1", 1, &err) == VIGEN_OK);
    CHECK(strcmp(vigen_expr_text(e), "t*pi + 1") == 0);
    CHECK(vigen_expr_depends_on_t(e));
    vigen_expr_free(e);
    CHECK(vigen_expr_parse(&e, "sqrt(2)", 1, &err) == VIGEN_OK);
    CHECK(!vigen_expr_depends_on_t(e));
    vigen_expr_free(e);
    vigen_error_clear(&err);
}

/* ---- domain errors ----------------------------------------------------- */

static void test_domain_errors(void)
{
    arb_t t, x;
    arb_init(t); arb_init(x);

    check_domain_error("log(1-1)", NULL, 64, "log of a value that is not certainly positive", 0);
    check_domain_error("log(-2)", NULL, 64, "log of a value that is not certainly positive", 0);
    check_domain_error("2*log(0)", NULL, 64, "column 3", 0);
    check_domain_error("1/(1-1)", NULL, 64, "division", 0);
    check_domain_error("sqrt(-1)", NULL, 64, "sqrt of a value that is not certainly nonnegative", 0);
    check_domain_error("(-8)^(1/3)", NULL, 64, "not certainly positive", 0);
    check_domain_error("(1-1)^(1/2)", NULL, 64, "not certainly positive", 0);
    check_domain_error("0^-1", NULL, 64, "nonzero", 0);
    check_domain_error("tan(pi/2)", NULL, 64, "tan", 1);

    /* balls that cannot decide at this precision: [0 +/- 1e-30] */
    arb_zero(t);
    mag_set_ui_2exp_si(arb_radref(t), 1, -100);
    check_domain_error("log(t)", t, 64, "log of a value that is not certainly positive", 1);
    check_domain_error("1/t", t, 64, "division by a value that is not certainly nonzero", 1);
    check_domain_error("sqrt(t)", t, 64, "sqrt", 1);
    check_domain_error("t^-2", t, 64, "nonzero", 1);
    check_domain_error("t^(1/2)", t, 64, "not certainly positive", 1);
    /* sin(pi) is 0 but never exactly so in ball arithmetic */
    check_domain_error("1/sin(pi)", NULL, 256, "division", 1);

    /* sqrt of an exact 0 is fine */
    check_exact_int("sqrt(1-1)", 0);

    /* t missing, or not finite */
    check_domain_error("t+1", NULL, 64, "t", 0);
    arb_indeterminate(t);
    check_domain_error("t+1", t, 64, "not finite", 0);

    /* eval_string: constants only */
    vigen_error err;
    vigen_error_init(&err);
    CHECK(vigen_expr_eval_string(x, "1/0", 64, &err) == VIGEN_E_DOMAIN);
    CHECK(contains(err.message, "\"1/0\""));
    CHECK(vigen_expr_eval_string(x, "t", 64, &err) == VIGEN_E_SYNTAX);
    CHECK(contains(err.message, "not allowed"));
    CHECK(vigen_expr_eval_string(x, "sqrt(16)/8", 64, &err) == VIGEN_OK);
    arb_set_d(t, 0.5);   /* 0.5 is exact in binary */
    CHECK(arb_equal(x, t));
    vigen_error_clear(&err);

    /* aliasing: res == t */
    vigen_expr *e;
    vigen_error_init(&err);
    if (vigen_expr_parse(&e, "t*t + t", 1, &err) == VIGEN_OK) {
        arb_set_ui(t, 3);
        CHECK(vigen_expr_eval_arb(t, e, t, 64, &err) == VIGEN_OK);
        CHECK(arb_equal_si(t, 12));
        vigen_expr_free(e);
    }
    vigen_error_clear(&err);
    arb_clear(t); arb_clear(x);
}

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

/* ---- the function table ------------------------------------------------ */

/* Identities that each function of the table must satisfy, written as two
 * expressions in t equal for every t > 0 short of pi/2 (the domain common to
 * all rows).  They are mathematics, not output of the code; a row of
 * functions.def without an entry here fails the test. */
static const struct { const char *name, *lhs, *rhs; } function_identities[] = {
    { "sqrt", "sqrt(t)^2", "t" },
    { "sqrt", "sqrt(4*t)", "2*sqrt(t)" },
    { "exp", "exp(log(t))", "t" },
    { "exp", "exp(2*t)", "exp(t)^2" },
    { "log", "log(exp(t))", "t" },
    { "log", "log(t^3)", "3*log(t)" },
    { "sin", "sin(t)^2 + cos(t)^2", "1" },
    { "sin", "sin(2*t)", "2*sin(t)*cos(t)" },
    { "cos", "cos(2*t)", "1 - 2*sin(t)^2" },
    { "cos", "cos(pi - t)", "-cos(t)" },
    { "tan", "tan(t)", "sin(t)/cos(t)" },
    { "tan", "tan(pi/4)", "1" },
    { "pi", "sin(pi/6)", "1/2" },
    { "pi", "cos(pi)", "-1" },
};

/* lhs and rhs agree at t to about prec - 40 bits. */
static void check_identity(const char *lhs, const char *rhs, const arb_t t, slong prec)
{
    arb_t x, y;
    arb_init(x); arb_init(y);
    if (eval_text(x, lhs, t, prec) == VIGEN_OK && eval_text(y, rhs, t, prec) == VIGEN_OK) {
        arb_sub(x, x, y, prec);
        CHECK_MSG(arb_contains_zero(x) && mag_cmp_2exp_si(arb_radref(x), 40 - prec) <= 0,
                  "%s = %s fails at t = %s", lhs, rhs, arb_get_str(t, 10, 0));
    }
    arb_clear(x); arb_clear(y);
}

static void check_has_identity(const char *name)
{
    int found = 0;
    for (size_t i = 0; i < sizeof function_identities / sizeof function_identities[0]; i++)
        found |= strcmp(function_identities[i].name, name) == 0;
    CHECK_MSG(found, "%s: no identity in function_identities (add one for the new row)", name);
}

/* Every row: the parser takes the name (and wants its parenthesis), the
 * unknown-name message lists it, the arb and acb evaluators agree at points
 * inside the domain, and its identities hold there. */
static void test_function_table(void)
{
    slong prec = 192;
    static const slong points[][2] = { { 1, 3 }, { 7, 10 }, { 6, 5 } };   /* in (0, pi/2) */
    arb_t t, x, y;
    acb_t tz, z, w;
    vigen_error err;
    arb_init(t); arb_init(x); arb_init(y);
    acb_init(tz); acb_init(z); acb_init(w);
    vigen_error_init(&err);

    CHECK(vigen_expr_function_count() > 0 && vigen_expr_constant_count() > 0);
    for (int i = 0; i < vigen_expr_function_count(); i++) {
        const vigen_expr_function *f = vigen_expr_function_at(i);
        CHECK_MSG(f->name != NULL && f->description != NULL && f->description[0] != '\0' && f->eval_acb != NULL,
                  "function row %d is incomplete", i);
        CHECK_MSG(contains(vigen_expr_function_names(), f->name), "%s is not in the name list", f->name);
        check_has_identity(f->name);

        char *call = vigen_strdup_printf("%s(t)", f->name);
        char *bare = vigen_strdup_printf("%s + 1", f->name);
        char *upper = vigen_strdup_printf("%c%s(1)", f->name[0] - 'a' + 'A', f->name + 1);
        check_syntax_error(bare, 1, "expected '('", f->name, NULL);
        check_syntax_error(upper, 0, "unknown name", vigen_expr_function_names(), f->name, NULL);
        vigen_expr *e = NULL;
        CHECK_MSG(vigen_expr_parse(&e, call, 1, &err) == VIGEN_OK, "%s: %s", call, err.message ? err.message : "");
        for (size_t k = 0; e != NULL && k < sizeof points / sizeof points[0]; k++) {
            arb_set_si(t, points[k][0]);
            arb_div_si(t, t, points[k][1], prec);
            acb_set_arb(tz, t);
            CHECK_MSG(vigen_expr_eval_arb(x, e, t, prec, &err) == VIGEN_OK, "%s: %s", call,
                      err.message ? err.message : "");
            for (int analytic = 0; analytic <= 1; analytic++) {
                CHECK(vigen_expr_eval_acb(z, e, tz, analytic, prec) == VIGEN_OK);
                CHECK_MSG(acb_is_finite(z) && arb_overlaps(acb_realref(z), x) && arb_contains_zero(acb_imagref(z)),
                          "%s: the real and complex evaluators disagree at t = %ld/%ld (analytic %d)",
                          call, (long)points[k][0], (long)points[k][1], analytic);
                f->eval_acb(w, tz, analytic, prec);    /* the row's evaluator, as the ball library calls it */
                CHECK_MSG(acb_overlaps(w, z), "%s: the row's acb evaluator differs from the tree's", call);
            }
            for (size_t j = 0; j < sizeof function_identities / sizeof function_identities[0]; j++)
                if (strcmp(function_identities[j].name, f->name) == 0)
                    check_identity(function_identities[j].lhs, function_identities[j].rhs, t, prec);
        }
        vigen_expr_free(e);
        free(call); free(bare); free(upper);
    }

    for (int i = 0; i < vigen_expr_constant_count(); i++) {
        const vigen_expr_constant *c = vigen_expr_constant_at(i);
        CHECK_MSG(contains(vigen_expr_constant_names(), c->name), "%s is not in the name list", c->name);
        check_has_identity(c->name);
        CHECK(eval_text(x, c->name, NULL, prec) == VIGEN_OK);
        c->eval_acb(z, prec);
        CHECK_MSG(arb_overlaps(acb_realref(z), x) && arb_is_zero(acb_imagref(z)),
                  "%s: the real and complex values disagree", c->name);
        arb_one(t);
        for (size_t j = 0; j < sizeof function_identities / sizeof function_identities[0]; j++)
            if (strcmp(function_identities[j].name, c->name) == 0)
                check_identity(function_identities[j].lhs, function_identities[j].rhs, t, prec);
    }
    /* the lists name each row once: count - 1 separators */
    int commas = 0;
    for (const char *p = vigen_expr_function_names(); (p = strstr(p, ", ")) != NULL; p += 2) commas++;
    CHECK(commas == vigen_expr_function_count() - 1);
    commas = 0;
    for (const char *p = vigen_expr_constant_names(); (p = strstr(p, ", ")) != NULL; p += 2) commas++;
    CHECK(commas == vigen_expr_constant_count() - 1);

    vigen_error_clear(&err);
    arb_clear(t); arb_clear(x); arb_clear(y);
    acb_clear(tz); acb_clear(z); acb_clear(w);
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
    test_function_table();
    test_quadratic();
    test_latex();
    test_closed_form_integrals();
    test_identities();
    test_numbers();
    test_powers();
    test_gauss_legendre();
    test_syntax_errors();
    test_domain_errors();
    test_poly();
    test_acb();
    test_integrals();
    TEST_MAIN_END();
}
