/* test_lagrangian_drive.c — the Lagrangian integrators (vigen_hp_type,
 * vigen_midpoint_vi_type, vigen_trapezoidal_vi_type, made by
 * vigen_lagrangian_integrator_alloc) through the runtime's drivers, as the
 * emitted steppers are tested (test_dense.c, test_events.c,
 * test_ensemble.c, test_restart.c).  Each assertion against an independent
 * source:
 *   - the vector field is the Euler-Lagrange flow in (q, p): for the
 *     relativistic oscillator L = -sqrt(1 - v^2) - q^2/2 the closed form
 *     q' = p / sqrt(1 + p^2), p' = -q of H = sqrt(1 + p^2) + q^2/2; for
 *     L = v atan(v) - ln(1 + v^2)/2 (p = atan v) the field is v = tan p
 *     where |p| < pi/2 and an error status (no velocity has that momentum:
 *     Newton cannot converge) where |p| > pi/2, never a value;
 *   - output at any time: for the harmonic oscillator L = v^2/2 - q^2/2,
 *     exact solution q = cos t + sin t / 2, the interpolated state's error
 *     at off-grid times falls by 4 (order min(p, 4) = 2) as h halves, an
 *     output time at a step end gets that step's state bit for bit, and the
 *     steps, final state and the integrator's statistics are those of
 *     vigen_integrate bit for bit (the flow touches nothing the steps read);
 *     a type without a vector field (and no Hamiltonian given) is refused
 *     before any step;
 *   - events: the zero crossings of q, exactly at pi - atan 2 + k pi,
 *     located with the method's O(h^2) error (ratio 4 as h halves);
 *   - ensembles: trajectories from a prototype workspace on 1 and 2 threads
 *     have the bits of a fresh clone stepping each alone;
 *   - restart through the type: a run saved half way and continued in a
 *     fresh clone ends with the bits of the run that went on. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/ensemble.h>
#include <vigen/lagrangian.h>
#include "testlib.h"

static const double PI = 3.14159265358979323846;
static const char *const method_names[] = { "hp-trapezoidal", "hp-midpoint", "midpoint-vi", "trapezoidal-vi" };
enum { NMETHODS = 4 };

/* ---- the harmonic oscillator L = v^2/2 - q^2/2, H = p^2/2 + q^2/2 ------- */
static void ho_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    o[0] = -q[0];
}
static void ho_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = v[0];
}
static void ho_g(double t, const double *q, const double *p, double *v, void *c)
{
    (void)t; (void)q; (void)c;
    v[0] = p[0];
}
static void ho_Lqq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = -1;
}
static void ho_Lvv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = 1;
}
static void ho_Lqv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = 0;
}
static const vigen_lagrangian ho = { 1, ho_dLdq, ho_dLdv, NULL, NULL, ho_Lqq, ho_Lvv, ho_Lqv };

/* q(0) = 1, p(0) = 1/2: q = cos t + sin t / 2, p = -sin t + cos t / 2 */
static void ho_exact(double t, double *q, double *p)
{
    q[0] = cos(t) + 0.5 * sin(t);
    p[0] = -sin(t) + 0.5 * cos(t);
}

static void *make(int method, const vigen_lagrangian *lag, vigen_lgrad_fn g, const vigen_stepper_type **T)
{
    void *w = vigen_lagrangian_integrator_alloc(method, lag, g, NULL, T);
    CHECK_MSG(w != NULL && *T != NULL, "%s: no workspace", method_names[method]);
    return w;
}

/* ---- the vector field ------------------------------------------------------ */

/* L = -sqrt(1 - v^2) - q^2/2: p = v / sqrt(1 - v^2) */
static void rel_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    o[0] = -q[0];
}
static void rel_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = v[0] / sqrt(1 - v[0] * v[0]);
}
/* L = v atan v - ln(1 + v^2)/2: dL/dv = atan v, d2L/dv2 = 1/(1 + v^2) */
static void at_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = 0;
}
static void at_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = atan(v[0]);
}
static void at_Lvv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = 1 / (1 + v[0] * v[0]);
}

static void test_field(void)
{
    const vigen_lagrangian rel = { 1, rel_dLdq, rel_dLdv, NULL, NULL, NULL, NULL, NULL };
    const vigen_lagrangian at = { 1, at_dLdq, at_dLdv, NULL, NULL, NULL, at_Lvv, NULL };
    for (int m = 0; m < NMETHODS; m++) {
        if (m == VIGEN_LAGRANGIAN_MIDPOINT_VI) continue;   /* needs g; its field is the same code */
        const vigen_stepper_type *T = NULL;
        void *w = make(m, &rel, NULL, &T);
        if (w == NULL) continue;
        CHECK(T->dim(w) == 1 && T->alloc == NULL);
        const double qs[] = { 0.3, -1.2, 2.0 }, ps[] = { 0.7, -3.0, 25.0 };
        double worst = 0;
        for (int k = 0; k < 3; k++) {
            double dq, dp;
            CHECK(T->vector_field(w, 0.1, qs + k, ps + k, &dq, &dp) == VIGEN_SUCCESS);
            worst = fmax(worst, fabs(dq - ps[k] / sqrt(1 + ps[k] * ps[k])) + fabs(dp + qs[k]));
        }
        CHECK_MSG(worst < 1e-14, "%s: relativistic field off by %.3e", method_names[m], worst);
        T->free(w);
        w = make(m, &at, NULL, &T);
        if (w == NULL) continue;
        double q = 0, p = 1, dq = 0, dp = 0;
        CHECK(T->vector_field(w, 0, &q, &p, &dq, &dp) == VIGEN_SUCCESS && fabs(dq - tan(1.0)) < 1e-14);
        p = 2;   /* atan v = 2 has no solution */
        const int st = T->vector_field(w, 0, &q, &p, &dq, &dp);
        CHECK_MSG(st != VIGEN_SUCCESS, "%s: p beyond the Legendre map's range gave v = %g", method_names[m], dq);
        T->free(w);
    }
}

