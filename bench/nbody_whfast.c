/* nbody_whfast.c — work against precision on the outer solar system (Sun
 * + 5, the data of the runtime's outer-solar-system problem, moved to the
 * centre-of-mass frame) over 10^6 days: REBOUND's WHFast (Jacobi, its
 * drift-kick-drift kernel, with and without symplectic correctors) and
 * vigen's emitted Kepler splittings (the split variant of
 * tableaux/published/wisdom_holman, saba_2..4, saba_10_6_4,
 * wisdom_holman_corrected, and the methods with a bracket flow sabac_2,
 * sabac_3, wh_modified_kick and wh_modified_kick_corrected, stepping the
 * runtime's Jacobi flows through a vigen_split_problem of their number of
 * flows), the Wisdom-Holman kernel also with the runtime's
 * correctors applied as WHFast applies its own (C^-1 once at the start, C
 * on a copy of the state at each output).  Built and run by rebound_run.sh
 * against a REBOUND built by its own Makefile and the steppers emitted by
 * the build's vigen.  Between two outputs the emitted steppers take their
 * steps in one call of NAME_advance, which merges the last substep of a
 * step with the first of the next and applies a processed method's
 * corrector at its ends only, as WHFast does between synchronizations.
 *
 * Per row: the method, the corrector order, the step, the maximum relative
 * energy error over 100 outputs (a run of its own), and the wall time of
 * the bare run (no outputs; best and median of `repeats` runs).  With the
 * arguments "one METHOD H CORRECTOR STEPS" it makes one bare run only and
 * prints its wall time in ms (rebound_run.sh counts its instructions with
 * callgrind, and takes the best of many such runs for the rows of the
 * ratios); with "only METHOD STEPS..." it prints that method's rows at
 * those step counts alone. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <rebound.h>
#include <vigen/nbody.h>
#include <vigen/problems.h>
#include "wisdom_holman.h"
#include "wisdom_holman_corrected.h"
#include "saba_2.h"
#include "saba_3.h"
#include "saba_4.h"
#include "saba_10_6_4.h"
#include "sabac_2.h"
#include "sabac_3.h"
#include "wh_modified_kick.h"
#include "wh_modified_kick_corrected.h"

enum { N = 6, D = 3 * N, OUTPUTS = 100 };

/* The masses of Hairer, Lubich and Wanner (those of the problem); main
 * checks them against the problem's energy. */
static const double mass[N] = { 1.00000597682, 0.000954786104043, 0.000285583733151,
                                0.0000437273164546, 0.0000517759138449, 1 / 1.3e8 };
static const double G = 2.95912208286e-4;
static const double T_END = 1e6;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double x0[D], v0[D];

/* ---- REBOUND's WHFast ---------------------------------------------------- */

static struct reb_simulation *rebound_new(double h, int corrector)
{
    struct reb_simulation *r = reb_simulation_create();
    r->G = G;
    r->dt = h;
    r->exact_finish_time = 0;
    reb_simulation_set_integrator(r, "whfast");
    struct reb_integrator_whfast_state *w = r->integrator.state;
    w->safe_mode = 0;
    w->corrector = (unsigned)corrector;
    w->keep_unsynchronized = 1;
    for (int i = 0; i < N; i++) {
        struct reb_particle p = { 0 };
        p.m = mass[i];
        p.x = x0[3 * i]; p.y = x0[3 * i + 1]; p.z = x0[3 * i + 2];
        p.vx = v0[3 * i]; p.vy = v0[3 * i + 1]; p.vz = v0[3 * i + 2];
        reb_simulation_add(r, p);
    }
    return r;
}

static double rebound_error(double h, int corrector, long nsteps)
{
    struct reb_simulation *r = rebound_new(h, corrector);
    double E0 = reb_simulation_energy(r), worst = 0;
    for (int k = 0; k < OUTPUTS; k++) {
        reb_simulation_steps(r, (size_t)(nsteps / OUTPUTS));
        reb_simulation_synchronize(r);
        double e = fabs(reb_simulation_energy(r) / E0 - 1);
        if (e > worst) worst = e;
    }
    reb_simulation_free(r);
    return worst;
}

static double rebound_time(double h, int corrector, long nsteps)
{
    struct reb_simulation *r = rebound_new(h, corrector);
    double t0 = now();
    reb_simulation_steps(r, (size_t)nsteps);
    reb_simulation_synchronize(r);
    double t = now() - t0;
    reb_simulation_free(r);
    return t;
}

/* ---- vigen's emitted steppers --------------------------------------------- */

/* One emitted stepper behind uniform signatures; kernel is the kernel the
 * runtime's correctors are applied for (the emitted wisdom_holman is
 * kick-drift-kick). */
typedef struct {
    const char *name;
    size_t nflows; /* 2: kepler, interaction; 3: also interaction_gradient (bracket methods) */
    void *(*alloc)(const vigen_split_problem *sp);
    int (*advance)(void *w, double *t, double *q, double *p, double h, long nsteps);
    void (*free)(void *w);
} method;

