/* test_poincare.c — the Poincaré time transformation (<vigen/poincare.h>)
 * with the golden Gauss-2 stepper of tests/data/emit/golden, against truths
 * from outside its code: central differences of K for both gradients (a
 * time-dependent H, a density depending on t, q and p, off the level K = 0);
 * Kepler (e = 0.9) with the reference from Kepler's equation, the period
 * 2 pi a^(3/2) of Kepler's third law, the eccentric anomaly as the fictive
 * time of g = r (t = E - e sin E); energy errors against constant steps
 * given at least the same work, and bounded over 10^4 periods; a forced
 * oscillator's closed-form solution; the refusals (density not positive or
 * not finite, a time-dependent H without dH/dt, bad arguments).  Links
 * vigen_runtime and vigen_problems. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <vigen/poincare.h>
#include <vigen/problems.h>
#include "testlib.h"
#include "../data/emit/golden/gauss2.c"

static const double PI = 3.14159265358979323846;

/* ---- a time-dependent problem: H = |p|^2/2 + q0^2/2 + q1^4/4 + eps q0 sin(w t) */
static const double EPS = 0.3, OMEGA = 1.7;
static double td_H(double t, const double *q, const double *p, void *c)
{
    (void)c;
    return (p[0] * p[0] + p[1] * p[1]) / 2 + q[0] * q[0] / 2 + q[1] * q[1] * q[1] * q[1] / 4
           + EPS * q[0] * sin(OMEGA * t);
}
static void td_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)p; (void)c;
    o[0] = q[0] + EPS * sin(OMEGA * t);
    o[1] = q[1] * q[1] * q[1];
}
static void td_dp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; o[1] = p[1]; }
static double td_dt(double t, const double *q, const double *p, void *c) { (void)p; (void)c; return EPS * OMEGA * q[0] * cos(OMEGA * t); }

/* g = (1 + q0^2 + p1^2 / 2) (2 + cos t) */
static double td_g(double t, const double *q, const double *p, double *gq, double *gp, double *gt, void *c)
{
    (void)c;
    double a = 1 + q[0] * q[0] + p[1] * p[1] / 2, b = 2 + cos(t);
    gq[0] = 2 * q[0] * b;
    gp[1] = p[1] * b;
    *gt = -a * sin(t);
    return a * b;
}

/* Both gradients of K against central differences of K itself, at a point
 * with H + e != 0 so that the terms (H + e) grad g count. */
static void test_gradient_fd(void)
{
    vigen_hamiltonian sys = { 2, td_dq, td_dp, td_H, NULL, 0, NULL };
    vigen_poincare_problem pb = { &sys, td_g, NULL, td_dt };
    vigen_poincare *pc;
    CHECK(vigen_poincare_alloc(&pc, &pb) == VIGEN_SUCCESS);
    const vigen_hamiltonian *K = vigen_poincare_hamiltonian(pc);
    CHECK(K->dim == 3 && K->separable == 0 && K->H != NULL);
    double q[2] = { 0.7, -0.4 }, p[2] = { 0.3, 0.9 }, Q[3], P[3];
    CHECK(vigen_poincare_extend(pc, 0.8, q, p, Q, P) == VIGEN_SUCCESS);
    CHECK(Q[0] == q[0] && Q[1] == q[1] && Q[2] == 0.8 && P[2] == -td_H(0.8, q, p, NULL));
    P[2] += 0.37;                                            /* off the level K = 0 */
    double gq[2] = { 0 }, gp[2] = { 0 }, gt = 0;
    double direct = td_g(Q[2], Q, P, gq, gp, &gt, NULL) * (td_H(Q[2], Q, P, NULL) + P[2]);
    CHECK(fabs(K->H(5.0, Q, P, K->ctx) - direct) <= 1e-15 * fabs(direct));
    double dQ[3], dP[3];
    K->dHdq(5.0, Q, P, dQ, K->ctx);
    K->dHdp(5.0, Q, P, dP, K->ctx);
    for (int part = 0; part < 2; part++)
        for (int k = 0; k < 3; k++) {
            double *x = part ? P : Q, x0 = x[k], d = 1e-5;
            x[k] = x0 + d;
            double kp = K->H(0, Q, P, K->ctx);
            x[k] = x0 - d;
            double km = K->H(0, Q, P, K->ctx);
            x[k] = x0;
            double fd = (kp - km) / (2 * d), an = part ? dP[k] : dQ[k];
            CHECK_MSG(fabs(fd - an) <= 1e-8 * (1 + fabs(an)), "dK/d%s[%d]: %.12g vs differences %.12g",
                      part ? "P" : "Q", k, an, fd);
        }
    vigen_poincare_free(pc);
}

