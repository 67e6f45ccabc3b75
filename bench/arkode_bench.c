/* arkode_bench.c — the emitted mechanical steppers side by side with SUNDIALS
 * ARKODE's SPRKStep on the same methods, on one problem of the collection
 * (runtime/problems/), in one run.
 *
 * For each method pair (ARKODE's table, vigen's library file of the same
 * method) three rows:
 *   - ARKODE SPRKStep, fixed step, its N_Vector serial state (q, p), the
 *     force and the velocity as its two right-hand sides;
 *   - vigen's stepper emitted with --dim and the force called directly
 *     (NAME_DIRECT_FORCE): what a user of `vigen emit` compiles;
 *   - vigen's stepper emitted for any dimension, through the mechanical
 *     callbacks (the same force function pointer ARKODE calls).
 * Both sides run with compensated summation off (ARKODE's default) and, in
 * a second block, on (ARKodeSetUseCompensatedSums, vigen's kahan = 1).
 * Columns: ns per step (fastest of 5 runs of STEPS steps from the problem's
 * initial state), forces per step, the largest relative energy error over
 * 100 equally spaced outputs (a run of its own), and time over ARKODE's.
 * The energy errors of a pair agree to several digits when the two sides
 * step the same method: a check that the pairing is right.  Prints
 * Markdown.  A measurement, not a test.
 *   arkode_bench [STEPS]       STEPS 0 or absent: ARK_STEPS
 *   arkode_bench one ID SIDE STEPS
 *                              one run of STEPS steps of method ID (ARKODE
 *                              side ark, vigen sides dim and cb),
 *                              compensation off, nothing printed: for
 *                              callgrind's instruction counts
 *   arkode_bench one force - STEPS
 *                              STEPS force evaluations alone
 *
 * bench/arkode_run.sh builds it once per problem with the macros ARK_FILE,
 * ARK_NAME, ARK_PARAMS, ARK_TITLE, ARK_DIM, ARK_UNIT_MASS, ARK_H, ARK_STEPS
 * and the emitted steppers ak_<id> (--dim, included here) and ak_<id>_any
 * (any dimension, linked).  ARKODE's MCLACHLAN_4_4 (McLachlan & Atela's
 * fourth order, four stages) and MCLACHLAN_5_6 have no counterpart in the
 * library and are left out. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <arkode/arkode.h>
#include <arkode/arkode_sprkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <vigen/problems.h>
#include <vigen/runtime.h>
#include ARK_FILE

/* The method pairs: id, ARKODE's table, vigen's library file (for the
 * table's caption). */
#define ARK_METHODS(X)                                                              \
    X(lf, "ARKODE_SPRK_LEAPFROG_2_2", "stormer_verlet_position")                  \
    X(plf, "ARKODE_SPRK_PSEUDO_LEAPFROG_2_2", "stormer_verlet_velocity")          \
    X(ruth3, "ARKODE_SPRK_RUTH_3_3", "ruth_3")                                    \
    X(mcl2, "ARKODE_SPRK_MCLACHLAN_2_2", "mclachlan_atela_2")                     \
    X(mcl3, "ARKODE_SPRK_MCLACHLAN_3_3", "mclachlan_atela_3")                     \
    X(cr4, "ARKODE_SPRK_CANDY_ROZMUS_4_4", "candy_rozmus_4")                      \
    X(y6, "ARKODE_SPRK_YOSHIDA_6_8", "yoshida_6_velocity")

/* f = -dV/dq from the problem's static dH/dq (p is not read by a separable
 * dH/dq) */
static inline void ark_force_q(double t, const double *q, double *f, void *ctx)
{
    dHdq(t, q, q, f, ctx);
    for (size_t k = 0; k < ARK_DIM; k++) f[k] = -f[k];
}

#define AK_DECLARE(id, ark, file)                                                   \
    extern const vigen_stepper_type ak_##id##_any_type;                           \
    void *ak_##id##_any_alloc_mechanical(const vigen_mechanical *m, const vigen_solver_options *o);
ARK_METHODS(AK_DECLARE)

#define AK_LF_DIRECT_FORCE ark_force_q
#include "ak_lf.c"
#define AK_PLF_DIRECT_FORCE ark_force_q
#include "ak_plf.c"
#define AK_RUTH3_DIRECT_FORCE ark_force_q
#include "ak_ruth3.c"
#define AK_MCL2_DIRECT_FORCE ark_force_q
#include "ak_mcl2.c"
#define AK_MCL3_DIRECT_FORCE ark_force_q
#include "ak_mcl3.c"
#define AK_CR4_DIRECT_FORCE ark_force_q
#include "ak_cr4.c"
#define AK_Y6_DIRECT_FORCE ark_force_q
#include "ak_y6.c"

static vigen_problem *pb;
static long steps;
static const double h = ARK_H;
static double inv_mass[ARK_DIM];

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double rel_energy_error(double t, const double *q, const double *p, double H0)
{
    return fabs((vigen_problem_energy(pb, t, q, p) - H0) / H0);
}

/* ------------------------------------------------------------ ARKODE side */
static long ark_forces;

