/* test_poincare_type.c — a Poincaré-transformed stepper through the runtime's
 * drivers (vigen_poincare_type, <vigen/poincare.h>), with the golden Gauss-2
 * stepper integrating K and the density g = r^(3/2) on Kepler e = 0.9
 * (period 2 pi).  Asserted, each against a source outside the type's code:
 *   - n steps through the type are the n fictive steps of
 *     vigen_poincare_integrate (capped at n steps) bit for bit, and the
 *     driver continues either trajectory to a physical time with the same
 *     bits;
 *   - output at physical times (vigen_integrate_at with the fictive step
 *     as h) has the error of the reference from Kepler's equation falling
 *     at order min(4, 4) = 4 as the fictive step halves (ratio near 16),
 *     and an output time at a step end gets that step's state bit for bit;
 *   - events: the passages through the pericentre (q_2 rising through 0)
 *     at t = 2 pi k (Kepler's third law), to the method's accuracy;
 *   - ensembles from a prototype on 1 and 2 threads have the bits of each
 *     trajectory alone, and a restart through the type those of the run
 *     that went on.  Links vigen_runtime and vigen_problems. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/ensemble.h>
#include <vigen/poincare.h>
#include <vigen/problems.h>
#include "testlib.h"
#include "../data/emit/golden/gauss2.c"

static const double PI = 3.14159265358979323846;
static vigen_problem *kepler;
static vigen_poincare_power power = { 1.5, 0, 2 };

static vigen_poincare_stepper *make(void)
{
    vigen_poincare_problem pp = { vigen_problem_hamiltonian(kepler), vigen_poincare_density_power, &power, NULL };
    vigen_poincare_stepper *s = vigen_poincare_stepper_alloc(&gauss2_type, &pp, NULL);
    CHECK(s != NULL);
    return s;
}

static void test_same_steps(void)
{
    const vigen_stepper_type *T = &vigen_poincare_type;
    vigen_poincare_stepper *s = make();
    double t, q[2], p[2];
    vigen_problem_initial(kepler, &t, q, p);
    CHECK(vigen_integrate(T, s, &t, q, p, 0.05, 500, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    CHECK(T->dim(s) == 2 && T->stats(s)->steps == 500);
    /* the driver of vigen/poincare.h, capped at the same number of steps */
    vigen_poincare_power pw = power;
    vigen_poincare_problem pp = { vigen_problem_hamiltonian(kepler), vigen_poincare_density_power, &pw, NULL };
    vigen_poincare *pc;
    CHECK(vigen_poincare_alloc(&pc, &pp) == VIGEN_SUCCESS);
    void *w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
    double t2, q2[2], p2[2];
    vigen_problem_initial(kepler, &t2, q2, p2);
    vigen_poincare_result res;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t2, q2, p2, 0.05, 1e6, 500, 0, NULL, NULL, &res) ==
          VIGEN_ESTOPPED);
    CHECK(res.capped && res.steps == 500);
    CHECK_MSG(t2 == t && memcmp(q2, q, sizeof q) == 0 && memcmp(p2, p, sizeof p) == 0,
              "the type's steps differ from vigen_poincare_integrate's: t %.17g vs %.17g", t, t2);
    /* on to t_end, 2 later: the driver after the type's steps continues the
     * trajectory, as the driver alone does */
    vigen_poincare_result r1, r2;
    const double t_end = t + 2;
    CHECK(vigen_poincare_stepper_integrate(s, &t, q, p, 0.05, t_end, 0, 0, NULL, NULL, &r1) == VIGEN_SUCCESS);
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t2, q2, p2, 0.05, t_end, 0, 0, NULL, NULL, &r2) ==
          VIGEN_SUCCESS);
    CHECK_MSG(t == t_end && t2 == t && memcmp(q2, q, sizeof q) == 0 && memcmp(p2, p, sizeof p) == 0 &&
                  r1.steps == r2.steps && r1.tau == r2.tau,
              "the type's trajectory continued by the driver differs from the driver's own");
    gauss2_type.free(w);
    vigen_poincare_free(pc);
    T->free(s);
}

