/* balls.c — balls and radii as short decimal text (see balls.h).
 */
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <stdlib.h>
#include "vigen/error.h"
#include "check/balls.h"
#include "support/strbuf.h"

/* Digits enough to see the difference between x and y (8 .. 45). */
slong vigen_ball_digits_to_separate(const arb_t x, const arb_t y, slong prec)
{
    /* from the binary exponents of the midpoints, so that a relative
     * difference far below the range of doubles is measured too */
    arb_t d;
    arb_init(d);
    arb_sub(d, x, y, prec);
    const arf_struct *dm = arb_midref(d), *xm = arb_midref(x), *ym = arb_midref(y);
    slong n = 8;
    if (!arf_is_zero(dm) && arf_is_finite(dm) && arf_is_finite(xm) && arf_is_finite(ym) &&
        !(arf_is_zero(xm) && arf_is_zero(ym))) {
        slong ed = arf_abs_bound_lt_2exp_si(dm);
        slong ex = arf_is_zero(xm) ? WORD_MIN : arf_abs_bound_lt_2exp_si(xm);
        slong ey = arf_is_zero(ym) ? WORD_MIN : arf_abs_bound_lt_2exp_si(ym);
        slong es = ex > ey ? ex : ey;
        if (es > ed + 16) {
            double digits = ceil((double)(es - ed) * 0.30102999566398120) + 4;
            n = digits > VIGEN_BALL_MAX_SEPARATING_DIGITS ? VIGEN_BALL_MAX_SEPARATING_DIGITS : (slong)digits;
        }
    }
    arb_clear(d);
    return n;
}

/* d significant digits of x, rounded down (up = 0) or up (up = 1). */
static char *arf_text(const arf_t x, slong d, int up)
{
    if (arf_is_zero(x)) return vigen_strdup("0");
    mpfr_t m;
    slong bits = arf_bits(x);
    mpfr_init2(m, bits < 2 ? 2 : bits);
    arf_get_mpfr(m, x, MPFR_RNDN);   /* exact: m has the bits of x */
    char fmt[32];
    snprintf(fmt, sizeof(fmt), "%%.%ldR%cg", (long)d, up ? 'U' : 'D');
    char *out = NULL;
    char *r;
    if (mpfr_asprintf(&out, fmt, m) >= 0) {
        r = vigen_strdup(out);
        mpfr_free_str(out);
    } else r = vigen_strdup("?");
    mpfr_clear(m);
    return r;
}

/* The interval [lo, hi] containing x, rounded outward, with enough digits to
 * show its width (3 .. digits). */
static char *interval_str(const arb_t x, slong digits, slong min_digits)
{
    slong acc = arb_rel_accuracy_bits(x);
    slong d = acc > 0 ? (slong)(acc * 0.30103) + 2 : 3;
    if (d < 3) d = 3;
    if (d > digits && digits >= 3) d = digits;
    if (min_digits > d) d = min_digits;
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    arb_get_lbound_arf(lo, x, 256);
    arb_get_ubound_arf(hi, x, 256);
    char *l = arf_text(lo, d, 0), *h = arf_text(hi, d, 1);
    char *r = vigen_strdup_printf("[%s, %s]", l, h);
    free(l);
    free(h);
    arf_clear(lo);
    arf_clear(hi);
    return r;
}

/* For messages: the `digits` digits of x when they are certain, otherwise the
 * interval [lo, hi] that contains x (rounded outward), so that a reader sees
 * at once whether the ball contains 0. */
char *vigen_ball_str(const arb_t x, slong digits)
{
    if (!arb_is_finite(x)) return vigen_strdup("[not finite]");
    int narrow = arb_is_exact(x) || arb_rel_accuracy_bits(x) >= (slong)(digits * 3.33);
    if (!narrow) return interval_str(x, digits, 0);
    char *s = arb_get_str(x, digits, ARB_STR_NO_RADIUS);
    char *r = vigen_strdup(s);
    flint_free(s);
    return r;
}

char *vigen_ball_str_apart(const arb_t x, const arb_t y, slong prec)
{
    slong digits = vigen_ball_digits_to_separate(x, y, prec);
    if (!arb_is_finite(x)) return vigen_strdup("[not finite]");
    int narrow = arb_is_exact(x) || arb_rel_accuracy_bits(x) >= (slong)(digits * 3.33);
    /* bounds with more digits only where the two values are close */
    if (!narrow) return interval_str(x, digits, digits > 8 ? digits : 0);
    return vigen_ball_str(x, digits);
}

/* For JSON: arb's "[mid +/- rad]" with the midpoint always shown. */
char *vigen_ball_json_str(const arb_t x, slong digits)
{
    int narrow = arb_is_exact(x) || arb_rel_accuracy_bits(x) >= (slong)(digits * 3.33);
    if (!narrow) {
        /* the midpoint to a few digits beyond the radius, not binary noise */
        slong acc = arb_rel_accuracy_bits(x);
        slong d = acc > 0 ? (slong)(acc * 0.30103) + 3 : 3;
        if (d < digits) digits = d;
    }
    char *s = arb_get_str(x, digits, narrow ? ARB_STR_NO_RADIUS : ARB_STR_MORE);
    char *r = vigen_strdup(s);
    flint_free(s);
    return r;
}

/* Radius (an upper bound) as a short decimal. */
char *vigen_mag_str(const mag_t m)
{
    arf_t x;
    arf_init(x);
    arf_set_mag(x, m);
    char *r = arf_text(x, 2, 1);
    arf_clear(x);
    return r;
}

