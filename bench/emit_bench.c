/* emit_bench.c — emitted steppers against hand-written ones and GSL's
 * implicit Gauss stepper (gsl_odeiv2_step_rk4imp), on Kepler (e = 0.6) and an
 * FPUT-beta chain (n = 1000; bench/emit_problems.h).  Built by
 * bench/emit_build.sh, which emits
 *   emit_g2   Gauss-2, callbacks          emit_sv   Stormer-Verlet, callbacks
 *   emit_g2k / emit_g2f, emit_svk / emit_svf: the same, compiled here with
 *   the gradients called directly (EMIT_*_DIRECT_DHDQ / _DHDP).
 * Prints Markdown:
 *  1. per problem, one row per stepper: ns per step (fastest of five runs
 *     from the same state), gradient evaluations per step, relative energy
 *     error at the end, and the share of the step time spent inside the
 *     gradient callbacks, measured by timing every call (emit_problems.h:
 *     timed_dq/timed_dp, clock cost subtracted) in a separate run of the same
 *     stepper code through the callback API;
 *  2. for the FPUT chain, the same share for an ideal fixed-point Gauss-2
 *     sweep that only computes the four stage vectors (no convergence test,
 *     no loads beyond the formula): the largest share any fixed-point
 *     Gauss-2 stepper can have on this gradient;
 *  2b. the gradient share of the emitted steppers on a Toda lattice
 *     (n = 1000, one exponential per bond): same vector work, dearer gradient;
 *  3. Kepler at equal accuracy against rk4imp: rk4imp takes each step of
 *     size H as one step of H and two of H/2 (step doubling: 3 implicit
 *     solves by modified Newton from y0, LU of the 8 x 8 iteration matrix for
 *     H and for H/2, analytic Jacobian) and returns the two-half-step result,
 *     i.e. Gauss-2 at H/2.  Over 100 periods, for a range of step sizes and
 *     of rk4imp's Newton tolerance (driver epsabs), the table gives the largest
 *     relative energy error, the position error at the end against the exact
 *     solution (Kepler's equation) and the cost per unit of simulated time;
 *     the ratio at equal accuracy interpolates the emitted stepper's
 *     cost-error curve (log-log) at each rk4imp error.
 *  4. Kepler over 2000 periods: the secular energy error of the emitted
 *     Gauss-2 and of rk4imp at its cheapest setting for errors ~5e-9.
 *   emit_bench [KEPLER_STEPS [FPUT_STEPS]]   defaults 1000000 2000
 *   EMIT_BENCH_SKIP_FPUT_GSL=1 skips rk4imp on the chain (one step ~ 10 s);
 *   EMIT_BENCH_TABLES_ONLY=1 stops after the Kepler and FPUT tables (1.). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <vigen/runtime.h>
#include "emit_problems.h"
#include "emit_g2.h"
#include "emit_sv.h"

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

/* hand-written steppers: direct, and through the timing probes */
#define HG2_NAME hg2k
#define HG2_DQ kep_dq
#define HG2_DP kep_dp
#include "hand_gauss2.h"
#define HG2_NAME hg2f
#define HG2_DQ fput_dq
#define HG2_DP fput_dp
#include "hand_gauss2.h"
#define HG2_NAME hg2t
#define HG2_DQ timed_dq
#define HG2_DP timed_dp
#include "hand_gauss2.h"
#define HV_NAME hvk
#define HV_DQ kep_dq
#define HV_DP kep_dp
#include "hand_verlet.h"
#define HV_NAME hvf
#define HV_DQ fput_dq
#define HV_DP fput_dp
#include "hand_verlet.h"
#define HV_NAME hvt
#define HV_DQ timed_dq
#define HV_DP timed_dp
#include "hand_verlet.h"

static double now(void) { return probe_now(); }
static double clock_cost;   /* seconds per clock read */

/* ------------------------------------------------------ uniform steppers */
typedef struct {
    const char *name;
    void *w;
    int (*step)(void *w, double *t, double *q, double *p, double h);
    void (*reset)(void *w);
    unsigned long (*evals)(void *w);
} stepper;

#define EMITTED(N)                                                                              \
    static int N##_stp(void *w, double *t, double *q, double *p, double h) { return N##_step(w, t, q, p, h); } \
    static void N##_rst(void *w) { N##_reset(w); }                                              \
    static unsigned long N##_ev(void *w) { const vigen_stats *s = N##_stats(w); return s->dHdq_evals + s->dHdp_evals; }
