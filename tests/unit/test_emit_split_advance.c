/* test_emit_split_advance.c — NAME_advance of the emitted splitting
 * steppers (`vigen emit`, split variant): many steps in one call, the
 * kernel's last substep merged with the next step's first and a processed
 * method's corrector applied once at each end.  Emitted at build time
 * (tests/CMakeLists.txt) from the library's wisdom_holman (kick-drift-kick,
 * the join a kick), saba_2 and saba_10_6_4 (the join a Kepler drift, flow 0,
 * which carries the time), wisdom_holman_corrected (a processed method) and
 * a Lie-Trotter splitting (tests/data/emit/split/lie_trotter.lua: its ends
 * are of different flows, nothing to join).  The truths:
 *   - H = A + eps B with A = (p^2 + q^2)/2 and B = q^2/2, the flows of both
 *     exact (a rotation and a kick); H is a harmonic oscillator of
 *     frequency sqrt(1 + eps), solved in closed form.  Over a fixed time the
 *     error of a method of generalized order (r1, r2, ...) is
 *     O(eps h^r1 + eps^2 h^r2 + ...) (Laskar & Robutel 2001; Blanes et al.
 *     2013): with eps so small that the first term dominates it falls by
 *     2^r1 per halving of h, with eps large enough and h small enough the
 *     eps^2 h^r2 term shows (wisdom_holman (2,2); saba_2 (4,2);
 *     wisdom_holman_corrected (4,2); saba_10_6_4 (10,6,4): on this
 *     problem its eps h^10 term stays at round-off, and the eps^2 h^6 and
 *     eps^3 h^4 terms show, the first also by its growth with eps^2);
 *   - NAME_advance against NAME_step called as often, on the same problem
 *     with a time-dependent perturbation (the kick p -= eps h (q + sin t),
 *     time frozen: a wrong time in a merged substep would show at O(h)):
 *     the same state to round-off, t bit for bit;
 *   - flow calls: the merged counts (wisdom_holman N + 1 kicks and N
 *     drifts, against 2N and N step by step), the corrector's substeps once;
 *   - a failure in any call of a flow (an error status, which ends the
 *     call at once, or a NaN, found at the end of its step at the latest):
 *     the status (VIGEN_ENONFINITE for the NaN), t, q, p those of the
 *     call's start bit for bit, steps not counted, one failed step;
 *   - the long double stepper of the processed method: NAME_advance
 *     against its NAME_step to long double round-off and against the double
 *     stepper to double round-off;
 *   - a saved state after NAME_advance continues bit for bit in a fresh
 *     workspace; NAME_step after NAME_advance continues the compensated
 *     time; bad arguments refused with nothing changed. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include <vigen/runtime.h>
#include "sa_wh.h"
#include "sa_saba2.h"
#include "sa_saba1064.h"
#include "sa_whc.h"
#include "sa_lt.h"
#include "sa_whc_ld.h"

/* ---- H = (p^2 + q^2)/2 + eps (q^2/2 + f q), f = 0 or sin t ---------------- */
typedef struct {
    double eps;
    int forced;        /* 1: the perturbation is eps (q^2/2 + q sin t) */
    long calls;        /* flow calls so far */
    long fail_at;      /* the call (1-based) that fails; 0 never */
    int fail_nan;      /* that call leaves a NaN instead of returning an error */
} osc;

/* a failure injected at one call, q changed either way (the stepper must
 * put it back) */
static int inject(osc *c, double *q, double *p)
{
    c->calls++;
    if (c->calls != c->fail_at) return VIGEN_SUCCESS;
    q[0] += 1;
    if (c->fail_nan) { p[0] = NAN; return VIGEN_SUCCESS; }
    return VIGEN_EUNSUPPORTED;
}

/* flow "kepler": the rotation of A by the angle h, exact */
static int rotation(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    const double c = cos(h), s = sin(h), q0 = q[0];
    q[0] = c * q0 + s * p[0];
    p[0] = c * p[0] - s * q0;
    return inject(ctx, q, p);
}

