/* kepler_drift.c — the two-body flow x'' = -mu x/|x|^3 by universal
 * variables (Danby, Fundamentals of Celestial Mechanics, ch. 6.9; Wisdom &
 * Hernandez 2015, MNRAS 453, 3015).
 *
 * With r0 = |x|, eta = x.v, beta = 2 mu/r0 - |v|^2 (> 0 bound) and
 * zeta = mu - beta r0, the universal anomaly s after time h solves
 *   F(s) = r0 s + eta G2(s) + zeta G3(s) - h = 0,   G_k(s) = s^k c_k(beta s^2),
 * c_k the Stumpff functions; F'(s) = r(s) = r0 + eta G1 + zeta G2 > 0, so
 * F increases and a bracket is kept while the iterations converge.  Then
 * x += (f - 1) x + g v, v += fdot x + (gdot - 1) v with f - 1 = -mu G2/r0,
 * g = r0 G1 + eta G2, fdot = -mu G1/(r r0), gdot - 1 = -mu G2/r.  g is
 * taken in the form r0 G1 + eta G2 rather than h - mu G3 (equal at the
 * exact root): with it f, g, fdot, gdot are the exact Kepler map of the
 * time that s stands for, so that the error left in s moves the orbit
 * along itself (a phase) and never changes its energy.
 *
 * The solve runs in double: Halley's method from the series of s in h to
 * third order (one evaluation of the G functions for the steps of
 * planetary integrations), accepted when the residual it leaves, estimated
 * from the second and third derivatives of F, is below eps |h|/4; else
 * (large steps, hyperbolic orbits far out) Laguerre-Conway inside a
 * bisection bracket.  The map itself is evaluated once, at the accepted s,
 * in an extended precision (long double, 64 bits on x86): the scalars r0,
 * |v|^2, eta, beta, zeta, the G functions, f, g, fdot, gdot and the new
 * state, which is rounded to double once.  Evaluated in double, their
 * rounding errors repeat from step to step (on a circular orbit the
 * scalars are the same at every step; on a step that divides the period
 * the orbit returns to the same points), and the energy of a two-body
 * orbit drifted linearly with the steps (measured: the scalars in double
 * alone, or the G functions alone, suffice for the drift); with the
 * extended map only the final rounding is left, which varies from step to
 * step, and the energy error grows like the square root of the steps
 * (Brouwer's law; docs/benchmarks.md).  Where long double has no more
 * digits than double, the drift returns. */
#include <float.h>
#include <math.h>
#include <vigen/nbody.h>

#define KEPLER_PI 3.14159265358979323846

/* c0..c3 of z: the series (to z^6 for |z| <= 0.1, to z^10 for |z| <= 1:
 * the first term left out below 1e-20 of the sum); above,
 * the trigonometric (z > 0) or hyperbolic (z < 0) closed forms in the
 * forms free of cancellation: c2 = 2 sin^2(y/2)/z, c3 = (y - sin y)/(z y)
 * (cancellation at most 6 to 1 for z > 1). */