EMITTED(emit_g2)
EMITTED(emit_g2k)
EMITTED(emit_g2f)
EMITTED(emit_sv)
EMITTED(emit_svk)
EMITTED(emit_svf)

#define HAND_G2(N)                                                                              \
    static int N##_stp(void *w, double *t, double *q, double *p, double h) { return N##_step(w, t, q, p, h, NULL); } \
    static void N##_rst(void *w) { N##_ws *x = w; x->hist = 0; memset(x->cq, 0, 2 * x->n * sizeof(double)); } \
    static unsigned long N##_ev(void *w) { return ((N##_ws *)w)->evals; }
HAND_G2(hg2k)
HAND_G2(hg2f)
HAND_G2(hg2t)
#define HAND_V(N)                                                                               \
    static int N##_stp(void *w, double *t, double *q, double *p, double h) { return N##_step(w, t, q, p, h, NULL); } \
    static void N##_rst(void *w) { N##_ws *x = w; x->have_g = 0; memset(x->cq, 0, 2 * x->n * sizeof(double)); } \
    static unsigned long N##_ev(void *w) { return ((N##_ws *)w)->evals; }
HAND_V(hvk)
HAND_V(hvf)
HAND_V(hvt)

#define STEPPER(label, N, ws) ((stepper){ label, ws, N##_stp, N##_rst, N##_ev })

typedef struct {
    const char *title;
    size_t n;
    vigen_grad_fn dq, dp;
    double (*H)(double, const double *, const double *, void *);
    const double *q0, *p0;
    double h;
    long steps;
} problem;

typedef struct {
    double ns, evals, energy, share;   /* share -1: not measured; -2: gradient calls too short to time */
} result;

/* nsteps steps from the problem's initial state; returns seconds, and the
 * gradient evaluations made in *evals. */
static double integrate(const stepper *S, const problem *P, double *q, double *p, double *t, long nsteps,
                        unsigned long *evals)
{
    memcpy(q, P->q0, P->n * sizeof(double));
    memcpy(p, P->p0, P->n * sizeof(double));
    *t = 0;
    S->reset(S->w);
    unsigned long e0 = S->evals(S->w);
    double t0 = now();
    for (long k = 0; k < nsteps; k++)
        if (S->step(S->w, t, q, p, P->h) != 0) { fprintf(stderr, "%s: step %ld failed\n", S->name, k); exit(1); }
    double el = now() - t0;
    *evals = S->evals(S->w) - e0;
    return el;
}

/* Fastest of five runs; with a probed twin (same code, timed callbacks) the
 * measured gradient share from one more run of the twin. */
static result measure(const stepper *S, const stepper *probed, const problem *P)
{
    double *q = malloc(P->n * sizeof(double)), *p = malloc(P->n * sizeof(double)), t = 0, best = 1e300;
    unsigned long ev = 0;
    for (int rep = 0; rep < 5; rep++) {
        double el = integrate(S, P, q, p, &t, P->steps, &ev);
        if (el < best) best = el;
    }
    result r = { 1e9 * best / P->steps, (double)ev / P->steps, fabs(P->H(t, q, p, NULL) / P->H(0, P->q0, P->p0, NULL) - 1), -1 };
    if (probed) {
        probe_dq = P->dq;
        probe_dp = P->dp;
        double bestshare = -1, bestel = 1e300;
        for (int rep = 0; rep < 3; rep++) {
            probe_seconds = 0;
            probe_calls = 0;
            double el = integrate(probed, P, q, p, &t, P->steps, &ev);
            double grad = probe_seconds - probe_calls * clock_cost, total = el - 2 * probe_calls * clock_cost;
            if (el < bestel) { bestel = el; bestshare = grad / total; }
            /* a clock read must be small against a gradient call to say anything */
            if (grad < 10 * clock_cost * probe_calls) bestshare = -2;
        }
        r.share = bestshare < 0 ? -2 : bestshare;
    }
    free(q);
    free(p);
    return r;
}

static void print_row(const char *name, const result *r)
{
    char share[32];
    if (r->share >= 0) snprintf(share, sizeof share, "%.2f", r->share);
    else if (r->share == -2) snprintf(share, sizeof share, "(n/a)");
    else snprintf(share, sizeof share, "-");
    printf("| %-36s | %9.1f | %9.2f | %10.2e | %10s |\n", name, r->ns, r->evals, r->energy, share);
}

