/* test_nbody_kepler.c — the universal-variable Kepler drift
 * (vigen_kepler_drift) against the solution of Kepler's equation, solved
 * here in long double by the classical anomalies (eccentric, hyperbolic,
 * Barker's parabolic): elliptic e = 0, 0.5, 0.9, 0.999, parabolic,
 * near-parabolic and hyperbolic e = 1.5, 5, over many periods, in many
 * small drifts and in one; the energy of pure Kepler orbits over 2 10^5
 * drifts growing like the square root of the steps; bad input refused with the state unchanged. */
#include <float.h>
#include <math.h>
#include <string.h>
#include <vigen/nbody.h>
#include "testlib.h"

#define M_PI_ 3.14159265358979323846

/* The orbit of pericentre distance qp and eccentricity e about mu, started
 * at the pericentre on the x axis moving along +y, at time t: in long
 * double from Kepler's equation, Newton's method safeguarded by
 * bisection. */
static void kepler_truth(long double mu, long double qp, long double e, long double t, double *x, double *v)
{
    long double X, Y, VX, VY;
    if (e < 1) {
        long double a = qp / (1 - e), n = sqrtl(mu / (a * a * a));
        long double M = fmodl(n * t, 2 * 3.14159265358979323846264338327950288L);
        long double lo = 0, hi = 2 * 3.14159265358979323846264338327950288L, E = M + e * sinl(M);
        for (int it = 0; it < 200; it++) {
            long double f = E - e * sinl(E) - M;
            if (f == 0) break;
            if (f > 0) hi = E; else lo = E;
            long double next = E - f / (1 - e * cosl(E));
            if (!(next >= lo && next <= hi)) next = (lo + hi) / 2;
            if (fabsl(next - E) <= 4 * LDBL_EPSILON * (1 + fabsl(E))) { E = next; break; }
            E = next;
        }
        long double b = a * sqrtl((1 - e) * (1 + e)), Ed = n / (1 - e * cosl(E));
        X = a * (cosl(E) - e); Y = b * sinl(E);
        VX = -a * sinl(E) * Ed; VY = b * cosl(E) * Ed;
    } else if (e > 1) {
        long double a = qp / (e - 1), n = sqrtl(mu / (a * a * a)), M = n * t;
        long double lo = -800, hi = 800, H = asinhl(M / e);
        for (int it = 0; it < 400; it++) {
            long double f = e * sinhl(H) - H - M;
            if (f == 0) break;
            if (f > 0) hi = H; else lo = H;
            long double next = H - f / (e * coshl(H) - 1);
            if (!(next >= lo && next <= hi)) next = (lo + hi) / 2;
            if (fabsl(next - H) <= 4 * LDBL_EPSILON * (1 + fabsl(H))) { H = next; break; }
            H = next;
        }
        long double b = a * sqrtl((e - 1) * (e + 1)), Hd = n / (e * coshl(H) - 1);
        X = a * (e - coshl(H)); Y = b * sinhl(H);
        VX = -a * sinhl(H) * Hd; VY = b * coshl(H) * Hd;
    } else {
        /* Barker: D + D^3/3 = t sqrt(mu/(2 qp^3)), D = tan(nu/2) */
        long double k = sqrtl(mu / (2 * qp * qp * qp)), M = k * t, D = cbrtl(3 * M);
        for (int it = 0; it < 200; it++) {
            long double next = D - (D + D * D * D / 3 - M) / (1 + D * D);
            if (fabsl(next - D) <= 4 * LDBL_EPSILON * (1 + fabsl(D))) { D = next; break; }
            D = next;
        }
        long double Dd = k / (1 + D * D);
        X = qp * (1 - D * D); Y = 2 * qp * D;
        VX = -2 * qp * D * Dd; VY = 2 * qp * Dd;
    }
    x[0] = (double)X; x[1] = (double)Y; x[2] = 0;
    v[0] = (double)VX; v[1] = (double)VY; v[2] = 0;
}