/* flow "interaction": the kick of eps B, exact (B depends on q and t only) */
static int kick(double t, double h, double *q, double *p, void *ctx)
{
    osc *c = ctx;
    p[0] -= c->eps * h * (q[0] + (c->forced ? sin(t) : 0));
    return inject(ctx, q, p);
}

static const vigen_flow_fn osc_flows[2] = { rotation, kick };

static vigen_split_problem osc_problem(osc *c)
{
    vigen_split_problem sp = { 1, 2, osc_flows, c, NULL, NULL };
    return sp;
}

/* The five steppers behind one set of signatures. */
typedef struct {
    const char *name;
    void *(*alloc)(const vigen_split_problem *sp);
    int (*step)(void *w, double *t, double *q, double *p, double h);
    int (*advance)(void *w, double *t, double *q, double *p, double h, long n);
    void (*free)(void *w);
    const vigen_stepper_type *type;
    unsigned long (*calls)(const void *w, int k);
    int r1, r2;                       /* the generalized order's first two entries */
} stepper;

#define STEPPER(N, R1, R2)                                                                                  \
    static void *N##_alloc_(const vigen_split_problem *sp) { return N##_alloc_split(sp, NULL); }          \
    static int N##_step_(void *w, double *t, double *q, double *p, double h) { return N##_step(w, t, q, p, h); } \
    static int N##_advance_(void *w, double *t, double *q, double *p, double h, long n)                    \
    {                                                                                                       \
        return N##_advance(w, t, q, p, h, n);                                                               \
    }                                                                                                       \
    static void N##_free_(void *w) { N##_free(w); }                                                         \
    static unsigned long N##_calls_(const void *w, int k) { return N##_flow_calls(w, k); }                  \
    static const stepper N##_s = { #N, N##_alloc_, N##_step_, N##_advance_, N##_free_, &N##_type, N##_calls_, R1, R2 };
STEPPER(sa_wh, 2, 2)
STEPPER(sa_saba2, 4, 2)
STEPPER(sa_saba1064, 10, 6)
STEPPER(sa_whc, 4, 2)
STEPPER(sa_lt, 1, 1)
static const stepper *const all[] = { &sa_wh_s, &sa_saba2_s, &sa_saba1064_s, &sa_whc_s, &sa_lt_s };
enum { NALL = sizeof all / sizeof all[0] };

/* ---- generalized orders, through NAME_advance ---------------------------- */

/* The error at T = 4 of n steps in one call, from (1, 0.5), against the
 * oscillator of frequency sqrt(1 + eps). */
static double adv_error(const stepper *s, double eps, long n)
{
    osc c = { eps, 0, 0, 0, 0 };
    vigen_split_problem sp = osc_problem(&c);
    void *w = s->alloc(&sp);
    double t = 0, q = 1, p = 0.5;
    const double T = 4, om = sqrt(1 + eps);
    CHECK(s->advance(w, &t, &q, &p, T / (double)n, n) == VIGEN_SUCCESS);
    s->free(w);
    const double qe = cos(om * T) + 0.5 / om * sin(om * T), pe = -om * sin(om * T) + 0.5 * cos(om * T);
    return hypot(q - qe, om * (p - pe));
}

/* The error ratio per halving of h from n0 steps, twice over, against 2^r. */
static void check_order(const stepper *s, double eps, long n0, int r, const char *term)
{
    const double e0 = adv_error(s, eps, n0), e1 = adv_error(s, eps, 2 * n0), e2 = adv_error(s, eps, 4 * n0);
    const double want = ldexp(1, r), r1 = e0 / e1, r2 = e1 / e2;
    CHECK_MSG(fabs(r1 / want - 1) < 0.15 && fabs(r2 / want - 1) < 0.15,
              "%s, eps = %g (the %s term): error ratios %.3f %.3f per halving from %ld steps, want %g "
              "(errors %.3g %.3g %.3g)", s->name, eps, term, r1, r2, n0, want, e0, e1, e2);
}