/* ---- Kepler through the problem library ---- */
typedef struct {
    const vigen_problem *pb;
    double H0, worst;               /* largest |H - H0| seen */
    double T, band[10];             /* largest |H - H0| in each tenth of [0, T] */
    /* periapsis passages: q1 crossing 0 upwards on the positive q0 side */
    double tprev, qprev[2], pprev[2];
    double passages[64];
    int npass;
} kwatch;

static int kwatch_obs(unsigned long step, double tau, double t, const double *q, const double *p, void *ctx)
{
    kwatch *kw = ctx;
    (void)tau;
    double d = fabs(vigen_problem_energy(kw->pb, t, q, p) - kw->H0);
    if (d > kw->worst) kw->worst = d;
    if (kw->T > 0) {
        int b = (int)(10 * t / kw->T);
        b = b < 0 ? 0 : b > 9 ? 9 : b;
        if (d > kw->band[b]) kw->band[b] = d;
    }
    if (step > 0 && kw->qprev[1] < 0 && q[1] >= 0 && q[0] > 0 && kw->npass < 64) {
        /* the crossing of q1 = 0 on the cubic Hermite interpolant in t
         * (q1' = p1 at both ends), by bisection */
        double h = t - kw->tprev, y0 = kw->qprev[1], y1 = q[1], m0 = h * kw->pprev[1], m1 = h * p[1];
        double lo = 0, hi = 1;
        for (int it = 0; it < 60; it++) {
            double s = (lo + hi) / 2, s2 = s * s, s3 = s2 * s;
            double y = (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * m1;
            if (y < 0) lo = s; else hi = s;
        }
        kw->passages[kw->npass++] = kw->tprev + h * (lo + hi) / 2;
    }
    kw->tprev = t;
    memcpy(kw->qprev, q, sizeof kw->qprev);
    memcpy(kw->pprev, p, sizeof kw->pprev);
    return 0;
}

/* Runs Poincaré Gauss-2 with g = r^alpha from Kepler's initial value to t_end;
 * returns the status; *work counts every call of a user function (gradients,
 * H and the density alike). */
static int kepler_poincare(const vigen_problem *pb, double alpha, double dtau, double t_end, int solver, kwatch *kw,
                           double *t, double *q, double *p, vigen_poincare_result *res, unsigned long *work)
{
    vigen_poincare_power pw = { alpha, 0, 2 };
    vigen_poincare_problem pp = { vigen_problem_hamiltonian(pb), vigen_poincare_density_power, &pw, NULL };
    vigen_poincare *pc;
    if (vigen_poincare_alloc(&pc, &pp) != VIGEN_SUCCESS) return VIGEN_ENOMEM;
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.solver = solver;
    void *w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), &opt);
    vigen_problem_initial(pb, t, q, p);
    kw->pb = pb;
    kw->H0 = vigen_problem_energy(pb, *t, q, p);
    int st = vigen_poincare_integrate(&gauss2_type, w, pc, t, q, p, dtau, t_end, 0, 1, kwatch_obs, kw, res);
    const vigen_poincare_stats *S = vigen_poincare_get_stats(pc);
    *work = S->dHdq_evals + S->dHdp_evals + S->H_evals + S->density_evals + S->dHdt_evals;
    gauss2_type.free(w);
    vigen_poincare_free(pc);
    return st;
}

/* At the same work the energy error is at least ten times smaller than with
 * constant steps: the constant-step run gets at least as many gradient calls
 * as the transformed run makes calls of all user functions. */
