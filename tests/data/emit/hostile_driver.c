/* hostile_driver.c — feeds an emitted stepper non-finite numbers and prints
 * key=value lines for tests/unit/test_emit_hostile.c.  Built with
 *   -DSTEPPER_HEADER='"NAME.h"' -DSTEPPER_TYPE=NAME_type [-DREAL_LD | -DREAL_Q]
 * and the runtime.
 *
 *   hostile_driver SEP KAHAN SOLVER
 *       the harmonic oscillator H = (q^2 + p^2)/2 from q = 1, p = 0 with
 *       sys.separable = SEP (1: the explicit path of a tableau that has one),
 *       the option kahan = KAHAN and the solver SOLVER (0 fixed point, 1
 *       Newton).  For each case C below: C_status (the status of the step
 *       that failed, or of the hostile call), C_unchanged (1 when t, q, p
 *       are bit for bit what they were before that call) and C_step (the
 *       number of the step that failed, from 1) and C_fired (the first step
 *       in which the gradient returned its bad value; 0 for none):
 *         nan_first   dH/dq returns NaN from the first call on
 *         nan_mid     dH/dq returns NaN once t > 0.55 (steps of 0.1)
 *         nanp_mid    dH/dp returns NaN once t > 0.55
 *         inf_mid     dH/dq returns +inf once t > 0.55
 *         nan_q       q = NaN at the start;  nan_p: p = NaN
 *         t_nan       t = NaN after three good steps
 *       and, from q = p = 1:
 *         h_nan, h_inf, h_minf  h = NaN, +inf, -inf after three good steps
 *                     (continuing the trajectory)
 *         tover_first t = h = BIG (1e308 for double, 3/4 of the largest
 *                     long double otherwise): t + h overflows; first call
 *         tover_mid   the same after a good step of h = 1 from t = BIG
 *         h_huge      t = 0, h = 1e300 (1e4900 for long double and
 *                     float128): t + h finite, the state overflows
 *       and recover_same: after nan_mid failed, the gradient is repaired and
 *       the step retried: 1 when t, q, p are then bit for bit those of a run
 *       that never failed.
 *   hostile_driver singular
 *       the 1-stage method (midpoint) with Newton on H = q p at h = 2, where
 *       I - h J = diag(1 - h/2, 1 + h/2) is singular: singular_status; and
 *       with dH/dq NaN from the first call: singular_nan_status.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include STEPPER_HEADER

#if defined(REAL_LD)
typedef long double real;
typedef vigen_hamiltonian_ld ham_t;
typedef vigen_stepper_type_ld type_t;
#define REAL_BYTES 10   /* the x87 format: the rest of sizeof(long double) is padding */
#define BIG ((real)LDBL_MAX * 0.75L)   /* BIG + BIG overflows */
#define HUGE_H ((real)1e4900L)         /* h^2 overflows */
#elif defined(REAL_Q)
typedef vigen_float128 real;
typedef vigen_hamiltonian_q ham_t;
typedef vigen_stepper_type_q type_t;
#define REAL_BYTES sizeof(real)
#define BIG ((real)LDBL_MAX * 0.75L)   /* above half the largest __float128 too */
#define HUGE_H ((real)1e4900L)
#else
typedef double real;
typedef vigen_hamiltonian ham_t;
typedef vigen_stepper_type type_t;
#define REAL_BYTES sizeof(real)
#define BIG 1e308
#define HUGE_H 1e300
#endif

extern const type_t STEPPER_TYPE;
static const type_t *T = &STEPPER_TYPE;

/* which gradient turns bad (0 none, 1 dH/dq, 2 dH/dp), to what, after
 * when; fired: a bad value has been returned */
static int bad_which, fired;
static real bad_value, bad_after;
static real bad(real t, real good)
{
    if (bad_which == 0 || !(t > bad_after)) return good;
    fired = 1;
    return bad_value;
}

static void ho_dq(real t, const real *q, const real *p, real *o, void *c)
{
    (void)p; (void)c;
    o[0] = bad_which == 1 ? bad(t, q[0]) : q[0];
}
static void ho_dp(real t, const real *q, const real *p, real *o, void *c)
{
    (void)q; (void)c;
    o[0] = bad_which == 2 ? bad(t, p[0]) : p[0];
}
static void qp_dq(real t, const real *q, const real *p, real *o, void *c)
{
    (void)q; (void)c;
    o[0] = bad_which == 1 ? bad(t, p[0]) : p[0];
}
static void qp_dp(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)p; (void)c; o[0] = q[0]; }

static int same(real a, real b) { return memcmp(&a, &b, REAL_BYTES) == 0; }

typedef struct { real t, q, p; } state;
static int unchanged(const state *s, real t, const real *q, const real *p)
{
    return same(s->t, t) && same(s->q, q[0]) && same(s->p, p[0]);
}

static int sep, kahan, solver;

static void *make(ham_t *sys)
{
    static ham_t ho;
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.kahan = kahan;
    opt.solver = solver ? VIGEN_SOLVER_NEWTON : VIGEN_SOLVER_FIXED_POINT;
    ho = (ham_t){ 1, ho_dq, ho_dp, NULL, NULL, sep, NULL };
    void *w = T->alloc(sys ? sys : &ho, &opt);
    if (w == NULL) { printf("alloc=failed\n"); exit(1); }
    return w;
}

