/* test_velocity_map.c — Hamilton–Pontryagin steppers with a velocity map of
 * their user (<vigen/lagrangian.h>), on the map with a genuine parameter of
 * tests/data/lagrangian/chord_map.h:
 *   - its derivatives D1phi, D2phi, Daphi against central differences of phi;
 *   - a user-written trivial map (q1 - q0)/h gives the trajectory of the
 *     built-in one (NULL) to round-off (the general code path against the
 *     special one);
 *   - on the Kepler problem (eccentricity 1/2), both rules: bounded energy
 *     with no drift over 10^5 steps; the parameter equation holds at every
 *     step in its closed form a = h c.p / ((q1 - q0).p) with p = v_{n+1/2}
 *     for this L; a varies along the orbit; the trajectory differs from the
 *     trivial map's by the O(h^3) per step the map changes;
 *   - order 2 against the exact solution of a harmonic oscillator;
 *   - the parameters before the first step and after a reset are a0;
 *   - maps that cannot be used are refused with their reason. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/lagrangian.h>
#include "testlib.h"
#include "../data/lagrangian/chord_map.h"

static double c_vec[2] = { 0.3, -0.2 };
static const double a0_val[1] = { 0.0 };

static vigen_velocity_map chord_map(void)
{
    vigen_velocity_map m = { 2, 1, chord_phi, chord_D1, chord_D2, chord_Da, a0_val, c_vec };
    return m;
}

static void test_derivatives(void)
{
    vigen_velocity_map m = chord_map();
    const double pts[3][6] = { { 0.1, -0.4, 0.35, -0.2, 0.7, 0.05 },
                               { 1.3, 0.2, 1.2, 0.31, -2.1, 0.2 },
                               { -0.5, 0.9, -0.45, 0.85, 0.01, 0.013 } };
    for (int k = 0; k < 3; k++) {
        double q0[2] = { pts[k][0], pts[k][1] }, q1[2] = { pts[k][2], pts[k][3] }, a[1] = { pts[k][4] }, h = pts[k][5];
        double D1[4], D2[4], Da[2], vp[2], vm[2];
        m.D1phi(h, q0, q1, a, D1, m.ctx);
        m.D2phi(h, q0, q1, a, D2, m.ctx);
        m.Daphi(h, q0, q1, a, Da, m.ctx);
        double err = 0;
        for (int j = 0; j < 3 * 2 - 1; j++) {      /* columns: q0_0, q0_1, q1_0, q1_1, a */
            double *x = j < 2 ? &q0[j] : j < 4 ? &q1[j - 2] : &a[0], x0 = *x, d = 1e-6 * fmax(1.0, fabs(x0));
            *x = x0 + d;
            m.phi(h, q0, q1, a, vp, m.ctx);
            *x = x0 - d;
            m.phi(h, q0, q1, a, vm, m.ctx);
            *x = x0;
            for (int i = 0; i < 2; i++) {
                double fd = (vp[i] - vm[i]) / (2 * d);
                double an = j < 2 ? D1[i * 2 + j] : j < 4 ? D2[i * 2 + j - 2] : Da[i];
                err = fmax(err, fabs(fd - an) / fmax(1.0, fabs(an)));
            }
        }
        CHECK_MSG(err < 1e-7, "point %d: derivatives vs central differences: %.3e", k, err);
    }
}

/* ---- Kepler, L = |v|^2/2 + 1/|q| ------------------------------------------- */
static void kep_dq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    o[0] = -q[0] / r3;
    o[1] = -q[1] / r3;
}
static void id_dv(double t, const double *q, const double *v, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = v[0]; o[1] = v[1]; }
static double kep_energy(const double *q, const double *p) { return 0.5 * (p[0] * p[0] + p[1] * p[1]) - 1.0 / sqrt(q[0] * q[0] + q[1] * q[1]); }

/* the trivial map written as a user would */
static void triv_phi(double h, const double *q0, const double *q1, const double *a, double *o, void *c)
{
    (void)a; (void)c;
    for (int i = 0; i < 2; i++) o[i] = (q1[i] - q0[i]) / h;
}
static void triv_D(double h, const double *q0, const double *q1, const double *a, double *o, void *c, double s)
{
    (void)q0; (void)q1; (void)a; (void)c;
    o[0] = s / h; o[1] = 0; o[2] = 0; o[3] = s / h;
}
static void triv_D1(double h, const double *q0, const double *q1, const double *a, double *o, void *c) { triv_D(h, q0, q1, a, o, c, -1); }
static void triv_D2(double h, const double *q0, const double *q1, const double *a, double *o, void *c) { triv_D(h, q0, q1, a, o, c, 1); }

