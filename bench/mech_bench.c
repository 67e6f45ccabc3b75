/* mech_bench.c — emitted steppers on Kepler (e = 0.6, h = 2 pi/200) through
 * the general callback API (NAME_alloc), as mechanical problems
 * (NAME_alloc_mechanical, Nystrom form), and as mechanical problems with a
 * static dimension (--dim 2) and the force called directly
 * (NAME_DIRECT_FORCE), side by side with the hand-written Gauss-2 and
 * Verlet steppers of bench/hand_gauss2.h and bench/hand_verlet.h (forces
 * inlined).  Built by bench/mech_build.sh.  Prints one Markdown row per
 * stepper: ns per step (fastest of five runs of STEPS steps from the same
 * state), gradient or force evaluations per step, stage sweeps per step,
 * relative energy error at the end.  A measurement, not a test.
 *   mech_bench [STEPS]   default 1000000 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <vigen/runtime.h>
#include "emit_problems.h"
#include "mech_g2.h"
#include "mech_sv.h"

/* f = -dV/dq for Kepler */
static inline void kep_force(double t, const double *q, double *f, void *c)
{
    (void)t; (void)c;
    double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    f[0] = -q[0] / r3;
    f[1] = -q[1] / r3;
}

#define MECH_G2D_DIRECT_FORCE kep_force
#include "mech_g2d.c"
#define MECH_SVD_DIRECT_FORCE kep_force
#include "mech_svd.c"

#define HG2_NAME hg2
#define HG2_DQ kep_dq
#define HG2_DP kep_dp
#include "hand_gauss2.h"
#define HV_NAME hv
#define HV_DQ kep_dq
#define HV_DP kep_dp
#include "hand_verlet.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

typedef int (*step_fn)(void *w, double *t, double *q, double *p, double h);
static int hg2_step_v(void *w, double *t, double *q, double *p, double h) { return hg2_step(w, t, q, p, h, NULL); }
static int hv_step_v(void *w, double *t, double *q, double *p, double h) { return hv_step(w, t, q, p, h, NULL); }
static int g2_step_v(void *w, double *t, double *q, double *p, double h) { return mech_g2_step(w, t, q, p, h); }
static int g2d_step_v(void *w, double *t, double *q, double *p, double h) { return mech_g2d_step(w, t, q, p, h); }
static int sv_step_v(void *w, double *t, double *q, double *p, double h) { return mech_sv_step(w, t, q, p, h); }
static int svd_step_v(void *w, double *t, double *q, double *p, double h) { return mech_svd_step(w, t, q, p, h); }

/* evals and sweeps since the start, from the stepper's own counters */
typedef void (*count_fn)(void *w, double *evals, double *sweeps);
static void hg2_count(void *w, double *e, double *s) { hg2_ws *x = w; *e = x->evals; *s = x->iters; }
static void hv_count(void *w, double *e, double *s) { hv_ws *x = w; *e = x->evals; *s = 0; }
static void g2_count(void *w, double *e, double *s)
{
    const vigen_stats *st = mech_g2_stats(w);
    *e = st->dHdq_evals + st->dHdp_evals; *s = st->iterations;
}
static void g2d_count(void *w, double *e, double *s)
{
    const vigen_stats *st = mech_g2d_stats(w);
    *e = st->dHdq_evals + st->dHdp_evals; *s = st->iterations;
}
static void sv_count(void *w, double *e, double *s)
{
    const vigen_stats *st = mech_sv_stats(w);
    *e = st->dHdq_evals + st->dHdp_evals; *s = st->iterations;
}
static void svd_count(void *w, double *e, double *s)
{
    const vigen_stats *st = mech_svd_stats(w);
    *e = st->dHdq_evals + st->dHdp_evals; *s = st->iterations;
}

