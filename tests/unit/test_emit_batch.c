/* test_emit_batch.c — the batched steppers of `vigen emit --batch`
 * (NAME_step_batch), emitted at build time from tableaux/published
 * (tests/CMakeLists.txt: Stormer-Verlet, McLachlan and Atela's third-order
 * method (no first-same-as-last force) and Yoshida's triple jump, explicit;
 * Gauss s = 2 and Lobatto IIIA-IIIB s = 3, implicit: fixed point per
 * trajectory, Lobatto's last force taken once at the new q and reused as
 * the next step's first), on an ensemble of
 * Kepler orbits (eccentricities 0 to 0.7, distinct start times).
 * The reference is the scalar stepper NAME_step driven trajectory by
 * trajectory with a fresh workspace, both from the file emitted with --batch
 * and from the one emitted without it (tests/CMakeLists.txt, ens_verlet),
 * whose explicit step is tested against exact solutions elsewhere
 * (test_emit, test_emit_mechanical).  Asserted, for the mechanical and the
 * general (gradient) problem, compensated and not:
 *   - every trajectory of the batch has the scalar bits after 400 steps
 *     (the batch runs the same operations per element, so equality is exact,
 *     not to round-off); for Gauss-2 also with the starting forces not
 *     extrapolated, and its counts (steps, failed steps, sweeps, forces)
 *     are the sums of the scalar stepper's over the trajectories;
 *   - the orbits are right: after one period (2 pi) each is back at its
 *     start and at energy -1/2 (Kepler's problem in closed form), to the
 *     method's error;
 *   - force evaluations per trajectory: Verlet 1 per step plus 1 at the
 *     start, Yoshida 3 per step plus 1 (first same as last),
 *     McLachlan-Atela 3 per step, the minimal counts;
 *   - a trajectory started at NaN is reported (VIGEN_ENONFINITE) with its
 *     state unchanged bit for bit, a trajectory whose force turns NaN
 *     midway stops at the scalar stepper's last good step with its status,
 *     and every other trajectory keeps the scalar bits;
 *   - a trajectory moved by hand between steps starts afresh, as with the
 *     scalar stepper (its compensation and cached force dropped);
 *   - t + h not finite for one trajectory: VIGEN_EINVAL for it only; h not
 *     finite or a NULL array: VIGEN_EINVAL, nothing changed;
 *   - with unequal masses (M^-1 = diag(1, 0.75)) the explicit batches
 *     still give the scalar bits, trajectory by trajectory;
 *   - Lobatto IIIA-IIIB s = 3 the same as Gauss-2 (bits, counts, orbits, a
 *     force turning NaN, a moved trajectory whose cached force is dropped,
 *     sweeps running out or stalling, blocks of every width);
 *   - Gauss-2 with trajectories that need different numbers of sweeps (the
 *     premise is checked on the scalar runs), that run out of sweeps
 *     (VIGEN_EMAXITER) or stall above the tolerance (VIGEN_ENOCONV) while
 *     the others go on: each has the scalar bits, status and counts (the
 *     batch's stopping test runs several trajectories per vector);
 *   - blocks of 1, 3, 8 and 64 trajectories (no whole vector; whole vectors
 *     only) with a force loop the compiler vectorises: the scalar bits;
 *   - the implicit batch refuses a general H and the Newton solver (NULL);
 *     --batch with another real type is refused with a message. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "vigen/emit.h"
#include "vigen/method.h"
#include "eb_verlet.h"
#include "eb_yoshida.h"
#include "eb_gauss2.h"
#include "eb_ma3.h"
#include "eb_lobatto3.h"
#include "ens_verlet.h"

enum { W = 37, NSTEPS = 400 };
static const double PI = 3.14159265358979323846;

/* A failure time per trajectory: the force is NaN from that time on
 * (INFINITY: never), the same rule for the scalar and the batched force. */
typedef struct { double fail_at[W]; size_t lane; int rough; /* 1: every trajectory, 2: odd ones */ } fail_ctx;

