/* emit_bench.c — emitted steppers against hand-written ones and GSL's
 * implicit Gauss stepper (gsl_odeiv2_step_rk4imp), on Kepler (e = 0.6) and an
 * FPUT-beta chain (n = 1000).  Built by bench/emit_build.sh, which emits
 *   emit_g2   Gauss-2, callbacks          emit_sv   Stormer-Verlet, callbacks
 *   emit_g2k / emit_g2f, emit_svk / emit_svf: the same, compiled here with
 *   the gradients called directly (EMIT_*_DIRECT_DHDQ / _DHDP).
 *  Prints a Markdown table: ns per step, gradient evaluations per step,
 * relative energy error at the end, share of the time spent in gradients.
 * rk4imp computes each step from two half steps (step doubling), so it is
 * run at step 2h against the Gauss-2 steppers at h: the same method and, if
 * its stage equations were solved as tightly, equal accuracy.  Its Newton
 * tolerance follows the driver's epsabs; on Kepler the iteration fails below
 * 1e-6, and at 1e-6 it is less accurate than the others (see the energy
 * column), so the speed ratio is a lower bound for equal accuracy. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <vigen/runtime.h>
#include "emit_g2.h"
#include "emit_sv.h"

/* ---------------------------------------------------------------- problems */
#define FPUT_N 1000
#define FPUT_BETA 1.0

static inline void kep_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)p; (void)c;
    double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    o[0] = q[0] / r3;
    o[1] = q[1] / r3;
}
static inline void kep_dp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; o[1] = p[1]; }
static double kep_H(double t, const double *q, const double *p, void *c)
{
    (void)t; (void)c;
    return (p[0] * p[0] + p[1] * p[1]) / 2 - 1 / sqrt(q[0] * q[0] + q[1] * q[1]);
}

/* fixed ends q_0 = q_{n+1} = 0, V(r) = r^2/2 + beta r^4/4 */
static inline void fput_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)p; (void)c;
    double left = q[0] + FPUT_BETA * q[0] * q[0] * q[0];   /* V'(q_0 - wall) */
    for (int i = 0; i < FPUT_N; i++) {
        double r = (i + 1 < FPUT_N ? q[i + 1] : 0) - q[i];
        double f = r + FPUT_BETA * r * r * r;             /* V'(q_{i+1} - q_i) */
        o[i] = left - f;
        left = f;
    }
}
static inline void fput_dp(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    memcpy(o, p, FPUT_N * sizeof(double));
}
static double fput_H(double t, const double *q, const double *p, void *c)
{
    (void)t; (void)c;
    double e = 0, prev = 0;
    for (int i = 0; i <= FPUT_N; i++) {
        double x = i < FPUT_N ? q[i] : 0, r = x - prev;
        e += r * r / 2 + FPUT_BETA * r * r * r * r / 4;
        if (i < FPUT_N) e += p[i] * p[i] / 2;
        prev = x;
    }
    return e;
}

/* the emitted steppers with gradients called directly */
#define EMIT_G2K_DIRECT_DHDQ kep_dq
#define EMIT_G2K_DIRECT_DHDP kep_dp
#include "emit_g2k.c"
#define EMIT_G2F_DIRECT_DHDQ fput_dq
#define EMIT_G2F_DIRECT_DHDP fput_dp
#include "emit_g2f.c"
#define EMIT_SVK_DIRECT_DHDQ kep_dq
#define EMIT_SVK_DIRECT_DHDP kep_dp
#include "emit_svk.c"
#define EMIT_SVF_DIRECT_DHDQ fput_dq
#define EMIT_SVF_DIRECT_DHDP fput_dp
#include "emit_svf.c"

/* hand-written steppers */
#define HG2_NAME hg2k
#define HG2_DQ kep_dq
#define HG2_DP kep_dp
#include "hand_gauss2.h"
#define HG2_NAME hg2f
#define HG2_DQ fput_dq
#define HG2_DP fput_dp
#include "hand_gauss2.h"
#define HV_NAME hvk
#define HV_DQ kep_dq
#define HV_DP kep_dp
#include "hand_verlet.h"
#define HV_NAME hvf
#define HV_DQ fput_dq
#define HV_DP fput_dp
#include "hand_verlet.h"