static void stumpff(double z, double c[4])
{
    if (fabs(z) <= 0.1) {
        c[3] = (1 - z * (1.0 / 20) * (1 - z * (1.0 / 42) * (1 - z * (1.0 / 72) * (1 - z * (1.0 / 110)
               * (1 - z * (1.0 / 156) * (1 - z * (1.0 / 210))))))) / 6;
        c[2] = (1 - z * (1.0 / 12) * (1 - z * (1.0 / 30) * (1 - z * (1.0 / 56) * (1 - z * (1.0 / 90)
               * (1 - z * (1.0 / 132) * (1 - z * (1.0 / 182))))))) / 2;
        c[1] = 1 - z * c[3];
        c[0] = 1 - z * c[2];
    } else if (fabs(z) <= 1) {
        c[3] = (1 - z * (1.0 / 20) * (1 - z * (1.0 / 42) * (1 - z * (1.0 / 72) * (1 - z * (1.0 / 110) * (1 - z * (1.0 / 156) * (1 - z * (1.0 / 210) * (1 - z * (1.0 / 272)
               * (1 - z * (1.0 / 342) * (1 - z * (1.0 / 420) * (1 - z * (1.0 / 506))))))))))) / 6;
        c[2] = (1 - z * (1.0 / 12) * (1 - z * (1.0 / 30) * (1 - z * (1.0 / 56) * (1 - z * (1.0 / 90) * (1 - z * (1.0 / 132) * (1 - z * (1.0 / 182) * (1 - z * (1.0 / 240)
               * (1 - z * (1.0 / 306) * (1 - z * (1.0 / 380) * (1 - z * (1.0 / 462))))))))))) / 2;
        c[1] = 1 - z * c[3];
        c[0] = 1 - z * c[2];
    } else if (z > 0) {
        double y = sqrt(z), sy = sin(y), hy = sin(y / 2);
        c[0] = cos(y);
        c[1] = sy / y;
        c[2] = 2 * hy * hy / z;
        c[3] = (y - sy) / (z * y);
    } else {
        double y = sqrt(-z), sy = sinh(y), hy = sinh(y / 2);
        c[0] = cosh(y);
        c[1] = sy / y;
        c[2] = -2 * hy * hy / z;
        c[3] = (sy - y) / (-z * y);
    }
}

/* 1 when the 3 + 3 values are finite: 0 x a is 0 for a finite a and NaN
 * for an infinite or NaN one, and a NaN stays in the sum. */
static int all_finite6(const double *a, const double *b)
{
    double z = (0 * a[0] + 0 * a[1]) + (0 * a[2] + 0 * b[0]) + (0 * b[1] + 0 * b[2]);
    return z == 0;
}

/* G0..G3 at s for beta. */
static void gfunctions(double beta, double s, double g[4])
{
    double c[4];
    stumpff(beta * s * s, c);
    g[0] = c[0];
    g[1] = s * c[1];
    g[2] = s * s * c[2];
    g[3] = s * s * s * c[3];
}

/* The extended type of the map; with no more digits than double the map
 * is evaluated in double (and the energy error may drift again). */
typedef long double xreal;

/* c0..c3 of z in xreal (c1..c3 only below z = -100): the series to z^8 for |z| <= 0.1 (the first term
 * left out below 3e-23 of the sum); above, z reduced by 4^k to |z| <= 0.1
 * and brought back by the doubling formulas (y = sqrt(z), y' = y/2):
 * c1(y) = c0(y') c1(y'), c2(y) = c1(y')^2/2, c3(y) = (c2(y') + c0(y') c3(y'))/4,
 * c0 = 1 - z c2; for z < -100 (hyperbolic only) the closed forms. */
static void stumpff_x(xreal z, xreal c[4])
{
    if (z < -100) {
        xreal y = sqrtl(-z), sy = sinhl(y), hy = sinhl(y / 2);
        c[1] = sy / y;
        c[2] = -2 * hy * hy / z;
        c[3] = (sy - y) / (-z * y);
        return;
    }
    int k = 0;
    while (fabsl(z) > 0.1L) {
        z /= 4;
        k++;
    }
    c[3] = (1 - z / 20 * (1 - z / 42 * (1 - z / 72 * (1 - z / 110 * (1 - z / 156 * (1 - z / 210 * (1 - z / 272
           * (1 - z / 342)))))))) / 6;
    c[2] = (1 - z / 12 * (1 - z / 30 * (1 - z / 56 * (1 - z / 90 * (1 - z / 132 * (1 - z / 182 * (1 - z / 240
           * (1 - z / 306)))))))) / 2;
    c[1] = 1 - z * c[3];
    c[0] = 1 - z * c[2];
    for (; k > 0; k--) {
        z *= 4;
        c[3] = (c[2] + c[0] * c[3]) / 4;
        c[2] = c[1] * c[1] / 2;
        c[1] = c[0] * c[1];
        c[0] = 1 - z * c[2];
    }
}

/* The orbit's constants in the equation F(s) = 0. */
typedef struct {
    double r0, eta, zeta, beta, h;
} equation;

/* F, F', F'', F''' at s into f (G0' = -beta G1), and the bracket (lo, hi)
 * narrowed to s: -1 when F is not finite, 1 when F(s) = 0 (s is the
 * root), else 0. */
