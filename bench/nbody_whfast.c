/* nbody_whfast.c — work against precision on the outer solar system (Sun
 * + 5, the data of the runtime's outer-solar-system problem, moved to the
 * centre-of-mass frame) over 10^6 days: REBOUND's WHFast (Jacobi, its
 * drift-kick-drift kernel, with and without symplectic correctors) and the
 * runtime's N-body flows (vigen/nbody.h) in the same drift-kick-drift
 * Wisdom-Holman loop (the first and last half drifts of neighbouring steps
 * merged, as WHFast does without safe mode), with the runtime's correctors.
 * Built and run by rebound_run.sh against a REBOUND built by its own
 * Makefile; the loop below stands in for an emitted splitting stepper.
 *
 * Per row: the method, the step, the maximum relative energy error over
 * 100 outputs (a run of its own, the corrector applied at each output),
 * and the wall time of the bare run (no outputs; best and median of
 * `repeats` runs).  With the arguments "one METHOD H CORRECTOR STEPS" it
 * makes one bare run only (rebound_run.sh counts its instructions with
 * callgrind). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <rebound.h>
#include <vigen/nbody.h>
#include <vigen/problems.h>

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

/* The drift-kick-drift loop of n steps, drifts merged: K(h/2) [I(h) K(h)]^(n-1)
 * I(h) K(h/2). */
static int vigen_steps(vigen_nbody *sys, double h, long n, double *q, double *p)
{
    int st = vigen_nbody_jacobi_kepler(0, h / 2, q, p, sys);
    for (long k = 0; k < n - 1 && st == VIGEN_SUCCESS; k++) {
        st = vigen_nbody_jacobi_interaction(0, h, q, p, sys);
        if (st == VIGEN_SUCCESS) st = vigen_nbody_jacobi_kepler(0, h, q, p, sys);
    }
    if (st == VIGEN_SUCCESS) st = vigen_nbody_jacobi_interaction(0, h, q, p, sys);
    if (st == VIGEN_SUCCESS) st = vigen_nbody_jacobi_kepler(0, h / 2, q, p, sys);
    return st;
}

static vigen_nbody *vigen_start(double h, int corrector, double *q, double *p)
{
    vigen_nbody *sys;
    if (vigen_nbody_alloc(&sys, N, G, mass) != VIGEN_SUCCESS) exit(1);
    double pm[D];
    for (int k = 0; k < D; k++) pm[k] = mass[k / 3] * v0[k];
    vigen_nbody_to_jacobi(sys, x0, pm, q, p);
    if (corrector) vigen_nbody_corrector_apply(sys, VIGEN_NBODY_KERNEL_DKD, corrector, h, q, p, -1);
    return sys;
}

static double vigen_energy_out(vigen_nbody *sys, double h, int corrector, const double *q, const double *p)
{
    double qo[D], po[D], x[D], pm[D];
    memcpy(qo, q, sizeof qo);
    memcpy(po, p, sizeof po);
    if (corrector) vigen_nbody_corrector_apply(sys, VIGEN_NBODY_KERNEL_DKD, corrector, h, qo, po, 1);
    vigen_nbody_from_jacobi(sys, qo, po, x, pm);
    return vigen_nbody_energy(sys, x, pm);
}

static double vigen_error(double h, int corrector, long nsteps)
{
    double q[D], p[D], pm[D], worst = 0;
    for (int k = 0; k < D; k++) pm[k] = mass[k / 3] * v0[k];
    vigen_nbody *sys = vigen_start(h, corrector, q, p);
    double E0 = vigen_nbody_energy(sys, x0, pm);
    for (int k = 0; k < OUTPUTS; k++) {
        if (vigen_steps(sys, h, nsteps / OUTPUTS, q, p) != VIGEN_SUCCESS) return INFINITY;
        double e = fabs(vigen_energy_out(sys, h, corrector, q, p) / E0 - 1);
        if (e > worst) worst = e;
    }
    vigen_nbody_free(sys);
    return worst;
}

static volatile double sink;

static double vigen_time(double h, int corrector, long nsteps)
{
    double q[D], p[D];
    double t0 = now();
    vigen_nbody *sys = vigen_start(h, corrector, q, p);
    vigen_steps(sys, h, nsteps, q, p);
    sink = vigen_energy_out(sys, h, corrector, q, p);
    double t = now() - t0;
    vigen_nbody_free(sys);
    return t;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void row(const char *name, int is_rebound, double h, int corrector, int repeats)
{
    long nsteps = (long)(T_END / h + 0.5);
    nsteps -= nsteps % OUTPUTS;
    double err = is_rebound ? rebound_error(h, corrector, nsteps) : vigen_error(h, corrector, nsteps);
    double t[32];
    for (int k = 0; k < repeats; k++)
        t[k] = is_rebound ? rebound_time(h, corrector, nsteps) : vigen_time(h, corrector, nsteps);
    qsort(t, (size_t)repeats, sizeof t[0], cmp);
    printf("%-10s %4d %8.3f %7ld %10.2e %9.3f %9.3f %7.0f\n", name, corrector, h, nsteps, err, 1e3 * t[0],
           1e3 * t[repeats / 2], 1e9 * t[0] / nsteps);
}

int main(int argc, char **argv)
{
    /* "one whfast|vigen H CORRECTOR STEPS": one bare run, for counting
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
        sink = strcmp(argv[2], "whfast") == 0 ? rebound_time(h, corrector, nsteps) : vigen_time(h, corrector, nsteps);
        return 0;
    }
    static const double steps[] = { 400, 200, 100, 50, 25, 12.5 };
    static const int correctors[] = { 0, 3, 11, 17 };
    printf("# method  corr     h/d   steps  max|dE/E|  best/ms  median/ms  ns/step\n");
    for (size_t c = 0; c < sizeof correctors / sizeof correctors[0]; c++)
        for (size_t s = 0; s < sizeof steps / sizeof steps[0]; s++) {
            row("whfast", 1, steps[s], correctors[c], repeats);
            row("vigen", 0, steps[s], correctors[c], repeats);
        }
    return 0;
}
