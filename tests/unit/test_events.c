/* test_events.c — events (vigen_integrate_events and its _sys, _ld and _q
 * variants) on Kepler's problem started at periapsis, with the golden
 * Gauss-2 stepper of tests/data/emit/golden and the long double and
 * __float128 triple jump of test_dense_kepler.h.  g = q.p (half the time
 * derivative of |q|^2) rises through zero at periapsis, at the multiples of
 * the period 2 pi, and falls through zero at apoapsis, at odd multiples of
 * pi, where the exact state is q = (-(1 + e), 0), p = (0, -sqrt((1 - e) /
 * (1 + e))).  Asserted:
 *   - the event times agree with these multiples, and their error falls by
 *     2^4 under step halving (a 4th-order method and an O(h^4) extension);
 *   - direction filtering: rising only, falling only, both (alternating);
 *   - each event time is a zero of g along the extension to the round-off of
 *     the time in the real type (a few eps (1 + |t dg/dt|)), also for long
 *     double and __float128, where the double root alone would be far off;
 *   - a terminal event stops at the first apoapsis with the exact state
 *     there, after the steps of vigen_integrate; a new run continues from it;
 *   - the steps and final state of a run with events are vigen_integrate's
 *     bit for bit, slopes are evaluated only for the steps that hold an
 *     event (two per event), more events than room are counted;
 *   - refused arguments and a non-finite g. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <vigen/runtime.h>
#include "testlib.h"
#include "test_dense_kepler.h"
#include "../data/emit/golden/gauss2.c"

#define MAXEV 16

/* g = q.p in each real type. */
#define RADIAL_DEFINE(R, S)                                    \
    static R radial##S(R t, const R *q, const R *p, void *ctx) \
    {                                                          \
        (void)t;                                               \
        (void)ctx;                                             \
        return q[0] * p[0] + q[1] * p[1];                      \
    }
RADIAL_DEFINE(double, )
RADIAL_DEFINE(long double, _ld)
#ifdef VIGEN_HAVE_FLOAT128
RADIAL_DEFINE(vigen_float128, _q)
#endif

/* Events of g = q.p over `periods` periods of Kepler with eccentricity e,
 * steps_per_period steps a period.  Returns the number found. */
static size_t kepler_events(double e, unsigned long steps_per_period, double periods, int direction, int terminal,
                            double *t_ev, vigen_dense_stats *st, double *t, double *q, double *p)
{
    vigen_hamiltonian sys = kepler_problem();
    void *w = gauss2_type.alloc(&sys, NULL);
    size_t n = 0;
    *t = 0;
    kepler_start(e, q, p);
    int status = vigen_integrate_events_sys(&gauss2_type, w, NULL, t, q, p, 2 * M_PI / (double)steps_per_period,
                                            (unsigned long)(periods * (double)steps_per_period), radial, direction,
                                            terminal, NULL, t_ev, MAXEV, &n, st);
    CHECK_MSG(status == VIGEN_SUCCESS, "e = %g: status %d", e, status);
    CHECK_MSG(st->steps == gauss2_type.stats(w)->steps, "the stepper took %lu steps, the driver reports %lu",
              gauss2_type.stats(w)->steps, st->steps);
    gauss2_type.free(w);
    return n;
}

/* Largest |t_k - (k + offset) 2 pi| over the events, NAN if the count is not
 * `expected`. */
static double event_error(const double *t_ev, size_t n, size_t expected, double offset, size_t stride)
{
    double worst = 0;
    if (n != expected) return NAN;
    for (size_t k = 0; k < n; k += stride)
        worst = fmax(worst, fabs(t_ev[k] - 2 * M_PI * ((double)(k / stride) + offset)));
    return worst;
}

