/* peer_bench.c — the emitted mechanical steppers side by side with their
 * peers on one problem of the collection (runtime/problems/), in one run:
 *   1. Gauss-2 (and Gauss-3, Lobatto IIIA-IIIB s = 3 against the
 *      hand-written anchors of bench/hand_gni_gauss.h): the hand-written
 *      stepper of bench/hand_gauss2.h with the
 *      problem's gradients inlined (the reference); the emitted Gauss-2 as a
 *      mechanical problem with --dim and the force called directly
 *      (NAME_DIRECT_FORCE), with and without start_force; through the
 *      mechanical callbacks; through the general callbacks (NAME_alloc), with
 *      the extrapolated start (default) and without; GSL's rk4imp at the same
 *      h, a check of scale only (another method: step doubling, modified
 *      Newton to a tolerance);
 *   2. Stormer-Verlet: a hand-written kick-drift-kick with static dimension
 *      and the force inlined (the reference) against the emitted Verlet with
 *      --dim and direct force, through the mechanical and the general
 *      callbacks;
 *   3. the fourth-order composition mclachlan_rkn_4 against the same method
 *      in Boost.Odeint (bench/peer_boost.cpp, run first; its figures and
 *      final state are read from BOOST_FILE), and the emitted yoshida_4.
 * Each row: ns per step (fastest of 5 runs of STEPS steps from the problem's
 * initial state), force (or dH/dq) and dH/dp evaluations per step, stage
 * sweeps per step, relative energy error at the end, time over the block's
 * reference.  Prints Markdown.  A measurement, not a test.
 *   peer_bench [STEPS [BOOST_FILE]]      STEPS 0: PEER_STEPS
 * PEER_SKIP_GSL set in the environment skips rk4imp (~10 s per apply on the
 * n = 1000 chain).
 *
 * bench/peer_run.sh builds it once per problem and passes the problem as
 * macros (PEER_FILE, PEER_NAME, PEER_PARAMS, PEER_TITLE, PEER_DIM,
 * PEER_UNIT_MASS, PEER_H, PEER_STEPS, PEER_GSL_APPLIES, PEER_GSL_RUNS).  The
 * problem's own file is compiled here, in place of its copy in the problem
 * library, so that its static force is inlined into the hand-written and the
 * direct-force steppers without being retyped.  With PEER_FORCE_ONLY only the
 * force is compiled, as peer_boost_force for bench/peer_boost.cpp (linked
 * with -flto so that it is inlined there too). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <vigen/problems.h>
#include <vigen/runtime.h>
#include PEER_FILE

/* f = -dV/dq from the problem's static dH/dq (the collection has no force of
 * its own; p is not read by a separable dH/dq) */
static inline void peer_force(double t, const double *q, double *f, void *ctx)
{
    dHdq(t, q, q, f, ctx);
    for (size_t k = 0; k < PEER_DIM; k++) f[k] = -f[k];
}

#ifdef PEER_FORCE_ONLY
void peer_boost_force(double t, const double *q, double *f, void *ctx);
void peer_boost_force(double t, const double *q, double *f, void *ctx) { peer_force(t, q, f, ctx); }
#else

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include "peer_g2.h"
#include "peer_mcl.h"
#include "peer_sv.h"

#define PEER_G2D_DIRECT_FORCE peer_force
#include "peer_g2d.c"
#define PEER_G3D_DIRECT_FORCE peer_force
#include "peer_g3d.c"
#define PEER_L3D_DIRECT_FORCE peer_force
#include "peer_l3d.c"
#define PEER_SVD_DIRECT_FORCE peer_force
#include "peer_svd.c"
#define PEER_MCLD_DIRECT_FORCE peer_force
#include "peer_mcld.c"
#define PEER_Y4D_DIRECT_FORCE peer_force
#include "peer_y4d.c"

/* dH/dp = M^-1 p, inlined: a copy for unit masses, else the problem's own */
#if PEER_UNIT_MASS
static inline void peer_dp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    for (size_t k = 0; k < PEER_DIM; k++) out[k] = p[k];
}
#define PEER_VELOCITY(k, x) (x)
#else
#define peer_dp dHdp
#define PEER_VELOCITY(k, x) (peer_inv_mass[k] * (x))
#endif
static double peer_inv_mass[PEER_DIM];

#define HG2_NAME hg2
#define HG2_DQ dHdq
#define HG2_DP peer_dp
#include "hand_gauss2.h"

