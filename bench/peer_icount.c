/* peer_icount.c — one stepper of bench/peer_bench.c's rows on one problem,
 * for instruction counts under valgrind's callgrind, which are repeatable
 * where wall time on a shared machine is not:
 *
 *   peer_icount ROW STEPS            STEPS steps from the problem's initial
 *                                    state, then t, a hash of the final q and
 *                                    p, and the energy error;
 *   PEER_TIME=1 peer_icount ROW STEPS   the fastest of 7 runs, ns per step.
 *
 * bench/peer_icount.sh builds it per problem (as peer_run.sh builds
 * peer_bench) and prints instructions per step, the difference of the counts
 * of the stepping loop (run_loop) at 2 N and N steps over N.  ROW:
 *   hsv   hand-written Verlet of peer_bench.c (static dimension, force
 *         inlined, compensated)
 *   gni   hand-written Gauss-2 of bench/hand_gni_gauss.h (GNI_IRK2 style)
 *   svg   emitted Verlet through the general callbacks (NAME_alloc)
 *   svd   emitted Verlet, --dim, mechanical, direct force
 *   g2g   emitted Gauss-2 through the general callbacks, extrapolated start
 *   mcld  emitted mclachlan_rkn_4, --dim, mechanical, direct force,
 *         compensated
 * The hash (FNV-1a of the bits of q and p) tells whether two builds give the
 * same trajectory bit for bit. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <vigen/problems.h>
#include <vigen/runtime.h>
#include PEER_FILE

static vigen_problem *pb;

/* f = -dV/dq from the problem's static dH/dq, as in peer_bench.c */
static inline void peer_force(double t, const double *q, double *f, void *ctx)
{
    dHdq(t, q, q, f, ctx);
    for (size_t k = 0; k < PEER_DIM; k++) f[k] = -f[k];
}

#include "peer_g2.h"
#include "peer_sv.h"
#define PEER_SVD_DIRECT_FORCE peer_force
#include "peer_svd.c"
#define PEER_MCLD_DIRECT_FORCE peer_force
#include "peer_mcld.c"

/* the rows run on unit masses or M^-1 from the problem, as peer_bench.c */
static double peer_inv_mass[PEER_DIM];
#if PEER_UNIT_MASS
#define PEER_VELOCITY(k, x) (x)
#else
#define PEER_VELOCITY(k, x) (peer_inv_mass[k] * (x))
#endif

#define GNI_NAME gni2
#define GNI_S 2
#define GNI_DIM PEER_DIM
#define GNI_FORCE peer_force
#define GNI_VEL(k, x) PEER_VELOCITY(k, x)
#include "hand_gni_gauss.h"

/* peer_bench.c's hand-written Verlet */
#include "hand_verlet_dim.h"
static void hsv_reset(void *w) { memset(w, 0, sizeof(hsv_ws)); }

static int gni2_step_v(void *w, double *t, double *q, double *p, double hh) { return gni2_step(w, t, q, p, hh, pb); }
static void gni2_reset_v(void *w) { gni2_reset(w); }

typedef int (*step_fn)(void *w, double *t, double *q, double *p, double h);

/* the loop that callgrind counts (--toggle-collect='run_loop*') */
__attribute__((noinline)) static int run_loop(step_fn f, void *w, double *t, double *q, double *p, long n)
{
    int st = 0;
    for (long k = 0; k < n && st == 0; k++) st = f(w, t, q, p, PEER_H);
    return st;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    char why[256];
    if (argc != 3) {
        fprintf(stderr, "usage: peer_icount hsv|gni|svg|svd|g2g|mcld STEPS\n");
        return 2;
    }
    const char *row = argv[1];
    const long steps = atol(argv[2]);
    if (vigen_problem_create(&pb, PEER_NAME, PEER_PARAMS, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "peer_icount: %s\n", why);
        return 1;
    }
    /* diag(M^-1): dH/dp of all momenta 1 (the mass matrices of the problems
     * are diagonal) */
    double ones[PEER_DIM];
    for (size_t k = 0; k < PEER_DIM; k++) ones[k] = 1;
    vigen_problem_hamiltonian(pb)->dHdp(0, ones, ones, peer_inv_mass, pb);
    vigen_mechanical mech = { PEER_DIM, peer_force, NULL, pb, PEER_UNIT_MASS ? NULL : peer_inv_mass };
    const vigen_hamiltonian *H = vigen_problem_hamiltonian(pb);
    void *w = NULL;
    step_fn f = NULL;
    void (*reset)(void *) = NULL;
    if (strcmp(row, "hsv") == 0) w = calloc(1, sizeof(hsv_ws)), f = hsv_step, reset = hsv_reset;
    else if (strcmp(row, "gni") == 0) w = gni2_alloc(), f = gni2_step_v, reset = gni2_reset_v;
    else if (strcmp(row, "svg") == 0) w = peer_sv_alloc(H, NULL), f = peer_sv_type.step, reset = peer_sv_type.reset;
    else if (strcmp(row, "svd") == 0)
        w = peer_svd_alloc_mechanical(&mech, NULL), f = peer_svd_type.step, reset = peer_svd_type.reset;
    else if (strcmp(row, "g2g") == 0) w = peer_g2_alloc(H, NULL), f = peer_g2_type.step, reset = peer_g2_type.reset;
    else if (strcmp(row, "mcld") == 0)
        w = peer_mcld_alloc_mechanical(&mech, NULL), f = peer_mcld_type.step, reset = peer_mcld_type.reset;
    if (f == NULL || w == NULL) {
        fprintf(stderr, "peer_icount: unknown row %s (or no memory)\n", row);
        return 2;
    }
    double t, q[PEER_DIM], p[PEER_DIM], t0, q0[PEER_DIM], p0[PEER_DIM];
    int st = 0;
    if (getenv("PEER_TIME") != NULL) {
        double best = 1e300;
        for (int run = 0; run < 7 && st == 0; run++) {
            vigen_problem_initial(pb, &t, q, p);
            reset(w);
            double a = now();
            st = run_loop(f, w, &t, q, p, steps);
            double el = now() - a;
            if (el < best) best = el;
        }
        printf("%s %.2f ns/step\n", row, 1e9 * best / (double)steps);
    } else {
        vigen_problem_initial(pb, &t, q, p);
        st = run_loop(f, w, &t, q, p, steps);
    }
    uint64_t hash = UINT64_C(0xcbf29ce484222325);
    for (size_t k = 0; k < 2 * PEER_DIM; k++) {
        uint64_t u;
        memcpy(&u, k < PEER_DIM ? &q[k] : &p[k - PEER_DIM], sizeof u);
        hash = (hash ^ u) * UINT64_C(0x100000001b3);
    }
    vigen_problem_initial(pb, &t0, q0, p0);
    double H0 = vigen_problem_energy(pb, t0, q0, p0);
    printf("%s status %d t %.17g hash %016llx rel. energy error %.3e\n", row, st, t, (unsigned long long)hash,
           fabs((vigen_problem_energy(pb, t, q, p) - H0) / H0));
    vigen_problem_free(pb);
    return 0;   /* the stepper's workspace goes with the process */
}
