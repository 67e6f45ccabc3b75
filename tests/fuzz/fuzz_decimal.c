/* fuzz_decimal.c — libFuzzer harness for the decimal reader
 * (src/core/decimal.h) and the tableau entry reader built on it: the input
 * is read as a plain decimal (rounded ball, exact fraction, half unit,
 * significant digits) and as a tableau entry.  Properties checked: the exact
 * fraction of a decimal lies in the ball it is read as; a decimal that the
 * formatter certifies for that ball, read back, contains the ball. */
#include <arb.h>
#include <flint/fmpq.h>
#include "core/decimal.h"
#include "vigen/tableau.h"
#include "fuzz_common.h"

enum { PREC = 128 };

/* x formatted with `digits` digits, when certified, read back contains x. */
static void round_trip(const arb_t x, slong digits)
{
    char *s = arb_contains_zero(x) ? vigen_decimal_format_zero(x) : vigen_decimal_format(x, digits);
    if (s == NULL) return;
    arb_t y;
    arb_init(y);
    if (strcmp(s, "0") == 0)
        arb_zero(y);
    else
        FUZZ_ASSERT(vigen_decimal_parse_rounded(y, s, PREC + 64));
    FUZZ_ASSERT(arb_contains(y, x));
    arb_clear(y);
    free(s);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_cstring(data, size);
    int rounded = vigen_decimal_is_rounded(text);
    arb_t x;
    arb_init(x);
    int parsed = vigen_decimal_parse_rounded(x, text, PREC);
    FUZZ_ASSERT(parsed == rounded);
    char *frac = vigen_decimal_exact_fraction(text);
    char *half = vigen_decimal_half_unit(text);
    if (parsed) {
        slong digits = vigen_decimal_significant_digits(text);
        FUZZ_ASSERT(digits >= 1);
        if (frac != NULL) {
            fmpq_t q;
            fmpq_init(q);
            FUZZ_ASSERT(fmpq_set_str(q, frac, 10) == 0);
            FUZZ_ASSERT(arb_contains_fmpq(x, q));
            fmpq_clear(q);
        }
        if (digits > 1 && digits <= 40) round_trip(x, digits - 1);
    }
    char *integer = vigen_decimal_format_integer(x);
    free(integer);
    free(frac);
    free(half);

    vigen_error err;
    vigen_error_init(&err);
    int rc = vigen_tableau_entry_eval(x, text, PREC, &err);
    FUZZ_ASSERT(rc == VIGEN_OK || err.message != NULL);
    vigen_error_clear(&err);
    arb_clear(x);
    free(text);
    return 0;
}