/* ------------------------------------------------------------------- GSL */
typedef struct {
    size_t n;
    vigen_grad_fn dq, dp;
    void (*jac)(const double *y, double *J);
    unsigned long fevals, jevals;
} gsl_ctx;

static int gsl_f(double t, const double y[], double f[], void *params)
{
    gsl_ctx *c = params;
    c->fevals++;
    c->dp(t, y, y + c->n, f, NULL);
    c->dq(t, y, y + c->n, f + c->n, NULL);
    for (size_t k = 0; k < c->n; k++) f[c->n + k] = -f[c->n + k];
    return GSL_SUCCESS;
}

static int gsl_jac(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    (void)t;
    gsl_ctx *c = params;
    c->jevals++;
    c->jac(y, dfdy);
    memset(dfdt, 0, 2 * c->n * sizeof(double));
    return GSL_SUCCESS;
}

static void kep_jac_fn(const double *y, double *J) { kep_jac(y, J); }
static void fput_jac_fn(const double *y, double *J) { fput_jac(y, J); }

/* ---------------------------------------------------------- the problems */
static void problem_table(const problem *P, stepper g2, stepper g2t, stepper g2d, stepper hg2, stepper hg2t,
                          stepper sv, stepper svt, stepper svd, stepper hv, stepper hvt, stepper sv0, stepper hv0,
                          stepper hv0t, void (*jac)(const double *, double *), long gsl_applies)
{
    printf("\n### %s, h = %g, %ld steps\n\n", P->title, P->h, P->steps);
    printf("| stepper                              |   ns/step | grad/step | energy err | grad share |\n");
    printf("|--------------------------------------|----------:|----------:|-----------:|-----------:|\n");
    result r[9];
    r[0] = measure(&g2, &g2t, P);   print_row("emitted Gauss-2 (callbacks)", &r[0]);
    r[1] = measure(&g2d, NULL, P);  print_row("emitted Gauss-2 (direct)", &r[1]);
    r[2] = measure(&hg2, &hg2t, P); print_row("hand-written Gauss-2 (direct)", &r[2]);
    if (gsl_applies > 0) {
        /* an apply at 2h = two Gauss-2 steps of h (step doubling) */
        gsl_ctx gc = { P->n, P->dq, P->dp, jac, 0, 0 };
        gsl_odeiv2_system sys = { gsl_f, gsl_jac, 2 * P->n, &gc };
        long applies = gsl_applies;
        gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk4imp, 2 * P->h, 1e-6, 0.0);
        double *y = malloc(2 * P->n * sizeof(double)), t = 0;
        memcpy(y, P->q0, P->n * sizeof(double));
        memcpy(y + P->n, P->p0, P->n * sizeof(double));
        double t0 = now();
        int st = gsl_odeiv2_driver_apply_fixed_step(d, &t, 2 * P->h, (unsigned long)applies, y);
        double el = now() - t0;
        result g = { 1e9 * el / (2.0 * applies), 2.0 * gc.fevals / (2.0 * applies),
                     fabs(P->H(t, y, y + P->n, NULL) / P->H(0, P->q0, P->p0, NULL) - 1), -1 };
        char name[64];
        snprintf(name, sizeof name, "GSL rk4imp, %ld apply%s at 2h%s", applies, applies == 1 ? "" : "s", st ? " FAILED" : "");
        print_row(name, &g);
        printf("|   (rk4imp per unit time / emitted Gauss-2 callbacks: %.3g) | | | | |\n", g.ns / r[0].ns);
        gsl_odeiv2_driver_free(d);
        free(y);
    }
    r[3] = measure(&sv, &svt, P);   print_row("emitted Verlet (callbacks)", &r[3]);
    r[4] = measure(&svd, NULL, P);  print_row("emitted Verlet (direct)", &r[4]);
    r[5] = measure(&hv, &hvt, P);   print_row("hand-written Verlet (direct)", &r[5]);
    r[6] = measure(&sv0, NULL, P);  print_row("emitted Verlet (callbacks, no Kahan)", &r[6]);
    r[7] = measure(&hv0, &hv0t, P); print_row("hand-written Verlet (no Kahan)", &r[7]);
    printf("\nTime ratios: emitted / hand-written Gauss-2 = %.3f (callbacks), %.3f (direct); "
           "emitted / hand-written Verlet = %.3f (callbacks), %.3f (direct), %.3f (no Kahan).\n",
           r[0].ns / r[2].ns, r[1].ns / r[2].ns, r[3].ns / r[5].ns, r[4].ns / r[5].ns, r[6].ns / r[7].ns);
}