static double rel_err(const double *a, const double *b)
{
    double d = 0, s = 0;
    for (int c = 0; c < 3; c++) {
        d += (a[c] - b[c]) * (a[c] - b[c]);
        s += b[c] * b[c];
    }
    return sqrt(d / s);
}

/* nsteps drifts of h from the pericentre; the position and velocity
 * errors against the truth at the end, relative. */
static void check_orbit(double mu, double qp, double e, double h, int nsteps, double tol)
{
    double x[3], v[3], xt[3], vt[3];
    kepler_truth(mu, qp, e, 0, x, v);
    int st = VIGEN_SUCCESS;
    for (int k = 0; k < nsteps && st == VIGEN_SUCCESS; k++) st = vigen_kepler_drift(mu, h, x, v);
    CHECK_MSG(st == VIGEN_SUCCESS, "e = %g: status %d", e, st);
    kepler_truth(mu, qp, e, (long double)h * nsteps, xt, vt);
    double ex = rel_err(x, xt), ev = rel_err(v, vt);
    CHECK_MSG(ex <= tol && ev <= tol, "e = %g, h = %g, %d drifts: position error %.3g, velocity error %.3g (tol %.3g)",
              e, h, nsteps, ex, ev, tol);
    /* one drift of the whole time */
    kepler_truth(mu, qp, e, 0, x, v);
    st = vigen_kepler_drift(mu, h * nsteps, x, v);
    CHECK_MSG(st == VIGEN_SUCCESS, "e = %g, one drift of %g: status %d", e, h * nsteps, st);
    ex = rel_err(x, xt);
    ev = rel_err(v, vt);
    CHECK_MSG(ex <= tol && ev <= tol, "e = %g, one drift of %g: position error %.3g, velocity error %.3g", e,
              h * nsteps, ex, ev);
}

static void elliptic(void)
{
    static const double ecc[] = { 0.0, 0.5, 0.9, 0.999 };
    for (size_t k = 0; k < sizeof ecc / sizeof ecc[0]; k++) {
        double e = ecc[k], qp = 1 - e, period = 2 * M_PI_; /* a = 1, mu = 1 */
        /* 100.5 periods (the end near the apocentre) in steps that are no
         * divisor of the period */
        int nsteps = 100 * 97;
        double h = 100.5 * period / nsteps;
        /* the sensitivity of the phase grows with the steps and with the
         * speed at the pericentre, 1/(1 - e) */
        check_orbit(1.0, qp, e, h, nsteps, 2e-9 * (e > 0.99 ? 100 : 1));
        check_orbit(1.0, qp, e, 0.37 * period, 31, 1e-12 / (1 - e));
    }
}

static void parabolic_and_hyperbolic(void)
{
    /* parabolic and near-parabolic (both sides), about mu = 2 with q = 0.5 */
    check_orbit(2.0, 0.5, 1.0, 0.05, 4000, 1e-11);
    check_orbit(2.0, 0.5, 1.0 + 1e-8, 0.05, 4000, 1e-11);
    check_orbit(2.0, 0.5, 1.0 - 1e-8, 0.05, 4000, 1e-11);
    check_orbit(1.0, 1.0, 1.5, 0.01, 10000, 1e-11);
    check_orbit(1.0, 1.0, 5.0, 0.01, 10000, 1e-11);
    check_orbit(1.0, 0.1, 5.0, 0.001, 1000, 1e-11);
}

/* The energy |v|^2/2 - mu/|x| (in long double) of orbits with e = 0 and
 * 0.5 in drifts of a tenth of the period, the hardest case for a bias:
 * every tenth step returns to the same point of the orbit, so that a
 * rounding error that depends on the point repeats.  Over 2 10^5 drifts
 * on each of 4 orbits (started at their own phases), the rms relative
 * error must stay within 3 eps sqrt(n) (a random walk of the round-off,
 * Brouwer's law: about 0.5 eps sqrt(n)); a drift of 0.02 eps per step,
 * that of a map evaluated in plain double, reaches 20 eps sqrt(n). */
