/* drivers_bench.c — the drivers of the runtime on one emitted stepper, for
 * instruction counts under callgrind (bench/drivers_compare.sh sets two
 * trees side by side): Gauss s = 2 and Stormer-Verlet, emitted as general
 * steppers (callbacks), on Kepler (e = 0.6, h = 2 pi/200).
 *
 *   drivers_bench STEPPER CASE STEPS
 *     STEPPER: gauss2 | verlet
 *     CASE:    integrate     vigen_integrate, no observer
 *              at            vigen_integrate_at, an output every 7.3 steps
 *              events        vigen_integrate_events, the pericentre passages
 *                            (q.p changes sign, rising)
 *              ensemble      vigen_integrate_ensemble, 16 trajectories on one
 *                            thread, STEPS/16 steps each
 * Each case runs inside driver_case_* (callgrind --toggle-collect) and
 * prints its final state, so that both trees can be compared bit for bit.
 * Uses only what both the runtime's seam and its predecessor offer
 * (NAME_type, NAME_alloc, the ensemble's type, sys and opt). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/runtime.h>
#include <vigen/ensemble.h>
#include "drv_g2.h"
#include "drv_sv.h"

static void kep_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)p; (void)c;
    const double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    o[0] = q[0] / r3;
    o[1] = q[1] / r3;
}
static void kep_dp(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = p[0];
    o[1] = p[1];
}
static double kep_H(double t, const double *q, const double *p, void *c)
{
    (void)t; (void)c;
    return 0.5 * (p[0] * p[0] + p[1] * p[1]) - 1.0 / sqrt(q[0] * q[0] + q[1] * q[1]);
}
static double pericentre(double t, const double *q, const double *p, void *c)
{
    (void)t; (void)c;
    return q[0] * p[0] + q[1] * p[1];
}

static const double e = 0.6;
static void start(double *q, double *p)
{
    q[0] = 1.0 - e; q[1] = 0.0;
    p[0] = 0.0; p[1] = sqrt((1.0 + e) / (1.0 - e));
}

__attribute__((noinline)) static int driver_case_integrate(const vigen_stepper_type *T, void *w, double *t,
                                                           double *q, double *p, double h, unsigned long n)
{
    return vigen_integrate(T, w, t, q, p, h, n, 0, NULL, NULL, NULL);
}

__attribute__((noinline)) static int driver_case_at(const vigen_stepper_type *T, void *w, double *t, double *q,
                                                    double *p, double h, unsigned long n, double *qo, double *po,
                                                    size_t nout)
{
    double *to = malloc(nout * sizeof *to);
    if (!to) return VIGEN_ENOMEM;
    for (size_t k = 0; k < nout; k++) to[k] = (double)(k + 1) * (7.3 * h);
    (void)n;
    int rc = vigen_integrate_at(T, w, t, q, p, h, to, nout, qo, po, NULL);
    free(to);
    return rc;
}

__attribute__((noinline)) static int driver_case_events(const vigen_stepper_type *T, void *w, double *t,
                                                        double *q, double *p, double h, unsigned long n,
                                                        double *te, size_t *ne)
{
    return vigen_integrate_events(T, w, t, q, p, h, n, pericentre, 1, 0, NULL, te, 64, ne);
}

__attribute__((noinline)) static int driver_case_ensemble(const vigen_ensemble *en, double *t, double *q,
                                                          double *p, double h, unsigned long n, int *st)
{
    return vigen_integrate_ensemble(en, 16, t, q, p, h, n, st, NULL);
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: drivers_bench gauss2|verlet integrate|at|events|ensemble STEPS\n");
        return 2;
    }
    const vigen_stepper_type *T = strcmp(argv[1], "gauss2") == 0 ? &drv_g2_type : &drv_sv_type;
    const unsigned long n = strtoul(argv[3], NULL, 10);
    const double h = 2.0 * 3.14159265358979323846 / 200.0;
    vigen_hamiltonian sys = { 2, kep_dq, kep_dp, kep_H, NULL, 1, NULL };
    void *w = T->alloc(&sys, NULL);
    double t = 0, q[2], p[2];
    start(q, p);
    int rc;
    if (strcmp(argv[2], "integrate") == 0) {
        rc = driver_case_integrate(T, w, &t, q, p, h, n);
    } else if (strcmp(argv[2], "at") == 0) {
        const size_t nout = (size_t)((double)n / 7.3) - 1;
        double *qo = malloc(2 * nout * sizeof *qo), *po = malloc(2 * nout * sizeof *po);
        rc = driver_case_at(T, w, &t, q, p, h, n, qo, po, nout);
        printf("last output %.17g %.17g\n", qo[2 * nout - 2], po[2 * nout - 1]);
        free(qo);
        free(po);
    } else if (strcmp(argv[2], "events") == 0) {
        double te[64];
        size_t ne = 0;
        rc = driver_case_events(T, w, &t, q, p, h, n, te, &ne);
        printf("%zu events, last %.17g\n", ne, ne ? te[(ne < 64 ? ne : 64) - 1] : 0.0);
    } else {
        vigen_ensemble en;
        memset(&en, 0, sizeof en);
        en.type = T;
        en.sys = &sys;
        en.threads = 1;
        double ts[16], qs[32], ps[32];
        int st[16];
        for (int k = 0; k < 16; k++) {
            ts[k] = 0;
            start(qs + 2 * k, ps + 2 * k);
            qs[2 * k] *= 1.0 + 0.001 * k;
        }
        rc = driver_case_ensemble(&en, ts, qs, ps, h, n / 16, st);
        t = ts[15]; q[0] = qs[30]; q[1] = qs[31]; p[0] = ps[30]; p[1] = ps[31];
    }
    printf("status %d t %.17g q %.17g %.17g p %.17g %.17g\n", rc, t, q[0], q[1], p[0], p[1]);
    T->free(w);
    return rc != VIGEN_SUCCESS;
}