static int ark_force(sunrealtype t, N_Vector y, N_Vector ydot, void *ud)
{
    const double *Y = N_VGetArrayPointer(y);
    double *D = N_VGetArrayPointer(ydot);
    ark_force_q(t, Y, D + ARK_DIM, ud);
    ark_forces++;
    return 0;
}

static int ark_velocity(sunrealtype t, N_Vector y, N_Vector ydot, void *ud)
{
    (void)t;
    (void)ud;
    const double *Y = N_VGetArrayPointer(y);
    double *D = N_VGetArrayPointer(ydot);
    for (size_t k = 0; k < ARK_DIM; k++) D[k] = (ARK_UNIT_MASS ? 1.0 : inv_mass[k]) * Y[ARK_DIM + k];
    return 0;
}

typedef struct {
    double ns, forces, err;
    int status;
} result;

static void *ark_make(SUNContext ctx, N_Vector y, const char *table, int comp)
{
    double t0;
    vigen_problem_initial(pb, &t0, N_VGetArrayPointer(y), N_VGetArrayPointer(y) + ARK_DIM);
    void *mem = SPRKStepCreate(ark_force, ark_velocity, t0, y, ctx);
    if (!mem || SPRKStepSetMethodName(mem, table) != 0 || ARKodeSetUseCompensatedSums(mem, comp) != 0 ||
        ARKodeSetFixedStep(mem, h) != 0 || ARKodeSetMaxNumSteps(mem, steps + 10) != 0 ||
        ARKodeSetUserData(mem, pb) != 0) {
        fprintf(stderr, "arkode_bench: %s: SPRKStep could not be set up\n", table);
        exit(3);
    }
    return mem;
}

/* nout outputs equally spaced over steps * h, each reached with the stop
 * time set (no interpolation); the largest energy error over them */
static int ark_run(void *mem, N_Vector y, int nout, double H0, double *err)
{
    double t0, t = 0, *Y = N_VGetArrayPointer(y);
    vigen_problem_initial(pb, &t0, Y, Y + ARK_DIM);
    if (ARKodeReset(mem, t0, y) != 0) return -1;
    *err = 0;
    for (int k = 1; k <= nout; k++) {
        double tout = t0 + h * (double)(steps * k / nout);
        ARKodeSetStopTime(mem, tout);
        int rc = ARKodeEvolve(mem, tout, y, &t, ARK_NORMAL);
        if (rc < 0) return rc;
        if (nout > 1) {
            double e = rel_energy_error(t, Y, Y + ARK_DIM, H0);
            if (e > *err) *err = e;
        }
    }
    *err = nout > 1 ? *err : rel_energy_error(t, Y, Y + ARK_DIM, H0);
    return 0;
}

static result ark_measure(SUNContext ctx, const char *table, int comp, double H0)
{
    result r = { 1e300, 0, 0, 0 };
    N_Vector y = N_VNew_Serial(2 * ARK_DIM, ctx);
    void *mem = ark_make(ctx, y, table, comp);
    double e1;
    for (int run = 0; run < 5 && r.status == 0; run++) {
        ark_forces = 0;
        double s = now();
        r.status = ark_run(mem, y, 1, H0, &e1);
        double el = now() - s;
        if (el < r.ns) r.ns = el;
        r.forces = (double)ark_forces / (double)steps;
    }
    r.ns *= 1e9 / (double)steps;
    if (r.status == 0) r.status = ark_run(mem, y, 100, H0, &r.err);
    ARKodeFree(&mem);
    N_VDestroy(y);
    return r;
}

/* ------------------------------------------------------------- vigen side */
static result vigen_measure(const vigen_stepper_type *T, void *w, double H0)
{
    result r = { 1e300, 0, 0, 0 };
    double q[ARK_DIM], p[ARK_DIM], t;
    for (int run = 0; run < 5 && r.status == 0; run++) {
        vigen_problem_initial(pb, &t, q, p);
        T->reset(w);
        vigen_stats s0 = *T->stats(w);
        double s = now();
        for (long k = 0; k < steps && r.status == 0; k++) r.status = T->step(w, &t, q, p, h);
        double el = now() - s;
        if (el < r.ns) r.ns = el;
        r.forces = (double)(T->stats(w)->dHdq_evals - s0.dHdq_evals) / (double)steps;
    }
    r.ns *= 1e9 / (double)steps;
    /* the accuracy run: 100 outputs */
    vigen_problem_initial(pb, &t, q, p);
    T->reset(w);
    for (long k = 0; k < steps && r.status == 0; k++) {
        r.status = T->step(w, &t, q, p, h);
        if ((k + 1) % (steps / 100 > 0 ? steps / 100 : 1) == 0) {
            double e = rel_energy_error(t, q, p, H0);
            if (e > r.err) r.err = e;
        }
    }
    return r;
}

static void row(const char *label, result r, double ref)
{
    if (r.status != 0) {
        printf("| %s | failed (status %d) | | | |\n", label, r.status);
        return;
    }
    printf("| %s | %.1f | %.2f | %.3e | %.2f |\n", label, r.ns, r.forces, r.err, r.ns / ref);
}