/* The largest gradient share a fixed-point Gauss-2 sweep can have: the stage
 * formula alone (4 vectors from q, p and the 4 gradient vectors), then the
 * four gradient calls, timed as in measure(). */
static void ideal_sweep_share(void)
{
    const size_t n = FPUT_N;
    const double h = 0.05, s3 = sqrt(3.0), a11 = 0.25, a12 = 0.25 - s3 / 6, a21 = 0.25 + s3 / 6, a22 = 0.25;
    double *m = calloc(10 * n, sizeof(double));
    double *q = m, *p = m + n, *Q1 = m + 2 * n, *Q2 = m + 3 * n, *P1 = m + 4 * n, *P2 = m + 5 * n;
    double *F1 = m + 6 * n, *F2 = m + 7 * n, *G1 = m + 8 * n, *G2 = m + 9 * n;
    fput_init(q, p);
    fput_dp(0, q, p, F1, NULL); fput_dq(0, q, p, G1, NULL);
    memcpy(F2, F1, n * sizeof(double)); memcpy(G2, G1, n * sizeof(double));
    probe_dq = fput_dq;
    probe_dp = fput_dp;
    const long sweeps = 20000;
    double best = -1, bestel = 1e300, bestns = 0;
    for (int rep = 0; rep < 3; rep++) {
        probe_seconds = 0;
        probe_calls = 0;
        double t0 = now();
        for (long s = 0; s < sweeps; s++) {
            for (size_t k = 0; k < n; k++) {
                double f1 = F1[k], f2 = F2[k], g1 = G1[k], g2 = G2[k], qk = q[k], pk = p[k];
                Q1[k] = qk + h * (a11 * f1 + a12 * f2);
                Q2[k] = qk + h * (a21 * f1 + a22 * f2);
                P1[k] = pk - h * (a11 * g1 + a12 * g2);
                P2[k] = pk - h * (a21 * g1 + a22 * g2);
            }
            timed_dp(0, Q1, P1, F1, NULL);
            timed_dq(0, Q1, P1, G1, NULL);
            timed_dp(0, Q2, P2, F2, NULL);
            timed_dq(0, Q2, P2, G2, NULL);
        }
        double el = now() - t0;
        double grad = probe_seconds - probe_calls * clock_cost, total = el - 2 * probe_calls * clock_cost;
        if (el < bestel) { bestel = el; best = grad / total; bestns = 1e9 * total / sweeps; }
    }
    printf("\nIdeal fixed-point Gauss-2 sweep on the chain (stage formula only, then 4 gradient calls): "
           "%.0f ns per sweep, gradient share %.2f.\n", bestns, best);
    free(m);
}

/* The gradient share on the Toda lattice (one exponential per bond): the same
 * stepper code and vector work as on the FPUT chain, a dearer gradient. */
static void toda_share(long steps)
{
    double *q = malloc(FPUT_N * sizeof(double)), *p = malloc(FPUT_N * sizeof(double));
    fput_init(q, p);
    problem T = { "Toda lattice, n = 1000, fixed ends", FPUT_N, toda_dq, fput_dp, toda_H, q, p, 0.05, steps };
    vigen_hamiltonian sys = { FPUT_N, toda_dq, fput_dp, toda_H, NULL, 1, NULL };
    vigen_hamiltonian tsys = { FPUT_N, timed_dq, timed_dp, toda_H, NULL, 1, NULL };
    emit_g2_workspace *g2 = emit_g2_alloc(&sys, NULL), *g2t = emit_g2_alloc(&tsys, NULL);
    emit_sv_workspace *sv = emit_sv_alloc(&sys, NULL), *svt = emit_sv_alloc(&tsys, NULL);
    printf("\n### %s, h = %g, %ld steps: the gradient share with a dearer gradient\n\n", T.title, T.h, T.steps);
    printf("| stepper                              |   ns/step | grad/step | energy err | grad share |\n");
    printf("|--------------------------------------|----------:|----------:|-----------:|-----------:|\n");
    stepper a = STEPPER("", emit_g2, g2), at = STEPPER("", emit_g2, g2t);
    stepper b = STEPPER("", emit_sv, sv), bt = STEPPER("", emit_sv, svt);
    result r = measure(&a, &at, &T);
    print_row("emitted Gauss-2 (callbacks)", &r);
    r = measure(&b, &bt, &T);
    print_row("emitted Verlet (callbacks)", &r);
    emit_g2_free(g2); emit_g2_free(g2t); emit_sv_free(sv); emit_sv_free(svt);
    free(q);
    free(p);
}