static inline int probe(const equation *e, double s, double f[4], double *lo, double *hi)
{
    double g[4];
    gfunctions(e->beta, s, g);
    f[0] = e->r0 * s + e->eta * g[2] + e->zeta * g[3] - e->h;
    f[1] = e->r0 + e->eta * g[1] + e->zeta * g[2];
    f[2] = e->eta * g[0] + e->zeta * g[1];
    f[3] = e->zeta * g[0] - e->beta * e->eta * g[1];
    if (isnan(f[0]) || !isfinite(f[1])) return -1;
    if (f[0] == 0) return 1;
    if (f[0] < 0) *lo = s; else *hi = s;
    return 0;
}

/* Laguerre-Conway (n = 5) inside the bracket (lo, hi) from s.  A step that
 * leaves the bracket, and every step after the 30th, bisects it instead,
 * or doubles s while one end is still infinite; within 2200 iterations the
 * doubles between the ends are exhausted.  Converged when the step is at
 * round-off, or when it stops decreasing near it: F is then at the noise
 * of its own round-off (terms of size h), where no step improves s (a
 * stall counts within 4096 eps of s only).  VIGEN_SUCCESS and *out, or
 * VIGEN_ENONFINITE or VIGEN_ENOCONV. */
static int solve_bracketed(const equation *e, double s, double lo, double hi, double *out)
{
    double last = INFINITY, f[4];
    for (int it = 0; it < 2200; it++) {
        int p = probe(e, s, f, &lo, &hi);
        if (p < 0) return VIGEN_ENONFINITE;
        if (p > 0) {
            *out = s;
            return VIGEN_SUCCESS;
        }
        double disc = fabs(16 * f[1] * f[1] - 20 * f[0] * f[2]);
        double den = f[1] + (f[1] >= 0 ? 1 : -1) * sqrt(disc);
        double next = den != 0 && isfinite(f[0]) ? s - 5 * f[0] / den : NAN;
        int bisect = !(next > lo && next < hi) || it >= 30;
        if (bisect) {
            next = isinf(hi) || isinf(lo) ? 2 * s : lo + (hi - lo) / 2;
            if (!isfinite(next)) return VIGEN_ENONFINITE;
        }
        double ds = fabs(next - s);
        if (ds <= 2 * DBL_EPSILON * fabs(next) || next == lo || next == hi
            || (!bisect && ds >= last && ds <= 4096 * DBL_EPSILON * fabs(next))) {
            *out = next;
            return VIGEN_SUCCESS;
        }
        s = next;
        if (!bisect) last = ds;
    }
    return VIGEN_ENOCONV;
}

/* The universal anomaly of time h: Halley's method from the series guess
 * while it stays in the bracket, accepted when the residual it leaves,
 * |F(s + d)| ~ |d|^3 (F''^2/(4 F') + |F'''|/6), is below eps |h|/4; else
 * the bracketed solve.  VIGEN_SUCCESS and *out or a status. */
static int solve(const equation *e, double *out)
{
    double r0 = e->r0, eta = e->eta, zeta = e->zeta, h = e->h;
    /* s has the sign of h (F(0) = -h, F increasing): the bracket starts as
     * (0, inf) or (-inf, 0); s = h/r0 (1 - eta h/(2 r0^2)
     * + (eta^2/(2 r0^4) - zeta/(6 r0^3)) h^2) is its series to h^3
     * (ds/dt = 1/r), kept when its corrections are below 1/2 */
    double lo = h > 0 ? 0 : -INFINITY, hi = h > 0 ? INFINITY : 0;
    double ir0 = 1 / r0, u = h * ir0, a = eta * ir0 * ir0 / 2, b = (2 * a * a - zeta * ir0 * ir0 * ir0 / 6);
    double corr = h * (b * h - a), s = fabs(corr) < 0.5 ? u * (1 + corr) : u;
    double f[4];
    for (int it = 0; it < 6; it++) {
        int p = probe(e, s, f, &lo, &hi);
        if (p < 0) return VIGEN_ENONFINITE;
        if (p > 0) {
            *out = s;
            return VIGEN_SUCCESS;
        }
        double den = 2 * f[1] * f[1] - f[0] * f[2];
        if (!(den > 0) || !(f[1] > 0)) break;
        double d = -2 * f[0] * f[1] / den, next = s + d;
        if (!(next > lo && next < hi)) break;
        double k = f[2] * f[2] / (4 * f[1]) + fabs(f[3]) / 6;
        if (k * d * d * fabs(d) <= 0.25 * DBL_EPSILON * fabs(h)) {
            *out = next;
            return VIGEN_SUCCESS;
        }
        s = next;
    }
    if (!(s > lo && s < hi)) s = isinf(hi) ? 2 * lo + ir0 * h : isinf(lo) ? 2 * hi + ir0 * h : lo + (hi - lo) / 2;
    return solve_bracketed(e, s, lo, hi, out);
}