static void test_user_trivial(void)
{
    vigen_lagrangian lag = { 2, kep_dq, id_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_velocity_map tm = { 2, 0, triv_phi, triv_D1, triv_D2, NULL, NULL, NULL };
    for (int rule = 0; rule < 2; rule++) {
        vigen_hp *wu = vigen_hp_alloc(&lag, rule, &tm, NULL), *wb = vigen_hp_alloc(&lag, rule, NULL, NULL);
        double tu = 0, qu[2] = { 1, 0 }, pu[2] = { 0, 1.2 }, tb = 0, qb[2] = { 1, 0 }, pb[2] = { 0, 1.2 }, err = 0;
        for (int k = 0; k < 1000; k++) {
            CHECK(vigen_hp_step(wu, &tu, qu, pu, 0.01) == 0 && vigen_hp_step(wb, &tb, qb, pb, 0.01) == 0);
            for (int i = 0; i < 2; i++) err = fmax(err, fmax(fabs(qu[i] - qb[i]), fabs(pu[i] - pb[i])));
        }
        CHECK_MSG(err < 1e-12, "rule %d: user trivial map vs built-in: %.3e", rule, err);
        vigen_hp_free(wu);
        vigen_hp_free(wb);
    }
}

static void test_kepler(void)
{
    vigen_lagrangian lag = { 2, kep_dq, id_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_velocity_map m = chord_map();
    const long n = 100000;
    const double h = 0.01;
    double *e = malloc(n * sizeof(double));
    for (int rule = 0; rule < 2; rule++) {
        vigen_hp *w = vigen_hp_alloc(&lag, rule, &m, NULL), *wt = vigen_hp_alloc(&lag, rule, NULL, NULL);
        CHECK(w != NULL && vigen_hp_nparams(w) == 1 && vigen_hp_params(w)[0] == 0.0);
        /* eccentricity 1/2: q = (1, 0), |p| = sqrt(1.5) */
        double t = 0, q[2] = { 1, 0 }, p[2] = { 0, sqrt(1.5) }, tt = 0, qt[2] = { 1, 0 }, pt[2] = { 0, sqrt(1.5) };
        const double e0 = kep_energy(q, p);
        double aerr = 0, amin = INFINITY, amax = -INFINITY, dtriv = 0;
        int st = 0;
        long k;
        for (k = 0; k < n && st == 0; k++) {
            double q0[2] = { q[0], q[1] };
            st = vigen_hp_step(w, &t, q, p, h);
            if (st) break;
            e[k] = kep_energy(q, p);
            /* the parameter equation in closed form, p_{n+1/2} = v_{n+1/2} */
            const double *v = vigen_hp_velocity(w), a = vigen_hp_params(w)[0];
            double dq0 = q[0] - q0[0], dq1 = q[1] - q0[1];
            double a_closed = h * (c_vec[0] * v[0] + c_vec[1] * v[1]) / (dq0 * v[0] + dq1 * v[1]);
            aerr = fmax(aerr, fabs(a - a_closed) / fmax(1.0, fabs(a_closed)));
            amin = fmin(amin, a);
            amax = fmax(amax, a);
            if (k < 100) {
                CHECK(vigen_hp_step(wt, &tt, qt, pt, h) == 0);
                if (k == 99) dtriv = fmax(fabs(q[0] - qt[0]), fabs(q[1] - qt[1]));
            }
        }
        CHECK_MSG(st == 0, "rule %d: status %d at step %ld", rule, st, k);
        if (st == 0) {
            double first = 0, last = 0;
            for (long j = 0; j < n / 10; j++) first = fmax(first, fabs(e[j] - e0));
            for (long j = n - n / 10; j < n; j++) last = fmax(last, fabs(e[j] - e0));
            CHECK_MSG(last <= 1.5 * first && first < 1e-3, "rule %d: energy error %.3e (first tenth), %.3e (last)", rule, first, last);
            fprintf(stderr, "  chord map, rule %d: energy error %.2e / %.2e, a in [%.3f, %.3f], %.2e from the trivial map\n",
                    rule, first, last, amin, amax, dtriv);
        }
        CHECK_MSG(aerr < 1e-9, "rule %d: parameter equation off by %.3e", rule, aerr);
        CHECK_MSG(amax - amin > 0.1, "rule %d: a stays in [%g, %g]", rule, amin, amax);
        CHECK_MSG(dtriv > 1e-9 && dtriv < 1e-3, "rule %d: %.3e from the trivial map after 100 steps", rule, dtriv);
        CHECK(vigen_hp_stats(w)->steps == (unsigned long)n);
        vigen_hp_reset(w);
        CHECK(vigen_hp_params(w)[0] == 0.0 && vigen_hp_stats(w)->steps == 0);
        vigen_hp_free(w);
        vigen_hp_free(wt);
    }
    free(e);
}

/* harmonic oscillator L = |v|^2/2 - |q|^2/2: q(t) = q0 cos t + p0 sin t */
static void ho_dq(double t, const double *q, const double *v, double *o, void *c) { (void)t; (void)v; (void)c; o[0] = -q[0]; o[1] = -q[1]; }

static void test_order(void)
{
    vigen_lagrangian lag = { 2, ho_dq, id_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_velocity_map m = chord_map();
    for (int rule = 0; rule < 2; rule++) {
        double prev = 0;
        for (int k = 0; k < 4; k++) {
            long n = 50L << k;
            double h = 5.0 / n, t = 0, q[2] = { 1, 0 }, p[2] = { 0.3, 0.8 }, err = 0;
            vigen_hp *w = vigen_hp_alloc(&lag, rule, &m, NULL);
            for (long s = 0; s < n; s++) {
                CHECK(vigen_hp_step(w, &t, q, p, h) == 0);
                for (int i = 0; i < 2; i++) {
                    double q0 = i ? 0.0 : 1.0, p0 = i ? 0.8 : 0.3;
                    err = fmax(err, fmax(fabs(q[i] - (q0 * cos(t) + p0 * sin(t))), fabs(p[i] - (-q0 * sin(t) + p0 * cos(t)))));
                }
            }
            if (k > 0) {
                double o = log2(prev / err);
                CHECK_MSG(fabs(o - 2) < 0.1, "chord map, rule %d: order %.3f (errors %.3e, %.3e)", rule, o, prev, err);
            }
            prev = err;
            vigen_hp_free(w);
        }
    }
}

static void test_refused(void)
{
    vigen_lagrangian lag = { 2, ho_dq, id_dv, NULL, NULL, NULL, NULL, NULL };
    const char *why = NULL;
    vigen_velocity_map m = chord_map();
    CHECK(vigen_lagrangian_validate(&lag, &m, &why) == VIGEN_SUCCESS && why == NULL);
    m.dim = 3;
    CHECK(vigen_lagrangian_validate(&lag, &m, &why) == VIGEN_EINVAL && why && strstr(why, "dim"));
    CHECK(vigen_hp_alloc(&lag, VIGEN_HP_TRAPEZOIDAL, &m, NULL) == NULL);
    m = chord_map();
    m.Daphi = NULL;
    CHECK(vigen_lagrangian_validate(&lag, &m, &why) == VIGEN_EINVAL && why && strstr(why, "Daphi"));
    CHECK(vigen_hp_alloc(&lag, VIGEN_HP_MIDPOINT, &m, NULL) == NULL);
    m.nparams = 0;      /* no parameters: Daphi is not needed */
    CHECK(vigen_lagrangian_validate(&lag, &m, &why) == VIGEN_SUCCESS);
    m = chord_map();
    m.phi = NULL;
    CHECK(vigen_lagrangian_validate(&lag, &m, &why) == VIGEN_EINVAL && why && strstr(why, "phi"));
    m = chord_map();
    m.D2phi = NULL;
    CHECK(vigen_lagrangian_validate(&lag, &m, &why) == VIGEN_EINVAL && why && strstr(why, "D2phi"));
    /* a0 NULL means zeros */
    m = chord_map();
    m.a0 = NULL;
    vigen_hp *w = vigen_hp_alloc(&lag, VIGEN_HP_TRAPEZOIDAL, &m, NULL);
    CHECK(w && vigen_hp_params(w)[0] == 0.0);
    vigen_hp_free(w);
}

int main(void)
{
    test_derivatives();
    test_user_trivial();
    test_kepler();
    test_order();
    test_refused();
    TEST_MAIN_END();
}
