/* test_ensemble.c — vigen_integrate_ensemble (runtime/drive/ensemble.c) with
 * steppers emitted at build time (tests/CMakeLists.txt: Gauss s = 2 and
 * Stormer-Verlet from tableaux/published), on an ensemble of Kepler orbits
 * of eccentricities 0 to 0.7.  Asserted:
 *   - 1 and 2 threads give the same bits, and both the bits of a fresh
 *     workspace looping NAME_step over each trajectory alone (the scalar
 *     stepper, independent of the ensemble's scheduling and reset);
 *   - the orbits are right: after one period (2 pi, semi-major axis 1) each
 *     is back at its start and its energy -1/2 (closed form of Kepler's
 *     problem), to the method's error;
 *   - a trajectory started at NaN is reported (VIGEN_ENONFINITE, 0 steps,
 *     state unchanged) and every other trajectory finishes with the bits it
 *     has without the failing one; the return value is that status;
 *   - a mechanical problem through the alloc hook (NAME_alloc_mechanical),
 *     or cloned by the type from a prototype workspace, gives the scalar
 *     bits too;
 *   - invalid arguments: VIGEN_EINVAL with nothing touched. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "vigen/ensemble.h"
#include "ens_gauss2.h"
#include "ens_verlet.h"

enum { N = 37, NSTEPS = 400 };   /* N odd: the two threads get unequal blocks */
static const double PI = 3.14159265358979323846;

static void kep_dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    const double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    out[0] = q[0] / r3;
    out[1] = q[1] / r3;
}
static void kep_dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    out[0] = p[0];
    out[1] = p[1];
}
static void kep_force(double t, const double *q, double *f, void *ctx)
{
    (void)t; (void)ctx;
    const double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    f[0] = -q[0] / r3;
    f[1] = -q[1] / r3;
}

/* Orbit i: pericentre at (1 - e, 0), speed sqrt((1 + e)/(1 - e)), a = 1. */
static void initial(double *t, double *q, double *p)
{
    for (int i = 0; i < N; i++) {
        const double e = 0.7 * i / (N - 1);
        t[i] = 0.25 * i;   /* distinct start times: the trajectories differ in t too */
        q[2 * i] = 1 - e;
        q[2 * i + 1] = 0;
        p[2 * i] = 0;
        p[2 * i + 1] = sqrt((1 + e) / (1 - e));
    }
}

static int same_bits(const double *a, const double *b, size_t n) { return memcmp(a, b, n * sizeof *a) == 0; }

typedef struct {
    double t[N], q[2 * N], p[2 * N];
    int status[N];
    unsigned long steps[N];
} run_state;

static int run_ensemble(run_state *R, const vigen_ensemble *e, double h)
{
    initial(R->t, R->q, R->p);
    return vigen_integrate_ensemble(e, N, R->t, R->q, R->p, h, NSTEPS, R->status, R->steps);
}

/* The scalar reference: a fresh workspace per trajectory, NAME_step looped. */
static void scalar_general(run_state *R, const vigen_stepper_type *T, const vigen_hamiltonian *sys, double h)
{
    initial(R->t, R->q, R->p);
    for (int i = 0; i < N; i++) {
        void *w = T->alloc(sys, NULL);
        R->status[i] = VIGEN_SUCCESS;
        R->steps[i] = 0;
        for (int k = 0; k < NSTEPS; k++) {
            int st = T->step(w, R->t + i, R->q + 2 * i, R->p + 2 * i, h);
            if (st != VIGEN_SUCCESS) { R->status[i] = st; break; }
            R->steps[i]++;
        }
        T->free(w);
    }
}

static void check_same(const run_state *a, const run_state *b, const char *what)
{
    CHECK_MSG(same_bits(a->t, b->t, N) && same_bits(a->q, b->q, 2 * N) && same_bits(a->p, b->p, 2 * N),
              "%s: states differ", what);
    CHECK_MSG(memcmp(a->status, b->status, sizeof a->status) == 0, "%s: statuses differ", what);
    CHECK_MSG(memcmp(a->steps, b->steps, sizeof a->steps) == 0, "%s: step counts differ", what);
}

static void check_orbits(const run_state *R, double tol, double etol, const char *what)
{
    double t0[N], q0[2 * N], p0[2 * N];
    initial(t0, q0, p0);
    for (int i = 0; i < N; i++) {
        const double *q = R->q + 2 * i, *p = R->p + 2 * i;
        const double dist = hypot(q[0] - q0[2 * i], q[1] - q0[2 * i + 1]);
        const double energy = 0.5 * (p[0] * p[0] + p[1] * p[1]) - 1 / hypot(q[0], q[1]);
        CHECK_MSG(R->status[i] == VIGEN_SUCCESS && R->steps[i] == NSTEPS, "%s: orbit %d status %d", what, i,
                  R->status[i]);
        CHECK_MSG(fabs(R->t[i] - (t0[i] + 2 * PI)) < 1e-12, "%s: orbit %d ends at t = %.17g", what, i, R->t[i]);
        CHECK_MSG(dist < tol && fabs(energy + 0.5) < etol, "%s: orbit %d: distance to the start %.3g, energy %.17g",
                  what, i, dist, energy);
    }
}

static void *alloc_mech(void *ctx) { return ens_verlet_alloc_mechanical(ctx, NULL); }