static void test_generalized_orders(void)
{
    /* eps h^r1 dominates: eps small */
    check_order(&sa_wh_s, 1e-6, 40, 2, "eps h^2");
    check_order(&sa_saba2_s, 1e-8, 8, 4, "eps h^4");
    check_order(&sa_whc_s, 1e-8, 8, 4, "eps h^4");
    check_order(&sa_lt_s, 1e-3, 40, 1, "eps h");
    /* eps^2 h^r2 dominates: eps larger, h small against sqrt(eps) */
    check_order(&sa_saba2_s, 0.1, 64, 2, "eps^2 h^2");
    check_order(&sa_whc_s, 0.1, 64, 2, "eps^2 h^2");
    /* saba_10_6_4 on this problem: the eps h^10 term stays below the
     * eps^2 h^6 term down to round-off, which shows for eps from 1e-4 on;
     * the eps^3 h^4 term for eps large */
    check_order(&sa_saba1064_s, 1e-3, 2, 6, "eps^2 h^6");
    check_order(&sa_saba1064_s, 0.3, 16, 4, "eps^3 h^4");
    /* ... and the eps^2 h^6 term is eps^2: 100 times larger for 10 times eps
     * (a term eps h^6, generalized order (6, ...), would be 10 times) */
    const double e2 = adv_error(&sa_saba1064_s, 1e-4, 4), e3 = adv_error(&sa_saba1064_s, 1e-3, 4),
                 e4 = adv_error(&sa_saba1064_s, 1e-2, 4);
    CHECK_MSG(fabs(e3 / e2 / 100 - 1) < 0.15 && fabs(e4 / e3 / 100 - 1) < 0.15,
              "saba_10_6_4: errors %.3g %.3g %.3g for eps 1e-4, 1e-3, 1e-2 at h = 1, want ratios 100", e2, e3, e4);
}

/* ---- NAME_advance against NAME_step --------------------------------------- */

/* n steps of h from (t0, 1, 0.5) by NAME_step and by NAME_advance (the
 * forced problem): the same t bit for bit, q and p to round-off; the flow
 * calls of the advance into calls[2]. */
static void compare(const stepper *s, double h, long n, unsigned long calls[2])
{
    osc c1 = { 0.3, 1, 0, 0, 0 }, c2 = c1;
    vigen_split_problem sp1 = osc_problem(&c1), sp2 = osc_problem(&c2);
    void *w1 = s->alloc(&sp1), *w2 = s->alloc(&sp2);
    CHECK(w1 != NULL && w2 != NULL);
    double t1 = 0.7, q1 = 1, p1 = 0.5, t2 = t1, q2 = q1, p2 = p1;
    for (long k = 0; k < n; k++) CHECK(s->step(w1, &t1, &q1, &p1, h) == VIGEN_SUCCESS);
    CHECK(s->advance(w2, &t2, &q2, &p2, h, n) == VIGEN_SUCCESS);
    const double tol = 64 * 2.2e-16 * (double)n;
    CHECK_MSG(t1 == t2, "%s, %ld steps of %g: t %.17g (step) and %.17g (advance)", s->name, n, h, t1, t2);
    CHECK_MSG(fabs(q1 - q2) < tol && fabs(p1 - p2) < tol, "%s, %ld steps of %g: (q, p) (%.17g, %.17g) by step, "
              "(%.17g, %.17g) by advance", s->name, n, h, q1, p1, q2, p2);
    CHECK(s->type->stats(w2)->steps == (unsigned long)n && s->type->stats(w2)->failed_steps == 0);
    calls[0] = s->calls(w2, 0);
    calls[1] = s->calls(w2, 1);
    s->free(w1);
    s->free(w2);
}