/* the GNI_IRK2-style anchors (bench/hand_gni_gauss.h): Nystrom form,
 * static dimension, force inlined */
#include "gni_anchors.h"

/* ------------------------------------------------------------ the problem */
static vigen_problem *pb;
static long steps;
static const double h = PEER_H;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double energy_error(double t, const double *q, const double *p)
{
    double q0[PEER_DIM], p0[PEER_DIM], t0;
    vigen_problem_initial(pb, &t0, q0, p0);
    double H0 = vigen_problem_energy(pb, t0, q0, p0);
    return fabs((vigen_problem_energy(pb, t, q, p) - H0) / H0);
}

/* --------------------------------------------- hand-written Stormer-Verlet */
#include "hand_verlet_dim.h"

static const vigen_stats *hsv_stats(const void *w) { return &((const hsv_ws *)w)->st; }
static void hsv_reset(void *ws)
{
    hsv_ws *w = ws;
    memset(w, 0, sizeof *w);
}

/* hand_gauss2.h counts dH/dq and dH/dp calls together (one each per stage) */
static vigen_stats hg2_counts;
static int hg2_step_v(void *w, double *t, double *q, double *p, double hh) { return hg2_step(w, t, q, p, hh, pb); }
static void hg2_reset_v(void *ws)
{
    hg2_ws *w = ws;
    w->hist = 0;
    memset(w->cq, 0, PEER_DIM * sizeof *w->cq);
    memset(w->cp, 0, PEER_DIM * sizeof *w->cp);
}
static const vigen_stats *hg2_stats_v(const void *ws)
{
    const hg2_ws *w = ws;
    hg2_counts.dHdq_evals = hg2_counts.dHdp_evals = w->evals / 2;
    hg2_counts.iterations = w->iters;
    return &hg2_counts;
}

/* the GNI-style anchors through the row interface: forces and sweeps */
#define GNI_ROW(x)                                                                                               \
    static vigen_stats x##_counts;                                                                            \
    static int x##_step_v(void *w, double *t, double *q, double *p, double hh)                                \
    {                                                                                                         \
        return x##_step(w, t, q, p, hh, pb);                                                                  \
    }                                                                                                         \
    static void x##_reset_v(void *w) { x##_reset(w); }                                                        \
    static const vigen_stats *x##_stats_v(const void *ws)                                                     \
    {                                                                                                         \
        const x##_ws *w = ws;                                                                                 \
        x##_counts.dHdq_evals = w->forces;                                                                    \
        x##_counts.iterations = w->sweeps;                                                                    \
        return &x##_counts;                                                                                   \
    }
GNI_ROW(gni2)
GNI_ROW(gni3)
GNI_ROW(gnil3)

/* ------------------------------------------------------------- one row */
typedef int (*step_fn)(void *w, double *t, double *q, double *p, double h);
typedef const vigen_stats *(*stats_fn)(const void *w);
typedef void (*reset_fn)(void *w);

typedef struct {
    double ns, forces, dhdp, sweeps, err;
    int status;
    double q[PEER_DIM], p[PEER_DIM];
} result;

/* fastest of 5 runs of `steps` steps from the initial state, each a new
 * trajectory (reset); the counts and the final state of the last run */
/* the step, stats and reset of an emitted stepper, from its type object */
#define EMITTED(name) name##_type.step, name##_type.stats, name##_type.reset

static result measure(void *w, step_fn step, stats_fn stats, reset_fn reset)
{
    result r = { 1e300, 0, 0, 0, 0, 0, { 0 }, { 0 } };
    double t;
    for (int run = 0; run < 5 && r.status == 0; run++) {
        vigen_problem_initial(pb, &t, r.q, r.p);
        reset(w);
        vigen_stats s0 = *stats(w);
        double t0 = now();
        for (long k = 0; k < steps && r.status == 0; k++) r.status = step(w, &t, r.q, r.p, h);
        double el = now() - t0;
        const vigen_stats *s1 = stats(w);
        if (el < r.ns) r.ns = el;
        r.forces = (double)(s1->dHdq_evals - s0.dHdq_evals) / (double)steps;
        r.dhdp = (double)(s1->dHdp_evals - s0.dHdp_evals) / (double)steps;
        r.sweeps = (double)(s1->iterations - s0.iterations) / (double)steps;
    }
    r.ns *= 1e9 / (double)steps;
    r.err = energy_error(t, r.q, r.p);
    return r;
}

