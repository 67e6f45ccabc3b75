/* test_expr.c — the expression parser and its ball evaluation (expr.h):
 * identities, exact numbers and powers, the precision ladder, syntax and
 * domain errors, and the table of functions (test_expr_calculus.c:
 * polynomials, complex evaluation and integrals; test_expr_exact.c: LaTeX,
 * exact values in Q and Q(sqrt d), decimals read rounded).
 *
 * Every expected value comes from mathematics, not from the code: identities
 * (sin(pi/6) = 1/2, exp(log 2) = 2), exact rationals written independently
 * with fmpq, reference values computed directly with arb functions, and
 * closed-form integrals. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq.h>
#include "test_expr.h"
#include "support/strbuf.h"

/* ---- helpers ----------------------------------------------------------- */

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

int main(void)
{
    test_function_table();
    test_identities();
    test_numbers();
    test_powers();
    test_gauss_legendre();
    test_syntax_errors();
    test_domain_errors();
    TEST_MAIN_END();
}