static void test_against_step(void)
{
    unsigned long c[2];
    for (int i = 0; i < NALL; i++) {
        compare(all[i], 0.37, 1, c);
        compare(all[i], 0.37, 2, c);
        compare(all[i], 0.1, 1000, c);
        compare(all[i], -0.05, 77, c);
    }
    /* the merged calls over N steps: wisdom_holman kick h/2, drift h, kick
     * h/2 -> N drifts and N + 1 kicks; saba_2 (drift, kick, drift, kick,
     * drift) -> 2N + 1 drifts and 2N kicks; the processed method C (5
     * substeps after merging: 3 drifts and 2 kicks), the kernel drift-kick-
     * drift merged, C^-1 -> N + 1 + 6 drifts and N + 4 kicks; Lie-Trotter
     * (drift, kick) unchanged -> N and N */
    compare(&sa_wh_s, 0.1, 50, c);
    CHECK(c[0] == 50 && c[1] == 51);
    compare(&sa_saba2_s, 0.1, 50, c);
    CHECK(c[0] == 101 && c[1] == 100);
    compare(&sa_whc_s, 0.1, 50, c);
    CHECK_MSG(c[0] == 57 && c[1] == 54, "wisdom_holman_corrected: %lu drifts and %lu kicks", c[0], c[1]);
    compare(&sa_lt_s, 0.1, 50, c);
    CHECK(c[0] == 50 && c[1] == 50);
}

/* ---- failures, restart, arguments ---------------------------------------- */

static void test_failures(void)
{
    for (int i = 0; i < NALL; i++) {
        const stepper *s = all[i];
        /* the calls of 10 steps, then a failure at each of them */
        osc c0 = { 0.3, 1, 0, 0, 0 };
        vigen_split_problem sp0 = osc_problem(&c0);
        void *w0 = s->alloc(&sp0);
        double t = 0.25, q = 1, p = 0.5;
        CHECK(s->advance(w0, &t, &q, &p, 0.1, 10) == VIGEN_SUCCESS);
        s->free(w0);
        for (int nan = 0; nan <= 1; nan++)
            for (long at = 1; at <= c0.calls; at++) {
                osc c = { 0.3, 1, 0, at, nan };
                vigen_split_problem sp = osc_problem(&c);
                void *w = s->alloc(&sp);
                t = 0.25; q = 1; p = 0.5;
                const double t0 = t, q0 = q, p0 = p;
                const int rc = s->advance(w, &t, &q, &p, 0.1, 10);
                CHECK_MSG(rc == (nan ? VIGEN_ENONFINITE : VIGEN_EUNSUPPORTED), "%s: failure at call %ld: %d",
                          s->name, at, rc);
                /* a status ends the call at once; a NaN at the end of its step */
                CHECK(nan ? c.calls >= at : c.calls == at);
                CHECK(memcmp(&t, &t0, sizeof t) == 0 && memcmp(&q, &q0, sizeof q) == 0 &&
                      memcmp(&p, &p0, sizeof p) == 0);
                CHECK(s->type->stats(w)->steps == 0 && s->type->stats(w)->failed_steps == 1);
                s->free(w);
            }
    }
}

static void test_restart_arguments(void)
{
    for (int i = 0; i < NALL; i++) {
        const stepper *s = all[i];
        osc c = { 0.3, 1, 0, 0, 0 };
        vigen_split_problem sp = osc_problem(&c);
        void *w = s->alloc(&sp), *x = s->alloc(&sp), *y = s->alloc(&sp);
        double t = 0, q = 1, p = 0.5;
        CHECK(s->advance(w, &t, &q, &p, 0.1, 37) == VIGEN_SUCCESS);
        /* a saved state continues bit for bit in a fresh workspace */
        unsigned char *buf = malloc(s->type->state_size(w));
        CHECK(buf != NULL && s->type->state_get(w, buf) == VIGEN_SUCCESS);
        CHECK(s->type->state_set(x, buf) == VIGEN_SUCCESS);
        double t2 = t, q2 = q, p2 = p;
        CHECK(s->advance(w, &t, &q, &p, 0.1, 29) == VIGEN_SUCCESS);
        CHECK(s->advance(x, &t2, &q2, &p2, 0.1, 29) == VIGEN_SUCCESS);
        CHECK(memcmp(&t, &t2, sizeof t) == 0 && memcmp(&q, &q2, sizeof q) == 0 && memcmp(&p, &p2, sizeof p) == 0);
        free(buf);
        /* steps after an advance continue the compensated time: 76 steps of
         * 0.1 by NAME_step alone give the same t */
        for (int k = 0; k < 10; k++) CHECK(s->step(w, &t, &q, &p, 0.1) == VIGEN_SUCCESS);
        double t3 = 0, q3 = 1, p3 = 0.5;
        for (int k = 0; k < 76; k++) CHECK(s->step(y, &t3, &q3, &p3, 0.1) == VIGEN_SUCCESS);
        CHECK_MSG(t == t3, "%s: t %.17g after advance and steps, %.17g by steps", s->name, t, t3);
        /* arguments: nothing changed, nothing called */
        const long calls = c.calls;
        const double tb = t, qb = q, pb = p;
        CHECK(s->advance(w, &t, &q, &p, 0.1, -1) == VIGEN_EINVAL);
        CHECK(s->advance(w, &t, &q, &p, INFINITY, 3) == VIGEN_EINVAL);
        CHECK(s->advance(w, &t, &q, &p, NAN, 3) == VIGEN_EINVAL);
        CHECK(s->advance(w, &t, &q, &p, 1e307, 1000) == VIGEN_EINVAL);   /* the end time overflows */
        CHECK(s->advance(w, NULL, &q, &p, 0.1, 3) == VIGEN_EINVAL);
        CHECK(s->advance(NULL, &t, &q, &p, 0.1, 3) == VIGEN_EINVAL);
        CHECK(s->advance(w, &t, &q, &p, 0.1, 0) == VIGEN_SUCCESS);
        CHECK(s->advance(w, &t, &q, &p, 0, 5) == VIGEN_SUCCESS);
        CHECK(t == tb && q == qb && p == pb && c.calls == calls);
        s->free(w);
        s->free(x);
        s->free(y);
    }
}

