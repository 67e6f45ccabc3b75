/* ensemble_bench.c — throughput of Kepler ensembles (N orbits, e = 0.7 i/N,
 * h = 2 pi/200, STEPS steps each) with an emitted explicit stepper
 * (Stormer-Verlet, Yoshida's triple jump, or Gauss s = 2 with its fixed
 * point; mechanical problem), side by side in one run:
 *   - scalar: a fresh workspace per orbit, NAME_step looped, one core;
 *   - vigen_integrate_ensemble with 1 and 2 OpenMP threads (the same scalar
 *     stepper per orbit);
 *   - batch: NAME_step_batch over blocks of W orbits, the batched force
 *     through the callback and called directly (NAME_DIRECT_FORCE_BATCH),
 *     on one core and over 2 OpenMP threads (blocks shared out statically).
 * Every configuration's final states are compared with the scalar run's:
 * they must be the same bits (else the row says so).  Prints one Markdown row
 * per configuration: ns per orbit-step (fastest of REPEAT runs), million
 * orbit-steps per second, ratio to the scalar loop.  Built and run by
 * bench/ensemble_run.sh.  A measurement, not a test.
 *   ensemble_bench [N [STEPS [W [REPEAT]]]]   defaults 100000 200 256 3 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <vigen/ensemble.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* f = -dV/dq for Kepler, one orbit and a block of W (component-major) */
static void kep_force(double t, const double *q, double *f, void *c)
{
    (void)t; (void)c;
    const double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    f[0] = -q[0] / r3;
    f[1] = -q[1] / r3;
}
static inline void kep_force_b(const double *t, const double *q, double *f, size_t W, void *c)
{
    (void)t; (void)c;
    const double *restrict x = q, *restrict y = q + W;
    double *restrict fx = f, *restrict fy = f + W;
    for (size_t j = 0; j < W; j++) {
        const double r2 = x[j] * x[j] + y[j] * y[j], r3 = r2 * sqrt(r2);
        fx[j] = -x[j] / r3;
        fy[j] = -y[j] / r3;
    }
}
/* the callback: the same loop, compiled for the machine's vector units as
 * the batched steps are (the force of a block is the user's code) */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx512f", "avx2", "default"), optimize("fp-contract=off")))
#endif
static void kep_force_cb(const double *t, const double *q, double *f, size_t W, void *c)
{
    kep_force_b(t, q, f, W, c);
}

#include "kepler_verlet_avx512.h"
#include "ens_sv.h"
#include "ens_y4.h"
#include "ens_g2.h"
/* the same steppers once more with the batched force called directly */
#define ENS_SVD_DIRECT_FORCE_BATCH kep_force_b
#include "ens_svd.c"
#define ENS_Y4D_DIRECT_FORCE_BATCH kep_force_b
#include "ens_y4d.c"
#define ENS_G2D_DIRECT_FORCE_BATCH kep_force_b
#include "ens_g2d.c"

static const double pi = 3.14159265358979323846;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* orbit i: q = (1 - e, 0), p = (0, sqrt((1 + e)/(1 - e))); aos: q[2 i + k] */
static void initial(size_t n, double *t, double *q, double *p)
{
    for (size_t i = 0; i < n; i++) {
        const double e = 0.7 * (double)i / (double)n;
        t[i] = 0;
        q[2 * i] = 1 - e;
        q[2 * i + 1] = 0;
        p[2 * i] = 0;
        p[2 * i + 1] = sqrt((1 + e) / (1 - e));
    }
}

typedef struct {
    const char *name;
    const vigen_stepper_type *type;
    void *(*alloc_mech)(const vigen_mechanical *, const vigen_solver_options *);
    void *(*balloc)(const vigen_mechanical_batch *, size_t, const vigen_solver_options *);
    int (*bstep)(void *, double *, double *, double *, double, int *);
    void (*bfree)(void *);
    void *(*balloc_d)(const vigen_mechanical_batch *, size_t, const vigen_solver_options *);
    int (*bstep_d)(void *, double *, double *, double *, double, int *);
    void (*bfree_d)(void *);
} stepper;

