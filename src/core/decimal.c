/* decimal.c — certified decimal strings for arb balls, and back.
 *
 * Printing: scale |x| by 10^(digits-1-e) so that the wanted digits form an
 * integer m, round the midpoint to the nearest integer, and accept m only if
 * the whole scaled ball lies within [m - 1/2, m + 1/2]: then the decimal string
 * is a correct rounding of every value in the ball, hence of the exact value.
 */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include "core/decimal.h"
#include "vigen/error.h"
#include "support/strbuf.h"

/* y = x * 10^k (k may be negative), at precision prec. */
static void scale_pow10(arb_t y, const arb_t x, slong k, slong prec)
{
    arb_t p;
    arb_init(p);
    arb_ui_pow_ui(p, 10, (ulong)(k >= 0 ? k : -k), prec);
    if (k >= 0) arb_mul(y, x, p, prec);
    else arb_div(y, x, p, prec);
    arb_clear(p);
}

/* floor(log10|mid x|) estimated from the binary exponent (exact enough to be
 * corrected by at most one step by the caller). */
static slong estimate_exponent10(const arb_t x)
{
    arf_srcptr m = arb_midref(x);
    /* callers have checked that the exponent fits (binary_exponent_fits) */
    /* |m| = f * 2^E with f in [1/2, 1): log10|m| ~ (E + log2 f) * log10(2). */
    slong E = ARF_EXP(m) == 0 ? 0 : fmpz_get_si(ARF_EXPREF(m));
    double f = 0.0;
    arf_t t;
    arf_init(t);
    arf_set(t, m);
    arf_abs(t, t);
    arf_mul_2exp_si(t, t, -E);
    f = arf_get_d(t, ARF_RND_NEAR);
    arf_clear(t);
    double l = ((double)E + log2(f)) * 0.30102999566398119521;
    return (slong)floor(l);
}

static char *render(int negative, const fmpz_t m, slong digits, slong e)
{
    char *ds = fmpz_get_str(NULL, 10, m); /* exactly `digits` characters */
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (negative) vigen_strbuf_append(&sb, "-");
    if (e >= 0 && e < digits - 1) {
        /* fixed notation with at least one fractional digit */
        vigen_strbuf_appendn(&sb, ds, (size_t)e + 1);
        vigen_strbuf_append(&sb, ".");
        vigen_strbuf_append(&sb, ds + e + 1);
    } else if (e < 0 && e >= -4) {
        vigen_strbuf_append(&sb, "0.");
        for (slong i = 0; i < -e - 1; i++) vigen_strbuf_append(&sb, "0");
        vigen_strbuf_append(&sb, ds);
    } else {
        vigen_strbuf_appendn(&sb, ds, 1);
        if (digits > 1) {
            vigen_strbuf_append(&sb, ".");
            vigen_strbuf_append(&sb, ds + 1);
        }
        vigen_strbuf_printf(&sb, "e%ld", (long)e);
    }
    flint_free(ds);
    return sb.data;
}

/* 1 when the binary exponent of the midpoint of x is within +-3 10^8, that is
 * |x| within 10^+-(9 10^7): the decimal exponents derived from it fit in a
 * slong with room for digits and corrections, and every decimal written stays
 * within the +-10^8 exponents the reader accepts, so that it reads back as the
 * ball it stands for. */
static int binary_exponent_fits(const arb_t x)
{
    arf_srcptr m = arb_midref(x);
    if (arf_is_zero(m)) return 1;
    return fmpz_cmp_si(ARF_EXPREF(m), 3 * VIGEN_DECIMAL_EXP_MAX) <= 0 &&
           fmpz_cmp_si(ARF_EXPREF(m), -3 * VIGEN_DECIMAL_EXP_MAX) >= 0;
}