/* ----------------------------------------- Kepler: equal accuracy vs rk4imp */
typedef struct { double N, energy, pos, ns_time, ns_step, evals; int ok; } wp_point;
typedef struct { double energy, pos, cost, ratio; } rk_point;

/* log-log interpolation of cost at error err on the emitted curve (errors
 * decreasing along the array); -1 outside the measured range */
static double cost_at(const wp_point *c, int nc, double err, int use_pos)
{
    for (int i = 0; i + 1 < nc; i++) {
        double e0 = use_pos ? c[i].pos : c[i].energy, e1 = use_pos ? c[i + 1].pos : c[i + 1].energy;
        if (err <= e0 && err >= e1) {
            double x = (log(err) - log(e0)) / (log(e1) - log(e0));
            return exp(log(c[i].ns_time) + x * (log(c[i + 1].ns_time) - log(c[i].ns_time)));
        }
    }
    return -1;
}

static void kepler_equal_accuracy(void)
{
    const double e = 0.6, T = 2 * 3.14159265358979323846;
    const int periods = 100;
    const int Ns[] = { 100, 200, 400, 800, 1600, 3200, 6400 };
    const int nN = (int)(sizeof Ns / sizeof Ns[0]);
    const double eps[] = { 1e-6, 1e-8, 1e-10, 1e-12 };
    const int neps = (int)(sizeof eps / sizeof eps[0]);
    double q0[2], p0[2], qx[2];
    kep_init(e, q0, p0);
    const double H0 = kep_H(0, q0, p0, NULL);
    vigen_hamiltonian sys = { 2, kep_dq, kep_dp, kep_H, NULL, 1, NULL };
    wp_point ours[8];

    printf("\n### Kepler, e = 0.6, at equal accuracy: emitted Gauss-2 (callbacks) and GSL rk4imp over %d periods\n\n", periods);
    printf("| stepper | steps per period | Newton epsabs | max energy err | position err at end | ns per unit time | ns per step (apply) | grad/step (f/apply) |\n");
    printf("|---|--:|--:|--:|--:|--:|--:|--:|\n");
    emit_g2_workspace *w = emit_g2_alloc(&sys, NULL);
    for (int i = 0; i < nN; i++) {
        double h = T / Ns[i], q[2], p[2], t = 0, maxe = 0;
        long steps = (long)periods * Ns[i];
        memcpy(q, q0, sizeof q); memcpy(p, p0, sizeof p);
        emit_g2_reset(w);
        const vigen_stats *S = emit_g2_stats(w);
        unsigned long ev0 = S->dHdq_evals + S->dHdp_evals;
        for (long k = 0; k < steps; k++) {
            if (emit_g2_step(w, &t, q, p, h)) { fprintf(stderr, "emitted Gauss-2 failed\n"); exit(1); }
            double de = fabs(kep_H(t, q, p, NULL) / H0 - 1);
            if (de > maxe) maxe = de;
        }
        double evals = (double)(S->dHdq_evals + S->dHdp_evals - ev0) / steps;
        kep_exact(e, t, qx);
        double pos = hypot(q[0] - qx[0], q[1] - qx[1]), best = 1e300;
        for (int rep = 0; rep < 5; rep++) {
            memcpy(q, q0, sizeof q); memcpy(p, p0, sizeof p);
            t = 0;
            emit_g2_reset(w);
            double t0 = now();
            for (long k = 0; k < steps; k++) emit_g2_step(w, &t, q, p, h);
            double el = now() - t0;
            if (el < best) best = el;
        }
        ours[i] = (wp_point){ Ns[i], maxe, pos, 1e9 * best / (periods * T), 1e9 * best / steps, evals, 1 };
        printf("| emitted Gauss-2 | %d | (round-off) | %.2e | %.2e | %.0f | %.1f | %.1f |\n", Ns[i], maxe, pos,
               ours[i].ns_time, ours[i].ns_step, evals);
    }
    emit_g2_free(w);

    /* rk4imp at H = T/M returns Gauss-2 at H/2: M = N/2 applies per period */
    rk_point rk[64];
    int nrk = 0;
    printf("\n| rk4imp applies per period (= Gauss-2 steps / 2) | epsabs | max energy err | position err at end | ns per unit time | ns per apply | f evals per apply | per step: apply / emitted step at the same h | ratio at equal energy err | ratio at equal position err |\n");
    printf("|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (int i = 0; i < nN; i++) {
        int M = Ns[i] / 2;
        double H = T / M;
        long applies = (long)periods * M;
        char failed[256] = "";
        for (int j = 0; j < neps; j++) {
            gsl_ctx gc = { 2, kep_dq, kep_dp, kep_jac_fn, 0, 0 };
            gsl_odeiv2_system gs = { gsl_f, gsl_jac, 4, &gc };
            gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&gs, gsl_odeiv2_step_rk4imp, H, eps[j], 0.0);
            double y[4], t = 0, maxe = 0;
            memcpy(y, q0, sizeof q0); memcpy(y + 2, p0, sizeof p0);
            long k;
            int st = 0;
            for (k = 0; k < applies; k++) {
                st = gsl_odeiv2_driver_apply_fixed_step(d, &t, H, 1, y);
                if (st) break;
                double de = fabs(kep_H(t, y, y + 2, NULL) / H0 - 1);
                if (de > maxe) maxe = de;
            }
            if (st) {
                size_t len = strlen(failed);
                snprintf(failed + len, sizeof failed - len, "%s%.0e (apply %ld)", len ? ", " : "", eps[j], k + 1);
                gsl_odeiv2_driver_free(d);
                continue;
            }
            double fev = (double)gc.fevals / applies;
            kep_exact(e, t, qx);
            double pos = hypot(y[0] - qx[0], y[1] - qx[1]), best = 1e300;
            for (int rep = 0; rep < 3; rep++) {
                gsl_odeiv2_driver_reset(d);
                memcpy(y, q0, sizeof q0); memcpy(y + 2, p0, sizeof p0);
                t = 0;
                double t0 = now();
                gsl_odeiv2_driver_apply_fixed_step(d, &t, H, (unsigned long)applies, y);
                double el = now() - t0;
                if (el < best) best = el;
            }
            gsl_odeiv2_driver_free(d);
            double nst = 1e9 * best / (periods * T);
            double ce = cost_at(ours, nN, maxe, 0), cp = cost_at(ours, nN, pos, 1);
            char re[32] = "outside range", rp[32] = "outside range";
            if (ce > 0) snprintf(re, sizeof re, "%.1f", nst / ce);
            if (cp > 0) snprintf(rp, sizeof rp, "%.1f", nst / cp);
            if (nrk < 64)
                rk[nrk++] = (rk_point){ maxe, pos, nst, ce > 0 && cp > 0 ? nst / (ce > cp ? ce : cp) : -1 };
            char ps[32] = "-";
            for (int m = 0; m < nN; m++)
                if (Ns[m] == M) snprintf(ps, sizeof ps, "%.1f", (1e9 * best / applies) / ours[m].ns_step);
            printf("| %d | %.0e | %.2e | %.2e | %.0f | %.0f | %.1f | %s | %s | %s |\n", M, eps[j], maxe, pos, nst,
                   1e9 * best / applies, fev, ps, re, rp);
        }
        if (failed[0]) printf("| %d | %s: the Newton iteration fails | | | | | | | | |\n", M, failed);
    }
    /* rk4imp's efficient settings: no other setting both cheaper and at least
     * as accurate in both errors */
    double lo = 1e300, hi = 0;
    int eff = 0;
    for (int a = 0; a < nrk; a++) {
        int dominated = 0;
        for (int b = 0; b < nrk && !dominated; b++)
            if (b != a && rk[b].cost <= rk[a].cost && rk[b].energy <= rk[a].energy && rk[b].pos <= rk[a].pos)
                dominated = 1;
        if (dominated || rk[a].ratio < 0) continue;
        eff++;
        if (rk[a].ratio < lo) lo = rk[a].ratio;
        if (rk[a].ratio > hi) hi = rk[a].ratio;
    }
    if (eff)
        printf("\nAt equal accuracy, on rk4imp's %d efficient settings (no other setting is both cheaper and at least as "
               "accurate) inside the measured range, rk4imp costs %.1f to %.1f times the emitted Gauss-2 per unit of "
               "simulated time (the less favourable of the energy and position ratios).\n", eff, lo, hi);
}