/* ------------------------------------------------------------------- GSL */
typedef struct { size_t n; vigen_grad_fn dq, dp; } gsl_ctx;

static int gsl_f(double t, const double y[], double f[], void *params)
{
    gsl_ctx *c = params;
    c->dp(t, y, y + c->n, f, NULL);
    c->dq(t, y, y + c->n, f + c->n, NULL);
    for (size_t k = 0; k < c->n; k++) f[c->n + k] = -f[c->n + k];
    return GSL_SUCCESS;
}

/* Jacobian by finite differences of f (GSL's rk4imp needs one) */
static int gsl_jac(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    gsl_ctx *c = params;
    size_t N = 2 * c->n;
    double *yy = malloc(N * sizeof(double)), *f0 = malloc(N * sizeof(double)), *f1 = malloc(N * sizeof(double));
    memcpy(yy, y, N * sizeof(double));
    gsl_f(t, yy, f0, params);
    for (size_t j = 0; j < N; j++) {
        double d = 1e-7 * (fabs(yy[j]) > 1 ? fabs(yy[j]) : 1), keep = yy[j];
        yy[j] = keep + d;
        gsl_f(t, yy, f1, params);
        yy[j] = keep;
        for (size_t i = 0; i < N; i++) dfdy[i * N + j] = (f1[i] - f0[i]) / d;
    }
    for (size_t i = 0; i < N; i++) dfdt[i] = 0;
    free(yy); free(f0); free(f1);
    return GSL_SUCCESS;
}

/* ------------------------------------------------------------------ timing */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

typedef struct {
    const char *name;
    double ns, evals, energy, share;
} row;

static double t_dq, t_dp;    /* seconds per gradient call of the current problem */
static double gsl_epsabs = 1e-6;   /* EMIT_BENCH_GSL_EPSABS overrides; smaller fails on Kepler */

static void measure_grad(vigen_grad_fn dq, vigen_grad_fn dp, const double *q, const double *p, size_t n)
{
    double *o = malloc(n * sizeof(double));
    long reps = n > 100 ? 20000 : 2000000;
    volatile double sink = 0;
    double t0 = now();
    for (long k = 0; k < reps; k++) { dq(0, q, p, o, NULL); sink += o[0]; }
    t_dq = (now() - t0) / reps;
    t0 = now();
    for (long k = 0; k < reps; k++) { dp(0, q, p, o, NULL); sink += o[0]; }
    t_dp = (now() - t0) / reps;
    (void)sink;
    free(o);
}

static void print_row(const row *r)
{
    printf("| %-34s | %10.1f | %6.2f | %9.2e | %5.2f |\n", r->name, r->ns, r->evals, r->energy, r->share);
}

/* generic runner over a step function */
typedef int (*step_fn)(void *w, double *t, double *q, double *p, double h, void *ctx);
static void (*reset_hook)(void *w);

/* Three timed runs from the same initial state (the first one also warms
 * caches and pages); the fastest counts.  Evaluation counts are of the last. */