static void test_kepler_work(const vigen_problem *pb)
{
    const double T = 100 * 2 * PI;
    kwatch kw = { 0 };
    double t, q[2], p[2];
    vigen_poincare_result res;
    unsigned long work;
    CHECK(kepler_poincare(pb, 2, 0.1, T, VIGEN_SOLVER_FIXED_POINT, &kw, &t, q, p, &res, &work) == VIGEN_SUCCESS);
    CHECK(t == T);
    /* the fewest constant steps (to 1 %) whose gradient calls reach the work */
    double worst_c = 0;
    unsigned long calls = 0, N = res.steps, lo = 0, hi = 0;
    for (int round = 0; round < 24 && (hi == 0 || hi - lo > hi / 100); round++) {
        gauss2_workspace *w = gauss2_alloc(vigen_problem_hamiltonian(pb), NULL);
        kwatch kc = { 0 };
        kc.pb = pb;
        vigen_problem_initial(pb, &t, q, p);
        kc.H0 = vigen_problem_energy(pb, t, q, p);
        int st = VIGEN_SUCCESS;
        for (unsigned long k = 0; k < N && st == VIGEN_SUCCESS; k++) {
            st = gauss2_step(w, &t, q, p, T / (double)N);
            kwatch_obs(k + 1, 0, t, q, p, &kc);
        }
        unsigned long c = gauss2_stats(w)->dHdq_evals + gauss2_stats(w)->dHdp_evals;
        gauss2_free(w);
        if (st == VIGEN_SUCCESS && c >= work) { hi = N; calls = c; worst_c = kc.worst; }
        else lo = N;                           /* too little work, or steps too large to solve */
        N = hi ? lo + (hi - lo) / 2 : 2 * N;
    }
    CHECK(calls >= work);
    CHECK_MSG(worst_c >= 10 * kw.worst, "energy error %.3g with g = r^2 (%lu calls), %.3g with constant steps "
              "(%lu gradients): ratio %.3g < 10", kw.worst, work, worst_c, calls, worst_c / kw.worst);
    printf("Kepler e = 0.9, 100 periods: energy error %.3g (g = r^2, %lu calls) vs %.3g (constant steps, %lu "
           "gradients)\n", kw.worst, work, worst_c, calls);
}

/* 10^4 periods: the largest energy error of the last tenth is that of the
 * first (no drift), and the whole run stays near the first period's. */
static void test_kepler_bounded(const vigen_problem *pb)
{
    const double T = 1e4 * 2 * PI;
    kwatch kw = { 0 };
    kw.T = T;
    double t, q[2], p[2];
    vigen_poincare_result res;
    unsigned long work;
    CHECK(kepler_poincare(pb, 1.5, 0.2, T, VIGEN_SOLVER_FIXED_POINT, &kw, &t, q, p, &res, &work) == VIGEN_SUCCESS);
    CHECK(t == T && kw.worst < 1e-4);
    CHECK_MSG(kw.band[9] <= 1.1 * kw.band[0] && kw.band[0] <= 1.1 * kw.band[9],
              "energy error %.3g in the first thousand periods, %.3g in the last", kw.band[0], kw.band[9]);
    /* e stays -H0 for an H without t (dK/dt = 0): H + e is the energy error */
    CHECK(fabs(res.energy_error - (vigen_problem_energy(pb, t, q, p) - kw.H0)) <= 1e-15);
    printf("Kepler e = 0.9, 10^4 periods (g = r^1.5, dtau = 0.2, %lu steps): energy error %.3g first tenth, %.3g "
           "last tenth\n", res.steps, kw.band[0], kw.band[9]);
}

/* The period from the periapsis passages (Kepler's third law, a = -1/(2 H0))
 * and the end state against Kepler's equation; the end time exactly. */