/* Kepler over a long horizon: the energy error at the pericentre at the end
 * of every PERIODS/10 periods, where the oscillating part of the error is
 * smallest and what remains is secular.  The emitted Gauss-2 solves its
 * stage equations to round-off; rk4imp stops its Newton iteration at its
 * tolerance, and what it leaves is a small systematic error per step, not a
 * symplectic map: at its cheapest setting for ~5e-9 (400 applies per period,
 * epsabs 1e-8, paired with 800 emitted steps per period) its energy drifts
 * linearly, and a long simulation must pay for a tighter setting. */
static void kepler_drift(int periods)
{
    const double T = 2 * 3.14159265358979323846;
    const int per = 800;
    double q0[2], p0[2];
    kep_init(0.6, q0, p0);
    const double H0 = kep_H(0, q0, p0, NULL);
    vigen_hamiltonian sys = { 2, kep_dq, kep_dp, kep_H, NULL, 1, NULL };
    emit_g2_workspace *w = emit_g2_alloc(&sys, NULL);
    gsl_ctx gc = { 2, kep_dq, kep_dp, kep_jac_fn, 0, 0 };
    gsl_odeiv2_system gs = { gsl_f, gsl_jac, 4, &gc };
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&gs, gsl_odeiv2_step_rk4imp, 2 * T / per, 1e-8, 0.0);
    double q[2], p[2], t = 0, y[4], ty = 0;
    memcpy(q, q0, sizeof q); memcpy(p, p0, sizeof p);
    memcpy(y, q0, sizeof q0); memcpy(y + 2, p0, sizeof p0);
    printf("\n### Kepler, e = 0.6, over %d periods: energy error at the pericentre (secular part)\n\n", periods);
    printf("| periods | emitted Gauss-2, %d steps per period | rk4imp, %d applies per period, epsabs 1e-8 |\n", per, per / 2);
    printf("|--:|--:|--:|\n");
    for (int P = 1; P <= periods; P++) {
        for (int k = 0; k < per; k++)
            if (emit_g2_step(w, &t, q, p, T / per)) { fprintf(stderr, "emitted Gauss-2 failed\n"); exit(1); }
        if (gsl_odeiv2_driver_apply_fixed_step(d, &ty, 2 * T / per, (unsigned long)(per / 2), y) != GSL_SUCCESS) {
            printf("| %d | | rk4imp failed |\n", P);
            break;
        }
        if (P % (periods / 10) == 0)
            printf("| %d | %.2e | %.2e |\n", P, fabs(kep_H(t, q, p, NULL) / H0 - 1), fabs(kep_H(ty, y, y + 2, NULL) / H0 - 1));
    }
    gsl_odeiv2_driver_free(d);
    emit_g2_free(w);
}