static row run(const char *name, void *w, step_fn step, double (*H)(double, const double *, const double *, void *),
               const double *q0, const double *p0, size_t n, double h, long steps, unsigned long *evq,
               unsigned long *evp, unsigned long *evtotal)
{
    double *q = malloc(n * sizeof(double)), *p = malloc(n * sizeof(double)), t = 0;
    double H0 = H(0, q0, p0, NULL), el = 1e300;
    unsigned long q_before = 0, p_before = 0, tot_before = 0;
    for (int rep = 0; rep < 3; rep++) {
        memcpy(q, q0, n * sizeof(double));
        memcpy(p, p0, n * sizeof(double));
        t = 0;
        if (reset_hook) reset_hook(w);
        q_before = evq ? *evq : 0;
        p_before = evp ? *evp : 0;
        tot_before = evtotal ? *evtotal : 0;
        double t0 = now();
        for (long k = 0; k < steps; k++)
            if (step(w, &t, q, p, h, NULL) != 0) { fprintf(stderr, "%s: step failed\n", name); break; }
        double e = now() - t0;
        if (e < el) el = e;
    }
    reset_hook = NULL;
    row r = { name, 1e9 * el / steps, 0, fabs(H(t, q, p, NULL) / H0 - 1), 0 };
    if (evtotal) {
        r.evals = (double)(*evtotal - tot_before) / steps;
        r.share = ((*evtotal - tot_before) / 2.0) * (t_dq + t_dp) / el;
    } else {
        double nq = (double)(*evq - q_before), np = (double)(*evp - p_before);
        r.evals = (nq + np) / steps;
        r.share = (nq * t_dq + np * t_dp) / el;
    }
    free(q);
    free(p);
    return r;
}

/* adapters */
static int st_g2(void *w, double *t, double *q, double *p, double h, void *c) { (void)c; return emit_g2_step(w, t, q, p, h); }
static int st_g2k(void *w, double *t, double *q, double *p, double h, void *c) { (void)c; return emit_g2k_step(w, t, q, p, h); }
static int st_g2f(void *w, double *t, double *q, double *p, double h, void *c) { (void)c; return emit_g2f_step(w, t, q, p, h); }
static int st_sv(void *w, double *t, double *q, double *p, double h, void *c) { (void)c; return emit_sv_step(w, t, q, p, h); }
static int st_svk(void *w, double *t, double *q, double *p, double h, void *c) { (void)c; return emit_svk_step(w, t, q, p, h); }
static int st_svf(void *w, double *t, double *q, double *p, double h, void *c) { (void)c; return emit_svf_step(w, t, q, p, h); }
static int st_hg2k(void *w, double *t, double *q, double *p, double h, void *c) { return hg2k_step(w, t, q, p, h, c); }
static int st_hg2f(void *w, double *t, double *q, double *p, double h, void *c) { return hg2f_step(w, t, q, p, h, c); }
static int st_hvk(void *w, double *t, double *q, double *p, double h, void *c) { return hvk_step(w, t, q, p, h, c); }
static int st_hvf(void *w, double *t, double *q, double *p, double h, void *c) { return hvf_step(w, t, q, p, h, c); }

typedef struct { gsl_odeiv2_driver *d; gsl_odeiv2_system sys; double *y; size_t n; } gsl_w;
static unsigned long gsl_evals;
static int gsl_f_count(double t, const double y[], double f[], void *params) { gsl_evals += 2; return gsl_f(t, y, f, params); }
static int st_gsl(void *wv, double *t, double *q, double *p, double h, void *c)
{
    (void)c;
    gsl_w *w = wv;
    memcpy(w->y, q, w->n * sizeof(double));
    memcpy(w->y + w->n, p, w->n * sizeof(double));
    int st = gsl_odeiv2_driver_apply_fixed_step(w->d, t, h, 1, w->y);
    memcpy(q, w->y, w->n * sizeof(double));
    memcpy(p, w->y + w->n, w->n * sizeof(double));
    return st;
}
static void gsl_reset(void *wv) { gsl_odeiv2_driver_reset(((gsl_w *)wv)->d); }

/* the hand-written workspaces start with the same fields: reset their history */
static void hg2_reset(void *w) { hg2k_ws *x = w; x->hist = 0; memset(x->cq, 0, 2 * x->n * sizeof(double)); }
static void hv_reset(void *w) { hvk_ws *x = w; x->have_g = 0; memset(x->cq, 0, 2 * x->n * sizeof(double)); }