static void print_row(const char *label, const result *r, double ref, int implicit)
{
    if (r->status != 0) {
        printf("| %s | failed: %s | | | | | |\n", label, vigen_strerror(r->status));
        return;
    }
    char sw[32] = "-";
    if (implicit) snprintf(sw, sizeof sw, "%.2f", r->sweeps);
    printf("| %s | %.1f | %.2f | %.2f | %s | %.2e | %.3f |\n", label, r->ns, r->forces, r->dhdp, sw, r->err,
           r->ns / ref);
}

static void table_head(const char *ref)
{
    printf("| stepper | ns / step | forces (dH/dq) / step | dH/dp / step | sweeps / step | rel. energy error | x %s |\n",
           ref);
    printf("|---|--:|--:|--:|--:|--:|--:|\n");
}

static vigen_solver_options options(int extrapolate, int start_force, int kahan)
{
    vigen_solver_options o;
    vigen_solver_options_default(&o);
    o.extrapolate = extrapolate;
    o.start_force = start_force;
    o.kahan = kahan;
    return o;
}

/* ---------------------------------------------------------- GSL rk4imp */
/* y = (q, p), y' = (dH/dp, -dH/dq) through the collection's callbacks;
 * Jacobian [[H_pq, H_pp], [-H_qq, -H_qp]] from its Hessian of H */
typedef struct {
    const vigen_hamiltonian *H;
    double *hess;
    unsigned long fevals, jevals;
} gsl_ctx;

static int gsl_f(double t, const double y[], double f[], void *params)
{
    gsl_ctx *c = params;
    c->fevals++;
    c->H->dHdp(t, y, y + PEER_DIM, f, c->H->ctx);
    c->H->dHdq(t, y, y + PEER_DIM, f + PEER_DIM, c->H->ctx);
    for (size_t k = 0; k < PEER_DIM; k++) f[PEER_DIM + k] = -f[PEER_DIM + k];
    return GSL_SUCCESS;
}

static int gsl_jac(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    gsl_ctx *c = params;
    const size_t n = PEER_DIM, m = 2 * PEER_DIM;
    c->jevals++;
    c->H->hessian(t, y, y + n, c->hess, c->H->ctx);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < m; j++) {
            dfdy[i * m + j] = c->hess[(n + i) * m + j];
            dfdy[(n + i) * m + j] = -c->hess[i * m + j];
        }
    memset(dfdt, 0, m * sizeof *dfdt);
    return GSL_SUCCESS;
}

/* PEER_GSL_APPLIES applies of size h (each: one step of h for the error
 * estimate and two of h/2 for the result), fastest of PEER_GSL_RUNS */
static void gsl_row(double ref)
{
    const long applies = PEER_GSL_APPLIES;
    if (getenv("PEER_SKIP_GSL") != NULL) {
        printf("| GSL rk4imp: skipped (PEER_SKIP_GSL) | | | | | | |\n");
        return;
    }
    gsl_ctx c = { vigen_problem_hamiltonian(pb), malloc(4 * PEER_DIM * PEER_DIM * sizeof(double)), 0, 0 };
    gsl_odeiv2_system sys = { gsl_f, gsl_jac, 2 * PEER_DIM, &c };
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk4imp, h, 1e-6, 0.0);
    double y[2 * PEER_DIM], t = 0, best = 1e300;
    int st = 0;
    for (int run = 0; run < PEER_GSL_RUNS && st == 0; run++) {
        gsl_odeiv2_driver_reset(d);
        vigen_problem_initial(pb, &t, y, y + PEER_DIM);
        c.fevals = c.jevals = 0;
        double t0 = now();
        st = gsl_odeiv2_driver_apply_fixed_step(d, &t, h, (unsigned long)applies, y);
        double el = now() - t0;
        if (el < best) best = el;
    }
    char label[200];
    snprintf(label, sizeof label,
             "GSL rk4imp, %ld appl%s of h (fastest of %d; another method: Gauss-2 with step doubling, "
             "modified Newton to epsabs 1e-6; f evals, Jacobians %.2f)",
             applies, applies == 1 ? "y" : "ies", PEER_GSL_RUNS, (double)c.jevals / (double)applies);
    if (st != GSL_SUCCESS) {
        printf("| %s | failed: %s | | | | | |\n", label, gsl_strerror(st));
    } else {
        double ns = 1e9 * best / (double)applies, f = (double)c.fevals / (double)applies;
        printf("| %s | %.1f | %.2f | %.2f | - | %.2e | %.3f |\n", label, ns, f, f, energy_error(t, y, y + PEER_DIM),
               ns / ref);
    }
    gsl_odeiv2_driver_free(d);
    free(c.hess);
}