char *vigen_decimal_format(const arb_t x, slong digits)
{
    if (digits < 1 || digits > VIGEN_DECIMAL_EXP_MAX) return NULL;
    if (arb_is_zero(x)) return vigen_strdup("0");
    if (!arb_is_finite(x) || arb_contains_zero(x) || !binary_exponent_fits(x)) return NULL;

    slong prec = arb_bits(x) + (slong)(3.33 * (double)digits) + 64;
    slong e = estimate_exponent10(x);
    int negative = arf_sgn(arb_midref(x)) < 0;
    char *result = NULL;
    arb_t y, d;
    fmpz_t m, lo, hi;
    arb_init(y); arb_init(d);
    fmpz_init(m); fmpz_init(lo); fmpz_init(hi);
    fmpz_ui_pow_ui(lo, 10, (ulong)(digits - 1));
    fmpz_ui_pow_ui(hi, 10, (ulong)digits);

    for (int attempt = 0; attempt < 3; attempt++) {
        arb_abs(y, x);
        scale_pow10(y, y, digits - 1 - e, prec);
        arf_get_fmpz(m, arb_midref(y), ARF_RND_NEAR);
        if (fmpz_cmp(m, hi) >= 0) { e++; continue; }
        if (fmpz_cmp(m, lo) < 0) { e--; continue; }
        arb_sub_fmpz(d, y, m, prec);
        arb_abs(d, d);
        arf_t u;
        arf_init(u);
        arb_get_abs_ubound_arf(u, d, prec);
        int ok = arf_cmp_2exp_si(u, -1) <= 0;
        arf_clear(u);
        if (ok) result = render(negative, m, digits, e);
        break;
    }
    arb_clear(y); arb_clear(d);
    fmpz_clear(m); fmpz_clear(lo); fmpz_clear(hi);
    return result;
}

char *vigen_decimal_format_zero(const arb_t x)
{
    if (arb_is_zero(x)) return vigen_strdup("0");
    if (!arb_is_finite(x)) return NULL;
    arf_t u;
    arf_init(u);
    arb_get_abs_ubound_arf(u, x, 64);
    /* need 2u <= 10^K with K <= 0 as large as possible */
    arf_mul_2exp_si(u, u, 1);
    char *result = NULL;
    if (arf_cmp_si(u, 1) <= 0) {
        arb_t twice;
        arb_init(twice);
        arb_set_arf(twice, u);
        /* below 10^-K_MIN (2^-(3.33 K_MIN)): written 0e-K_MIN, certified as well */
        slong K = -VIGEN_DECIMAL_ZERO_EXP_MIN;
        if (!arf_is_zero(u) && arf_cmp_2exp_si(u, -(slong)(3.33 * VIGEN_DECIMAL_ZERO_EXP_MIN)) > 0)
            K = estimate_exponent10(twice) + 1; /* first guess: 10^K >= 2u */
        if (K > 0) K = 0;
        for (;;) {
            arb_t p;
            arb_init(p);
            arb_one(p);
            scale_pow10(p, p, K, 64 + 4 * (K < 0 ? -K : K));
            /* p is a ball around 10^K; accept K when 2u <= lower bound of p */
            arf_t lowp;
            arf_init(lowp);
            arb_get_lbound_arf(lowp, p, 64);
            int ok = arf_cmp(u, lowp) <= 0;
            arf_clear(lowp);
            arb_clear(p);
            if (ok) break;
            K--;
        }
        result = vigen_strdup_printf("0e%ld", (long)K);
        arb_clear(twice);
    }
    arf_clear(u);
    return result;
}

/* Splits a plain decimal: sign, digit string without point, power of ten of
 * the last digit.  Returns 0 if text is not [+-]digits[.digits][e[+-]digits]
 * with a point or an exponent. */
static int split_decimal(const char *text, int *negative, char **digits_out, slong *exp10)
{
    const char *p = text;
    while (isspace((unsigned char)*p)) p++;
    *negative = 0;
    if (*p == '+' || *p == '-') { *negative = (*p == '-'); p++; }
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    slong ndig = 0, nfrac = 0;
    int point = 0, expo = 0;
    while (isdigit((unsigned char)*p)) { vigen_strbuf_appendn(&sb, p, 1); p++; ndig++; }
    if (*p == '.') {
        point = 1;
        p++;
        while (isdigit((unsigned char)*p)) { vigen_strbuf_appendn(&sb, p, 1); p++; ndig++; nfrac++; }
    }
    long e = 0;
    if (ndig > 0 && (*p == 'e' || *p == 'E')) {
        p++;
        int eneg = 0;
        if (*p == '+' || *p == '-') { eneg = (*p == '-'); p++; }
        if (!isdigit((unsigned char)*p)) { vigen_strbuf_clear(&sb); return 0; }
        while (isdigit((unsigned char)*p)) {
            e = 10 * e + (*p - '0');
            /* an absurd exponent is not read as a rounded decimal (the exact
             * expression parser, which handles any exponent, reads it) */
            if (e > VIGEN_DECIMAL_EXP_MAX) { vigen_strbuf_clear(&sb); return 0; }
            p++;
        }
        if (eneg) e = -e;
        expo = 1;
    }
    while (isspace((unsigned char)*p)) p++;
    if (ndig == 0 || *p != '\0' || (!point && !expo)) { vigen_strbuf_clear(&sb); return 0; }
    *digits_out = sb.data;
    *exp10 = (slong)e - nfrac;
    return 1;
}