static void problem(const char *title, size_t n, vigen_grad_fn dq, vigen_grad_fn dp,
                    double (*H)(double, const double *, const double *, void *), const double *q0,
                    const double *p0, double h, long steps, long gsl_steps, step_fn g2direct,
                    void *(*alloc_g2direct)(const vigen_hamiltonian *), step_fn hg2, void *hg2w, step_fn svdirect,
                    void *(*alloc_svdirect)(const vigen_hamiltonian *), step_fn hv, void *hvw, void *hvw_nokahan,
                    unsigned long *hg2_evals, unsigned long *hv_evals, unsigned long *hv_evals_nk)
{
    measure_grad(dq, dp, q0, p0, n);
    printf("\n### %s (h = %g, %ld steps)\n\n", title, h, steps);
    printf("Gradient calls: dH/dq %.0f ns, dH/dp %.0f ns.\n\n", 1e9 * t_dq, 1e9 * t_dp);
    printf("| stepper                            |    ns/step | grad/step | energy err | grad share |\n");
    printf("|------------------------------------|-----------:|-------:|----------:|------:|\n");
    vigen_hamiltonian sys = { n, dq, dp, H, NULL, 1, NULL };
    row r[10];
    int nr = 0;

    emit_g2_workspace *g2 = emit_g2_alloc(&sys, NULL);
    r[nr] = run("emitted Gauss-2 (callbacks)", g2, st_g2, H, q0, p0, n, h, steps, &((vigen_stats *)emit_g2_stats(g2))->dHdq_evals,
                &((vigen_stats *)emit_g2_stats(g2))->dHdp_evals, NULL);
    print_row(&r[nr++]);
    emit_g2_free(g2);
    void *g2d = alloc_g2direct(&sys);
    const vigen_stats *S = g2direct == st_g2k ? emit_g2k_stats(g2d) : emit_g2f_stats(g2d);
    r[nr] = run("emitted Gauss-2 (direct)", g2d, g2direct, H, q0, p0, n, h, steps, (unsigned long *)&S->dHdq_evals,
                (unsigned long *)&S->dHdp_evals, NULL);
    print_row(&r[nr++]);
    reset_hook = hg2_reset;
    r[nr] = run("hand-written Gauss-2 (direct)", hg2w, hg2, H, q0, p0, n, h, steps, NULL, NULL, hg2_evals);
    print_row(&r[nr++]);

    gsl_ctx gc = { n, dq, dp };
    gsl_w gw;
    gw.n = n;
    gw.sys.function = gsl_f_count;
    gw.sys.jacobian = gsl_jac;
    gw.sys.dimension = 2 * n;
    gw.sys.params = &gc;
    gw.d = gsl_odeiv2_driver_alloc_y_new(&gw.sys, gsl_odeiv2_step_rk4imp, 2 * h, gsl_epsabs, 0.0);
    gw.y = malloc(2 * n * sizeof(double));
    gsl_evals = 0;
    reset_hook = gsl_reset;
    row gr = run("GSL rk4imp at 2h, epsabs 1e-6", &gw, st_gsl, H, q0, p0, n, 2 * h, gsl_steps, NULL, NULL, &gsl_evals);
    gsl_odeiv2_driver_free(gw.d);
    free(gw.y);
    print_row(&gr);

    emit_sv_workspace *sv = emit_sv_alloc(&sys, NULL);
    r[nr] = run("emitted Verlet (callbacks)", sv, st_sv, H, q0, p0, n, h, steps, &((vigen_stats *)emit_sv_stats(sv))->dHdq_evals,
                &((vigen_stats *)emit_sv_stats(sv))->dHdp_evals, NULL);
    print_row(&r[nr++]);
    emit_sv_free(sv);
    void *svd = alloc_svdirect(&sys);
    S = svdirect == st_svk ? emit_svk_stats(svd) : emit_svf_stats(svd);
    r[nr] = run("emitted Verlet (direct)", svd, svdirect, H, q0, p0, n, h, steps, (unsigned long *)&S->dHdq_evals,
                (unsigned long *)&S->dHdp_evals, NULL);
    print_row(&r[nr++]);
    reset_hook = hv_reset;
    r[nr] = run("hand-written Verlet (direct)", hvw, hv, H, q0, p0, n, h, steps, NULL, NULL, hv_evals);
    print_row(&r[nr++]);
    vigen_solver_options nk;
    vigen_solver_options_default(&nk);
    nk.kahan = 0;
    sv = emit_sv_alloc(&sys, &nk);
    r[nr] = run("emitted Verlet (callbacks, no Kahan)", sv, st_sv, H, q0, p0, n, h, steps, &((vigen_stats *)emit_sv_stats(sv))->dHdq_evals,
                &((vigen_stats *)emit_sv_stats(sv))->dHdp_evals, NULL);
    print_row(&r[nr++]);
    emit_sv_free(sv);
    reset_hook = hv_reset;
    r[nr] = run("hand-written Verlet (no Kahan)", hvw_nokahan, hv, H, q0, p0, n, h, steps, NULL, NULL, hv_evals_nk);
    print_row(&r[nr++]);
    printf("\nRatios: rk4imp / emitted Gauss-2 per unit time = %.1f (callbacks), %.1f (direct); "
           "emitted Gauss-2 / hand-written = %.3f (callbacks), %.3f (direct); "
           "emitted Verlet / hand-written = %.3f (callbacks), %.3f (direct), %.3f (no Kahan, callbacks).\n",
           gr.ns / 2 / r[0].ns, gr.ns / 2 / r[1].ns, r[0].ns / r[2].ns, r[1].ns / r[2].ns, r[3].ns / r[5].ns,
           r[4].ns / r[5].ns, r[6].ns / r[7].ns);
}