static void test_passages(double e, unsigned long n0)
{
    double err[3], t_ev[MAXEV], t, q[2], p[2];
    vigen_dense_stats st;
    for (int k = 0; k < 3; k++) {
        size_t n = kepler_events(e, n0 << k, 5.1, +1, 0, t_ev, &st, &t, q, p);
        err[k] = event_error(t_ev, n, 5, 1, 1);
        CHECK_MSG(n == 5, "e = %g: %zu periapsis passages in 5.1 periods", e, n);
        CHECK_MSG(st.dHdq_evals == 2 * n && st.dHdp_evals == 2 * n, "e = %g: %lu slopes for %zu events", e,
                  st.dHdq_evals, n);
        CHECK_MSG(st.event_evals > st.steps + 1, "e = %g: g called %lu times in %lu steps", e, st.event_evals,
                  st.steps);
        if (k == 0)
            fprintf(stderr, "  e = %.1f: g called %.1f times  beyond the step ends per event, %.1f root iterations\n",
                    e, (double)(st.event_evals - st.steps - 1) / (double)n, (double)st.root_iterations / (double)n);
    }
    fprintf(stderr, "  periapsis e = %.1f: time errors %.3e %.3e %.3e, ratios %.2f %.2f\n", e, err[0], err[1], err[2],
            err[0] / err[1], err[1] / err[2]);
    CHECK_MSG(err[0] < 1e-3 && err[1] / err[2] > 12 && err[1] / err[2] < 20,
              "e = %g: event time errors %.3e %.3e %.3e", e, err[0], err[1], err[2]);
}

static void test_directions(void)
{
    double t_ev[MAXEV], t, q[2], p[2];
    vigen_dense_stats st;
    size_t n = kepler_events(0.5, 400, 5.1, -1, 0, t_ev, &st, &t, q, p);
    double err = event_error(t_ev, n, 5, 0.5, 1);
    CHECK_MSG(err < 1e-5, "falling: %zu events, error %.3e", n, err);
    n = kepler_events(0.5, 400, 5.1, 0, 0, t_ev, &st, &t, q, p);
    err = fmax(event_error(t_ev, n, 10, 0.5, 2), event_error(t_ev + 1, n - 1, 9, 1, 2));
    CHECK_MSG(err < 1e-5, "both: %zu events, error %.3e", n, err);
    /* more events than room: all counted, the first kept */
    double few[2];
    vigen_hamiltonian sys = kepler_problem();
    void *w = gauss2_type.alloc(&sys, NULL);
    t = 0;
    kepler_start(0.5, q, p);
    CHECK(vigen_integrate_events(&gauss2_type, w, &t, q, p, 2 * M_PI / 400, 2040, radial, 0, 0, NULL, few, 2, &n) ==
          VIGEN_SUCCESS);
    CHECK_MSG(n == 10 && fabs(few[0] - M_PI) < 1e-5 && fabs(few[1] - 2 * M_PI) < 1e-5, "%zu events, first %g %g", n,
              few[0], few[1]);
    gauss2_type.free(w);
}

/* The steps and the final state are those of vigen_integrate. */
static void test_same_steps(void)
{
    double t_ev[MAXEV], t, q[2], p[2], t2 = 0, q2[2], p2[2];
    vigen_dense_stats st;
    size_t n = kepler_events(0.7, 300, 5.5, 0, 0, t_ev, &st, &t, q, p);
    vigen_hamiltonian sys = kepler_problem();
    void *w = gauss2_type.alloc(&sys, NULL);
    kepler_start(0.7, q2, p2);
    CHECK(vigen_integrate(&gauss2_type, w, &t2, q2, p2, 2 * M_PI / 300, st.steps, 0, NULL, NULL, NULL) ==
          VIGEN_SUCCESS);
    CHECK_MSG(n == 11 && st.steps == 1650 && memcmp(&t, &t2, sizeof t) == 0 && memcmp(q, q2, sizeof q) == 0 &&
                  memcmp(p, p2, sizeof p) == 0, "%zu events, %lu steps: the final state differs from vigen_integrate's",
              n, st.steps);
    gauss2_type.free(w);
}