static void kep_f1(double t, const double *q, double *f, const fail_ctx *fc, size_t lane)
{
    const double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    f[0] = -q[0] / r3;
    f[1] = -q[1] / r3;
    if (fc && t >= fc->fail_at[lane]) f[0] = NAN;
    if (fc && fc->rough && (fc->rough == 1 || lane % 2))
        /* a force that depends on the last bit of q: the stage iteration
         * then ends in a cycle of the last bits (a stall) rather than at an
         * exact fixed point, at a sweep that differs between trajectories,
         * and a trajectory that went on sweeping would end elsewhere */
        for (int k = 0; k < 2; k++) {
            uint64_t u;
            memcpy(&u, &q[k], sizeof u);
            f[k] += (u & 1) ? 1e-9 : -1e-9;
        }
}
/* scalar: ctx holds the lane it is used for */
static void kep_force(double t, const double *q, double *f, void *ctx) { kep_f1(t, q, f, ctx, ctx ? ((fail_ctx *)ctx)->lane : 0); }
static void kep_dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)p;
    kep_force(t, q, out, ctx);
    out[0] = -out[0];
    out[1] = -out[1];
}
static void kep_dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    out[0] = p[0];
    out[1] = p[1];
}
/* batched: the same expressions per trajectory, component-major */
static void kep_force_b(const double *t, const double *q, double *f, size_t nw, void *ctx)
{
    for (size_t j = 0; j < nw; j++) {
        double qj[2] = { q[j], q[nw + j] }, fj[2];
        kep_f1(t[j], qj, fj, ctx, j);
        f[j] = fj[0];
        f[nw + j] = fj[1];
    }
}
static void kep_dHdq_b(const double *t, const double *q, const double *p, double *out, size_t nw, void *ctx)
{
    (void)p;
    kep_force_b(t, q, out, nw, ctx);
    for (size_t k = 0; k < 2 * nw; k++) out[k] = -out[k];
}
static void kep_dHdp_b(const double *t, const double *q, const double *p, double *out, size_t nw, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    memcpy(out, p, 2 * nw * sizeof *out);
}

/* Orbit j: pericentre (1 - e, 0), speed sqrt((1 + e)/(1 - e)); aos: q[2 j + k]. */
static void initial_aos(double *t, double *q, double *p)
{
    for (int j = 0; j < W; j++) {
        const double e = 0.7 * j / (W - 1);
        t[j] = 0.25 * j;
        q[2 * j] = 1 - e;
        q[2 * j + 1] = 0;
        p[2 * j] = 0;
        p[2 * j + 1] = sqrt((1 + e) / (1 - e));
    }
}
static void to_soa(double *dst, const double *aos) { for (int j = 0; j < W; j++) for (int k = 0; k < 2; k++) dst[k * W + j] = aos[2 * j + k]; }
static int lane_equal(const double *soa, const double *aos, int j)
{
    return memcmp(&soa[j], &aos[2 * j], sizeof(double)) == 0 && memcmp(&soa[W + j], &aos[2 * j + 1], sizeof(double)) == 0;
}

typedef struct {
    const char *name;
    const vigen_stepper_type *type;
    void *(*alloc_mech)(const vigen_mechanical *, const vigen_solver_options *);
    void *(*balloc)(const vigen_hamiltonian_batch *, size_t, const vigen_solver_options *);
    void *(*balloc_mech)(const vigen_mechanical_batch *, size_t, const vigen_solver_options *);
    int (*bstep)(void *, double *, double *, double *, double, int *);
    const vigen_stats *(*bstats)(const void *);
    void (*bfree)(void *);
    int evals_per_step;   /* 0: implicit */
    int fsal;             /* the first force of a step is the last of the previous one */
} stepper;

