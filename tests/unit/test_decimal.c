/* test_decimal.c — certified decimal printing and rounded-decimal reading.
 * The truths: a printed string must be a correct rounding of the exact value
 * (checked independently with exact rational arithmetic), and reading it back
 * as a half-unit ball must contain the exact value. */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq.h>
#include "core/decimal.h"
#include "testlib.h"

static void check_format_q(slong p, slong q, slong digits, const char *expected)
{
    arb_t x;
    arb_init(x);
    arb_set_si(x, p);
    arb_div_si(x, x, q, 256);
    char *s = vigen_decimal_format(x, digits);
    CHECK_MSG(s != NULL && strcmp(s, expected) == 0, "%ld/%ld at %ld digits: got %s, want %s", (long)p, (long)q,
              (long)digits, s ? s : "NULL", expected);
    free(s);
    arb_clear(x);
}

/* |p/q - d| <= u/2 checked with exact rationals, u = 10^(e) of the last digit. */
static int is_correct_rounding(const fmpq_t v, const char *text)
{
    arb_t ball, exact;
    arb_init(ball);
    arb_init(exact);
    int ok = vigen_decimal_parse_rounded(ball, text, 512);
    arb_set_fmpq(exact, v, 512);
    ok = ok && arb_contains(ball, exact);
    arb_clear(ball);
    arb_clear(exact);
    return ok;
}