/* ---- output at any time ------------------------------------------------------- */

static double q_of(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    return q[0];
}

enum { NOUT = 23 };

/* The worst error at NOUT off-grid times in [0, 4 pi] with step h; also
 * checks the run against vigen_integrate's. */
static double dense_error(int m, double h)
{
    const vigen_stepper_type *T = NULL;
    void *w = make(m, &ho, ho_g, &T);
    if (w == NULL) return INFINITY;
    double t = 0, q = 1, p = 0.5, t_out[NOUT], q_out[NOUT], p_out[NOUT];
    for (int k = 0; k < NOUT; k++) t_out[k] = 4 * PI * (k + 0.6180339887) / NOUT;
    unsigned long done = 0;
    CHECK(vigen_integrate_at(T, w, &t, &q, &p, h, t_out, NOUT, q_out, p_out, &done) == VIGEN_SUCCESS);
    const vigen_stats st = *T->stats(w);
    double worst = 0;
    for (int k = 0; k < NOUT; k++) {
        double qe, pe;
        ho_exact(t_out[k], &qe, &pe);
        worst = fmax(worst, fmax(fabs(q_out[k] - qe), fabs(p_out[k] - pe)));
    }
    /* the same steps by vigen_integrate, from a fresh clone */
    void *w2 = T->clone(w);
    double t2 = 0, q2 = 1, p2 = 0.5;
    CHECK(w2 && vigen_integrate(T, w2, &t2, &q2, &p2, h, done, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    CHECK_MSG(t2 == t && q2 == q && p2 == p, "%s: the final state differs from vigen_integrate's", method_names[m]);
    const vigen_stats *st2 = T->stats(w2);
    CHECK_MSG(st2->steps == st.steps && st2->dHdq_evals == st.dHdq_evals && st2->dHdp_evals == st.dHdp_evals &&
                  st2->iterations == st.iterations,
              "%s: the statistics differ from vigen_integrate's", method_names[m]);
    /* an output time at a step end: that step's state */
    double te = t2, qo, po;
    t2 = 0, q2 = 1, p2 = 0.5;
    T->reset(w2);
    CHECK(vigen_integrate_at(T, w2, &t2, &q2, &p2, h, &te, 1, &qo, &po, NULL) == VIGEN_SUCCESS);
    CHECK_MSG(t2 == te && qo == q && po == p, "%s: the output at a step end is not the step's state",
              method_names[m]);
    T->free(w2);
    T->free(w);
    return worst;
}

/* A type without a vector field and no Hamiltonian given: refused before
 * any step. */
static void test_no_field(void)
{
    const vigen_stepper_type *T = NULL;
    void *w = make(VIGEN_LAGRANGIAN_HP_MIDPOINT, &ho, NULL, &T);
    if (w == NULL) return;
    vigen_stepper_type bare = *T;
    bare.vector_field = NULL;
    double t = 0, q = 1, p = 0.5, t_out = 1, qo, po, t_ev[1];
    size_t n = 7;
    CHECK(vigen_integrate_at(&bare, w, &t, &q, &p, 0.1, &t_out, 1, &qo, &po, NULL) == VIGEN_EINVAL);
    CHECK(vigen_integrate_events(&bare, w, &t, &q, &p, 0.1, 10, q_of, 0, 0, NULL, t_ev, 1, &n) == VIGEN_EINVAL);
    CHECK(t == 0 && q == 1 && p == 0.5 && n == 0 && T->stats(w)->steps == 0);
    T->free(w);
}

static void test_dense(void)
{
    for (int m = 0; m < NMETHODS; m++) {
        const double e1 = dense_error(m, 0.1), e2 = dense_error(m, 0.05), e3 = dense_error(m, 0.025);
        fprintf(stderr, "  %s: dense errors %.3e %.3e %.3e, ratios %.2f %.2f\n", method_names[m], e1, e2, e3,
                e1 / e2, e2 / e3);
        CHECK_MSG(e1 < 0.05 && e1 / e2 > 3.5 && e1 / e2 < 4.5 && e2 / e3 > 3.5 && e2 / e3 < 4.5,
                  "%s: not order 2 at off-grid times", method_names[m]);
    }
}

/* ---- events --------------------------------------------------------------- */

enum { NEV = 3 };

static double event_error(int m, double h)
{
    const vigen_stepper_type *T = NULL;
    void *w = make(m, &ho, ho_g, &T);
    if (w == NULL) return INFINITY;
    double t = 0, q = 1, p = 0.5, t_ev[8];
    size_t n = 0;
    const unsigned long steps = (unsigned long)(10.0 / h);
    CHECK(vigen_integrate_events(T, w, &t, &q, &p, h, steps, q_of, 0, 0, NULL, t_ev, 8, &n) == VIGEN_SUCCESS);
    CHECK_MSG(n == NEV, "%s: %zu zero crossings of q in [0, 10], expected 3", method_names[m], n);
    double worst = 0;
    for (size_t k = 0; k < n && k < NEV; k++) worst = fmax(worst, fabs(t_ev[k] - (PI - atan(2.0) + k * PI)));
    T->free(w);
    return worst;
}

static void test_events(void)
{
    for (int m = 0; m < NMETHODS; m++) {
        const double e1 = event_error(m, 0.1), e2 = event_error(m, 0.05), e3 = event_error(m, 0.025);
        fprintf(stderr, "  %s: event time errors %.3e %.3e %.3e, ratios %.2f %.2f\n", method_names[m], e1, e2, e3,
                e1 / e2, e2 / e3);
        CHECK_MSG(e1 < 0.05 && e1 / e2 > 3.5 && e1 / e2 < 4.5 && e2 / e3 > 3.5 && e2 / e3 < 4.5,
                  "%s: event times not located to the method's order 2", method_names[m]);
    }
}

/* ---- ensembles and restart ------------------------------------------------- */

enum { NTRAJ = 7, NSTEPS = 300 };

static void test_ensemble(void)
{
    for (int m = 0; m < NMETHODS; m++) {
        const vigen_stepper_type *T = NULL;
        void *proto = make(m, &ho, ho_g, &T);
        if (proto == NULL) continue;
        double ref_t[NTRAJ], ref_q[NTRAJ], ref_p[NTRAJ];
        for (int i = 0; i < NTRAJ; i++) {
            void *w = T->clone(proto);
            ref_t[i] = 0.1 * i, ref_q[i] = 1 + 0.3 * i, ref_p[i] = 0.5 - 0.2 * i;
            CHECK(w && vigen_integrate(T, w, ref_t + i, ref_q + i, ref_p + i, 0.02, NSTEPS, 0, NULL, NULL, NULL) ==
                           VIGEN_SUCCESS);
            T->free(w);
        }
        for (int threads = 1; threads <= 2; threads++) {
            vigen_ensemble e = { T, NULL, NULL, NULL, NULL, 0, threads, proto };
            double t[NTRAJ], q[NTRAJ], p[NTRAJ];
            int status[NTRAJ];
            for (int i = 0; i < NTRAJ; i++) t[i] = 0.1 * i, q[i] = 1 + 0.3 * i, p[i] = 0.5 - 0.2 * i;
            CHECK(vigen_integrate_ensemble(&e, NTRAJ, t, q, p, 0.02, NSTEPS, status, NULL) == VIGEN_SUCCESS);
            int same = 1;
            for (int i = 0; i < NTRAJ; i++) same &= t[i] == ref_t[i] && q[i] == ref_q[i] && p[i] == ref_p[i];
            CHECK_MSG(same, "%s, %d thread(s): the ensemble differs from each trajectory alone", method_names[m],
                      threads);
        }
        CHECK_MSG(T->stats(proto)->steps == 0, "%s: the prototype stepped", method_names[m]);
        T->free(proto);
    }
}

static void test_restart(void)
{
    for (int m = 0; m < NMETHODS; m++) {
        const vigen_stepper_type *T = NULL;
        void *w = make(m, &ho, ho_g, &T);
        if (w == NULL) continue;
        double t = 0, q = 1, p = 0.5, h = 0.03;
        CHECK(vigen_integrate(T, w, &t, &q, &p, h, 100, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
        void *buf = malloc(T->state_size(w));
        CHECK(buf && T->state_get(w, buf) == VIGEN_SUCCESS);
        double ts = t, qs = q, ps = p;
        CHECK(vigen_integrate(T, w, &t, &q, &p, h, 100, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
        void *w2 = T->clone(w);
        CHECK(w2 && T->state_set(w2, buf) == VIGEN_SUCCESS);
        CHECK(vigen_integrate(T, w2, &ts, &qs, &ps, h, 100, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
        CHECK_MSG(ts == t && qs == q && ps == p, "%s: the restarted run differs", method_names[m]);
        CHECK_MSG(T->stats(w2)->steps == T->stats(w)->steps, "%s: the restarted statistics differ", method_names[m]);
        free(buf);
        T->free(w2);
        T->free(w);
    }
}

int main(void)
{
    test_field();
    test_no_field();
    test_dense();
    test_events();
    test_ensemble();
    test_restart();
    if (testlib_failures) fprintf(stderr, "%d check(s) failed\n", testlib_failures);
    return testlib_failures != 0;
}