static void energy_drift(void)
{
    static const double ecc[] = { 0.0, 0.5 };
    long n = 200000;
    for (int k = 0; k < 2; k++) {
        double e = ecc[k], h = 2 * M_PI_ / 10, sum2 = 0;
        for (int o = 0; o < 4; o++) {
            double x[3], v[3];
            kepler_truth(1, 1 - e, e, 0.7 * o + 0.1, x, v);
            long double E0 = ((long double)v[0] * v[0] + (long double)v[1] * v[1]) / 2
                             - 1 / sqrtl((long double)x[0] * x[0] + (long double)x[1] * x[1]);
            for (long j = 0; j < n; j++)
                if (vigen_kepler_drift(1, h, x, v) != VIGEN_SUCCESS) { CHECK(0); break; }
            long double E = ((long double)v[0] * v[0] + (long double)v[1] * v[1] + (long double)v[2] * v[2]) / 2
                            - 1 / sqrtl((long double)x[0] * x[0] + (long double)x[1] * x[1] + (long double)x[2] * x[2]);
            double err = (double)(E / E0 - 1);
            sum2 += err * err;
        }
        double ratio = sqrt(sum2 / 4) / (sqrt((double)n) * DBL_EPSILON);
        /* the unbiased map needs a long double wider than double */
        CHECK_MSG(ratio <= 3 || LDBL_MANT_DIG <= DBL_MANT_DIG,
                  "e = %g: rms energy error %.3g eps sqrt(n) over %ld drifts", e, ratio, n);
        printf("kepler drift, e = %g, h = period/10: rms energy error %.3g eps sqrt(n) over %ld drifts\n", e,
               ratio, n);
    }
}

static void bad_input(void)
{
    double x[3] = { 1, 0, 0 }, v[3] = { 0, 1, 0 }, x0[3], v0[3];
    memcpy(x0, x, sizeof x);
    memcpy(v0, v, sizeof v);
    CHECK(vigen_kepler_drift(1, NAN, x, v) == VIGEN_EINVAL);
    CHECK(vigen_kepler_drift(-1, 1, x, v) == VIGEN_EINVAL);
    CHECK(vigen_kepler_drift(NAN, 1, x, v) == VIGEN_EINVAL);
    x[1] = NAN;
    CHECK(vigen_kepler_drift(1, 1, x, v) == VIGEN_ENONFINITE);
    CHECK(isnan(x[1]) && x[0] == 1 && v[1] == 1);
    x[1] = 0;
    /* at the centre */
    double z[3] = { 0, 0, 0 };
    CHECK(vigen_kepler_drift(1, 1, z, v) == VIGEN_EINVAL);
    CHECK(z[0] == 0 && z[1] == 0 && z[2] == 0 && v[1] == 1);
    /* radial infall: a collision orbit */
    double vr[3] = { -0.5, 0, 0 };
    CHECK(vigen_kepler_drift(1, 0.1, x, vr) == VIGEN_EINVAL);
    CHECK(memcmp(x, x0, sizeof x) == 0 && vr[0] == -0.5);
    /* a hyperbolic orbit driven past overflow */
    double vh[3] = { 0, 10, 0 };
    int st = vigen_kepler_drift(1, 1e300, x, vh);
    CHECK(st == VIGEN_ENONFINITE || st == VIGEN_SUCCESS);
    if (st != VIGEN_SUCCESS) CHECK(memcmp(x, x0, sizeof x) == 0 && vh[1] == 10);
    CHECK(memcmp(v, v0, sizeof v) == 0);
}

int main(void)
{
    elliptic();
    parabolic_and_hyperbolic();
    energy_drift();
    bad_input();
    TEST_MAIN_END();
}
