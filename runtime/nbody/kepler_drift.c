/* kepler_drift.c — the two-body flow x'' = -mu x/|x|^3 by universal
 * variables (Danby, Fundamentals of Celestial Mechanics, ch. 6.9; Wisdom &
 * Hernandez 2015, MNRAS 453, 3015).
 *
 * With r0 = |x|, eta = x.v, beta = 2 mu/r0 - |v|^2 (> 0 bound) and
 * zeta = mu - beta r0, the universal anomaly s after time h solves
 *   F(s) = r0 s + eta G2(s) + zeta G3(s) - h = 0,   G_k(s) = s^k c_k(beta s^2),
 * c_k the Stumpff functions; F'(s) = r(s) = r0 + eta G1 + zeta G2 > 0, so
 * F increases and a bracket is kept while Laguerre-Conway iterations
 * converge.  Then x += (f - 1) x + g v, v += fdot x + (gdot - 1) v with
 * f - 1 = -mu G2/r0, g = r0 G1 + eta G2, fdot = -mu G1/(r r0),
 * gdot - 1 = -mu G2/r: the increments, small for small h, keep the round-off
 * of the update small.  g is taken in the form r0 G1 + eta G2 rather than
 * h - mu G3 (equal at the exact root): with it f, g, fdot, gdot are the
 * exact Kepler map of the time that s stands for, so that the round-off
 * left in s moves the orbit along itself (a phase) and never changes its
 * energy, which would otherwise drift steadily. */
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

int vigen_kepler_drift(double mu, double h, double *x, double *v)
{
    if (x == NULL || v == NULL || !(mu > 0) || !isfinite(mu) || !isfinite(h)) return VIGEN_EINVAL;
    if (!all_finite6(x, v)) return VIGEN_ENONFINITE;
    double r0 = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (!(r0 > 0)) return VIGEN_EINVAL;
    if (h == 0) return VIGEN_SUCCESS;
    double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    double eta = x[0] * v[0] + x[1] * v[1] + x[2] * v[2];
    double beta = 2 * mu / r0 - v2, zeta = mu - beta * r0;
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
    /* s has the sign of h (F(0) = -h, F increasing): the bracket starts as
     * (0, inf) or (-inf, 0) and closes as F is evaluated; the first guess
     * is the series s = h/r0 - eta h^2/(2 r0^3) (its first term when the
     * second flips the sign) */
    double s = h / r0 - eta * h * h / (2 * r0 * r0 * r0), g[4];
    if (!(s * h > 0)) s = h / r0;
    double lo = h > 0 ? 0 : -INFINITY, hi = h > 0 ? INFINITY : 0;
    /* Laguerre-Conway (n = 5) inside the bracket.  A step that leaves the
     * bracket, and every step after the 30th, bisects it instead, or
     * doubles s while one end is still infinite; within 2200 iterations
     * the doubles between the ends are exhausted.  Converged when the step
     * is at round-off, or when it stops decreasing near it: F is then at
     * the noise of its own round-off (terms of size h), where no step
     * improves s (a stall counts within 4096 eps of s only). */
    int converged = 0;
    double last = INFINITY;
    for (int it = 0; it < 2200; it++) {
        gfunctions(beta, s, g);
        double f = r0 * s + eta * g[2] + zeta * g[3] - h;
        double fp = r0 + eta * g[1] + zeta * g[2];
        double fpp = eta * g[0] + zeta * g[1];
        if (isnan(f) || !isfinite(fp)) return VIGEN_ENONFINITE;
        if (f == 0) {
            converged = 1;
            break;
        }
        if (f < 0) lo = s; else hi = s;
        double disc = fabs(16 * fp * fp - 20 * f * fpp);
        double den = fp + (fp >= 0 ? 1 : -1) * sqrt(disc);
        double next = den != 0 && isfinite(f) ? s - 5 * f / den : NAN;
        int bisect = !(next > lo && next < hi) || it >= 30;
        if (bisect) {
            if (isinf(hi)) next = 2 * s;
            else if (isinf(lo)) next = 2 * s;
            else next = lo + (hi - lo) / 2;
            if (!isfinite(next)) return VIGEN_ENONFINITE;
        }
        double ds = fabs(next - s);
        if (ds <= 2 * DBL_EPSILON * fabs(next) || next == lo || next == hi
            || (!bisect && ds >= last && ds <= 4096 * DBL_EPSILON * fabs(next))) {
            /* the G functions at the last, round-off step by their
             * derivatives (G_k' = G_(k-1), G0' = -beta G1): the error is
             * (4096 eps s)^2 at most, far below round-off */
            double d = next - s;
            g[3] += g[2] * d;
            g[2] += g[1] * d;
            g[1] += g[0] * d;
            g[0] -= beta * g[1] * d;
            s = next;
            converged = 1;
            break;
        }
        s = next;
        if (!bisect) last = ds;
    }
    if (!converged) return VIGEN_ENOCONV;
    double r = r0 + eta * g[1] + zeta * g[2];
    if (!(r > 0) || !isfinite(r)) return r > 0 ? VIGEN_ENONFINITE : VIGEN_EINVAL;
    double ir0 = 1 / r0, ir = 1 / r;
    double fm1 = -mu * g[2] * ir0, gg = r0 * g[1] + eta * g[2];
    double fdot = -mu * g[1] * ir * ir0, gdm1 = -mu * g[2] * ir;
    double xn[3], vn[3];
    for (int c = 0; c < 3; c++) {
        xn[c] = x[c] + (fm1 * x[c] + gg * v[c]);
        vn[c] = v[c] + (fdot * x[c] + gdm1 * v[c]);
    }
    if (!all_finite6(xn, vn)) return VIGEN_ENONFINITE;
    for (int c = 0; c < 3; c++) {
        x[c] = xn[c];
        v[c] = vn[c];
    }
    return VIGEN_SUCCESS;
}