int main(void)
{
    /* hand-checked roundings */
    check_format_q(1, 3, 10, "0.3333333333");
    check_format_q(2, 3, 5, "0.66667");
    check_format_q(-1, 7, 5, "-0.14286");
    check_format_q(1, 1, 5, "1.0000");
    check_format_q(22, 7, 6, "3.14286");
    check_format_q(123456, 1, 3, "1.23e5");
    check_format_q(999999, 1, 3, "1.00e6");     /* carries into a new leading digit */
    check_format_q(1, 70000000, 4, "1.429e-8");
    check_format_q(1, 800, 3, "0.00125");
    /* -5/2 is a tie at one digit: -2e0 and -3e0 are both correct roundings */
    {
        arb_t h;
        arb_init(h);
        arb_set_si(h, -5);
        arb_mul_2exp_si(h, h, -1);
        char *t = vigen_decimal_format(h, 1);
        CHECK(t != NULL && (strcmp(t, "-2e0") == 0 || strcmp(t, "-3e0") == 0));
        free(t);
        arb_clear(h);
    }

    /* exact zero prints "0"; a ball around zero is refused by the relative format */
    arb_t x, y;
    arb_init(x);
    arb_init(y);
    arb_zero(x);
    char *s = vigen_decimal_format(x, 10);
    CHECK(s != NULL && strcmp(s, "0") == 0);
    free(s);
    arb_zero(x);
    mag_set_ui_2exp_si(arb_radref(x), 1, -200);
    CHECK(vigen_decimal_format(x, 10) == NULL);
    /* |x| <= 2^-200 ~ 6.2e-61: 0.5e-59 bounds it, 0.5e-60 does not */
    s = vigen_decimal_format_zero(x);
    CHECK_MSG(s != NULL && strcmp(s, "0e-59") == 0, "got %s", s ? s : "NULL");
    CHECK(vigen_decimal_parse_rounded(y, s, 512) && arb_contains(y, x));
    free(s);

    /* a ball that straddles a rounding boundary cannot be certified */
    arb_set_str(x, "0.125 +/- 1e-20", 256);
    CHECK(vigen_decimal_format(x, 2) == NULL);
    s = vigen_decimal_format(x, 3);
    CHECK(s != NULL && strcmp(s, "0.125") == 0);
    free(s);

    /* reading: half a unit in the last digit */
    CHECK(vigen_decimal_parse_rounded(x, "0.125", 256));
    arb_set_str(y, "0.1254", 256);
    CHECK(arb_contains(x, y));
    arb_set_str(y, "0.1256", 256);
    CHECK(!arb_contains(x, y));
    CHECK(vigen_decimal_parse_rounded(x, "-2.5e-3", 256));
    arb_set_str(y, "-0.00255", 256);
    CHECK(arb_contains(x, y));
    arb_set_str(y, "-0.002551", 256);
    CHECK(!arb_contains(x, y));

    /* what counts as a rounded decimal */
    CHECK(vigen_decimal_is_rounded("0.5"));
    CHECK(vigen_decimal_is_rounded("-1.25e-7"));
    CHECK(vigen_decimal_is_rounded("1e3"));
    CHECK(vigen_decimal_is_rounded(".5"));
    CHECK(vigen_decimal_is_rounded("0e-40"));
    CHECK(!vigen_decimal_is_rounded("1"));
    CHECK(!vigen_decimal_is_rounded("1/2"));
    CHECK(!vigen_decimal_is_rounded("0.5*2"));
    CHECK(!vigen_decimal_is_rounded("1e"));
    CHECK(!vigen_decimal_is_rounded("e5"));
    CHECK(!vigen_decimal_is_rounded("1.2.3"));
    CHECK(vigen_decimal_significant_digits("0.0012300") == 5);
    CHECK(vigen_decimal_significant_digits("1.000") == 4);

    /* the exact value of a decimal, as a fraction in lowest terms */
    {
        static const char *const cases[][2] = {
            {"0.5", "1/2"}, {"0.25", "1/4"}, {"0.125", "1/8"}, {"0.375", "3/8"}, {"-1.50", "-3/2"}, {"2.0", "2"},
            {"5e-1", "1/2"}, {"1.2e2", "120"}, {"0.0", "0"}, {"0e-50", "0"}, {"0.33", "33/100"}};
        for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
            char *f = vigen_decimal_exact_fraction(cases[k][0]);
            CHECK_MSG(f != NULL && strcmp(f, cases[k][1]) == 0, "%s: got %s, want %s", cases[k][0], f ? f : "NULL",
                      cases[k][1]);
            free(f);
        }
        CHECK(vigen_decimal_exact_fraction("1/2") == NULL && vigen_decimal_exact_fraction("1") == NULL);
        /* half a unit in the last digit: the radius the decimal is read with */
        static const char *const radii[][2] = {
            {"0.5", "0.05"}, {"0.25", "0.005"}, {"-0.125", "0.0005"}, {"3.0", "0.05"}, {"1.5e-8", "5e-10"},
            {"1e2", "50"}, {"0e-50", "5e-51"}};
        for (size_t k = 0; k < sizeof radii / sizeof radii[0]; k++) {
            char *r = vigen_decimal_half_unit(radii[k][0]);
            CHECK_MSG(r != NULL && strcmp(r, radii[k][1]) == 0, "%s: got %s, want %s", radii[k][0], r ? r : "NULL",
                      radii[k][1]);
            /* and it is the radius vigen_decimal_parse_rounded reads (a mag_t
             * upper bound: equal to about 2^-25 relative) */
            arb_t b, rr, q;
            arb_init(b);
            arb_init(rr);
            arb_init(q);
            CHECK(vigen_decimal_parse_rounded(b, radii[k][0], 256));
            if (r) arb_set_str(rr, r, 256);
            arf_t rad;
            arf_init(rad);
            arf_set_mag(rad, arb_radref(b));
            arb_set_arf(q, rad);
            arb_div(q, q, rr, 256);
            arb_sub_ui(q, q, 1, 256);
            CHECK_MSG(arf_cmpabs_2exp_si(arb_midref(q), -20) < 0, "%s: radius %s", radii[k][0], r ? r : "NULL");
            arf_clear(rad);
            arb_clear(b);
            arb_clear(rr);
            arb_clear(q);
            free(r);
        }
    }

    /* exact integers are written as integers (exact literals); anything
     * else is not an integer literal */
    arb_set_si(x, 1);
    s = vigen_decimal_format_integer(x);
    CHECK(s != NULL && strcmp(s, "1") == 0);
    free(s);
    arb_set_si(x, -12);
    s = vigen_decimal_format_integer(x);
    CHECK(s != NULL && strcmp(s, "-12") == 0);
    free(s);
    arb_zero(x);
    s = vigen_decimal_format_integer(x);
    CHECK(s != NULL && strcmp(s, "0") == 0);
    free(s);
    arb_set_si(x, 1);
    mag_set_ui_2exp_si(arb_radref(x), 1, -300);     /* 1 +/- 2^-300: not known to be an integer */
    CHECK(vigen_decimal_format_integer(x) == NULL);
    arb_set_si(x, 1);
    arb_mul_2exp_si(x, x, -1);                       /* exactly 1/2 */
    CHECK(vigen_decimal_format_integer(x) == NULL);

    /* property: for many rationals and digit counts, the printed string is a
     * correct rounding (exact check), and has exactly `digits` significant digits */
    flint_rand_t state;
    flint_randinit(state);
    fmpq_t v;
    fmpq_init(v);
    for (int iter = 0; iter < 2000; iter++) {
        fmpq_randtest_not_zero(v, state, 80);
        slong digits = 1 + (slong)n_randint(state, 60);
        arb_set_fmpq(x, v, 1024);
        s = vigen_decimal_format(x, digits);
        CHECK(s != NULL);
        if (s == NULL) continue;
        CHECK_MSG(is_correct_rounding(v, s), "not a correct rounding: %s", s);
        CHECK_MSG(vigen_decimal_significant_digits(s) == digits, "%s has not %ld digits", s, (long)digits);
        free(s);
    }
    fmpq_clear(v);
    flint_randclear(state);

    /* hostile magnitudes: a zero of radius 2^-4000000000 is certified below
     * 10^-1000000 / 2 (2^-4000000000 < 10^-1200000) without trying every
     * exponent down to -1.2e9; balls beyond 10^+-10^8 are not formatted (their
     * decimal exponents would overflow the arithmetic); exponents beyond
     * 10^8 are not read as rounded decimals */
    arb_zero(x);
    mag_set_ui_2exp_si(arb_radref(x), 1, -4000000000L);
    s = vigen_decimal_format_zero(x);
    CHECK_MSG(s != NULL && strcmp(s, "0e-1000000") == 0, "got %s", s ? s : "NULL");
    free(s);
    arb_one(x);
    arb_mul_2exp_si(x, x, (slong)1 << 50);
    CHECK(vigen_decimal_format(x, 10) == NULL);
    arb_one(x);
    arb_mul_2exp_si(x, x, -((slong)1 << 50));
    CHECK(vigen_decimal_format(x, 10) == NULL);
    CHECK(vigen_decimal_is_rounded("1e100000000"));
    CHECK(!vigen_decimal_is_rounded("1e100000001"));
    CHECK(!vigen_decimal_is_rounded("0.5e-99999999999999999999"));
    arb_clear(x);
    arb_clear(y);
    TEST_MAIN_END();
}