/* the single run of `arkode_bench one ID SIDE STEPS` */
static int one_run(const char *id, const char *side, SUNContext ctx, const vigen_mechanical *mech, double H0)
{
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.kahan = 0;
    double e, q[ARK_DIM], p[ARK_DIM], t;
#define AK_ONE(mid, ark, file)                                                                    \
    if (!strcmp(id, #mid)) {                                                                      \
        if (!strcmp(side, "ark")) {                                                               \
            N_Vector y = N_VNew_Serial(2 * ARK_DIM, ctx);                                         \
            void *mem = ark_make(ctx, y, ark, 0);                                                 \
            int rc = ark_run(mem, y, 1, H0, &e);                                                  \
            ARKodeFree(&mem);                                                                     \
            N_VDestroy(y);                                                                        \
            return rc;                                                                            \
        }                                                                                         \
        const vigen_stepper_type *T = !strcmp(side, "dim") ? &ak_##mid##_type : &ak_##mid##_any_type; \
        void *w = !strcmp(side, "dim") ? ak_##mid##_alloc_mechanical(mech, &opt)                  \
                                       : ak_##mid##_any_alloc_mechanical(mech, &opt);             \
        int rc = 0;                                                                               \
        vigen_problem_initial(pb, &t, q, p);                                                      \
        for (long k = 0; k < steps && rc == 0; k++) rc = T->step(w, &t, q, p, h);                 \
        T->free(w);                                                                               \
        return rc;                                                                                \
    }
    ARK_METHODS(AK_ONE)
    (void)e;
    if (!strcmp(id, "force")) { /* the force alone, for the force-bound of a step */
        volatile double sink = 0;
        vigen_problem_initial(pb, &t, q, p);
        for (long k = 0; k < steps; k++) {
            q[0] += 1e-12;
            ark_force_q(t, q, p, pb);
            sink += p[0];
        }
        return 0;
    }
    return 2;
}

int main(int argc, char **argv)
{
    int one = argc == 5 && !strcmp(argv[1], "one");
    steps = one ? atol(argv[4]) : argc > 1 ? atol(argv[1]) : 0;
    if (steps <= 0) steps = ARK_STEPS;
    char why[256];
    if (vigen_problem_create(&pb, ARK_NAME, ARK_PARAMS, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "arkode_bench: problem %s: %s\n", ARK_NAME, why);
        return 3;
    }
    double t0, q0[ARK_DIM], p0[ARK_DIM];
    vigen_problem_initial(pb, &t0, q0, p0);
    double H0 = vigen_problem_energy(pb, t0, q0, p0);
    /* the diagonal of M^-1 from the problem's dH/dp = M^-1 p */
    const vigen_hamiltonian *Hs = vigen_problem_hamiltonian(pb);
    for (size_t k = 0; k < ARK_DIM; k++) {
        double e[ARK_DIM] = { 0 }, v[ARK_DIM];
        e[k] = 1;
        Hs->dHdp(t0, q0, e, v, Hs->ctx);
        inv_mass[k] = v[k];
    }
    vigen_mechanical mech = { ARK_DIM, ark_force_q, NULL, pb, ARK_UNIT_MASS ? NULL : inv_mass };
    SUNContext ctx;
    if (SUNContext_Create(SUN_COMM_NULL, &ctx) != 0) return 3;

    if (one) {
        int rc = one_run(argv[2], argv[3], ctx, &mech, H0);
        SUNContext_Free(&ctx);
        vigen_problem_free(pb);
        return rc;
    }
    printf("### %s, %ld steps\n\n", ARK_TITLE, steps);
    for (int comp = 0; comp <= 1; comp++) {
        vigen_solver_options opt;
        vigen_solver_options_default(&opt);
        opt.kahan = comp;
        printf("Compensated summation %s on both sides.\n\n", comp ? "**on**" : "**off**");
        printf("| method | ns/step | forces/step | max rel. energy error | time / ARKODE |\n|---|---|---|---|---|\n");
#define AK_ROWS(id, ark, file)                                                                    \
    {                                                                                             \
        result a = ark_measure(ctx, ark, comp, H0);                                               \
        char lab[200];                                                                            \
        snprintf(lab, sizeof lab, "ARKODE %s", ark + 12);                                         \
        row(lab, a, a.ns);                                                                        \
        void *w = ak_##id##_alloc_mechanical(&mech, &opt);                                        \
        snprintf(lab, sizeof lab, "vigen `%s`, --dim, direct force", file);                       \
        row(lab, vigen_measure(&ak_##id##_type, w, H0), a.ns);                                    \
        ak_##id##_type.free(w);                                                                   \
        w = ak_##id##_any_alloc_mechanical(&mech, &opt);                                          \
        snprintf(lab, sizeof lab, "vigen `%s`, force callback", file);                            \
        row(lab, vigen_measure(&ak_##id##_any_type, w, H0), a.ns);                                \
        ak_##id##_any_type.free(w);                                                               \
    }
        ARK_METHODS(AK_ROWS)
        printf("\n");
    }
    SUNContext_Free(&ctx);
    vigen_problem_free(pb);
    return 0;
}