#define EMITTED(NAME)                                                                                         \
    static void *NAME##_alloc_(const vigen_split_problem *sp) { return NAME##_alloc_split(sp, NULL); }      \
    static int NAME##_advance_(void *w, double *t, double *q, double *p, double h, long nsteps)               \
    {                                                                                                         \
        return NAME##_advance(w, t, q, p, h, nsteps);                                                         \
    }                                                                                                         \
    static void NAME##_free_(void *w) { NAME##_free(w); }
EMITTED(wisdom_holman)
EMITTED(wisdom_holman_corrected)
EMITTED(saba_2)
EMITTED(saba_3)
EMITTED(saba_4)
EMITTED(saba_10_6_4)
EMITTED(sabac_2)
EMITTED(sabac_3)
EMITTED(wh_modified_kick)
EMITTED(wh_modified_kick_corrected)
#define METHOD(NAME, NF) { #NAME, NF, NAME##_alloc_, NAME##_advance_, NAME##_free_ }
static const method methods[] = { METHOD(wisdom_holman, 2), METHOD(saba_2, 2), METHOD(saba_3, 2), METHOD(saba_4, 2),
                                  METHOD(saba_10_6_4, 2), METHOD(wisdom_holman_corrected, 2), METHOD(sabac_2, 3),
                                  METHOD(sabac_3, 3), METHOD(wh_modified_kick, 3),
                                  METHOD(wh_modified_kick_corrected, 3) };

typedef struct {
    vigen_nbody *sys;
    vigen_split_problem sp;
    void *w;
    double t;
} run;

static int run_start(run *r, const method *m, double h, int corrector, double *q, double *p)
{
    if (vigen_nbody_alloc(&r->sys, N, G, mass) != VIGEN_SUCCESS) exit(1);
    if (vigen_nbody_split(r->sys, VIGEN_NBODY_JACOBI, &r->sp) != VIGEN_SUCCESS) exit(1);
    r->sp.nflows = m->nflows; /* kepler, interaction (and interaction_gradient): the first ones */
    r->w = m->alloc(&r->sp);
    if (!r->w) exit(1);
    r->t = 0;
    double pm[D];
    for (int k = 0; k < D; k++) pm[k] = mass[k / 3] * v0[k];
    vigen_nbody_to_jacobi(r->sys, x0, pm, q, p);
    if (corrector)
        return vigen_nbody_corrector_apply(r->sys, VIGEN_NBODY_KERNEL_KDK, corrector, h, q, p, -1);
    return VIGEN_SUCCESS;
}

static void run_free(run *r, const method *m)
{
    m->free(r->w);
    vigen_nbody_free(r->sys);
}

/* n steps between two outputs in one call of NAME_advance (the last
 * substep of a step merged with the first of the next, a processed
 * method's corrector applied at the ends only), as WHFast steps between
 * two synchronizations */
static int run_steps(run *r, const method *m, double h, long n, double *q, double *p)
{
    return m->advance(r->w, &r->t, q, p, h, n);
}

/* The energy of the true state: the corrector applied to a copy. */
static double run_energy(run *r, double h, int corrector, const double *q, const double *p)
{
    double qo[D], po[D], x[D], pm[D];
    memcpy(qo, q, sizeof qo);
    memcpy(po, p, sizeof po);
    if (corrector && vigen_nbody_corrector_apply(r->sys, VIGEN_NBODY_KERNEL_KDK, corrector, h, qo, po, 1))
        return NAN;
    vigen_nbody_from_jacobi(r->sys, qo, po, x, pm);
    return vigen_nbody_energy(r->sys, x, pm);
}

static double vigen_error(const method *m, double h, int corrector, long nsteps)
{
    double q[D], p[D], pm[D], worst = 0;
    for (int k = 0; k < D; k++) pm[k] = mass[k / 3] * v0[k];
    run r;
    if (run_start(&r, m, h, corrector, q, p) != VIGEN_SUCCESS) worst = INFINITY;
    double E0 = vigen_nbody_energy(r.sys, x0, pm);
    for (int k = 0; k < OUTPUTS && worst < INFINITY; k++) {
        if (run_steps(&r, m, h, nsteps / OUTPUTS, q, p) != VIGEN_SUCCESS) {
            worst = INFINITY;
            break;
        }
        double e = fabs(run_energy(&r, h, corrector, q, p) / E0 - 1);
        if (!(e <= worst)) worst = isnan(e) ? INFINITY : e;
    }
    run_free(&r, m);
    return worst;
}

static volatile double sink;

static double vigen_time(const method *m, double h, int corrector, long nsteps)
{
    double q[D], p[D];
    run r;
    double t0 = now();
    run_start(&r, m, h, corrector, q, p);
    run_steps(&r, m, h, nsteps, q, p);
    sink = run_energy(&r, h, corrector, q, p);
    double t = now() - t0;
    run_free(&r, m);
    return t;
}

