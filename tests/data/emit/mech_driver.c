/* mech_driver.c — runs one emitted stepper through both of its problem
 * types, the general Hamiltonian (NAME_alloc) and the mechanical problem
 * (NAME_alloc_mechanical), on the same two problems, and prints key=value
 * lines for tests/unit/test_emit_mechanical.c.  Built with
 *   -DSTEPPER_HEADER='"NAME.h"' -DSTEPPER_TYPE=NAME_type -DSTEPPER_NAME=NAME_
 * (and -DREAL_LD for a stepper emitted for long double) and the runtime.
 *
 * Problems, H = 1/2 p^T M^-1 p + V(t, q):
 *   kepler: V = -1/|q|, q in R^2, M = I, eccentricity 0.6 from the
 *           pericentre: q = (0.4, 0), p = (0, sqrt(1.6/0.4)) (GNI I.2.3);
 *   fput:   a chain of 8 moving masses with fixed ends, spring potential
 *           phi(d) = d^2/2 + alpha d^3/3 (alpha = 1/4) on d_j = q_{j+1} - q_j,
 *           q_0 = q_9 = 0, a driving force 0.1 cos(t) on the first mass
 *           (the stage times matter) and masses m_j = 1 + j/10
 *           (inv_mass given); q_j = sin(pi j / 9) / 2, p = 0.
 * The general problem is the same H written with dH/dq = -f and
 * dH/dp = M^-1 p, separable set.
 *
 *   mech_driver compare PROBLEM SOLVER KAHAN N H [START_FORCE]
 *       N steps of size H from the start with each problem type (SOLVER 0
 *       fixed point, 1 Newton; KAHAN compensated updates; START_FORCE the
 *       solver option start_force, default 0): maxdiff = the
 *       largest |(q, p)_mech - (q, p)_general| over the steps, relative to
 *       the largest |component|; bitequal = 1 when every state was equal
 *       bit for bit; status_g, status_m; the statistics of the mechanical
 *       run (m_dHdq, m_dHdp, m_iter, m_fsal) and of the general one (g_dHdq,
 *       g_dHdp, g_iter); energy_drift = max |H - H0| of the mechanical run.
 *   mech_driver verlet N H
 *       the mechanical run (no compensation) against the Stormer-Verlet
 *       formula written here (kick, drift, kick) on kepler: verlet_maxdiff.
 *   mech_driver nan SOLVER
 *       kepler with a force that turns NaN on its 7th call: nan_status (the
 *       failing step's status), nan_enonfinite = 1 when it is
 *       VIGEN_ENONFINITE, nan_unchanged = 1 when t, q and p were left
 *       bit for bit as they were, nan_steps (successful steps before).
 *   mech_driver final PROBLEM SOLVER N H
 *       the final state of both runs in hexadecimal (final_g_<k>,
 *       final_m_<k>, as text) to compare two builds.
 *   mech_driver dim
 *       stepper_dim = NAME_dim(); refused_g, refused_m = 1 when alloc with
 *       a dimension other than a nonzero NAME_dim() returned NULL;
 *       accepted = 1 when alloc with dimension NAME_dim() (or 2) succeeded.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include STEPPER_HEADER

#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define FN(x) CAT(STEPPER_NAME, x)
#ifdef REAL_LD
typedef long double real;
typedef vigen_hamiltonian_ld ham;
typedef vigen_mechanical_ld mechanical;
#define RSQRT sqrtl
#define RCOS cosl
#else
typedef double real;
typedef vigen_hamiltonian ham;
typedef vigen_mechanical mechanical;
#define RSQRT sqrt
#define RCOS cos
#endif

enum { KEPLER, FPUT, NF = 8 };
static int problem;
static real inv_mass[NF];
static long force_calls, nan_after = -1;

static void force(real t, const real *q, real *f, void *ctx)
{
    (void)ctx;
    force_calls++;
    if (problem == KEPLER) {
        real r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * RSQRT(r2);
        f[0] = -q[0] / r3;
        f[1] = -q[1] / r3;
    } else {
        const real a = 0.25;
        for (int j = 0; j < NF; j++) {
            real left = j > 0 ? q[j] - q[j - 1] : q[j];            /* d_{j-1} */
            real right = (j < NF - 1 ? q[j + 1] : 0) - q[j];         /* d_j */
            f[j] = (right + a * right * right) - (left + a * left * left);
        }
        f[0] += (real)0.1 * RCOS(t);
    }
    if (nan_after >= 0 && force_calls > nan_after) f[0] = NAN;
}

static real potential(real t, const real *q, void *ctx)
{
    (void)ctx;
    if (problem == KEPLER) return -1 / RSQRT(q[0] * q[0] + q[1] * q[1]);
    real v = 0;
    for (int j = 0; j <= NF; j++) {
        real d = (j < NF ? q[j] : 0) - (j > 0 ? q[j - 1] : 0);
        v += d * d / 2 + (real)0.25 * d * d * d / 3;
    }
    return v - (real)0.1 * RCOS(t) * q[0];
}