#define STEPPER(N, E, F)                                                                                        \
    { #N, &N##_type, (void *(*)(const vigen_mechanical *, const vigen_solver_options *))N##_alloc_mechanical,   \
      (void *(*)(const vigen_hamiltonian_batch *, size_t, const vigen_solver_options *))N##_batch_alloc,        \
      (void *(*)(const vigen_mechanical_batch *, size_t, const vigen_solver_options *))N##_batch_alloc_mechanical, \
      (int (*)(void *, double *, double *, double *, double, int *))N##_step_batch,                             \
      (const vigen_stats *(*)(const void *))N##_batch_stats, (void (*)(void *))N##_batch_free, E, F }

/* The scalar reference, trajectory by trajectory (fresh workspace each),
 * with an optional hand move of trajectory `moved` after `at` steps. */
typedef struct { double t[W], q[2 * W], p[2 * W]; int status[W]; vigen_stats sum; unsigned long iters[W]; } aos_state;

static void scalar_run(aos_state *R, const stepper *S, const vigen_stepper_type *T, int mech, const vigen_solver_options *opt,
                       fail_ctx *fc, double h, int moved, int at)
{
    initial_aos(R->t, R->q, R->p);
    memset(&R->sum, 0, sizeof R->sum);
    for (int j = 0; j < W; j++) {
        fail_ctx one;
        if (fc) { one = *fc; one.lane = (size_t)j; }
        vigen_mechanical m = { .dim = 2, .force = kep_force, .ctx = fc ? &one : NULL };
        vigen_hamiltonian g = { .dim = 2, .dHdq = kep_dHdq, .dHdp = kep_dHdp, .ctx = fc ? &one : NULL, .separable = 1 };
        void *w = mech ? S->alloc_mech(&m, opt) : T->alloc(&g, opt);
        R->status[j] = VIGEN_SUCCESS;
        for (int k = 0; k < NSTEPS && R->status[j] == VIGEN_SUCCESS; k++) {
            if (j == moved && k == at) { R->q[2 * j] = 0.5; R->q[2 * j + 1] = 0.0; R->p[2 * j] = 0; R->p[2 * j + 1] = sqrt(3.0); }
            R->status[j] = T->step(w, R->t + j, R->q + 2 * j, R->p + 2 * j, h);
        }
        const vigen_stats *st = T->stats(w);
        R->iters[j] = st->iterations;
        R->sum.steps += st->steps;
        R->sum.failed_steps += st->failed_steps;
        R->sum.iterations += st->iterations;
        R->sum.dHdq_evals += st->dHdq_evals;
        R->sum.dHdp_evals += st->dHdp_evals;
        T->free(w);
    }
}

static void compare(const stepper *S, const vigen_stepper_type *T, int mech, int kahan, fail_ctx *fc, int nan_lane,
                    int moved, int at)
{
    const double h = 2 * PI / NSTEPS;
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.kahan = kahan & 1;
    if (kahan & 2) opt.extrapolate = 0;
    if (kahan & 4) opt.max_iter = 2;      /* trajectories of high eccentricity run out of sweeps */
    if (kahan & 8) opt.tol = 1e-300;      /* a stall is never calm: three of them end in VIGEN_ENOCONV */
    static aos_state R;
    static double t[W], q[2 * W], p[2 * W];
    int status[W];
    vigen_stats st;
    scalar_run(&R, S, T, mech, &opt, fc, h, moved, at);
    if (nan_lane >= 0) {
        /* the scalar trajectory started at NaN: refused at its first step */
        double t0[W], q0[2 * W], p0[2 * W];
        initial_aos(t0, q0, p0);
        void *w = T->alloc(&(vigen_hamiltonian){ .dim = 2, .dHdq = kep_dHdq, .dHdp = kep_dHdp, .separable = 1 }, &opt);
        q0[2 * nan_lane] = NAN;
        R.status[nan_lane] = T->step(w, t0 + nan_lane, q0 + 2 * nan_lane, p0 + 2 * nan_lane, h);
        R.t[nan_lane] = t0[nan_lane];
        memcpy(R.q + 2 * nan_lane, q0 + 2 * nan_lane, 2 * sizeof(double));
        memcpy(R.p + 2 * nan_lane, p0 + 2 * nan_lane, 2 * sizeof(double));
        T->free(w);
    }
    /* the batch, with the same NaN start */
    double qa[2 * W], pa[2 * W];
    int rc;
    {
        initial_aos(t, qa, pa);
        if (nan_lane >= 0) qa[2 * nan_lane] = NAN;
        to_soa(q, qa);
        to_soa(p, pa);
        vigen_mechanical_batch mb = { .dim = 2, .force = kep_force_b, .ctx = fc };
        vigen_hamiltonian_batch gb = { .dim = 2, .dHdq = kep_dHdq_b, .dHdp = kep_dHdp_b, .ctx = fc };
        void *b = mech ? S->balloc_mech(&mb, W, &opt) : S->balloc(&gb, W, &opt);
        CHECK(b != NULL);
        for (int j = 0; j < W; j++) status[j] = VIGEN_SUCCESS;
        rc = VIGEN_SUCCESS;
        for (int k = 0; k < NSTEPS; k++) {
            if (moved >= 0 && k == at) { q[moved] = 0.5; q[W + moved] = 0.0; p[moved] = 0; p[W + moved] = sqrt(3.0); }
            int s = S->bstep(b, t, q, p, h, status);
            if (s != VIGEN_SUCCESS && rc == VIGEN_SUCCESS) rc = s;
        }
        st = *S->bstats(b);
        S->bfree(b);
    }
    int failures = 0;
    for (int j = 0; j < W; j++) {
        const int same = memcmp(&t[j], &R.t[j], sizeof(double)) == 0 && lane_equal(q, R.q, j) && lane_equal(p, R.p, j)
                         && status[j] == R.status[j];
        if (!same) failures++;
        CHECK_MSG(same, "%s %s kahan %d: trajectory %d: batch t %.17g q %.17g %.17g status %d, scalar t %.17g q %.17g %.17g status %d",
                  S->name, mech ? "mechanical" : "general", kahan, j, t[j], q[j], q[W + j], status[j], R.t[j],
                  R.q[2 * j], R.q[2 * j + 1], R.status[j]);
    }
    int any_fail = 0, expected = VIGEN_SUCCESS;
    for (int j = 0; j < W; j++) {
        any_fail |= R.status[j] != VIGEN_SUCCESS;
        if (expected == VIGEN_SUCCESS) expected = R.status[j];
    }
    CHECK_MSG(rc == expected || (any_fail && rc != VIGEN_SUCCESS && nan_lane >= 0), "%s: batch returned %d", S->name, rc);
    if (S->evals_per_step == 0 && nan_lane < 0) {
        /* the premise of the per-trajectory masks: the trajectories of the
         * block need different numbers of sweeps (the scalar stepper's) */
        unsigned long lo = R.iters[0], hi = R.iters[0];
        for (int j = 1; j < W; j++) {
            lo = R.iters[j] < lo ? R.iters[j] : lo;
            hi = R.iters[j] > hi ? R.iters[j] : hi;
        }
        CHECK_MSG(lo < hi, "%s: every trajectory took %lu sweeps", S->name, lo);
    }
    if (kahan & 12) {
        /* the premise of the failure tests: some trajectories end with the
         * solver's failure, others go on to the end */
        int failed = 0, through = 0;
        for (int j = 0; j < W; j++) {
            failed += R.status[j] == ((kahan & 4) ? VIGEN_EMAXITER : VIGEN_ENOCONV);
            through += R.status[j] == VIGEN_SUCCESS;
        }
        CHECK_MSG(failed > 0 && through > 0, "%s kahan %d: %d trajectories failed, %d went through", S->name, kahan,
                  failed, through);
    }
    if (S->evals_per_step == 0 && nan_lane < 0)
        /* the implicit batch counts per trajectory what the scalar stepper counts */
        CHECK_MSG(st.steps == R.sum.steps && st.failed_steps == R.sum.failed_steps && st.iterations == R.sum.iterations
                      && st.dHdq_evals == R.sum.dHdq_evals && st.dHdp_evals == 0,
                  "%s: batch counts steps %lu failed %lu sweeps %lu forces %lu, scalar %lu %lu %lu %lu", S->name, st.steps,
                  st.failed_steps, st.iterations, st.dHdq_evals, R.sum.steps, R.sum.failed_steps, R.sum.iterations,
                  R.sum.dHdq_evals);
    if (fc == NULL && nan_lane < 0 && moved < 0 && failures == 0 && !(kahan & 12)) {
        /* the physics, and the force count per trajectory */
        double t0[W], q0[2 * W], p0[2 * W];
        initial_aos(t0, q0, p0);
        /* Verlet order 2, McLachlan-Atela order 3, Yoshida order 4, Gauss-2
         * order 4 (energy error at round-off on Kepler) */
        const double tol = S->evals_per_step == 1 ? 0.3 : !S->fsal && S->evals_per_step ? 0.05 : S->evals_per_step == 3 ? 2e-3 : 3e-5;
        const double etol = S->evals_per_step == 1 ? 1e-3 : !S->fsal && S->evals_per_step ? 1e-3 : S->evals_per_step == 3 ? 1e-4 : 1e-9;
        for (int j = 0; j < W; j++) {
            const double dist = hypot(q[j] - q0[2 * j], q[W + j]);
            const double H = 0.5 * (p[j] * p[j] + p[W + j] * p[W + j]) - 1 / hypot(q[j], q[W + j]);
            CHECK_MSG(dist < tol && fabs(H + 0.5) < etol && fabs(t[j] - t0[j] - 2 * PI) < 1e-12,
                      "%s orbit %d: distance %.3g energy %.17g", S->name, j, dist, H);
        }
        CHECK_MSG(S->evals_per_step == 0 || (st.dHdq_evals == (unsigned long)W * ((unsigned long)S->fsal + (unsigned long)S->evals_per_step * NSTEPS)
                      && st.steps == (unsigned long)W * NSTEPS && st.dHdp_evals == (mech ? 0 : (unsigned long)W * (unsigned long)S->evals_per_step * NSTEPS)),
                  "%s: %lu force evaluations, %lu steps", S->name, st.dHdq_evals, st.steps);
    }
}

static void check_args(const stepper *S)
{
    double t[W], q[2 * W], p[2 * W], qa[2 * W], pa[2 * W];
    int status[W];
    initial_aos(t, qa, pa);
    to_soa(q, qa);
    to_soa(p, pa);
    for (int j = 0; j < W; j++) status[j] = VIGEN_SUCCESS;
    vigen_mechanical_batch mb = { .dim = 2, .force = kep_force_b };
    void *b = S->balloc_mech(&mb, W, NULL);
    CHECK(S->bstep(b, t, q, p, NAN, status) == VIGEN_EINVAL);
    CHECK(S->bstep(b, t, NULL, p, 0.01, status) == VIGEN_EINVAL);
    CHECK(lane_equal(q, qa, 0) && t[1] == 0.25 && status[0] == VIGEN_SUCCESS);
    t[3] = INFINITY;
    CHECK(S->bstep(b, t, q, p, 0.01, status) == VIGEN_EINVAL);
    CHECK(status[3] == VIGEN_EINVAL && t[3] == INFINITY && lane_equal(q, qa, 3));
    CHECK(status[4] == VIGEN_SUCCESS && t[4] == 1.0 + 0.01 && !lane_equal(q, qa, 4));
    S->bfree(b);
    vigen_mechanical_batch bad = { .dim = 2 };
    CHECK(S->balloc_mech(&bad, W, NULL) == NULL);
    CHECK(S->balloc_mech(&mb, 0, NULL) == NULL);
}

/* Unequal masses (M^-1 = diag(1, 0.75)): the batch multiplies by M^-1 in
 * every drift, the scalar stepper too (its copy for M = I is not taken), and
 * every trajectory still has the scalar bits. */
static void check_masses(const stepper *S, int kahan)
{
    static const double im[2] = { 1, 0.75 };
    const double h = 2 * PI / NSTEPS;
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.kahan = kahan;
    double t[W], q[2 * W], p[2 * W], ta[W], qa[2 * W], pa[2 * W];
    int status[W];
    initial_aos(ta, qa, pa);
    memcpy(t, ta, sizeof t);
    to_soa(q, qa);
    to_soa(p, pa);
    vigen_mechanical_batch mb = { .dim = 2, .force = kep_force_b, .inv_mass = im };
    void *b = S->balloc_mech(&mb, W, &opt);
    CHECK(b != NULL);
    if (b == NULL) return;
    for (int j = 0; j < W; j++) status[j] = VIGEN_SUCCESS;
    for (int k = 0; k < NSTEPS; k++) S->bstep(b, t, q, p, h, status);
    S->bfree(b);
    for (int j = 0; j < W; j++) {
        vigen_mechanical m = { .dim = 2, .force = kep_force, .inv_mass = im };
        void *w = S->alloc_mech(&m, &opt);
        int st = VIGEN_SUCCESS;
        for (int k = 0; k < NSTEPS && st == VIGEN_SUCCESS; k++) st = S->type->step(w, ta + j, qa + 2 * j, pa + 2 * j, h);
        S->type->free(w);
        CHECK_MSG(st == status[j] && memcmp(&t[j], &ta[j], sizeof(double)) == 0 && lane_equal(q, qa, j) &&
                      lane_equal(p, pa, j), "%s, unequal masses, kahan %d: trajectory %d: batch q %.17g %.17g, "
                  "scalar q %.17g %.17g", S->name, kahan, j, q[j], q[W + j], qa[2 * j], qa[2 * j + 1]);
    }
}

/* Blocks of other widths (1 and 3: no full vector; 8 and 64: whole
 * vectors, no remainder), each trajectory against the scalar stepper, bit
 * for bit, with the force of the block vectorisable (no per-trajectory
 * call). */
static void kep_force_plain(const double *t, const double *q, double *f, size_t nw, void *ctx)
{
    (void)t; (void)ctx;
    for (size_t j = 0; j < nw; j++) {
        const double r2 = q[j] * q[j] + q[nw + j] * q[nw + j], r3 = r2 * sqrt(r2);
        f[j] = -q[j] / r3;
        f[nw + j] = -q[nw + j] / r3;
    }
}
static void check_widths(const stepper *S)
{
    static const size_t widths[] = { 1, 3, 8, 64 };
    const double h = 2 * PI / 100;
    for (size_t i = 0; i < sizeof widths / sizeof widths[0]; i++) {
        const size_t nw = widths[i];
        double *t = calloc(nw, sizeof *t), *q = calloc(2 * nw, sizeof *q), *p = calloc(2 * nw, sizeof *p);
        int *status = calloc(nw, sizeof *status);
        vigen_mechanical_batch mb = { .dim = 2, .force = kep_force_plain };
        void *b = S->balloc_mech(&mb, nw, NULL);
        CHECK(b && t && q && p && status);
        if (!(b && t && q && p && status)) return;
        for (size_t j = 0; j < nw; j++) {
            const double e = 0.7 * (double)j / (double)nw;
            q[j] = 1 - e;
            p[nw + j] = sqrt((1 + e) / (1 - e));
        }
        for (int k = 0; k < 150; k++) S->bstep(b, t, q, p, h, status);
        S->bfree(b);
        int same = 1;
        for (size_t j = 0; j < nw; j++) {
            const double e = 0.7 * (double)j / (double)nw;
            double ts = 0, qs[2] = { 1 - e, 0 }, ps[2] = { 0, sqrt((1 + e) / (1 - e)) };
            void *w = S->alloc_mech(&(vigen_mechanical){ .dim = 2, .force = kep_force }, NULL);
            int st = VIGEN_SUCCESS;
            for (int k = 0; k < 150 && st == VIGEN_SUCCESS; k++) st = S->type->step(w, &ts, qs, ps, h);
            S->type->free(w);
            same &= st == status[j] && memcmp(&ts, &t[j], sizeof ts) == 0 && memcmp(&qs[0], &q[j], sizeof(double)) == 0
                    && memcmp(&qs[1], &q[nw + j], sizeof(double)) == 0 && memcmp(&ps[0], &p[j], sizeof(double)) == 0
                    && memcmp(&ps[1], &p[nw + j], sizeof(double)) == 0;
        }
        CHECK_MSG(same, "%s: a block of %zu trajectories differs from the scalar stepper", S->name, nw);
        free(t);
        free(q);
        free(p);
        free(status);
    }
}

int main(void)
{
    const stepper S[5] = { STEPPER(eb_verlet, 1, 1), STEPPER(eb_yoshida, 3, 1), STEPPER(eb_gauss2, 0, 0),
                           STEPPER(eb_ma3, 3, 0), STEPPER(eb_lobatto3, 0, 1) };
    static fail_ctx fc, rough;
    for (int j = 0; j < W; j++) fc.fail_at[j] = rough.fail_at[j] = INFINITY;
    fc.fail_at[7] = 2.0;    /* trajectory 7 (t0 = 1.75): its force turns NaN after a few steps */
    fc.fail_at[30] = 8.0;   /* trajectory 30 (t0 = 7.5) */
    for (int s = 0; s < 4; s += s == 1 ? 2 : 1)
        for (int mech = 0; mech < 2; mech++)
            for (int kahan = 0; kahan < 2; kahan++) {
                compare(&S[s], S[s].type, mech, kahan, NULL, -1, -1, 0);
                compare(&S[s], S[s].type, mech, kahan, &fc, 5, 11, 150);
            }
    /* Gauss s = 2 (implicit): mechanical problems, fixed point, with and
     * without extrapolated starting forces */
    for (int kahan = 0; kahan < 4; kahan++) {
        compare(&S[2], S[2].type, 1, kahan, NULL, -1, -1, 0);
        compare(&S[2], S[2].type, 1, kahan, &fc, 5, 11, 150);
        rough.rough = 1;
        compare(&S[2], S[2].type, 1, kahan, &rough, -1, -1, 0);
    }
    /* trajectories that run out of sweeps (VIGEN_EMAXITER) or stall above
     * the tolerance (VIGEN_ENOCONV) while the others go on */
    compare(&S[2], S[2].type, 1, 1 | 2 | 4, NULL, -1, -1, 0);
    rough.rough = 2;
    compare(&S[2], S[2].type, 1, 1 | 8, &rough, -1, -1, 0);
    /* Lobatto IIIA-IIIB s = 3 (implicit, first same as last: the last
     * stage's force taken once at the new q and reused as the next step's
     * first, per trajectory): the scalar bits and counts, with and without
     * extrapolation, a force turning NaN midway, stalls and caps */
    for (int kahan = 0; kahan < 4; kahan++) {
        compare(&S[4], S[4].type, 1, kahan, NULL, -1, -1, 0);
        compare(&S[4], S[4].type, 1, kahan, &fc, 5, 11, 150);
    }
    compare(&S[4], S[4].type, 1, 1 | 2 | 4, NULL, -1, -1, 0);
    compare(&S[4], S[4].type, 1, 1 | 8, &rough, -1, -1, 0);
    check_widths(&S[4]);
    for (int s = 0; s < 3; s++) check_widths(&S[s]);
    /* the scalar stepper of the file emitted without --batch gives the same bits */
    compare(&S[0], &ens_verlet_type, 0, 1, NULL, -1, -1, 0);
    for (int s = 0; s < 4; s++) check_args(&S[s]);
    for (int s = 0; s < 4; s += s == 1 ? 2 : 1)
        for (int kahan = 0; kahan < 2; kahan++) check_masses(&S[s], kahan);
    /* the implicit batch: mechanical problems by fixed point only */
    vigen_hamiltonian_batch gb = { .dim = 2, .dHdq = kep_dHdq_b, .dHdp = kep_dHdp_b };
    vigen_mechanical_batch mb = { .dim = 2, .force = kep_force_b };
    vigen_solver_options newton;
    vigen_solver_options_default(&newton);
    newton.solver = VIGEN_SOLVER_NEWTON;
    CHECK(eb_gauss2_batch_alloc(&gb, W, NULL) == NULL && eb_gauss2_batch_alloc_mechanical(&mb, W, &newton) == NULL);

    /* --batch is for double only */
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau tab;
    int loaded = 0;
    char *h = NULL, *c = NULL, *id = NULL;
    vigen_emit_options o = { .name = "g", .real = VIGEN_REAL_LONG_DOUBLE, .batch = 1 };
    int rc = vigen_emit_load_render(&tab, &loaded, VIGEN_SOURCE_DIR "/tableaux/published/gauss_2.lua", &o, &h, &c, &id, &err);
    CHECK(rc == VIGEN_E_USAGE && err.message && strstr(err.message, "--batch is for the prk variant in double precision only"));
    if (loaded) vigen_tableau_clear(&tab);
    vigen_error_clear(&err);
    free(h); free(c); free(id);
    TEST_MAIN_END();
}