/* The power of ten of the last digit of a plain decimal; 0 if text is not one. */
static int decimal_last_exponent(const char *text, slong *e)
{
    int neg;
    char *digits;
    if (!split_decimal(text, &neg, &digits, e)) return 0;
    free(digits);
    return 1;
}

int vigen_decimal_is_rounded(const char *text)
{
    slong e;
    return decimal_last_exponent(text, &e);
}

int vigen_decimal_parse_rounded(arb_t res, const char *text, slong prec)
{
    int neg;
    char *digits;
    slong e;
    if (!split_decimal(text, &neg, &digits, &e)) return 0;
    fmpz_t m;
    fmpz_init(m);
    fmpz_set_str(m, digits, 10);
    free(digits);
    if (neg) fmpz_neg(m, m);
    arb_t unit, half;
    arb_init(unit); arb_init(half);
    arb_one(unit);
    scale_pow10(unit, unit, e, prec + 16);     /* 10^e */
    arb_mul_fmpz(res, unit, m, prec);          /* m * 10^e */
    arb_mul_2exp_si(half, unit, -1);           /* 10^e / 2 */
    /* add the rounding radius: every value within half a unit is possible */
    mag_t r;
    mag_init(r);
    arb_get_mag(r, half);
    mag_add(arb_radref(res), arb_radref(res), r);
    mag_clear(r);
    arb_clear(unit); arb_clear(half);
    fmpz_clear(m);
    return 1;
}

slong vigen_decimal_significant_digits(const char *text)
{
    int neg;
    char *digits;
    slong e;
    if (!split_decimal(text, &neg, &digits, &e)) return 0;
    const char *p = digits;
    while (*p == '0' && p[1] != '\0') p++;
    slong n = (slong)strlen(p);
    free(digits);
    return n;
}

/* A string from flint (fmpz_get_str, fmpq_get_str) as a heap string of ours. */
static char *own_flint_str(char *s)
{
    char *r = vigen_strdup(s);
    flint_free(s);
    return r;
}

char *vigen_decimal_format_integer(const arb_t x)
{
    if (!arb_is_exact(x) || !arf_is_int(arb_midref(x))) return NULL;
    if (!arf_is_zero(arb_midref(x)) && arf_cmpabs_2exp_si(arb_midref(x), 256) >= 0) return NULL;
    fmpz_t m;
    fmpz_init(m);
    arf_get_fmpz(m, arb_midref(x), ARF_RND_DOWN);   /* exact: the midpoint is an integer */
    char *r = own_flint_str(fmpz_get_str(NULL, 10, m));
    fmpz_clear(m);
    return r;
}

char *vigen_decimal_exact_fraction(const char *text)
{
    int neg;
    char *digits;
    slong e;
    if (!split_decimal(text, &neg, &digits, &e)) return NULL;
    if (e > 1000 || e < -1000) {
        free(digits);
        return NULL;
    }
    fmpq_t q;
    fmpz_t p;
    fmpq_init(q);
    fmpz_init(p);
    fmpz_set_str(fmpq_numref(q), digits, 10);
    free(digits);
    if (neg) fmpz_neg(fmpq_numref(q), fmpq_numref(q));
    fmpz_ui_pow_ui(p, 10, (ulong)(e >= 0 ? e : -e));
    if (e >= 0) fmpz_mul(fmpq_numref(q), fmpq_numref(q), p);
    else fmpz_set(fmpq_denref(q), p);
    fmpq_canonicalise(q);
    char *r = own_flint_str(fmpq_get_str(NULL, 10, q));
    fmpz_clear(p);
    fmpq_clear(q);
    return r;
}

char *vigen_decimal_half_unit(const char *text)
{
    slong e;
    if (!decimal_last_exponent(text, &e)) return NULL;
    /* a unit in the last digit is 10^e, half of it 5 10^(e-1) */
    slong k = e - 1;
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (k >= 0 && k <= 6) {
        vigen_strbuf_append(&sb, "5");
        for (slong i = 0; i < k; i++) vigen_strbuf_append(&sb, "0");
    } else if (k < 0 && k >= -8) {
        vigen_strbuf_append(&sb, "0.");
        for (slong i = 0; i < -k - 1; i++) vigen_strbuf_append(&sb, "0");
        vigen_strbuf_append(&sb, "5");
    } else vigen_strbuf_printf(&sb, "5e%ld", (long)k);
    return sb.data;
}
