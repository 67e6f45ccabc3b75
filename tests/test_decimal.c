/* test_decimal.c — certified decimal printing and rounded-decimal reading.
 * The truths: a printed string must be a correct rounding of the exact value
 * (checked independently with exact rational arithmetic), and reading it back
 * as a half-unit ball must contain the exact value. */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq.h>
#include "decimal.h"
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
    arb_clear(x);
    arb_clear(y);
    TEST_MAIN_END();
}