/* ------------------------------------------------------------- blocks */
/* A row of a block: a stepper and what to call it. */
typedef struct {
    const char *label;
    void *w;
    step_fn step;
    stats_fn stats;
    reset_fn reset;
} row;

/* measures and prints rows[0..n-1]: times over ref, or over rows[0] when ref
 * is 0; results into res (NULL: not kept) */
static double run_rows(const row *rows, int n, double ref, int implicit, result *res)
{
    for (int i = 0; i < n; i++) {
        if (rows[i].w == NULL) {
            fprintf(stderr, "peer_bench: %s: could not be allocated\n", rows[i].label);
            exit(1);
        }
    }
    for (int i = 0; i < n; i++) {
        result r = measure(rows[i].w, rows[i].step, rows[i].stats, rows[i].reset);
        if (ref == 0) ref = r.ns;
        print_row(rows[i].label, &r, ref, implicit);
        if (res != NULL) res[i] = r;
    }
    return ref;
}

static void gauss2_block(void)
{
    const vigen_hamiltonian *H = vigen_problem_hamiltonian(pb);
    vigen_mechanical mech = { PEER_DIM, peer_force, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    vigen_solver_options dflt = options(1, 0, 1), sf = options(1, 1, 1), noex = options(0, 0, 1);
    row rows[] = {
        { "hand-written Gauss-2, GNI_IRK2 style (bench/hand_gni_gauss.h: Nystrom form, static dimension, force "
          "inlined)", gni2_alloc(), gni2_step_v, gni2_stats_v, gni2_reset_v },
        { "hand-written Gauss-2 (bench/hand_gauss2.h, general form, gradients inlined)", hg2_alloc(PEER_DIM),
          hg2_step_v, hg2_stats_v, hg2_reset_v },
        { "emitted Gauss-2, mechanical, --dim, direct force", peer_g2d_alloc_mechanical(&mech, &dflt),
          EMITTED(peer_g2d) },
        { "emitted Gauss-2, mechanical, --dim, direct force, start_force = 1",
          peer_g2d_alloc_mechanical(&mech, &sf), EMITTED(peer_g2d) },
        { "emitted Gauss-2, mechanical callbacks", peer_g2_alloc_mechanical(&mech, &dflt), EMITTED(peer_g2) },
        { "emitted Gauss-2, general callbacks (NAME_alloc), extrapolated start", peer_g2_alloc(H, &dflt),
          EMITTED(peer_g2) },
        { "emitted Gauss-2, general callbacks, no extrapolation (start at the step's start)",
          peer_g2_alloc(H, &noex), EMITTED(peer_g2) },
    };
    enum { N = sizeof rows / sizeof rows[0] };
    result res[N];
    printf("Gauss-2 (x hand: over the hand-written stepper)\n\n");
    table_head("hand");
    gsl_row(run_rows(rows, N, 0, 1, res));
    const result *d = &res[2], *s = &res[3], *g = &res[5];
    printf("\nSweeps per step against the general stepper's extrapolated start (%.2f): mechanical, default start "
           "%.2f (%.1f%% fewer); with start_force %.2f (%.1f%% fewer).\n\n",
           g->sweeps, d->sweeps, 100 * (1 - d->sweeps / g->sweeps), s->sweeps, 100 * (1 - s->sweeps / g->sweeps));
    free(rows[0].w);
    hg2_free(rows[1].w);
    for (int i = 2; i < 4; i++) peer_g2d_free(rows[i].w);
    for (int i = 4; i < N; i++) peer_g2_free(rows[i].w);
}

static void gauss3_block(void)
{
    vigen_mechanical mech = { PEER_DIM, peer_force, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    vigen_solver_options dflt = options(1, 0, 1), sf = options(1, 1, 1);
    row rows[] = {
        { "hand-written Gauss-3, GNI_IRK2 style (bench/hand_gni_gauss.h)", gni3_alloc(), gni3_step_v, gni3_stats_v,
          gni3_reset_v },
        { "emitted Gauss-3, mechanical, --dim, direct force", peer_g3d_alloc_mechanical(&mech, &dflt),
          EMITTED(peer_g3d) },
        { "emitted Gauss-3, mechanical, --dim, direct force, start_force = 1",
          peer_g3d_alloc_mechanical(&mech, &sf), EMITTED(peer_g3d) },
    };
    enum { N = sizeof rows / sizeof rows[0] };
    printf("\nGauss-3 (x hand: over the hand-written stepper)\n\n");
    table_head("hand");
    run_rows(rows, N, 0, 1, NULL);
    printf("\n");
    free(rows[0].w);
    for (int i = 1; i < N; i++) peer_g3d_free(rows[i].w);
}

static void lobatto3_block(void)
{
    vigen_mechanical mech = { PEER_DIM, peer_force, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    vigen_solver_options dflt = options(1, 0, 1);
    row rows[] = {
        { "hand-written Lobatto IIIA-IIIB s = 3, GNI_IRK2 style (bench/hand_gni_gauss.h)", gnil3_alloc(),
          gnil3_step_v, gnil3_stats_v, gnil3_reset_v },
        { "emitted Lobatto IIIA-IIIB s = 3, mechanical, --dim, direct force", peer_l3d_alloc_mechanical(&mech, &dflt),
          EMITTED(peer_l3d) },
    };
    enum { N = sizeof rows / sizeof rows[0] };
    printf("Lobatto IIIA-IIIB s = 3 (x hand: over the hand-written stepper)\n\n");
    table_head("hand");
    run_rows(rows, N, 0, 1, NULL);
    printf("\n");
    free(rows[0].w);
    for (int i = 1; i < N; i++) peer_l3d_free(rows[i].w);
}

static void verlet_block(void)
{
    vigen_mechanical mech = { PEER_DIM, peer_force, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    row rows[] = {
        { "hand-written Verlet, static dimension, force inlined, compensated", calloc(1, sizeof(hsv_ws)), hsv_step,
          hsv_stats, hsv_reset },
        { "emitted Verlet, mechanical, --dim, direct force", peer_svd_alloc_mechanical(&mech, NULL),
          EMITTED(peer_svd) },
        { "emitted Verlet, mechanical callbacks", peer_sv_alloc_mechanical(&mech, NULL), EMITTED(peer_sv) },
        { "emitted Verlet, general callbacks (NAME_alloc)", peer_sv_alloc(vigen_problem_hamiltonian(pb), NULL),
          EMITTED(peer_sv) },
    };
    printf("Stormer-Verlet, kick-drift-kick (x hand: over the hand-written stepper)\n\n");
    table_head("hand");
    run_rows(rows, 4, 0, 0, NULL);
    printf("\n");
    free(rows[0].w);
    peer_svd_free(rows[1].w);
    peer_sv_free(rows[2].w);
    peer_sv_free(rows[3].w);
}

/* Boost's figures: "ns forces energy_error steps", then (hex) q and p after
 * those steps and after one step */
typedef struct {
    int ok;
    double ns, forces, err;
    double q[PEER_DIM], p[PEER_DIM], q1[PEER_DIM], p1[PEER_DIM];
} boost_result;

static const boost_result *read_boost(const char *path)
{
    static boost_result b;
    FILE *f = path ? fopen(path, "r") : NULL;
    long n = 0;
    if (f == NULL) return &b;
    int ok = fscanf(f, "%lf %lf %lf %ld", &b.ns, &b.forces, &b.err, &n) == 4 && n == steps;
    double *x[] = { b.q, b.p, b.q1, b.p1 };
    for (size_t i = 0; i < 4; i++)
        for (size_t k = 0; ok && k < PEER_DIM; k++) ok = fscanf(f, "%la", &x[i][k]) == 1;
    fclose(f);
    if (!ok) fprintf(stderr, "peer_bench: %s is not Boost's result for %ld steps; no Boost row\n", path, steps);
    b.ok = ok;
    return &b;
}

/* max |x - y| over q and p, and the largest |x| beside it */
static void difference(const double *q, const double *p, const double *qr, const double *pr, long n, const char *what)
{
    double dq = 0, dp = 0, sq = 0, sp = 0;
    for (size_t k = 0; k < PEER_DIM; k++) {
        dq = fmax(dq, fabs(q[k] - qr[k]));
        dp = fmax(dp, fabs(p[k] - pr[k]));
        sq = fmax(sq, fabs(qr[k]));
        sp = fmax(sp, fabs(pr[k]));
    }
    printf("- %s after the same %ld step%s: max |dq| = %.2e (max |q| %.2e), max |dp| = %.2e (max |p| %.2e)\n", what,
           n, n == 1 ? "" : "s", dq, sq, dp, sp);
}

static void composition_block(const char *boost_file)
{
    vigen_mechanical mech = { PEER_DIM, peer_force, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    vigen_solver_options plain = options(1, 0, 0);
    row rows[] = {
        { "emitted mclachlan_rkn_4, mechanical, --dim, direct force", peer_mcld_alloc_mechanical(&mech, NULL),
          EMITTED(peer_mcld) },
        { "emitted mclachlan_rkn_4, mechanical, --dim, direct force, no compensation (kahan = 0)",
          peer_mcld_alloc_mechanical(&mech, &plain), EMITTED(peer_mcld) },
        { "emitted mclachlan_rkn_4, mechanical callbacks", peer_mcl_alloc_mechanical(&mech, NULL), EMITTED(peer_mcl) },
        { "emitted yoshida_4, mechanical, --dim, direct force", peer_y4d_alloc_mechanical(&mech, NULL),
          EMITTED(peer_y4d) },
    };
    result res[4];
    const boost_result *b = read_boost(boost_file);
    printf("Fourth-order compositions (x %s)\n\n", b->ok ? "Boost: over Boost.Odeint's stepper of the same method"
                                                         : "emitted: over the emitted mclachlan_rkn_4 (no Boost figures)");
    table_head(b->ok ? "Boost" : "emitted");
    if (b->ok)
        printf("| Boost.Odeint symplectic_rkn_sb3a_mclachlan, std::array, force inlined (LTO) | %.1f | %.2f | %.2f | - | "
               "%.2e | 1.000 |\n", b->ns, b->forces, 0.0, b->err);
    run_rows(rows, 4, b->ok ? b->ns : 0, 0, res);
    printf("\n");
    if (b->ok) {
        double t, q[PEER_DIM], p[PEER_DIM];
        vigen_problem_initial(pb, &t, q, p);
        peer_mcld_reset(rows[0].w);
        int st = peer_mcld_step(rows[0].w, &t, q, p, h);
        if (st == VIGEN_SUCCESS)
            difference(q, p, b->q1, b->p1, 1, "emitted mclachlan_rkn_4 (compensated) against Boost");
        difference(res[0].q, res[0].p, b->q, b->p, steps, "emitted mclachlan_rkn_4 (compensated) against Boost");
        difference(res[1].q, res[1].p, b->q, b->p, steps, "emitted mclachlan_rkn_4 (no compensation) against Boost");
        difference(res[0].q, res[0].p, res[1].q, res[1].p, steps,
                   "for scale, round-off alone: emitted compensated against not compensated");
        printf("\n");
    }
    peer_mcld_free(rows[0].w);
    peer_mcld_free(rows[1].w);
    peer_mcl_free(rows[2].w);
    peer_y4d_free(rows[3].w);
}

int main(int argc, char **argv)
{
    char why[256];
    steps = argc > 1 ? atol(argv[1]) : 0;
    if (steps <= 0) steps = PEER_STEPS;
    if (vigen_problem_create(&pb, PEER_NAME, PEER_PARAMS, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "peer_bench: %s\n", why);
        return 1;
    }
    if (vigen_problem_dim(pb) != PEER_DIM) {
        fprintf(stderr, "peer_bench: %s has dimension %zu, built for %d\n", PEER_NAME, vigen_problem_dim(pb),
                (int)PEER_DIM);
        return 1;
    }
    /* diag(M^-1) from the problem's dH/dp of unit momenta */
    double e[PEER_DIM] = { 0 }, v[PEER_DIM];
    for (size_t k = 0; k < PEER_DIM; k++) {
        e[k] = 1;
        vigen_problem_hamiltonian(pb)->dHdp(0, e, e, v, pb);
        peer_inv_mass[k] = v[k];
        e[k] = 0;
    }
    gsl_set_error_handler_off();
    printf("#### %s, %ld steps\n\n", PEER_TITLE, steps);
    gauss2_block();
    gauss3_block();
    lobatto3_block();
    verlet_block();
    composition_block(argc > 2 ? argv[2] : NULL);
    vigen_problem_free(pb);
    return 0;
}
#endif