int vigen_kepler_drift(double mu, double h, double *x, double *v)
{
    if (x == NULL || v == NULL || !(mu > 0) || !isfinite(mu) || !isfinite(h)) return VIGEN_EINVAL;
    if (!all_finite6(x, v)) return VIGEN_ENONFINITE;
    xreal r0x = sqrtl((xreal)x[0] * x[0] + (xreal)x[1] * x[1] + (xreal)x[2] * x[2]);
    xreal v2x = (xreal)v[0] * v[0] + (xreal)v[1] * v[1] + (xreal)v[2] * v[2];
    xreal etax = (xreal)x[0] * v[0] + (xreal)x[1] * v[1] + (xreal)x[2] * v[2];
    xreal betax = 2 * mu / r0x - v2x, zetax = mu - betax * r0x;
    double r0 = (double)r0x, v2 = (double)v2x, eta = (double)etax, beta = (double)betax, zeta = (double)zetax;
    if (!(r0 > 0)) return VIGEN_EINVAL;
    if (h == 0) return VIGEN_SUCCESS;
    if (!isfinite(beta) || !isfinite(eta)) return VIGEN_ENONFINITE;
    /* a radial orbit (angular momentum zero to round-off) reaches the
     * centre when it falls inward or is bound: a collision */
    double lx = x[1] * v[2] - x[2] * v[1], ly = x[2] * v[0] - x[0] * v[2], lz = x[0] * v[1] - x[1] * v[0];
    double l2 = lx * lx + ly * ly + lz * lz;
    if (l2 <= 64 * DBL_EPSILON * DBL_EPSILON * r0 * r0 * v2 && (eta * h < 0 || beta > 0 || v2 == 0))
        return VIGEN_EINVAL;
    /* a bound orbit: h modulo the period 2 pi mu / beta^(3/2) */
    if (beta > 0 && h * h * beta * beta * beta > 4 * KEPLER_PI * KEPLER_PI * mu * mu) {
        h = remainder(h, 2 * KEPLER_PI * mu / (beta * sqrt(beta)));
        if (h == 0) return VIGEN_SUCCESS;
    }
    double s;
    equation e = { r0, eta, zeta, beta, h };
    int st = solve(&e, &s);
    if (st != VIGEN_SUCCESS) return st;
    /* the map at s, extended */
    xreal c[4];
    stumpff_x(betax * s * s, c);
    xreal g1 = s * c[1], g2 = (xreal)s * s * c[2];
    xreal r = r0x + etax * g1 + zetax * g2;
    if (!(r > 0) || !isfinite(r)) return r > 0 ? VIGEN_ENONFINITE : VIGEN_EINVAL;
    xreal fm1 = -mu * g2 / r0x, gg = r0x * g1 + etax * g2;
    xreal fdot = -mu * g1 / (r * r0x), gdm1 = -mu * g2 / r;
    double xn[3], vn[3];
    for (int k = 0; k < 3; k++) {
        xn[k] = (double)(x[k] + (fm1 * x[k] + gg * v[k]));
        vn[k] = (double)(v[k] + (fdot * x[k] + gdm1 * v[k]));
    }
    if (!all_finite6(xn, vn)) return VIGEN_ENONFINITE;
    for (int k = 0; k < 3; k++) {
        x[k] = xn[k];
        v[k] = vn[k];
    }
    return VIGEN_SUCCESS;
}