/* ------------------------------------------------------------------ main */
int main(int argc, char **argv)
{
    long ksteps = argc > 1 ? atol(argv[1]) : 1000000, fsteps = argc > 2 ? atol(argv[2]) : 2000;
    gsl_set_error_handler_off();
    clock_cost = probe_clock_cost();
    printf("Clock read: %.1f ns (subtracted from the measured gradient shares).\n", 1e9 * clock_cost);

    /* Kepler */
    double kq[2], kp[2];
    kep_init(0.6, kq, kp);
    problem K = { "Kepler, e = 0.6", 2, kep_dq, kep_dp, kep_H, kq, kp, 0.01, ksteps };
    vigen_hamiltonian ksys = { 2, kep_dq, kep_dp, kep_H, NULL, 1, NULL };
    vigen_hamiltonian tsys = { 2, timed_dq, timed_dp, kep_H, NULL, 1, NULL };
    vigen_solver_options nk;
    vigen_solver_options_default(&nk);
    nk.kahan = 0;
    {
        emit_g2_workspace *g2 = emit_g2_alloc(&ksys, NULL), *g2t = emit_g2_alloc(&tsys, NULL);
        emit_g2k_workspace *g2d = emit_g2k_alloc(&ksys, NULL);
        emit_sv_workspace *sv = emit_sv_alloc(&ksys, NULL), *svt = emit_sv_alloc(&tsys, NULL), *sv0 = emit_sv_alloc(&ksys, &nk);
        emit_svk_workspace *svd = emit_svk_alloc(&ksys, NULL);
        hg2k_ws *hg2 = hg2k_alloc(2);
        hg2t_ws *hg2t = hg2t_alloc(2);
        hvk_ws *hv = hvk_alloc(2, 1), *hv0 = hvk_alloc(2, 0);
        hvt_ws *hvt = hvt_alloc(2, 1), *hv0t = hvt_alloc(2, 0);
        problem_table(&K, STEPPER("", emit_g2, g2), STEPPER("", emit_g2, g2t), STEPPER("", emit_g2k, g2d),
                      STEPPER("", hg2k, hg2), STEPPER("", hg2t, hg2t), STEPPER("", emit_sv, sv),
                      STEPPER("", emit_sv, svt), STEPPER("", emit_svk, svd), STEPPER("", hvk, hv),
                      STEPPER("", hvt, hvt), STEPPER("", emit_sv, sv0), STEPPER("", hvk, hv0),
                      STEPPER("", hvt, hv0t), kep_jac_fn, 0);
        emit_g2_free(g2); emit_g2_free(g2t); emit_g2k_free(g2d);
        emit_sv_free(sv); emit_sv_free(svt); emit_sv_free(sv0); emit_svk_free(svd);
        hg2k_free(hg2); hg2t_free(hg2t); hvk_free(hv); hvk_free(hv0); hvt_free(hvt); hvt_free(hv0t);
    }

    /* FPUT */
    double *fq = malloc(FPUT_N * sizeof(double)), *fp = malloc(FPUT_N * sizeof(double));
    fput_init(fq, fp);
    problem F = { "FPUT-beta chain, n = 1000, beta = 1, fixed ends", FPUT_N, fput_dq, fput_dp, fput_H, fq, fp, 0.05, fsteps };
    vigen_hamiltonian fsys = { FPUT_N, fput_dq, fput_dp, fput_H, NULL, 1, NULL };
    vigen_hamiltonian ftsys = { FPUT_N, timed_dq, timed_dp, fput_H, NULL, 1, NULL };
    {
        emit_g2_workspace *g2 = emit_g2_alloc(&fsys, NULL), *g2t = emit_g2_alloc(&ftsys, NULL);
        emit_g2f_workspace *g2d = emit_g2f_alloc(&fsys, NULL);
        emit_sv_workspace *sv = emit_sv_alloc(&fsys, NULL), *svt = emit_sv_alloc(&ftsys, NULL), *sv0 = emit_sv_alloc(&fsys, &nk);
        emit_svf_workspace *svd = emit_svf_alloc(&fsys, NULL);
        hg2f_ws *hg2 = hg2f_alloc(FPUT_N);
        hg2t_ws *hg2t = hg2t_alloc(FPUT_N);
        hvf_ws *hv = hvf_alloc(FPUT_N, 1), *hv0 = hvf_alloc(FPUT_N, 0);
        hvt_ws *hvt = hvt_alloc(FPUT_N, 1), *hv0t = hvt_alloc(FPUT_N, 0);
        problem_table(&F, STEPPER("", emit_g2, g2), STEPPER("", emit_g2, g2t), STEPPER("", emit_g2f, g2d),
                      STEPPER("", hg2f, hg2), STEPPER("", hg2t, hg2t), STEPPER("", emit_sv, sv),
                      STEPPER("", emit_sv, svt), STEPPER("", emit_svf, svd), STEPPER("", hvf, hv),
                      STEPPER("", hvt, hvt), STEPPER("", emit_sv, sv0), STEPPER("", hvf, hv0),
                      STEPPER("", hvt, hv0t), fput_jac_fn, getenv("EMIT_BENCH_SKIP_FPUT_GSL") ? 0 : 1);
        emit_g2_free(g2); emit_g2_free(g2t); emit_g2f_free(g2d);
        emit_sv_free(sv); emit_sv_free(svt); emit_sv_free(sv0); emit_svf_free(svd);
        hg2f_free(hg2); hg2t_free(hg2t); hvf_free(hv); hvf_free(hv0); hvt_free(hvt); hvt_free(hv0t);
    }
    if (getenv("EMIT_BENCH_TABLES_ONLY")) {
        /* the two tables only (side-by-side timing of two builds) */
        free(fq);
        free(fp);
        return 0;
    }
    ideal_sweep_share();
    toda_share(fsteps / 4 > 0 ? fsteps / 4 : 1);
    free(fq);
    free(fp);

    kepler_equal_accuracy();
    kepler_drift(2000);
    return 0;
}