static void dHdq(real t, const real *q, const real *p, real *out, void *ctx)
{
    (void)p;
    size_t n = problem == KEPLER ? 2 : NF;
    force(t, q, out, ctx);
    for (size_t k = 0; k < n; k++) out[k] = -out[k];
}

static void dHdp(real t, const real *q, const real *p, real *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    size_t n = problem == KEPLER ? 2 : NF;
    for (size_t k = 0; k < n; k++) out[k] = problem == KEPLER ? p[k] : inv_mass[k] * p[k];
}

static size_t start(real *q, real *p)
{
    if (problem == KEPLER) {
        q[0] = 0.4; q[1] = 0; p[0] = 0; p[1] = RSQRT((real)1.6 / (real)0.4);
        return 2;
    }
    for (int j = 0; j < NF; j++) {
        q[j] = (real)(sin(3.14159265358979323846 * (j + 1) / (NF + 1)) / 2);
        p[j] = 0;
        inv_mass[j] = 1 / (1 + (real)(j + 1) / 10);
    }
    return NF;
}

static real energy(real t, const real *q, const real *p, size_t n)
{
    real e = potential(t, q, NULL);
    for (size_t k = 0; k < n; k++) e += p[k] * p[k] * (problem == KEPLER ? 1 : inv_mass[k]) / 2;
    return e;
}

static int start_force;

static FN(workspace) *alloc_pair(int mech, size_t n, int solver, int kahan)
{
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.solver = solver;
    opt.kahan = kahan;
    opt.start_force = start_force;
    if (mech) {
        mechanical m = { n, force, potential, NULL, problem == KEPLER ? NULL : inv_mass };
        return FN(alloc_mechanical)(&m, &opt);
    }
    ham g = { n, dHdq, dHdp, NULL, NULL, 1, NULL };
    return FN(alloc)(&g, &opt);
}

static int set_problem(const char *name)
{
    if (strcmp(name, "kepler") == 0) problem = KEPLER;
    else if (strcmp(name, "fput") == 0) problem = FPUT;
    else return 0;
    return 1;
}

static int compare(int argc, char **argv)
{
    if (argc < 7 || !set_problem(argv[2])) return 2;
    int solver = atoi(argv[3]), kahan = atoi(argv[4]);
    long N = atol(argv[5]);
    real h = (real)strtod(argv[6], NULL);
    start_force = argc > 7 ? atoi(argv[7]) : 0;
    real qg[NF], pg[NF], qm[NF], pm[NF], tg = 0, tm = 0;
    size_t n = start(qg, pg);
    start(qm, pm);
    FN(workspace) *wg = alloc_pair(0, n, solver, kahan), *wm = alloc_pair(1, n, solver, kahan);
    if (!wg || !wm) { printf("alloc_failed=1\n"); return 1; }
    real e0 = energy(0, qm, pm, n), drift = 0, diff = 0, scale = 0;
    int stg = 0, stm = 0, bitequal = 1;
    long m_calls = 0;   /* forces the mechanical stepper called, counted here */
    for (long k = 0; k < N && stg == 0 && stm == 0; k++) {
        stg = FN(step)(wg, &tg, qg, pg, h);
        const long before = force_calls;
        stm = FN(step)(wm, &tm, qm, pm, h);
        m_calls += force_calls - before;
        for (size_t j = 0; j < n; j++) {
            real d1 = fabsl(qg[j] - qm[j]), d2 = fabsl(pg[j] - pm[j]);
            diff = d1 > diff ? d1 : diff;
            diff = d2 > diff ? d2 : diff;
            scale = fabsl(qg[j]) > scale ? fabsl(qg[j]) : scale;
            scale = fabsl(pg[j]) > scale ? fabsl(pg[j]) : scale;
            if (qg[j] != qm[j] || pg[j] != pm[j]) bitequal = 0;   /* == on values: long double has padding bytes */
        }
        if (tg != tm) bitequal = 0;
        real e = fabsl(energy(tm, qm, pm, n) - e0);
        drift = e > drift ? e : drift;
    }
    const vigen_stats *sg = FN(stats)(wg), *sm = FN(stats)(wm);
    printf("status_g=%d\nstatus_m=%d\nmaxdiff=%.6Le\nbitequal=%d\nenergy_drift=%.6Le\n", stg, stm,
           (long double)(diff / scale), bitequal, (long double)drift);
    printf("steps=%lu\nm_dHdq=%lu\nm_dHdp=%lu\nm_iter=%lu\nm_fsal=%lu\n", sm->steps, sm->dHdq_evals, sm->dHdp_evals,
           sm->iterations, sm->fsal_reuses);
    printf("g_dHdq=%lu\ng_dHdp=%lu\ng_iter=%lu\nm_calls=%ld\n", sg->dHdq_evals, sg->dHdp_evals, sg->iterations,
           m_calls);
    FN(free)(wg);
    FN(free)(wm);
    return 0;
}

