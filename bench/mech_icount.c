/* mech_icount.c — one implicit mechanical stepper on one problem of the
 * collection, for instruction counts under callgrind (bench/mech_icount.sh):
 * the count of a run of 2N steps less that of N steps, over N, is the
 * instructions per step of the stepper, everything else (start-up, the
 * problem's set-up, the output) cancelling.
 *
 *   mech_icount STEPPER STEPS [newton]
 *
 * STEPPER: gni2, gni3, gnil3 (the hand-written anchors of
 * bench/hand_gni_gauss.h: Gauss s = 2, 3 and Lobatto IIIA-IIIB s = 3, static
 * dimension, force inlined); g2d, g3d, l3d (the emitted steppers of
 * gauss_2.lua, gauss_3.lua and lobatto_iiia_iiib_3.lua with --dim and the
 * force called directly); g2, g3, l3 (the same emitted without --dim,
 * through the mechanical callbacks, the force an out-of-line function).
 * "newton" selects the emitted steppers' simplified Newton iteration.
 * Prints the forces and sweeps per step, the relative energy error at the
 * end, the status, the final q[0], p[0] (hexadecimal: bits to compare
 * between two builds) and the wall time per step of this run (a single
 * run: noise on a loaded machine).  Built per problem like bench/peer_bench.c (the
 * problem as macros PEER_FILE, PEER_NAME, PEER_PARAMS, PEER_DIM,
 * PEER_UNIT_MASS, PEER_H; the problem's file compiled here so that its
 * static force is inlined).  A measurement, not a test. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <vigen/problems.h>
#include <vigen/runtime.h>
#include PEER_FILE

/* f = -dV/dq from the problem's static dH/dq */
static inline void peer_force(double t, const double *q, double *f, void *ctx)
{
    dHdq(t, q, q, f, ctx);
    for (size_t k = 0; k < PEER_DIM; k++) f[k] = -f[k];
}

/* the same force out of line, for the steppers through the callbacks */
static void __attribute__((noinline)) peer_force_cb(double t, const double *q, double *f, void *ctx)
{
    peer_force(t, q, f, ctx);
}

#include "mi_g2.h"
#include "mi_g3.h"
#include "mi_l3.h"
#define MI_G2D_DIRECT_FORCE peer_force
#include "mi_g2d.c"
#define MI_G3D_DIRECT_FORCE peer_force
#include "mi_g3d.c"
#define MI_L3D_DIRECT_FORCE peer_force
#include "mi_l3d.c"

static double peer_inv_mass[PEER_DIM];
#if PEER_UNIT_MASS
#define PEER_VELOCITY(k, x) (x)
#else
#define PEER_VELOCITY(k, x) (peer_inv_mass[k] * (x))
#endif

#include "gni_anchors.h"

static vigen_problem *pb;

#define GNI_RUN(x)                                                                                           \
    static int x##_run(long steps, double *t, double *q, double *p, double *forces, double *sweeps)          \
    {                                                                                                     \
        x##_ws *w = x##_alloc();                                                                          \
        if (w == NULL) return 1;                                                                          \
        x##_reset(w);                                                                                     \
        int st = 0;                                                                                       \
        for (long k = 0; k < steps && st == 0; k++) st = x##_step(w, t, q, p, PEER_H, pb);               \
        *forces = (double)w->forces / (double)steps;                                                      \
        *sweeps = (double)w->sweeps / (double)steps;                                                      \
        free(w);                                                                                          \
        return st;                                                                                        \
    }
GNI_RUN(gni2)
GNI_RUN(gni3)
GNI_RUN(gnil3)

#define EMITTED_RUN(x)                                                                                       \
    static int x##_run(const vigen_mechanical *m, const vigen_solver_options *o, long steps, double *t,     \
                       double *q, double *p, double *forces, double *sweeps)                              \
    {                                                                                                     \
        x##_workspace *w = x##_alloc_mechanical(m, o);                                                    \
        int st = w == NULL;                                                                               \
        for (long k = 0; k < steps && st == 0; k++) st = x##_step(w, t, q, p, PEER_H);                    \
        *forces = (double)x##_stats(w)->dHdq_evals / (double)steps;                                       \
        *sweeps = (double)x##_stats(w)->iterations / (double)steps;                                       \
        x##_free(w);                                                                                      \
        return st;                                                                                        \
    }
EMITTED_RUN(mi_g2d)
EMITTED_RUN(mi_g3d)
EMITTED_RUN(mi_l3d)
EMITTED_RUN(mi_g2)
EMITTED_RUN(mi_g3)
EMITTED_RUN(mi_l3)

int main(int argc, char **argv)
{
    char why[256];
    if (argc < 3) {
        fprintf(stderr, "usage: mech_icount STEPPER STEPS [newton]\n");
        return 2;
    }
    const char *which = argv[1];
    long steps = atol(argv[2]);
    if (vigen_problem_create(&pb, PEER_NAME, PEER_PARAMS, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "mech_icount: %s\n", why);
        return 1;
    }
    double e[PEER_DIM] = { 0 }, v[PEER_DIM];
    for (size_t k = 0; k < PEER_DIM; k++) {
        e[k] = 1;
        vigen_problem_hamiltonian(pb)->dHdp(0, e, e, v, pb);
        peer_inv_mass[k] = v[k];
        e[k] = 0;
    }
    vigen_mechanical direct = { PEER_DIM, peer_force, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    vigen_mechanical cb = { PEER_DIM, peer_force_cb, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    vigen_solver_options o;
    vigen_solver_options_default(&o);
    if (argc > 3 && strcmp(argv[3], "newton") == 0) o.solver = VIGEN_SOLVER_NEWTON;
    double t, q[PEER_DIM], p[PEER_DIM], t0, q0[PEER_DIM], p0[PEER_DIM], forces = 0, sweeps = 0;
    vigen_problem_initial(pb, &t0, q0, p0);
    t = t0;
    memcpy(q, q0, sizeof q);
    memcpy(p, p0, sizeof p);
    int st;
    struct timespec ts0, ts1;
    clock_gettime(CLOCK_MONOTONIC, &ts0);
    if (strcmp(which, "gni2") == 0) st = gni2_run(steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "gni3") == 0) st = gni3_run(steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "gnil3") == 0) st = gnil3_run(steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "g2d") == 0) st = mi_g2d_run(&direct, &o, steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "g3d") == 0) st = mi_g3d_run(&direct, &o, steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "l3d") == 0) st = mi_l3d_run(&direct, &o, steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "g2") == 0) st = mi_g2_run(&cb, &o, steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "g3") == 0) st = mi_g3_run(&cb, &o, steps, &t, q, p, &forces, &sweeps);
    else if (strcmp(which, "l3") == 0) st = mi_l3_run(&cb, &o, steps, &t, q, p, &forces, &sweeps);
    else {
        fprintf(stderr, "mech_icount: unknown stepper %s\n", which);
        return 2;
    }
    clock_gettime(CLOCK_MONOTONIC, &ts1);
    const double ns = 1e9 * ((double)(ts1.tv_sec - ts0.tv_sec) + 1e-9 * (double)(ts1.tv_nsec - ts0.tv_nsec)) / (double)steps;
    double H0 = vigen_problem_energy(pb, t0, q0, p0), H = vigen_problem_energy(pb, t, q, p);
    printf("%s %ld forces/step %.3f sweeps/step %.3f rel.energy.error %.3e status %d q0 %a p0 %a ns/step %.1f\n", which,
           steps, forces, sweeps, fabs((H - H0) / H0), st, q[0], p[0], ns);
    vigen_problem_free(pb);
    return st != 0;
}