/* Terminal: the first apoapsis, its exact state; then the run goes on. */
static void test_terminal(void)
{
    const double e = 0.5, h = 2 * M_PI / 400;
    double t_ev[MAXEV], t, q[2], p[2];
    vigen_dense_stats st;
    size_t n = kepler_events(e, 400, 3, -1, 1, t_ev, &st, &t, q, p);
    const double pa = sqrt((1 - e) / (1 + e));
    CHECK_MSG(n == 1 && t == t_ev[0] && fabs(t - M_PI) < 1e-6 && st.steps == 200 + (t > 200 * h),
              "terminal: %zu events, stopped at t = %.17g after %lu steps", n, t, st.steps);
    CHECK_MSG(fabs(q[0] + 1 + e) < 1e-6 && fabs(q[1]) < 1e-6 && fabs(p[0]) < 1e-6 && fabs(p[1] + pa) < 1e-6,
              "terminal state (%g %g %g %g), expected (%g 0 0 %g)", q[0], q[1], p[0], p[1], -1 - e, -pa);
    /* the state is the extension of the last step after the steps of
     * vigen_integrate: the same as vigen_integrate_at there */
    vigen_hamiltonian sys = kepler_problem();
    void *w = gauss2_type.alloc(&sys, NULL);
    double t2 = 0, q2[2], p2[2], qo[2], po[2];
    kepler_start(e, q2, p2);
    CHECK(vigen_integrate_at(&gauss2_type, w, &t2, q2, p2, h, &t, 1, qo, po, NULL) == VIGEN_SUCCESS);
    CHECK_MSG(fabs(qo[0] - q[0]) < 1e-14 && fabs(qo[1] - q[1]) < 1e-14 && fabs(po[0] - p[0]) < 1e-14 &&
                  fabs(po[1] - p[1]) < 1e-14, "terminal state differs from the extension by %.3e",
              fmax(fabs(qo[0] - q[0]), fabs(po[1] - p[1])));
    gauss2_type.free(w);
    /* continue in a workspace that ran up to the event: next periapsis */
    w = gauss2_type.alloc(&sys, NULL);
    t2 = 0;
    kepler_start(e, q2, p2);
    CHECK(vigen_integrate(&gauss2_type, w, &t2, q2, p2, h, st.steps, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    CHECK(vigen_integrate_events(&gauss2_type, w, &t, q, p, h, 400, radial, +1, 1, NULL, t_ev, MAXEV, &n) ==
          VIGEN_SUCCESS);
    CHECK_MSG(n == 1 && fabs(t - 2 * M_PI) < 1e-6 && fabs(q[0] - (1 - e)) < 1e-6,
              "after the terminal event: %zu events, stopped at %.17g", n, t);
    gauss2_type.free(w);
}

static int nan_after;
static double radial_nan(double t, const double *q, const double *p, void *ctx)
{
    return t > nan_after ? NAN : radial(t, q, p, ctx);
}

static void test_refused(void)
{
    vigen_hamiltonian sys = kepler_problem();
    void *w = gauss2_type.alloc(&sys, NULL);
    double t = 0, q[2], p[2], t_ev[MAXEV];
    size_t n = 5;
    kepler_start(0.5, q, p);
    CHECK(vigen_integrate_events(&gauss2_type, w, &t, q, p, 0.01, 10, radial, 2, 0, NULL, t_ev, MAXEV, &n) ==
          VIGEN_EINVAL && n == 0 && t == 0);
    CHECK(vigen_integrate_events(&gauss2_type, w, &t, q, p, 0.01, 10, NULL, 0, 0, NULL, t_ev, MAXEV, &n) ==
          VIGEN_EINVAL && t == 0);
    CHECK(vigen_integrate_events(&gauss2_type, w, &t, q, p, 0.01, 10, radial, 0, 0, NULL, NULL, 1, &n) ==
          VIGEN_EINVAL && t == 0);
    CHECK(vigen_integrate_events(&gauss2_type, w, &t, q, p, INFINITY, 10, radial, 0, 0, NULL, t_ev, MAXEV, &n) ==
          VIGEN_EINVAL && t == 0);
    nan_after = 1;
    CHECK(vigen_integrate_events(&gauss2_type, w, &t, q, p, 0.01, 1000, radial_nan, 0, 0, NULL, t_ev, MAXEV, &n) ==
          VIGEN_ENONFINITE && t > 1 && t < 1.02);
    gauss2_type.free(w);
}

/* Each event is a zero of g along the extension to the time's round-off,
 * in every real type: g at the event (through vigen_integrate_at from the
 * same start) below a few eps (1 + |t| |dg/dt|), dg/dt = |p|^2 - 1/|q|.
 * The event times also match the periapsis passages. */
#define TEST_ROOTS(R, S, EPS)                                                                               \
    static void test_roots##S(const vigen_stepper_type##S *T, const char *label, int per)                   \
    {                                                                                                       \
        vigen_hamiltonian##S sys = { 2, kepler_dHdq##S, kepler_dHdp##S, kepler_H##S, NULL, 1, NULL };       \
        const R e = (R)0.8, h = 2 * (R)KEPLER_PI / per;                                                     \
        R t = 0, q[2], p[2], t_ev[MAXEV];                                                                   \
        size_t n = 0;                                                                                       \
        void *w = T->alloc(&sys, NULL);                                                                     \
        kepler_start##S(e, q, p);                                                                           \
        CHECK(vigen_integrate_events##S(T, w, &t, q, p, h, 31 * per / 10, radial##S, 0, 0, NULL, t_ev,      \
                                        MAXEV, &n) == VIGEN_SUCCESS);                                       \
        T->free(w);                                                                                         \
        CHECK_MSG(n == 6, "%s: %zu events in 3.1 periods", label, n);                                       \
        double worst = 0, worst_time = 0;                                                                   \
        for (size_t k = 0; k < n && k < MAXEV; k++) {                                                       \
            R t2 = 0, q2[2], p2[2], qo[2], po[2];                                                           \
            w = T->alloc(&sys, NULL);                                                                       \
            kepler_start##S(e, q2, p2);                                                                     \
            CHECK(vigen_integrate_at##S(T, w, &t2, q2, p2, h, t_ev + k, 1, qo, po, NULL) == VIGEN_SUCCESS); \
            T->free(w);                                                                                     \
            R g = radial##S(t_ev[k], qo, po, NULL), r = qo[0] * qo[0] + qo[1] * qo[1];                      \
            R slope = po[0] * po[0] + po[1] * po[1] - 1 / (R)sqrtl(r);                                      \
            if (g < 0) g = -g;                                                                              \
            if (slope < 0) slope = -slope;                                                                  \
            const double ratio = (double)(g / ((R)EPS * (1 + t_ev[k] * slope)));                            \
            if (ratio > worst) worst = ratio;                                                               \
            const double dt = fabs((double)t_ev[k] - M_PI * (double)(k + 1));                               \
            if (dt > worst_time) worst_time = dt;                                                           \
        }                                                                                                   \
        fprintf(stderr, "  %s: |g| at the events up to %.2f eps (1 + |t dg/dt|), times within %.2e\n",      \
                label, worst, worst_time);                                                                  \
        CHECK_MSG(worst < 16, "%s: |g| at an event is %.1f eps (1 + |t dg/dt|)", label, worst);             \
        CHECK_MSG(worst_time < 1e-3, "%s: event time off by %.3e", label, worst_time);                      \
    }

TEST_ROOTS(double, , DBL_EPSILON)
TEST_ROOTS(long double, _ld, LDBL_EPSILON)
#ifdef VIGEN_HAVE_FLOAT128
TEST_ROOTS(vigen_float128, _q, 1.925929944387235853055977942584927319e-34L)
#endif

int main(void)
{
    test_passages(0.5, 200);
    test_passages(0.9, 1000);
    test_directions();
    test_same_steps();
    test_terminal();
    test_refused();
    test_roots(&gauss2_type, "double Gauss-2", 600);
    test_roots_ld(&yoshida_type_ld, "long double triple jump", 2000);
#ifdef VIGEN_HAVE_FLOAT128
    test_roots_q(&yoshida_type_q, "float128 triple jump", 2000);
#endif
    TEST_MAIN_END();
}