static int verlet(int argc, char **argv)
{
    if (argc < 4) return 2;
    problem = KEPLER;
    long N = atol(argv[2]);
    real h = (real)strtod(argv[3], NULL);
    real q[2], p[2], qv[2], pv[2], t = 0, f[2], diff = 0;
    start(q, p);
    start(qv, pv);
    FN(workspace) *w = alloc_pair(1, 2, 0, 0);
    if (!w) { printf("alloc_failed=1\n"); return 1; }
    int st = 0;
    for (long k = 0; k < N && st == 0; k++) {
        st = FN(step)(w, &t, q, p, h);
        /* Stormer-Verlet: p_{1/2} = p + h/2 f(q), q1 = q + h p_{1/2}, p1 = p_{1/2} + h/2 f(q1) */
        force(0, qv, f, NULL);
        for (int j = 0; j < 2; j++) pv[j] += h / 2 * f[j];
        for (int j = 0; j < 2; j++) qv[j] += h * pv[j];
        force(0, qv, f, NULL);
        for (int j = 0; j < 2; j++) pv[j] += h / 2 * f[j];
        for (int j = 0; j < 2; j++) {
            real d1 = fabsl(q[j] - qv[j]), d2 = fabsl(p[j] - pv[j]);
            diff = d1 > diff ? d1 : diff;
            diff = d2 > diff ? d2 : diff;
        }
    }
    printf("verlet_status=%d\nverlet_maxdiff=%.6Le\n", st, (long double)diff);
    FN(free)(w);
    return 0;
}

static int nan_run(int argc, char **argv)
{
    if (argc < 3) return 2;
    problem = KEPLER;
    real q[2], p[2], t = 0, h = (real)0.03;
    start(q, p);
    FN(workspace) *w = alloc_pair(1, 2, atoi(argv[2]), 1);
    if (!w) { printf("alloc_failed=1\n"); return 1; }
    force_calls = 0;
    nan_after = 6;
    int st = 0;
    long steps = 0;
    real q0[2], p0[2], t0 = 0;
    while (st == 0 && steps < 1000) {
        memcpy(q0, q, sizeof q);
        memcpy(p0, p, sizeof p);
        t0 = t;
        st = FN(step)(w, &t, q, p, h);
        if (st == 0) steps++;
    }
#ifdef REAL_LD
    /* values: the padding bytes of a long double are not part of it */
    int unchanged = q0[0] == q[0] && q0[1] == q[1] && p0[0] == p[0] && p0[1] == p[1] && t0 == t;
#else
    int unchanged = memcmp(q0, q, sizeof q) == 0 && memcmp(p0, p, sizeof p) == 0 && memcmp(&t0, &t, sizeof t) == 0;
#endif
    printf("nan_status=%d\nnan_enonfinite=%d\nnan_unchanged=%d\nnan_steps=%ld\n", st, st == VIGEN_ENONFINITE,
           unchanged, steps);
    FN(free)(w);
    return 0;
}

static int final(int argc, char **argv)
{
    if (argc < 6 || !set_problem(argv[2])) return 2;
    int solver = atoi(argv[3]);
    long N = atol(argv[4]);
    real h = (real)strtod(argv[5], NULL);
    for (int mech = 0; mech <= 1; mech++) {
        real q[NF], p[NF], t = 0;
        size_t n = start(q, p);
        FN(workspace) *w = alloc_pair(mech, n, solver, 1);
        if (!w) { printf("alloc_failed=1\n"); return 1; }
        int st = 0;
        for (long k = 0; k < N && st == 0; k++) st = FN(step)(w, &t, q, p, h);
        printf("final_status_%c=%d\n", mech ? 'm' : 'g', st);
        for (size_t j = 0; j < n; j++)
            printf("final_%c_%zu=%La %La\n", mech ? 'm' : 'g', j, (long double)q[j], (long double)p[j]);
        FN(free)(w);
    }
    return 0;
}

static int dim(void)
{
    size_t d = FN(dim)();
    problem = KEPLER;
    size_t other = d == 0 ? 2 : d + 1, good = d == 0 ? 2 : d;
    FN(workspace) *g = alloc_pair(0, other, 0, 1), *m = alloc_pair(1, other, 0, 1);
    FN(workspace) *ga = alloc_pair(0, good, 0, 1), *ma = alloc_pair(1, good, 0, 1);
    printf("stepper_dim=%zu\nrefused_g=%d\nrefused_m=%d\naccepted=%d\n", d, g == NULL, m == NULL, ga && ma);
    FN(free)(g);
    FN(free)(m);
    FN(free)(ga);
    FN(free)(ma);
    return 0;
}

int main(int argc, char **argv)
{
    (void)STEPPER_TYPE;
    if (argc < 2) return 2;
    if (strcmp(argv[1], "compare") == 0) return compare(argc, argv);
    if (strcmp(argv[1], "verlet") == 0) return verlet(argc, argv);
    if (strcmp(argv[1], "nan") == 0) return nan_run(argc, argv);
    if (strcmp(argv[1], "final") == 0) return final(argc, argv);
    if (strcmp(argv[1], "dim") == 0) return dim();
    return 2;
}