/* The long double stepper of the processed method: NAME_advance agrees
 * with the double one to double round-off, and with its own NAME_step to
 * long double round-off. */
static int rotation_ld(long double t, long double h, long double *q, long double *p, void *ctx)
{
    (void)t; (void)ctx;
    const long double c = cosl(h), s = sinl(h), q0 = q[0];
    q[0] = c * q0 + s * p[0];
    p[0] = c * p[0] - s * q0;
    return VIGEN_SUCCESS;
}
static int kick_ld(long double t, long double h, long double *q, long double *p, void *ctx)
{
    (void)t; (void)ctx;
    p[0] -= 0.3L * h * q[0];
    return VIGEN_SUCCESS;
}

static void test_long_double(void)
{
    const vigen_flow_fn_ld fl[2] = { rotation_ld, kick_ld };
    vigen_split_problem_ld spl = { 1, 2, fl, NULL, NULL, NULL };
    sa_whc_ld_workspace *a = sa_whc_ld_alloc_split(&spl, NULL), *b = sa_whc_ld_alloc_split(&spl, NULL);
    CHECK(a != NULL && b != NULL);
    long double ta = 0, qa = 1, pa = 0.5L, tb = 0, qb = 1, pb = 0.5L;
    CHECK(sa_whc_ld_advance(a, &ta, &qa, &pa, 0.01L, 400) == VIGEN_SUCCESS);
    for (int k = 0; k < 400; k++) CHECK(sa_whc_ld_step(b, &tb, &qb, &pb, 0.01L) == VIGEN_SUCCESS);
    CHECK(ta == tb && fabsl(qa - qb) < 1e-15L && fabsl(pa - pb) < 1e-15L);
    osc c = { 0.3, 0, 0, 0, 0 };
    vigen_split_problem sp = osc_problem(&c);
    sa_whc_workspace *w = sa_whc_alloc_split(&sp, NULL);
    double t = 0, q = 1, p = 0.5;
    CHECK(sa_whc_advance(w, &t, &q, &p, 0.01, 400) == VIGEN_SUCCESS);
    CHECK_MSG(fabsl(qa - q) < 1e-13L && fabsl(pa - p) < 1e-13L, "long double (%.17Lg, %.17Lg), double (%.17g, %.17g)",
              qa, pa, q, p);
    sa_whc_ld_free(a);
    sa_whc_ld_free(b);
    sa_whc_free(w);
}

int main(void)
{
    test_generalized_orders();
    test_against_step();
    test_failures();
    test_restart_arguments();
    test_long_double();
    TEST_MAIN_END();
}