enum { NOUT = 17 };

static double dense_error(double dtau)
{
    const vigen_stepper_type *T = &vigen_poincare_type;
    vigen_poincare_stepper *s = make();
    double t, q[2], p[2], t_out[NOUT], q_out[2 * NOUT], p_out[2 * NOUT];
    vigen_problem_initial(kepler, &t, q, p);
    for (int k = 0; k < NOUT; k++) t_out[k] = 4 * PI * (k + 0.6180339887) / NOUT;
    unsigned long done = 0;
    CHECK(vigen_integrate_at(T, s, &t, q, p, dtau, t_out, NOUT, q_out, p_out, &done) == VIGEN_SUCCESS);
    double worst = 0;
    for (int k = 0; k < NOUT; k++) {
        double qe[2], pe[2];
        CHECK(vigen_problem_reference(kepler, t_out[k], qe, pe));
        for (int i = 0; i < 2; i++)
            worst = fmax(worst, fmax(fabs(q_out[2 * k + i] - qe[i]), fabs(p_out[2 * k + i] - pe[i])));
    }
    /* the last step's end as an output time, from a fresh clone */
    vigen_poincare_stepper *s2 = T->clone(s);
    double t2, q2[2], p2[2], qo[2], po[2], te = t;
    vigen_problem_initial(kepler, &t2, q2, p2);
    CHECK(vigen_integrate_at(T, s2, &t2, q2, p2, dtau, &te, 1, qo, po, NULL) == VIGEN_SUCCESS);
    CHECK_MSG(t2 == t && memcmp(qo, q, sizeof q) == 0 && memcmp(po, p, sizeof p) == 0,
              "the output at a step end is not the step's state");
    T->free(s2);
    T->free(s);
    return worst;
}

static void test_dense(void)
{
    const double e1 = dense_error(0.04), e2 = dense_error(0.02), e3 = dense_error(0.01);
    fprintf(stderr, "  dense output at physical times: errors %.3e %.3e %.3e, ratios %.2f %.2f\n", e1, e2, e3,
            e1 / e2, e2 / e3);
    CHECK_MSG(e1 < 1e-3 && e2 / e3 > 12 && e2 / e3 < 20, "not order 4: ratio %.2f", e2 / e3);
}

static double q2_of(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    return q[1];
}

static double event_error(double dtau)
{
    vigen_poincare_stepper *s = make();
    double t, q[2], p[2], t_ev[8];
    size_t n = 0;
    vigen_problem_initial(kepler, &t, q, p);
    /* 3.2 periods: with dt = r dE (a = 1), the fictive time of a period is
     * the integral of r^(-3/2) dt = r^(-1/2) dE, r = 1 - e cos E, over
     * [0, 2 pi] (the midpoint rule: exact to round-off for this periodic
     * integrand) */
    double period = 0;
    for (int k = 0; k < 4096; k++) period += 2 * PI / 4096 / sqrt(1 - 0.9 * cos(2 * PI * (k + 0.5) / 4096));
    const unsigned long steps = (unsigned long)(3.2 * period / dtau);
    CHECK(vigen_integrate_events(&vigen_poincare_type, s, &t, q, p, dtau, steps, q2_of, 1, 0, NULL, t_ev, 8, &n) ==
          VIGEN_SUCCESS);
    CHECK_MSG(n == 3 && t > 6 * PI && t < 8 * PI, "%zu pericentre passages up to t = %g, expected 3", n, t);
    double worst = 0;
    for (size_t k = 0; k < n && k < 3; k++) worst = fmax(worst, fabs(t_ev[k] - 2 * PI * (double)(k + 1)));
    vigen_poincare_type.free(s);
    return worst;
}