#define STEPPER(N, D)                                                                                        \
    { #N, &N##_type, (void *(*)(const vigen_mechanical *, const vigen_solver_options *))N##_alloc_mechanical, \
      (void *(*)(const vigen_mechanical_batch *, size_t, const vigen_solver_options *))N##_batch_alloc_mechanical, \
      (int (*)(void *, double *, double *, double *, double, int *))N##_step_batch, (void (*)(void *))N##_batch_free, \
      (void *(*)(const vigen_mechanical_batch *, size_t, const vigen_solver_options *))D##_batch_alloc_mechanical, \
      (int (*)(void *, double *, double *, double *, double, int *))D##_step_batch, (void (*)(void *))D##_batch_free }

typedef struct {
    size_t n, steps, W;
    double h;
    double *t, *q, *p;        /* the run's state, orbit-major */
    double *ref_q, *ref_p;    /* the scalar loop's final state */
    int *status;
} run;

static void scalar_loop(const stepper *S, run *R)
{
    vigen_mechanical sys = { .dim = 2, .force = kep_force };
    void *w = S->alloc_mech(&sys, NULL);
    for (size_t i = 0; i < R->n; i++) {
        S->type->reset(w);
        for (size_t k = 0; k < R->steps; k++) S->type->step(w, R->t + i, R->q + 2 * i, R->p + 2 * i, R->h);
    }
    S->type->free(w);
}

static const stepper *cur;
static void *alloc_cur(void *sys) { return cur->alloc_mech(sys, NULL); }

static void ensemble(const stepper *S, run *R, int threads)
{
    vigen_mechanical sys = { .dim = 2, .force = kep_force };
    cur = S;
    vigen_ensemble e = { .type = S->type, .alloc = alloc_cur, .alloc_ctx = &sys, .dim = 2, .threads = threads };
    vigen_integrate_ensemble(&e, R->n, R->t, R->q, R->p, R->h, (unsigned long)R->steps, R->status, NULL);
}

/* blocks of W orbits (the last one shorter), each copied into the
 * structure-of-arrays layout, stepped, and copied back */
static void batch(const stepper *S, run *R, int direct, int hand, int threads)
{
    const size_t nb = (R->n + R->W - 1) / R->W;
    vigen_mechanical_batch sys = { .dim = 2, .force = kep_force_cb };
    (void)threads;
    (void)hand;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
        double *t = malloc(R->W * sizeof *t), *q = malloc(2 * R->W * sizeof *q), *p = malloc(2 * R->W * sizeof *p);
        int *st = malloc(R->W * sizeof *st);
        void *b = NULL, *b_last = NULL;
        size_t last = R->n - (nb - 1) * R->W;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (size_t k = 0; k < nb; k++) {
            const size_t lo = k * R->W, W = k + 1 < nb ? R->W : last;
            void **slot = W == R->W ? &b : &b_last;
            if (*slot == NULL) *slot = direct ? S->balloc_d(&sys, W, NULL) : S->balloc(&sys, W, NULL);
            for (size_t j = 0; j < W; j++) {
                t[j] = R->t[lo + j];
                q[j] = R->q[2 * (lo + j)];
                q[W + j] = R->q[2 * (lo + j) + 1];
                p[j] = R->p[2 * (lo + j)];
                p[W + j] = R->p[2 * (lo + j) + 1];
                st[j] = VIGEN_SUCCESS;
            }
#if KV512_AVAILABLE
            if (hand && W % 8 == 0) kv512_run(W, t, q, p, R->h, R->steps);
            else
#endif
            for (size_t s = 0; s < R->steps; s++) (direct ? S->bstep_d : S->bstep)(*slot, t, q, p, R->h, st);
            for (size_t j = 0; j < W; j++) {
                R->t[lo + j] = t[j];
                R->q[2 * (lo + j)] = q[j];
                R->q[2 * (lo + j) + 1] = q[W + j];
                R->p[2 * (lo + j)] = p[j];
                R->p[2 * (lo + j) + 1] = p[W + j];
            }
        }
        (direct ? S->bfree_d : S->bfree)(b);
        (direct ? S->bfree_d : S->bfree)(b_last);
        free(t);
        free(q);
        free(p);
        free(st);
    }
}

enum { SCALAR, ENS, BATCH, BATCH_DIRECT, HAND };

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* fastest of `repeat` runs, in ns per orbit-step, and the median in *med;
 * *same: the final state has the scalar loop's bits */
static double measure(const stepper *S, run *R, int kind, int threads, int repeat, int *same, double *med)
{
    double best = INFINITY, dts[64];
    if (repeat > 64) repeat = 64;
    for (int r = 0; r < repeat; r++) {
        initial(R->n, R->t, R->q, R->p);
        const double t0 = now();
        switch (kind) {
        case SCALAR: scalar_loop(S, R); break;
        case ENS: ensemble(S, R, threads); break;
        default: batch(S, R, kind == BATCH_DIRECT, kind == HAND, threads); break;
        }
        const double dt = now() - t0;
        dts[r] = dt;
        if (dt < best) best = dt;
    }
    qsort(dts, (size_t)repeat, sizeof dts[0], cmp_double);
    const double m = repeat % 2 ? dts[repeat / 2] : 0.5 * (dts[repeat / 2 - 1] + dts[repeat / 2]);
    *med = m * 1e9 / ((double)R->n * (double)R->steps);
    if (kind == SCALAR) {
        memcpy(R->ref_q, R->q, 2 * R->n * sizeof(double));
        memcpy(R->ref_p, R->p, 2 * R->n * sizeof(double));
    }
    *same = memcmp(R->ref_q, R->q, 2 * R->n * sizeof(double)) == 0
            && memcmp(R->ref_p, R->p, 2 * R->n * sizeof(double)) == 0;
    return best * 1e9 / ((double)R->n * (double)R->steps);
}

