/* balls.c — balls and radii as short decimal text (see balls.h).
 */
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <stdlib.h>
#include "vigen/error.h"
#include "check/balls.h"

/* Digits enough to see the difference between x and y (8 .. 45). */
slong vigen_ball_digits_to_separate(const arb_t x, const arb_t y, slong prec)
{
    arb_t d;
    arb_init(d);
    arb_sub(d, x, y, prec);
    double dd = fabs(arf_get_d(arb_midref(d), ARF_RND_NEAR));
    double yy = fabs(arf_get_d(arb_midref(y), ARF_RND_NEAR));
    double xx = fabs(arf_get_d(arb_midref(x), ARF_RND_NEAR));
    arb_clear(d);
    double scale = yy > xx ? yy : xx;
    if (scale == 0.0 || dd == 0.0 || !isfinite(scale) || !isfinite(dd)) return 8;
    double rel = dd / scale;
    if (rel >= 1e-5) return 8;
    if (rel < 1e-40) return 45;
    slong n = (slong)ceil(-log10(rel)) + 4;
    return n > 45 ? 45 : n;
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
static char *interval_str(const arb_t x, slong digits)
{
    slong acc = arb_rel_accuracy_bits(x);
    slong d = acc > 0 ? (slong)(acc * 0.30103) + 2 : 3;
    if (d < 3) d = 3;
    if (d > digits && digits >= 3) d = digits;
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
    if (!narrow) return interval_str(x, digits);
    char *s = arb_get_str(x, digits, ARB_STR_NO_RADIUS);
    char *r = vigen_strdup(s);
    flint_free(s);
    return r;
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