static void test_events(void)
{
    const double e1 = event_error(0.04), e2 = event_error(0.02);
    fprintf(stderr, "  pericentre times: errors %.3e %.3e, ratio %.2f\n", e1, e2, e1 / e2);
    CHECK_MSG(e1 < 1e-3 && e1 / e2 > 8, "pericentre times not to the method's accuracy: %.3e %.3e", e1, e2);
}

enum { NTRAJ = 5, NSTEPS = 400 };

static void start(int i, double *t, double *q, double *p)
{
    vigen_problem_initial(kepler, t, q, p);
    const double c = cos(0.3 * i), s = sin(0.3 * i), q0 = q[0], p1 = p[1] * (1 - 0.01 * i);
    q[0] = c * q0, q[1] = s * q0;
    p[0] = -s * p1, p[1] = c * p1;
    *t = 0.5 * i;
}

static void test_ensemble_restart(void)
{
    const vigen_stepper_type *T = &vigen_poincare_type;
    vigen_poincare_stepper *proto = make();
    double rt[NTRAJ], rq[2 * NTRAJ], rp[2 * NTRAJ];
    for (int i = 0; i < NTRAJ; i++) {
        void *w = T->clone(proto);
        start(i, rt + i, rq + 2 * i, rp + 2 * i);
        CHECK(w && vigen_integrate(T, w, rt + i, rq + 2 * i, rp + 2 * i, 0.03, NSTEPS, 0, NULL, NULL, NULL) ==
                       VIGEN_SUCCESS);
        T->free(w);
    }
    for (int threads = 1; threads <= 2; threads++) {
        vigen_ensemble e = { T, NULL, NULL, NULL, NULL, 0, threads, proto };
        double t[NTRAJ], q[2 * NTRAJ], p[2 * NTRAJ];
        int status[NTRAJ];
        for (int i = 0; i < NTRAJ; i++) start(i, t + i, q + 2 * i, p + 2 * i);
        CHECK(vigen_integrate_ensemble(&e, NTRAJ, t, q, p, 0.03, NSTEPS, status, NULL) == VIGEN_SUCCESS);
        CHECK_MSG(memcmp(t, rt, sizeof t) == 0 && memcmp(q, rq, sizeof q) == 0 && memcmp(p, rp, sizeof p) == 0,
                  "%d thread(s): the ensemble differs from each trajectory alone", threads);
    }
    /* restart half way */
    double t, q[2], p[2];
    start(2, &t, q, p);
    CHECK(vigen_integrate(T, proto, &t, q, p, 0.03, NSTEPS / 2, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    void *buf = malloc(T->state_size(proto));
    CHECK(buf && T->state_get(proto, buf) == VIGEN_SUCCESS);
    double ts = t, qs[2] = { q[0], q[1] }, ps[2] = { p[0], p[1] };
    CHECK(vigen_integrate(T, proto, &t, q, p, 0.03, NSTEPS / 2, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    void *w = T->clone(proto);
    CHECK(w && T->state_set(w, buf) == VIGEN_SUCCESS);
    CHECK(vigen_integrate(T, w, &ts, qs, ps, 0.03, NSTEPS / 2, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    CHECK_MSG(ts == t && memcmp(qs, q, sizeof q) == 0 && memcmp(ps, p, sizeof p) == 0,
              "the restarted run differs from the one that went on");
    CHECK_MSG(ts == rt[2] && memcmp(qs, rq + 4, sizeof qs) == 0, "the restarted run differs from the whole run");
    ((unsigned char *)buf)[3] ^= 1;
    CHECK(T->state_set(w, buf) == VIGEN_ESTATE);
    free(buf);
    T->free(w);
    T->free(proto);
}

int main(void)
{
    char why[200];
    CHECK(vigen_problem_create(&kepler, "kepler", "e=0.9", why, sizeof why) == VIGEN_SUCCESS);
    test_same_steps();
    test_dense();
    test_events();
    test_ensemble_restart();
    vigen_problem_free(kepler);
    return testlib_failures != 0;
}