static void row(const char *what, void *w, step_fn step, count_fn count, long steps, double ref)
{
    const double e = 0.6, h = 2 * 3.14159265358979323846 / 200;
    double best = 1e300, q[2], p[2], t = 0, ev0, sw0, ev1, sw1;
    for (int run = 0; run < 5; run++) {
        kep_init(e, q, p);
        t = 0;
        count(w, &ev0, &sw0);
        double t0 = now();
        for (long k = 0; k < steps; k++)
            if (step(w, &t, q, p, h) != 0) { printf("| %s | failed |\n", what); return; }
        double el = now() - t0;
        count(w, &ev1, &sw1);
        if (el < best) best = el;
    }
    double ns = 1e9 * best / steps, H0;
    double q0[2], p0[2];
    kep_init(e, q0, p0);
    H0 = kep_H(0, q0, p0, NULL);
    printf("| %s | %.1f | %.2f | %.2f | %.1e | %.2f |\n", what, ns, (ev1 - ev0) / steps, (sw1 - sw0) / steps,
           fabs((kep_H(t, q, p, NULL) - H0) / H0), ref > 0 ? ns / ref : 1.0);
}

static double time_of(void *w, step_fn step, long steps)
{
    const double e = 0.6, h = 2 * 3.14159265358979323846 / 200;
    double best = 1e300, q[2], p[2], t;
    for (int run = 0; run < 5; run++) {
        kep_init(e, q, p);
        t = 0;
        double t0 = now();
        for (long k = 0; k < steps; k++) step(w, &t, q, p, h);
        double el = now() - t0;
        if (el < best) best = el;
    }
    return 1e9 * best / steps;
}

int main(int argc, char **argv)
{
    long steps = argc > 1 ? atol(argv[1]) : 1000000;
    vigen_hamiltonian gen = { 2, kep_dq, kep_dp, kep_H, NULL, 1, NULL };
    vigen_mechanical mech = { 2, kep_force, NULL, NULL, NULL };
    hg2_ws *hg = hg2_alloc(2);
    hv_ws *hv = hv_alloc(2, 1);
    void *g2g = mech_g2_alloc(&gen, NULL), *g2m = mech_g2_alloc_mechanical(&mech, NULL);
    void *g2d = mech_g2d_alloc_mechanical(&mech, NULL);
    void *svg = mech_sv_alloc(&gen, NULL), *svm = mech_sv_alloc_mechanical(&mech, NULL);
    void *svd = mech_svd_alloc_mechanical(&mech, NULL);
    printf("Kepler, e = 0.6, h = 2 pi/200, %ld steps (fastest of 5 runs); evals: gradient calls "
           "(dH/dq + dH/dp) or forces per step\n\n", steps);
    printf("| stepper | ns / step | evals / step | sweeps / step | rel. energy error | x hand |\n");
    printf("|---|---|---|---|---|---|\n");
    double ref = time_of(hg, hg2_step_v, steps);
    row("hand Gauss-2 (force inlined)", hg, hg2_step_v, hg2_count, steps, ref);
    row("emitted Gauss-2, general callbacks", g2g, g2_step_v, g2_count, steps, ref);
    row("emitted Gauss-2, mechanical callbacks", g2m, g2_step_v, g2_count, steps, ref);
    row("emitted Gauss-2, mechanical, --dim 2, direct force", g2d, g2d_step_v, g2d_count, steps, ref);
    ref = time_of(hv, hv_step_v, steps);
    row("hand Verlet (force inlined)", hv, hv_step_v, hv_count, steps, ref);
    row("emitted Verlet, general callbacks", svg, sv_step_v, sv_count, steps, ref);
    row("emitted Verlet, mechanical callbacks", svm, sv_step_v, sv_count, steps, ref);
    row("emitted Verlet, mechanical, --dim 2, direct force", svd, svd_step_v, svd_count, steps, ref);
    hg2_free(hg);
    hv_free(hv);
    mech_g2_free(g2g);
    mech_g2_free(g2m);
    mech_g2d_free(g2d);
    mech_sv_free(svg);
    mech_sv_free(svm);
    mech_svd_free(svd);
    return 0;
}