static void test_kepler_period_and_end(const vigen_problem *pb)
{
    kwatch kw = { 0 };
    double t, q[2], p[2], qr[2], pr[2];
    vigen_poincare_result res;
    unsigned long work;
    const double t_end = 123.456;
    CHECK(kepler_poincare(pb, 1.5, 0.05, t_end, VIGEN_SOLVER_NEWTON, &kw, &t, q, p, &res, &work) == VIGEN_SUCCESS);
    CHECK(t == t_end);
    CHECK_MSG(fabs(res.t_mismatch) <= 2 * DBL_EPSILON * t_end, "t mismatch %g", res.t_mismatch);
    CHECK(res.last_dtau > 0 && res.last_dtau < 0.05 && res.end_trials >= 1);
    vigen_problem_reference(pb, t_end, qr, pr);
    double err = hypot(q[0] - qr[0], q[1] - qr[1]) + hypot(p[0] - pr[0], p[1] - pr[1]);
    CHECK_MSG(err < 1e-5, "state at t = %g off the solution of Kepler's equation by %g", t_end, err);
    double a = -1 / (2 * kw.H0), period = 2 * PI * pow(a, 1.5);
    CHECK(kw.npass == 19);                                 /* 123.456 / (2 pi) = 19.6 */
    if (kw.npass == 19) {
        double measured = (kw.passages[18] - kw.passages[0]) / 18;
        CHECK_MSG(fabs(kw.passages[0] - period) < 1e-7, "first passage at %.12g, period %.12g", kw.passages[0], period);
        CHECK_MSG(fabs(measured - period) < 1e-7, "period from 19 passages %.12g, Kepler's third law %.12g", measured,
                  period);
    }

    /* forward to t = 10, then a second call continues the trajectory back to
     * t = 0 with negative fictive steps */
    double t0, q0[2], p0[2];
    vigen_problem_initial(pb, &t0, q0, p0);
    vigen_poincare_power pw = { 1.5, 0, 2 };
    vigen_poincare_problem pp = { vigen_problem_hamiltonian(pb), vigen_poincare_density_power, &pw, NULL };
    vigen_poincare *pc;
    CHECK(vigen_poincare_alloc(&pc, &pp) == VIGEN_SUCCESS);
    void *w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
    double tb = t0, qb[2] = { q0[0], q0[1] }, pb2[2] = { p0[0], p0[1] };
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &tb, qb, pb2, 0.05, 10.0, 0, 0, NULL, NULL, &res) == VIGEN_SUCCESS);
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &tb, qb, pb2, -0.05, 0.0, 0, 0, NULL, NULL, &res) == VIGEN_SUCCESS);
    CHECK(tb == 0.0);
    CHECK_MSG(hypot(qb[0] - q0[0], qb[1] - q0[1]) < 1e-5 && hypot(pb2[0] - p0[0], pb2[1] - p0[1]) < 1e-5,
              "back at t = 0: q off by %g", hypot(qb[0] - q0[0], qb[1] - q0[1]));
    gauss2_type.free(w);
    vigen_poincare_free(pc);
}

/* g = r: dt/dE = a^(1/2) r for the eccentric anomaly E, so with a = 1 the
 * fictive time is E, 2 pi k after k periods. */
static void test_kepler_eccentric_anomaly(const vigen_problem *pb)
{
    double err[2];
    for (int k = 0; k < 2; k++) {
        kwatch kw = { 0 };
        double t, q[2], p[2];
        vigen_poincare_result res;
        unsigned long work;
        const unsigned long n = 400UL << k;        /* steps per period */
        CHECK(kepler_poincare(pb, 1, 2 * PI / (double)n, 3 * 2 * PI, VIGEN_SOLVER_FIXED_POINT, &kw, &t, q, p, &res,
                              &work) == VIGEN_SUCCESS);
        CHECK(res.steps == 3 * n || res.steps == 3 * n + 1);
        err[k] = fabs(res.tau - 3 * 2 * PI);
    }
    /* the method's error, of order 4: 16 times smaller at half the step */
    CHECK_MSG(err[0] < 2e-6 && err[1] < err[0] / 10, "fictive time after three periods off 6 pi by %.3g, "
              "then %.3g at half the step", err[0], err[1]);
}

/* ---- forced oscillator: q'' + q = -eps sin(w t), H = p^2/2 + q^2/2 + eps q sin(w t) */
static double fo_H(double t, const double *q, const double *p, void *c) { (void)c; return p[0] * p[0] / 2 + q[0] * q[0] / 2 + EPS * q[0] * sin(OMEGA * t); }
static void fo_dq(double t, const double *q, const double *p, double *o, void *c) { (void)p; (void)c; o[0] = q[0] + EPS * sin(OMEGA * t); }
static void fo_dp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }
static double fo_dt(double t, const double *q, const double *p, void *c) { (void)p; (void)c; return EPS * OMEGA * q[0] * cos(OMEGA * t); }
static double fo_g(double t, const double *q, const double *p, double *gq, double *gp, double *gt, void *c)
{
    (void)t; (void)c;
    double s = 1 + q[0] * q[0] + p[0] * p[0];
    gq[0] = -2 * q[0] / (s * s);
    gp[0] = -2 * p[0] / (s * s);
    return 1 / s;
}
/* a continuous g that reaches 0 only freezes the physical time (dt/dtau = g
 * -> 0); a density that is not positive is a wrong one, here a jump */