int main(void)
{
    const double h = 2 * PI / NSTEPS;
    vigen_hamiltonian sys = { .dim = 2, .dHdq = kep_dHdq, .dHdp = kep_dHdp, .separable = 1 };
    static run_state one, two, ref, dflt;
    printf("OpenMP threads by default: %d%s\n", vigen_ensemble_max_threads(),
#ifdef _OPENMP
           ""
#else
           " (this test is compiled without OpenMP; the runtime may still have it)"
#endif
    );

    const vigen_stepper_type *types[2] = { &ens_gauss2_type, &ens_verlet_type };
    /* errors after one period at h = 2 pi/400, e <= 0.7 (1.1e-5 and 0.14 at
     * e = 0.7, the largest): Gauss-2 is of order 4 and its energy error is
     * round-off here, Verlet of order 2 */
    const double tol[2] = { 3e-5, 0.3 }, etol[2] = { 1e-9, 1e-3 };
    for (int m = 0; m < 2; m++) {
        const char *name = types[m]->name;
        vigen_ensemble e = { .type = types[m], .sys = &sys, .threads = 1 };
        CHECK(run_ensemble(&one, &e, h) == VIGEN_SUCCESS);
        e.threads = 2;
        CHECK(run_ensemble(&two, &e, h) == VIGEN_SUCCESS);
        e.threads = 0;
        CHECK(run_ensemble(&dflt, &e, h) == VIGEN_SUCCESS);
        scalar_general(&ref, types[m], &sys, h);
        check_same(&one, &two, name);
        check_same(&one, &dflt, name);
        check_same(&one, &ref, name);
        check_orbits(&one, tol[m], etol[m], name);

        /* one trajectory fails: the others keep their bits */
        vigen_ensemble e2 = { .type = types[m], .sys = &sys, .threads = 2 };
        initial(two.t, two.q, two.p);
        two.q[2 * 5] = NAN;
        const double p5[2] = { two.p[10], two.p[11] }, t5 = two.t[5];
        int rc = vigen_integrate_ensemble(&e2, N, two.t, two.q, two.p, h, NSTEPS, two.status, two.steps);
        CHECK_MSG(rc == VIGEN_ENONFINITE, "%s: NaN trajectory: ensemble returned %d", name, rc);
        CHECK(two.status[5] == VIGEN_ENONFINITE && two.steps[5] == 0);
        CHECK(isnan(two.q[10]) && two.q[11] == 0 && two.p[10] == p5[0] && two.p[11] == p5[1] && two.t[5] == t5);
        for (int i = 0; i < N; i++) {
            if (i == 5) continue;
            CHECK_MSG(two.status[i] == VIGEN_SUCCESS && two.steps[i] == NSTEPS && two.t[i] == one.t[i]
                          && same_bits(two.q + 2 * i, one.q + 2 * i, 2) && same_bits(two.p + 2 * i, one.p + 2 * i, 2),
                      "%s: trajectory %d disturbed by the failing one", name, i);
        }
    }

    /* a mechanical problem through the alloc hook */
    vigen_mechanical mech = { .dim = 2, .force = kep_force };
    vigen_ensemble em = { .type = &ens_verlet_type, .alloc = alloc_mech, .alloc_ctx = &mech, .dim = 2, .threads = 2 };
    CHECK(run_ensemble(&two, &em, h) == VIGEN_SUCCESS);
    initial(ref.t, ref.q, ref.p);
    for (int i = 0; i < N; i++) {
        ens_verlet_workspace *w = ens_verlet_alloc_mechanical(&mech, NULL);
        for (int k = 0; k < NSTEPS; k++) CHECK(ens_verlet_step(w, ref.t + i, ref.q + 2 * i, ref.p + 2 * i, h) == 0);
        ens_verlet_free(w);
    }
    CHECK_MSG(same_bits(two.q, ref.q, 2 * N) && same_bits(two.p, ref.p, 2 * N) && same_bits(two.t, ref.t, N),
              "mechanical Verlet: ensemble and scalar loop differ");

    /* the same problem from a prototype workspace: the type clones it (no
     * dimension given: the type's) and the prototype steps nothing */
    ens_verlet_workspace *proto = ens_verlet_alloc_mechanical(&mech, NULL);
    vigen_ensemble ep = { .type = &ens_verlet_type, .threads = 2, .prototype = proto };
    CHECK(run_ensemble(&two, &ep, h) == VIGEN_SUCCESS);
    CHECK_MSG(same_bits(two.q, ref.q, 2 * N) && same_bits(two.p, ref.p, 2 * N) && same_bits(two.t, ref.t, N),
              "mechanical Verlet from a prototype: ensemble and scalar loop differ");
    CHECK(ens_verlet_stats(proto)->steps == 0);
    ens_verlet_free(proto);

    /* invalid arguments: nothing touched */
    vigen_ensemble bad = { .type = &ens_verlet_type, .sys = &sys, .threads = 2 };
    initial(one.t, one.q, one.p);
    memset(one.status, 0x5a, sizeof one.status);
    int before = one.status[0];
    CHECK(vigen_integrate_ensemble(&bad, N, one.t, one.q, one.p, NAN, NSTEPS, one.status, NULL) == VIGEN_EINVAL);
    CHECK(vigen_integrate_ensemble(&bad, N, one.t, one.q, one.p, h, NSTEPS, NULL, NULL) == VIGEN_EINVAL);
    bad.dim = 3;
    CHECK(vigen_integrate_ensemble(&bad, N, one.t, one.q, one.p, h, NSTEPS, one.status, NULL) == VIGEN_EINVAL);
    bad.dim = 0;
    bad.sys = NULL;
    CHECK(vigen_integrate_ensemble(&bad, N, one.t, one.q, one.p, h, NSTEPS, one.status, NULL) == VIGEN_EINVAL);
    CHECK(one.status[0] == before && one.t[1] == 0.25 && one.q[0] == 1);
    TEST_MAIN_END();
}