static void report(const char *name, int st, int same_state, int step)
{
    printf("%s_status=%d\n%s_unchanged=%d\n%s_step=%d\n", name, st, name, same_state, name, step);
}

/* Steps of 0.1 from (t0, q0, p0) until one fails (at most 20); reports it. */
static void run(const char *name, int which, real value, real after, real t0, real q0, real p0)
{
    bad_which = which;
    bad_value = value;
    bad_after = after;
    void *w = make(NULL);
    real t = t0, q[1] = { q0 }, p[1] = { p0 };
    state before = { t, q[0], p[0] };
    int st = VIGEN_SUCCESS, k = 0, fired_step = 0;
    fired = 0;
    while (k < 20 && st == VIGEN_SUCCESS) {
        before = (state){ t, q[0], p[0] };
        st = T->step(w, &t, q, p, (real)0.1);
        k++;
        if (fired && fired_step == 0) fired_step = k;
    }
    report(name, st, unchanged(&before, t, q, p), k);
    printf("%s_fired=%d\n", name, fired_step);
    if (strcmp(name, "nan_mid") == 0 && st != VIGEN_SUCCESS) {
        /* repaired, the retried step gives what a run without failures gives */
        bad_which = 0;
        int st2 = T->step(w, &t, q, p, (real)0.1);
        void *w2 = make(NULL);
        real t2 = t0, q2[1] = { q0 }, p2[1] = { p0 };
        for (int j = 0; j < k; j++) st2 |= T->step(w2, &t2, q2, p2, (real)0.1);
        printf("recover_same=%d\n", st2 == 0 && same(t, t2) && same(q[0], q2[0]) && same(p[0], p2[0]));
        T->free(w2);
    }
    bad_which = 0;
    T->free(w);
}

/* A hostile h after `good` steps of size h0 from t = tstart (continuing
 * that trajectory). */
static void call(const char *name, real tstart, real h0, int good, real hbad)
{
    bad_which = 0;
    void *w = make(NULL);
    real t = tstart, q[1] = { 1 }, p[1] = { 1 };
    int st = VIGEN_SUCCESS;
    for (int k = 0; k < good && st == VIGEN_SUCCESS; k++) st = T->step(w, &t, q, p, h0);
    if (st != VIGEN_SUCCESS) { printf("%s_setup=%d\n", name, st); T->free(w); return; }
    state before = { t, q[0], p[0] };
    st = T->step(w, &t, q, p, hbad);
    report(name, st, unchanged(&before, t, q, p), 1);
    T->free(w);
}

int main(int argc, char **argv)
{
    const real nan = (real)NAN, inf = (real)INFINITY;
    if (argc == 2 && strcmp(argv[1], "singular") == 0) {
        ham_t qp = { 1, qp_dq, qp_dp, NULL, NULL, 0, NULL };
        sep = 0; kahan = 1; solver = 1;
        bad_which = 0;
        void *w = make(&qp);
        real t = 0, q[1] = { 1 }, p[1] = { (real)0.5 };
        state before = { t, q[0], p[0] };
        int st = T->step(w, &t, q, p, 2);
        printf("singular_status=%d\nsingular_unchanged=%d\n", st, unchanged(&before, t, q, p));
        T->free(w);
        bad_which = 1; bad_value = nan; bad_after = -inf;
        w = make(&qp);
        st = T->step(w, &t, q, p, 2);
        printf("singular_nan_status=%d\nsingular_nan_unchanged=%d\n", st, unchanged(&before, t, q, p));
        T->free(w);
        return 0;
    }
    if (argc != 4) {
        fprintf(stderr, "usage: hostile_driver SEP KAHAN SOLVER | singular\n");
        return 2;
    }
    sep = atoi(argv[1]);
    kahan = atoi(argv[2]);
    solver = atoi(argv[3]);
    run("nan_first", 1, nan, -inf, 0, 1, 0);
    run("nan_mid", 1, nan, (real)0.55, 0, 1, 0);
    run("nanp_mid", 2, nan, (real)0.55, 0, 1, 0);
    run("inf_mid", 1, inf, (real)0.55, 0, 1, 0);
    run("nan_q", 0, 0, 0, 0, nan, 0);
    run("nan_p", 0, 0, 0, 0, 1, nan);
    /* t = NaN replaces the t of a trajectory; the others continue it */
    {
        void *w = make(NULL);
        real t = 0, q[1] = { 1 }, p[1] = { 0 };
        int st = 0;
        for (int k = 0; k < 3; k++) st |= T->step(w, &t, q, p, (real)0.1);
        t = nan;
        state before = { t, q[0], p[0] };
        st = st ? -1 : T->step(w, &t, q, p, (real)0.1);
        report("t_nan", st, unchanged(&before, t, q, p), 1);
        T->free(w);
    }
    call("h_nan", 0, (real)0.1, 3, nan);
    call("h_inf", 0, (real)0.1, 3, inf);
    call("h_minf", 0, (real)0.1, 3, -inf);
    call("tover_first", BIG, 1, 0, BIG);
    call("tover_mid", BIG, 1, 1, BIG);
    call("h_huge", 0, (real)0.1, 0, HUGE_H);
    return 0;
}
