/* kepler_drift_bench.c — the runtime's Kepler drift alone, on orbits of
 * mu = 1, semi-major axis 1 (period 2 pi) and eccentricity E, each started
 * at its own mean anomaly in its own inclined plane (every coordinate
 * moves):
 *   kepler_drift_bench count E HFRAC N    N drifts of HFRAC periods (for
 *                                         callgrind: the instructions of N
 *                                         drifts minus those of N/2)
 *   kepler_drift_bench energy E HFRAC N [ORBITS]
 *                                         N drifts on each orbit; prints at
 *                                         steps 10^k, 2 10^k, 5 10^k the
 *                                         rms over the orbits and the
 *                                         largest relative energy error, and
 *                                         the rms over eps sqrt(steps)
 *                                         (Brouwer's law: about constant).
 *                                         The energy is evaluated in long
 *                                         double, below the state's
 *                                         round-off.
 * drift_run.sh runs the energy figures of docs/benchmarks.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/nbody.h>

static long double energy(const double *x, const double *v)
{
    long double r = sqrtl((long double)x[0] * x[0] + (long double)x[1] * x[1] + (long double)x[2] * x[2]);
    long double v2 = (long double)v[0] * v[0] + (long double)v[1] * v[1] + (long double)v[2] * v[2];
    return v2 / 2 - 1 / r;
}

/* The state at mean anomaly 0.7 k (Kepler's equation by Newton's method in
 * long double) in the plane, turned by 0.3 + 0.1 k about x and 0.2 about z:
 * orbit k of the energy runs. */
static void start(double e, int k, double *x, double *v)
{
    long double M = 0.7L * k, E = M;
    for (int it = 0; it < 60; it++) E -= (E - e * sinl(E) - M) / (1 - e * cosl(E));
    long double c = cosl(E), sn = sinl(E), d = 1 - e * c, s = sqrtl(1 - (long double)e * e);
    double xp[3] = { (double)(c - e), (double)(s * sn), 0 }, vp[3] = { (double)(-sn / d), (double)(s * c / d), 0 };
    double ci = cos(0.3 + 0.1 * k), si = sin(0.3 + 0.1 * k), co = cos(0.2), so = sin(0.2);
    for (int j = 0; j < 2; j++) {
        const double *a = j ? vp : xp;
        double *b = j ? v : x;
        double y = a[1] * ci, z = a[1] * si;
        b[0] = a[0] * co - y * so;
        b[1] = a[0] * so + y * co;
        b[2] = z;
    }
}

enum { CHECKS = 64 };

int main(int argc, char **argv)
{
    if (argc < 5 || argc > 6 || (strcmp(argv[1], "count") != 0 && strcmp(argv[1], "energy") != 0)) {
        fprintf(stderr, "usage: kepler_drift_bench count|energy E HFRAC N [ORBITS]\n");
        return 2;
    }
    double e = atof(argv[2]), h = atof(argv[3]) * 2 * 3.14159265358979323846, x[3], v[3];
    long n = atol(argv[4]);
    int orbits = argc == 6 ? atoi(argv[5]) : 1;
    if (strcmp(argv[1], "count") == 0) {
        start(e, 0, x, v);
        for (long k = 0; k < n; k++)
            if (vigen_kepler_drift(1, h, x, v) != VIGEN_SUCCESS) return 1;
        printf("%.17g %.17g\n", x[0], v[0]);
        return 0;
    }
    /* checkpoints 10, 20, 50, 100, ... and n */
    long at[CHECKS];
    int nat = 0;
    for (long dec = 10; nat < CHECKS - 4 && dec <= n; dec *= 10)
        for (int j = 0; j < 3; j++) {
            long c = dec * (j == 0 ? 1 : j == 1 ? 2 : 5);
            if (c < n) at[nat++] = c;
        }
    at[nat++] = n;
    double sum2[CHECKS] = { 0 }, worst[CHECKS] = { 0 };
    printf("# e = %g, h = %s periods, %d orbit(s): steps, rms and largest relative energy error,"
           " rms/(eps sqrt(steps))\n", e, argv[3], orbits);
    fflush(stdout);
    for (int o = 0; o < orbits; o++) {
        start(e, o, x, v);
        long double E0 = energy(x, v);
        int j = 0;
        for (long k = 1; k <= n; k++) {
            int st = vigen_kepler_drift(1, h, x, v);
            if (st != VIGEN_SUCCESS) {
                fprintf(stderr, "orbit %d, drift %ld: status %d\n", o, k, st);
                return 1;
            }
            if (k == at[j]) {
                double err = (double)((energy(x, v) - E0) / E0);
                sum2[j] += err * err;
                if (fabs(err) > worst[j]) worst[j] = fabs(err);
                if (orbits == 1) { /* a long single run: each row as it comes */
                    printf("%ld %.3e %.3e %.3f\n", k, fabs(err), fabs(err),
                           fabs(err) / (2.220446049250313e-16 * sqrt((double)k)));
                    fflush(stdout);
                }
                j++;
            }
        }
    }
    if (orbits == 1) return 0;
    for (int j = 0; j < nat; j++) {
        double rms = sqrt(sum2[j] / orbits);
        printf("%ld %.3e %.3e %.3f\n", at[j], rms, worst[j], rms / (2.220446049250313e-16 * sqrt((double)at[j])));
    }
    return 0;
}