static double shifted_g(double t, const double *q, const double *p, double *gq, double *gp, double *gt, void *c)
{
    (void)t; (void)p; (void)gq; (void)gp; (void)gt; (void)c;
    return q[0] > -0.5 ? 1.0 : -1.0;
}
static double nan_g(double t, const double *q, const double *p, double *gq, double *gp, double *gt, void *c)
{
    (void)q; (void)p; (void)gq; (void)gp; (void)gt; (void)c;
    return t < 1 ? 1.0 : NAN;                   /* refused at the first stage past t = 1 */
}
static int stop_at_5(unsigned long step, double tau, double t, const double *q, const double *p, void *c)
{
    (void)tau; (void)t; (void)q; (void)p; (void)c;
    return step >= 5;
}

static void test_forced_oscillator(void)
{
    vigen_hamiltonian sys = { 1, fo_dq, fo_dp, fo_H, NULL, 0, NULL };
    vigen_poincare_problem pb = { &sys, fo_g, NULL, fo_dt };
    vigen_poincare *pc;
    CHECK(vigen_poincare_alloc(&pc, &pb) == VIGEN_SUCCESS);
    void *w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
    double t = 0, q[1] = { 1.2 }, p[1] = { -0.4 };
    const double q0 = q[0], p0 = p[0], t_end = 10;
    vigen_poincare_result res;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.01, t_end, 0, 0, NULL, NULL, &res) == VIGEN_SUCCESS);
    const double c = EPS / (1 - OMEGA * OMEGA), A = q0, B = p0 + c * OMEGA;
    const double qe = A * cos(t_end) + B * sin(t_end) - c * sin(OMEGA * t_end);
    const double pe = -A * sin(t_end) + B * cos(t_end) - c * OMEGA * cos(OMEGA * t_end);
    CHECK(t == t_end);
    CHECK_MSG(fabs(q[0] - qe) < 1e-7 && fabs(p[0] - pe) < 1e-7, "forced oscillator at t = 10: (%.10g, %.10g), "
              "exact (%.10g, %.10g)", q[0], p[0], qe, pe);
    /* e follows -H(t): the level H + e stays at the method's error */
    CHECK_MSG(fabs(res.energy_error) < 1e-7, "H + e = %g", res.energy_error);
    gauss2_type.free(w);
    vigen_poincare_free(pc);

    /* the same H without dH/dt is refused, naming the field */
    pb.dHdt = NULL;
    CHECK(vigen_poincare_alloc(&pc, &pb) == VIGEN_SUCCESS);
    w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
    t = 0.3; q[0] = q0; p[0] = p0;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.01, t_end, 0, 0, NULL, NULL, &res) == VIGEN_EINVAL);
    CHECK(strstr(vigen_poincare_message(pc), "dHdt") != NULL);
    CHECK(t == 0.3 && q[0] == q0 && p[0] == p0);
    gauss2_type.free(w);
    vigen_poincare_free(pc);
}

/* Bad densities, arguments and the stops. */
static double ho_H(double t, const double *q, const double *p, void *c) { (void)t; (void)c; return (q[0] * q[0] + p[0] * p[0]) / 2; }
static void ho_dq(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)p; (void)c; o[0] = q[0]; }
static void ho_dp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }

static void test_refusals(void)
{
    vigen_hamiltonian sys = { 1, ho_dq, ho_dp, ho_H, NULL, 1, NULL };
    vigen_poincare_problem pb = { &sys, shifted_g, NULL, NULL };
    vigen_poincare *pc;
    vigen_poincare_result res;
    CHECK(vigen_poincare_alloc(&pc, &pb) == VIGEN_SUCCESS);
    void *w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
    double t = 0, q[1] = { 1 }, p[1] = { 0 };
    /* q = cos t reaches -1/2 at t = 2 pi / 3: the step that gets there is refused */
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.05, 10, 0, 0, NULL, NULL, &res) == VIGEN_EINVAL);
    CHECK_MSG(strstr(vigen_poincare_message(pc), "not positive") != NULL, "message: %s", vigen_poincare_message(pc));
    CHECK_MSG(t > 1.5 && t < 2.3 && isfinite(p[0]), "stopped at t = %g, q = %g", t, q[0]);
    CHECK(fabs(q[0] - cos(t)) < 1e-6);                     /* a state of the orbit, not of the failed step */
    /* a start where g <= 0: refused before any step, nothing changed */
    t = 0; q[0] = -0.7; p[0] = 0;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.05, 10, 0, 0, NULL, NULL, &res) == VIGEN_EINVAL);
    CHECK(strstr(vigen_poincare_message(pc), "not positive") != NULL && t == 0 && q[0] == -0.7 && res.steps == 0);
    gauss2_type.free(w);
    vigen_poincare_free(pc);

    pb.density = nan_g;
    CHECK(vigen_poincare_alloc(&pc, &pb) == VIGEN_SUCCESS);
    w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
    t = 0; q[0] = 1; p[0] = 0;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.1, 10, 0, 0, NULL, NULL, &res) == VIGEN_ENONFINITE);
    CHECK(strstr(vigen_poincare_message(pc), "not finite") != NULL && t < 1.2 && isfinite(q[0]));
    /* arguments: wrong sign of dtau, non-finite values, NULLs */
    t = 0; q[0] = 1; p[0] = 0;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, -0.1, 10, 0, 0, NULL, NULL, &res) == VIGEN_EINVAL);
    CHECK(strstr(vigen_poincare_message(pc), "sign") != NULL);
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.1, INFINITY, 0, 0, NULL, NULL, &res) == VIGEN_EINVAL);
    q[0] = NAN;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.1, 0.5, 0, 0, NULL, NULL, &res) == VIGEN_EINVAL);
    CHECK(vigen_poincare_integrate(&gauss2_type, NULL, pc, &t, q, p, 0.1, 0.5, 0, 0, NULL, NULL, &res) == VIGEN_EINVAL);
    gauss2_type.free(w);
    vigen_poincare_free(pc);

    vigen_hamiltonian noH = { 1, ho_dq, ho_dp, NULL, NULL, 1, NULL };
    vigen_poincare_problem bad = { &noH, fo_g, NULL, NULL };
    CHECK(vigen_poincare_alloc(&pc, &bad) == VIGEN_EINVAL && pc == NULL);
    bad.sys = &sys;
    bad.density = NULL;
    CHECK(vigen_poincare_alloc(&pc, &bad) == VIGEN_EINVAL);

    /* the step cap and the observer stop: VIGEN_ESTOPPED at a state of the orbit */
    pb.density = fo_g;
    CHECK(vigen_poincare_alloc(&pc, &pb) == VIGEN_SUCCESS);
    w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
    t = 0; q[0] = 1; p[0] = 0;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.1, 10, 7, 0, NULL, NULL, &res) == VIGEN_ESTOPPED);
    CHECK(res.capped == 1 && res.steps == 7 && t > 0 && t < 10 && fabs(q[0] - cos(t)) < 1e-5);
    t = 0; q[0] = 1; p[0] = 0;
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.1, 10, 0, 1, stop_at_5, NULL, &res) == VIGEN_ESTOPPED);
    CHECK(res.capped == 0 && res.steps == 5);
    /* t_end = t: nothing to do */
    double t1 = t, q1 = q[0];
    CHECK(vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, 0.1, t, 0, 0, NULL, NULL, &res) == VIGEN_SUCCESS);
    CHECK(t == t1 && q[0] == q1 && res.steps == 0);
    gauss2_type.free(w);
    vigen_poincare_free(pc);
}

int main(void)
{
    vigen_problem *pb;
    char why[200];
    test_gradient_fd();
    test_forced_oscillator();
    test_refusals();
    CHECK(vigen_problem_create(&pb, "kepler", "e=0.9", why, sizeof why) == VIGEN_SUCCESS);
    test_kepler_eccentric_anomaly(pb);
    test_kepler_period_and_end(pb);
    test_kepler_work(pb);
    test_kepler_bounded(pb);
    vigen_problem_free(pb);
    TEST_MAIN_END();
}