/* ---- the table ------------------------------------------------------------ */

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* nsteps steps of T_END / nsteps (a multiple of OUTPUTS); m NULL: WHFast */
static void row(const method *m, long nsteps, int corrector, int repeats)
{
    double h = T_END / (double)nsteps;
    double err = m ? vigen_error(m, h, corrector, nsteps) : rebound_error(h, corrector, nsteps);
    double t[32];
    for (int k = 0; k < repeats; k++)
        t[k] = m ? vigen_time(m, h, corrector, nsteps) : rebound_time(h, corrector, nsteps);
    qsort(t, (size_t)repeats, sizeof t[0], cmp);
    printf("%-24s %4d %8.3f %7ld %10.2e %9.3f %9.3f %7.0f\n", m ? m->name : "whfast", corrector, h, nsteps, err,
           1e3 * t[0], 1e3 * t[repeats / 2], 1e9 * t[0] / nsteps);
    fflush(stdout);
}

static const method *method_find(const char *name)
{
    for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++)
        if (strcmp(methods[k].name, name) == 0) return &methods[k];
    return NULL;
}

int main(int argc, char **argv)
{
    /* "one whfast|METHOD H CORRECTOR STEPS": one bare run, for counting
     * instructions under callgrind */
    int one = argc == 6 && strcmp(argv[1], "one") == 0;
    int repeats = argc > 1 && !one ? atoi(argv[1]) : 5;
    if (repeats < 1 || repeats > 32) repeats = 5;
    vigen_problem *pb;
    if (vigen_problem_create(&pb, "outer-solar-system", NULL, NULL, 0) != VIGEN_SUCCESS) return 1;
    double t, q[D], p[D];
    vigen_problem_initial(pb, &t, q, p);
    /* the masses above are the problem's: the same energy */
    vigen_nbody *sys;
    vigen_nbody_alloc(&sys, N, G, mass);
    double E = vigen_problem_energy(pb, t, q, p), E2 = vigen_nbody_energy(sys, q, p);
    if (fabs(E2 / E - 1) > 1e-14) {
        fprintf(stderr, "nbody_whfast: masses differ from the problem's (%g vs %g)\n", E, E2);
        return 1;
    }
    vigen_nbody_free(sys);
    vigen_problem_free(pb);
    /* centre-of-mass frame */
    double M = 0, X[3] = { 0 }, V[3] = { 0 };
    for (int i = 0; i < N; i++) {
        M += mass[i];
        for (int c = 0; c < 3; c++) {
            X[c] += mass[i] * q[3 * i + c];
            V[c] += p[3 * i + c];
        }
    }
    for (int k = 0; k < D; k++) {
        x0[k] = q[k] - X[k % 3] / M;
        v0[k] = p[k] / mass[k / 3] - V[k % 3] / M;
    }
    if (one) {
        double h = atof(argv[3]);
        int corrector = atoi(argv[4]);
        long nsteps = atol(argv[5]);
        const method *m = method_find(argv[2]);
        if (!m && strcmp(argv[2], "whfast") != 0) return 2;
        sink = m ? vigen_time(m, h, corrector, nsteps) : rebound_time(h, corrector, nsteps);
        printf("%.3f\n", 1e3 * sink);
        return 0;
    }
    /* "only METHOD [STEPS...]": that method's rows alone */
    if (argc > 2 && strcmp(argv[1], "only") == 0) {
        const method *m = method_find(argv[2]);
        if (!m) return 2;
        for (int k = 3; k < argc; k++) row(m, atol(argv[k]), 0, 5);
        return 0;
    }
    static const long wh_steps[] = { 2500, 3000, 3500, 4000, 4500, 5000, 10000, 20000, 25000, 30000, 35000, 40000, 80000 };
    static const long long_steps[] = { 500, 800, 1000, 1200, 1400, 1600, 1800, 2000, 2500, 4000, 5000, 10000, 20000 };
    enum { NW = sizeof wh_steps / sizeof wh_steps[0], NL = sizeof long_steps / sizeof long_steps[0] };
    static const int correctors[] = { 0, 3, 11, 17 };
    printf("# method                corr      h/d   steps  max|dE/E|   best/ms median/ms ns/step\n");
    for (size_t c = 0; c < sizeof correctors / sizeof correctors[0]; c++)
        for (size_t s = 0; s < NW; s++) row(NULL, wh_steps[s], correctors[c], repeats);
    /* the Wisdom-Holman kernel with the runtime's correctors (order 17 is
     * order 11's to the digits shown, as for WHFast) */
    for (int c = 0; c <= 11; c += c ? 8 : 3)
        for (size_t s = 0; s < NW; s++) row(&methods[0], wh_steps[s], c, repeats);
    for (size_t k = 1; k < sizeof methods / sizeof methods[0]; k++)
        for (size_t s = 0; s < NL; s++) row(&methods[k], long_steps[s], 0, repeats);
    return 0;
}