static void *a_g2k(const vigen_hamiltonian *s) { return emit_g2k_alloc(s, NULL); }
static void *a_g2f(const vigen_hamiltonian *s) { return emit_g2f_alloc(s, NULL); }
static void *a_svk(const vigen_hamiltonian *s) { return emit_svk_alloc(s, NULL); }
static void *a_svf(const vigen_hamiltonian *s) { return emit_svf_alloc(s, NULL); }

int main(int argc, char **argv)
{
    long ksteps = argc > 1 ? atol(argv[1]) : 1000000, fsteps = argc > 2 ? atol(argv[2]) : 2000;
    gsl_set_error_handler_off();
    if (getenv("EMIT_BENCH_GSL_EPSABS")) gsl_epsabs = atof(getenv("EMIT_BENCH_GSL_EPSABS"));
    double e = 0.6, q0[2] = { 1 - e, 0 }, p0[2] = { 0, sqrt((1 + e) / (1 - e)) };
    unsigned long a = 0, b = 0, c = 0;
    hg2k_ws *hk = hg2k_alloc(2);
    hvk_ws *vk = hvk_alloc(2, 1), *vk0 = hvk_alloc(2, 0);
    problem("Kepler, e = 0.6", 2, kep_dq, kep_dp, kep_H, q0, p0, 0.01, ksteps, ksteps / 4, st_g2k, a_g2k, st_hg2k,
            hk, st_svk, a_svk, st_hvk, vk, vk0, &hk->evals, &vk->evals, &vk0->evals);
    (void)a; (void)b; (void)c;

    double *fq = malloc(FPUT_N * sizeof(double)), *fp = malloc(FPUT_N * sizeof(double));
    for (int i = 0; i < FPUT_N; i++) {
        fq[i] = 0;
        fp[i] = sin(3.14159265358979 * (i + 1) / (FPUT_N + 1));   /* first normal mode, energy ~ n/4 */
    }
    hg2f_ws *hf = hg2f_alloc(FPUT_N);
    hvf_ws *vf = hvf_alloc(FPUT_N, 1), *vf0 = hvf_alloc(FPUT_N, 0);
    problem("FPUT-beta chain, n = 1000, beta = 1", FPUT_N, fput_dq, fput_dp, fput_H, fq, fp, 0.05, fsteps, 2, st_g2f,
            a_g2f, st_hg2f, hf, st_svf, a_svf, st_hvf, vf, vf0, &hf->evals, &vf->evals, &vf0->evals);
    hg2k_free(hk); hvk_free(vk); hvk_free(vk0);
    hg2f_free(hf); hvf_free(vf); hvf_free(vf0);
    free(fq); free(fp);
    return 0;
}