int main(int argc, char **argv)
{
    run R;
    R.n = argc > 1 ? strtoul(argv[1], NULL, 10) : 100000;
    R.steps = argc > 2 ? strtoul(argv[2], NULL, 10) : 200;
    R.W = argc > 3 ? strtoul(argv[3], NULL, 10) : 256;
    const int repeat = argc > 4 ? atoi(argv[4]) : 3;
    int only_s = -1, only_r = -1;   /* ONLY = "S:R": that configuration alone, no reference run */
    if (argc > 5 && sscanf(argv[5], "%d:%d", &only_s, &only_r) != 2) only_s = 99;
    if (R.n == 0 || R.steps == 0 || R.W == 0 || repeat <= 0 || only_s > 2) {
        fprintf(stderr, "usage: ensemble_bench [N [STEPS [W [REPEAT [S:R]]]]] (positive integers; S stepper 0-2, "
                        "R row)\n");
        return 2;
    }
    R.h = 2 * pi / 200;
    R.t = malloc(R.n * sizeof(double));
    R.q = malloc(2 * R.n * sizeof(double));
    R.p = malloc(2 * R.n * sizeof(double));
    R.ref_q = malloc(2 * R.n * sizeof(double));
    R.ref_p = malloc(2 * R.n * sizeof(double));
    R.status = malloc(R.n * sizeof(int));
    if (!R.t || !R.q || !R.p || !R.ref_q || !R.ref_p || !R.status) return 1;
    const stepper S[3] = { STEPPER(ens_sv, ens_svd), STEPPER(ens_y4, ens_y4d), STEPPER(ens_g2, ens_g2d) };
    int hand = 0;
#if KV512_AVAILABLE
    hand = __builtin_cpu_supports("avx512f") && R.W % 8 == 0;
#endif
    printf("Kepler ensemble: %zu orbits, %zu steps each (h = 2 pi/200), batch blocks of %zu, best and median of %d; "
           "OpenMP threads available: %d; AVX-512: %s\n\n", R.n, R.steps, R.W, repeat, vigen_ensemble_max_threads(),
           hand ? "yes" : "no (or W not a multiple of 8): no hand-written row");
    printf("| stepper | configuration | cores | ns per orbit-step (best) | ns (median) | vs scalar loop (best) | "
           "vs scalar loop (median) | same bits |\n");
    printf("|---|---|---|---|---|---|---|---|\n");
    for (int s = 0; s < 3; s++) {
        struct { const char *what; int kind, threads; } rows[] = {
            { "scalar loop (NAME_step)", SCALAR, 1 },
            { "vigen_integrate_ensemble", ENS, 1 },
            { "vigen_integrate_ensemble", ENS, 2 },
            { "batch, force by callback", BATCH, 1 },
            { "batch, force by callback", BATCH, 2 },
            { "batch, force direct", BATCH_DIRECT, 1 },
            { "batch, force direct", BATCH_DIRECT, 2 },
            { "hand-written AVX-512 intrinsics (limit)", HAND, 1 },
            { "hand-written AVX-512 intrinsics (limit)", HAND, 2 },
        };
        size_t nrows = sizeof rows / sizeof rows[0] - (s == 0 && hand ? 0 : 2);
        double base = 0, base_med = 0;
        for (size_t r = 0; r < nrows; r++) {
            if (only_s >= 0 && (s != only_s || (int)r != only_r)) continue;
            int same;
            double med;
            const double ns = measure(&S[s], &R, rows[r].kind, rows[r].threads, repeat, &same, &med);
            if (r == 0) {
                base = ns;
                base_med = med;
            }
            if (only_s >= 0) {
                printf("| %s | %s | %d | %.2f | %.2f | | | |\n", S[s].type->name, rows[r].what, rows[r].threads, ns,
                       med);
                continue;
            }
            printf("| %s | %s | %d | %.2f | %.2f | %.2f | %.2f | %s |\n", S[s].type->name, rows[r].what,
                   rows[r].threads, ns, med, base / ns, base_med / med, same ? "yes" : "NO");
            fflush(stdout);
        }
    }
    free(R.t);
    free(R.q);
    free(R.p);
    free(R.ref_q);
    free(R.ref_p);
    free(R.status);
    return 0;
}
