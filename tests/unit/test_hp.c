/* test_hp.c — the Hamilton–Pontryagin steppers of <vigen/lagrangian.h>
 * (trivial velocity map; the parametric map has test_velocity_map.c), each
 * against an independent source:
 *   - trapezoidal rule, L = 1/2 v^T M v - V: the Stormer–Verlet formulas
 *     written out here, over 1000 non-uniform steps of the Henon–Heiles
 *     potential, with the exact and the difference Jacobian;
 *   - midpoint rule: the implicit midpoint rule as the emitted Gauss s = 1
 *     stepper (tests/data/emit/midpoint.lua), and the trapezoidal rule as
 *     the emitted Stormer–Verlet stepper, over 1000 non-uniform steps
 *     (driver tests/data/lagrangian/hp_vs_prk.c);
 *   - the relativistic particle L = -m c^2 sqrt(1 - |v|^2/c^2) - k|q|^2/2:
 *     the energy c sqrt(m^2 c^2 + |p|^2) + V(q) has no drift over 10^5 steps
 *     and the angular momentum q x p (Noether, rotations) is conserved to
 *     round-off; at 0.95 c, where plain Newton steps overshoot beyond c,
 *     the steps succeed with a small energy error;
 *   - a charged particle in an axially symmetric static magnetic field,
 *     L = 1/2 |v|^2 + A(q).v - phi(q): bounded energy 1/2 |p - A|^2 + phi over
 *     10^5 steps, canonical angular momentum x p_y - y p_x (Noether) to
 *     round-off;
 *   - the exact Jacobian (second derivatives of L) against differences:
 *     same trajectory, Newton's iteration counts (a wrong block shows);
 *   - the predictor: extrapolation saves iterations and changes nothing
 *     beyond round-off; a state changed from outside restarts the history
 *     (bit for bit a fresh workspace);
 *   - symmetry: a step with -h undoes a step with h (both discrete
 *     Lagrangians are symmetric), also for a time-dependent L;
 *   - order 2 against the exact solution of a forced oscillator (time
 *     dependent L, so the time arguments are checked too);
 *   - t as a compensated sum of the steps, v_{n+1/2} = (q_{n+1} - q_n)/h,
 *     reset, statistics;
 *   - bad input: validation reasons, h zero or not finite, NaN from a
 *     callback, no solution of the step equations (h far too large), a
 *     degenerate Lagrangian (dL/dv not invertible), each leaving the state
 *     unchanged bit for bit. */
#include <math.h>
#include <string.h>
#include <vigen/lagrangian.h>
#include "test_emit_harness.h"
#include "support/strbuf.h"

#define NOUNUSED (void)t; (void)c

/* ---- Henon–Heiles with a diagonal mass matrix ---------------------------- */
static const double hh_m[2] = { 1.5, 0.7 };
static void hh_gradV(const double *q, double *g)
{
    g[0] = q[0] + 2 * q[0] * q[1];
    g[1] = q[1] + q[0] * q[0] - q[1] * q[1];
}
static void hh_dq(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)v;
    hh_gradV(q, o);
    o[0] = -o[0];
    o[1] = -o[1];
}
static void hh_dv(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)q;
    o[0] = hh_m[0] * v[0];
    o[1] = hh_m[1] * v[1];
}
static void hh_qq(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)v;
    o[0] = -(1 + 2 * q[1]); o[1] = -2 * q[0];
    o[2] = -2 * q[0];       o[3] = -(1 - 2 * q[1]);
}
static void hh_vv(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)q; (void)v;
    o[0] = hh_m[0]; o[1] = 0; o[2] = 0; o[3] = hh_m[1];
}
static void zero_qv(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)q; (void)v;
    memset(o, 0, 4 * sizeof(double));
}

static double step_size(int k) { return 0.05 + 0.04 * sin(0.37 * k); }

/* Stormer–Verlet, written out: p+ = p - h/2 V'(q), q1 = q + h M^-1 p+, p1 = p+ - h/2 V'(q1) */
static void verlet(double *q, double *p, double h)
{
    double g[2];
    hh_gradV(q, g);
    for (int i = 0; i < 2; i++) p[i] -= 0.5 * h * g[i];
    for (int i = 0; i < 2; i++) q[i] += h * p[i] / hh_m[i];
    hh_gradV(q, g);
    for (int i = 0; i < 2; i++) p[i] -= 0.5 * h * g[i];
}

static void test_verlet(void)
{
    for (int exact = 0; exact < 2; exact++) {
        vigen_lagrangian lag = { 2, hh_dq, hh_dv, NULL, NULL, NULL, NULL, NULL };
        if (exact) { lag.d2Ldq2 = hh_qq; lag.d2Ldv2 = hh_vv; lag.d2Ldqdv = zero_qv; }
        vigen_hp *w = vigen_hp_alloc(&lag, VIGEN_HP_TRAPEZOIDAL, NULL, NULL);
        CHECK(w != NULL);
        if (!w) return;
        double t = 0, q[2] = { 0.1, -0.2 }, p[2] = { 0.25, 0.1 }, qv[2] = { 0.1, -0.2 }, pv[2] = { 0.25, 0.1 };
        double err = 0;
        int st = 0;
        for (int k = 0; k < 1000 && st == 0; k++) {
            double h = step_size(k), q0[2] = { q[0], q[1] };
            st = vigen_hp_step(w, &t, q, p, h);
            verlet(qv, pv, h);
            for (int i = 0; i < 2; i++) {
                err = fmax(err, fmax(fabs(q[i] - qv[i]), fabs(p[i] - pv[i])));
                /* v_{n+1/2} is (q_{n+1} - q_n)/h for the trivial map */
                double v = vigen_hp_velocity(w)[i];
                CHECK_MSG(fabs(v - (q[i] - q0[i]) / h) <= 1e-13 * fmax(1.0, fabs(v)), "v %g vs %g", v, (q[i] - q0[i]) / h);
            }
        }
        CHECK_MSG(st == 0, "status %d", st);
        CHECK_MSG(err < 1e-13, "HP trapezoidal vs Stormer-Verlet (exact Jacobian %d): %.3e", exact, err);
        const vigen_stats *s = vigen_hp_stats(w);
        CHECK(s->steps == 1000 && s->failed_steps == 0 && s->dHdq_evals > 0 && s->dHdp_evals > 0);
        CHECK(s->iterations >= s->steps && s->hessian_evals > 0 && s->lu_decompositions == s->hessian_evals);
        CHECK(vigen_hp_params(w) == NULL && vigen_hp_nparams(w) == 0);
        /* reset forgets statistics and history: a fresh run is bit for bit the first one */
        double t1 = t, q1[2] = { q[0], q[1] }, p1[2] = { p[0], p[1] };
        vigen_hp_reset(w);
        CHECK(vigen_hp_stats(w)->steps == 0 && vigen_hp_stats(w)->iterations == 0);
        vigen_hp *w2 = vigen_hp_alloc(&lag, VIGEN_HP_TRAPEZOIDAL, NULL, NULL);
        double t2 = t1, q2[2] = { q1[0], q1[1] }, p2[2] = { p1[0], p1[1] };
        for (int k = 0; k < 5; k++) {
            vigen_hp_step(w, &t1, q1, p1, 0.07);
            vigen_hp_step(w2, &t2, q2, p2, 0.07);
        }
        CHECK(memcmp(q1, q2, sizeof q1) == 0 && memcmp(p1, p2, sizeof p1) == 0 && t1 == t2);
        vigen_hp_free(w2);
        vigen_hp_free(w);
    }
}

/* ---- against emitted steppers -------------------------------------------- */
static void test_emitted(void)
{
    if (!harness_init("hp")) return;
    struct { const char *file, *name; int rule; } runs[] = {
        { "tests/data/emit/midpoint.lua", "midpoint", VIGEN_HP_MIDPOINT },
        { "tests/data/emit/verlet.lua", "stormer_verlet", VIGEN_HP_TRAPEZOIDAL },
    };
    for (int r = 0; r < 2; r++) {
        if (!harness_emit(runs[r].file, runs[r].name, VIGEN_REAL_DOUBLE, NULL)) continue;
        char *exe = harness_build("gcc", "../lagrangian/hp_vs_prk.c", runs[r].name, "", runs[r].name);
        if (!exe) continue;
        char *cmd = vigen_strdup_printf("%s hp %d 1000", exe, runs[r].rule);
        char *out = harness_capture(cmd);
        CHECK_MSG(harness_value(out, "status", -1) == 0 && harness_value(out, "steps", 0) == 1000, "%s: %s", runs[r].name, out);
        double dq = harness_value(out, "dq", 1), dp = harness_value(out, "dp", 1);
        CHECK_MSG(dq < 1e-12 && dp < 1e-12, "HP rule %d vs emitted %s: dq %.3e dp %.3e", runs[r].rule, runs[r].name, dq, dp);
        fprintf(stderr, "  HP rule %d vs emitted %s, 1000 steps: dq %.2e, dp %.2e (relative)\n", runs[r].rule, runs[r].name, dq, dp);
        CHECK_MSG(harness_value(out, "tdiff", 1) == 0, "%s: t differs", runs[r].name);
        free(out);
        free(cmd);
        free(exe);
    }
    harness_done();
}

/* ---- the relativistic particle in a harmonic well --------------------------- */
typedef struct { double m, c, k; } rel_ctx;
static double rel_gamma(const rel_ctx *r, const double *v)
{
    return 1.0 / sqrt(1.0 - (v[0] * v[0] + v[1] * v[1]) / (r->c * r->c));
}
static void rel_dq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v;
    const rel_ctx *r = c;
    o[0] = -r->k * q[0];
    o[1] = -r->k * q[1];
}
static void rel_dv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q;
    const rel_ctx *r = c;
    double g = rel_gamma(r, v);
    o[0] = r->m * g * v[0];
    o[1] = r->m * g * v[1];
}
static void rel_vv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q;
    const rel_ctx *r = c;
    double g = rel_gamma(r, v), g3 = g * g * g / (r->c * r->c);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) o[2 * i + j] = r->m * ((i == j) * g + g3 * v[i] * v[j]);
}
static void rel_qq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v;
    const rel_ctx *r = c;
    o[0] = -r->k; o[1] = 0; o[2] = 0; o[3] = -r->k;
}
static double rel_energy(const rel_ctx *r, const double *q, const double *p)
{
    return r->c * sqrt(r->m * r->m * r->c * r->c + p[0] * p[0] + p[1] * p[1]) + 0.5 * r->k * (q[0] * q[0] + q[1] * q[1]);
}

/* Energy over a long run: no drift (the largest error over the last tenth is
 * not above 1.5 times that over the first tenth) and small. */
static void check_no_drift(const char *what, const double *e, long n, double e0, double bound)
{
    double first = 0, last = 0;
    for (long k = 0; k < n / 10; k++) first = fmax(first, fabs(e[k] - e0));
    for (long k = n - n / 10; k < n; k++) last = fmax(last, fabs(e[k] - e0));
    CHECK_MSG(last <= 1.5 * first + 1e-13 && first < bound, "%s: energy error %.3e over the first tenth, %.3e over the last",
              what, first, last);
    fprintf(stderr, "  %s: energy error %.2e (first tenth), %.2e (last tenth)\n", what, first, last);
}

static void test_relativistic(void)
{
    rel_ctx r = { 1.0, 1.0, 1.0 };
    const long n = 100000;
    double *e = malloc(n * sizeof(double));
    for (int rule = 0; rule < 2; rule++) {
        vigen_lagrangian lag = { 2, rel_dq, rel_dv, NULL, &r, NULL, NULL, NULL };
        if (rule == 1) { lag.d2Ldq2 = rel_qq; lag.d2Ldv2 = rel_vv; lag.d2Ldqdv = zero_qv; }
        vigen_hp *w = vigen_hp_alloc(&lag, rule, NULL, NULL);
        double t = 0, q[2] = { 1.0, 0.0 }, p[2] = { 0.0, 0.9 };
        const double e0 = rel_energy(&r, q, p), l0 = q[0] * p[1] - q[1] * p[0];
        double lerr = 0;
        int st = 0;
        long k;
        for (k = 0; k < n && st == 0; k++) {
            st = vigen_hp_step(w, &t, q, p, 0.05);
            e[k] = rel_energy(&r, q, p);
            lerr = fmax(lerr, fabs(q[0] * p[1] - q[1] * p[0] - l0));
        }
        CHECK_MSG(st == 0, "relativistic, rule %d: status %d at step %ld", rule, st, k);
        if (st == 0) check_no_drift(rule ? "relativistic, HP midpoint" : "relativistic, HP trapezoidal", e, n, e0, 1e-3);
        CHECK_MSG(lerr < 1e-12, "relativistic rule %d: angular momentum drifts by %.3e", rule, lerr);
        vigen_hp_free(w);
        /* |p| = 3 m c (v = 0.95 c): a plain Newton step from v = 0 would
         * overshoot to |v| > c, where L is not defined; the steps succeed */
        w = vigen_hp_alloc(&lag, rule, NULL, NULL);
        double tf = 0, qf[2] = { 1.0, 0.0 }, pf[2] = { 0.0, 3.0 }, ef = 0;
        const double ef0 = rel_energy(&r, qf, pf);
        for (k = 0, st = 0; k < 2000 && st == 0; k++) {
            st = vigen_hp_step(w, &tf, qf, pf, 0.01);
            ef = fmax(ef, fabs(rel_energy(&r, qf, pf) - ef0));
        }
        CHECK_MSG(st == 0 && ef < 1e-3 * ef0, "relativistic at 0.95 c, rule %d: status %d at step %ld, energy error %.3e", rule,
                  st, k, ef);
        vigen_hp_free(w);
    }
    free(e);
}

/* ---- a charged particle in an axially symmetric magnetic field --------------
 * A = f(rho^2, z) (-y, x, 0), f = B0 (1 + kappa rho^2 + mu z^2) / 2;
 * phi = w2 rho^2 / 2 + z^2 / 2. */
static const double cp_B0 = 1.0, cp_kappa = 0.3, cp_mu = 0.2, cp_w2 = 0.5;
static double cp_f(const double *q) { return 0.5 * cp_B0 * (1 + cp_kappa * (q[0] * q[0] + q[1] * q[1]) + cp_mu * q[2] * q[2]); }
static void cp_A(const double *q, double *A)
{
    double f = cp_f(q);
    A[0] = -f * q[1];
    A[1] = f * q[0];
    A[2] = 0;
}
static void cp_dq(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED;
    double f = cp_f(q), fx = cp_B0 * cp_kappa * q[0], fy = cp_B0 * cp_kappa * q[1], fz = cp_B0 * cp_mu * q[2];
    double s = q[0] * v[1] - q[1] * v[0];   /* A.v = f s */
    o[0] = fx * s + f * v[1] - cp_w2 * q[0];
    o[1] = fy * s - f * v[0] - cp_w2 * q[1];
    o[2] = fz * s - q[2];
}
static void cp_dv(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED;
    double A[3];
    cp_A(q, A);
    for (int i = 0; i < 3; i++) o[i] = v[i] + A[i];
}
static double cp_energy(const double *q, const double *p)
{
    double A[3], e = 0;
    cp_A(q, A);
    for (int i = 0; i < 3; i++) e += 0.5 * (p[i] - A[i]) * (p[i] - A[i]);
    return e + 0.5 * cp_w2 * (q[0] * q[0] + q[1] * q[1]) + 0.5 * q[2] * q[2];
}

static void test_charged(void)
{
    const long n = 100000;
    double *e = malloc(n * sizeof(double));
    for (int rule = 0; rule < 2; rule++) {
        vigen_lagrangian lag = { 3, cp_dq, cp_dv, NULL, NULL, NULL, NULL, NULL };
        vigen_hp *w = vigen_hp_alloc(&lag, rule, NULL, NULL);
        double t = 0, q[3] = { 1.0, 0.2, 0.3 }, v0[3] = { 0.1, 0.6, -0.2 }, p[3], A[3];
        cp_A(q, A);
        for (int i = 0; i < 3; i++) p[i] = v0[i] + A[i];
        const double e0 = cp_energy(q, p), j0 = q[0] * p[1] - q[1] * p[0];
        double jerr = 0;
        int st = 0;
        long k;
        for (k = 0; k < n && st == 0; k++) {
            st = vigen_hp_step(w, &t, q, p, 0.05);
            e[k] = cp_energy(q, p);
            jerr = fmax(jerr, fabs(q[0] * p[1] - q[1] * p[0] - j0));
        }
        CHECK_MSG(st == 0, "charged particle, rule %d: status %d at step %ld", rule, st, k);
        if (st == 0) check_no_drift(rule ? "charged particle, HP midpoint" : "charged particle, HP trapezoidal", e, n, e0, 1e-2);
        CHECK_MSG(jerr < 1e-12 * fmax(1.0, fabs(j0)), "charged particle rule %d: canonical angular momentum drifts by %.3e",
                  rule, jerr);
        vigen_hp_free(w);
    }
    free(e);
}

/* second derivatives of the charged particle's L, for the exact Jacobian */
static void cp_qq(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED;
    double f_x = cp_B0 * cp_kappa * q[0], f_y = cp_B0 * cp_kappa * q[1], f_z = cp_B0 * cp_mu * q[2];
    double s = q[0] * v[1] - q[1] * v[0];
    o[0] = cp_B0 * cp_kappa * s + 2 * f_x * v[1] - cp_w2; o[1] = f_y * v[1] - f_x * v[0]; o[2] = f_z * v[1];
    o[3] = o[1]; o[4] = cp_B0 * cp_kappa * s - 2 * f_y * v[0] - cp_w2; o[5] = -f_z * v[0];
    o[6] = o[2]; o[7] = o[5]; o[8] = cp_B0 * cp_mu * s - 1;
}
static void cp_qv(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)v;
    double f = cp_f(q), f_x = cp_B0 * cp_kappa * q[0], f_y = cp_B0 * cp_kappa * q[1], f_z = cp_B0 * cp_mu * q[2];
    o[0] = -f_x * q[1];     o[1] = f_x * q[0] + f; o[2] = 0;
    o[3] = -f_y * q[1] - f; o[4] = f_y * q[0];     o[5] = 0;
    o[6] = -f_z * q[1];     o[7] = f_z * q[0];     o[8] = 0;
}
static void id3_vv(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)q; (void)v;
    for (int k = 0; k < 9; k++) o[k] = (k % 4 == 0);
}

/* The exact Jacobian (second derivatives given) against differences on a
 * non-separable L with d2L/dqdv not symmetric: the same trajectory, and
 * Newton's iteration counts of an exact Jacobian (a wrong block, e.g. a
 * transposed d2L/dqdv, shows as slow or failed convergence at this h). */
static void test_exact_jacobian(void)
{
    for (int rule = 0; rule < 2; rule++) {
        vigen_lagrangian lf = { 3, cp_dq, cp_dv, NULL, NULL, NULL, NULL, NULL };
        vigen_lagrangian lx = { 3, cp_dq, cp_dv, NULL, NULL, cp_qq, id3_vv, cp_qv };
        vigen_hp *wf = vigen_hp_alloc(&lf, rule, NULL, NULL), *wx = vigen_hp_alloc(&lx, rule, NULL, NULL);
        double tf = 0, qf[3] = { 1.0, 0.2, 0.3 }, pf[3] = { 0.1, 1.2, -0.2 };
        double tx = 0, qx[3] = { 1.0, 0.2, 0.3 }, px[3] = { 0.1, 1.2, -0.2 }, err = 0;
        for (int k = 0; k < 300; k++) {
            CHECK(vigen_hp_step(wf, &tf, qf, pf, 0.3) == 0 && vigen_hp_step(wx, &tx, qx, px, 0.3) == 0);
            for (int i = 0; i < 3; i++) err = fmax(err, fmax(fabs(qf[i] - qx[i]), fabs(pf[i] - px[i])));
        }
        const vigen_stats *sf = vigen_hp_stats(wf), *sx = vigen_hp_stats(wx);
        CHECK_MSG(err < 1e-11, "rule %d: exact vs difference Jacobian: trajectories differ by %.3e", rule, err);
        CHECK_MSG(sx->iterations <= sf->iterations + sf->iterations / 20 && sx->max_iterations <= 12,
                  "rule %d: %lu iterations (max %lu per step) with the exact Jacobian, %lu with differences", rule,
                  sx->iterations, sx->max_iterations, sf->iterations);
        /* differences cost 3 residuals per Jacobian, the exact one none */
        CHECK(sx->dHdq_evals < sf->dHdq_evals);
        vigen_hp_free(wf);
        vigen_hp_free(wx);
    }
}

/* The predictor: extrapolating v_{n-1/2} in time saves Newton iterations
 * without changing the result beyond round-off; a state other than the one
 * the last step returned drops the history, so the step is bit for bit
 * that of a fresh workspace. */
static void test_predictor(void)
{
    vigen_lagrangian lag = { 3, cp_dq, cp_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_solver_options o;
    vigen_solver_options_default(&o);
    double qe[2][3], pe[2][3];
    unsigned long its[2];
    for (int ex = 0; ex < 2; ex++) {
        o.extrapolate = ex;
        vigen_hp *w = vigen_hp_alloc(&lag, VIGEN_HP_MIDPOINT, NULL, &o);
        double t = 0, q[3] = { 1.0, 0.2, 0.3 }, p[3] = { 0.1, 1.2, -0.2 };
        for (int k = 0; k < 500; k++) CHECK(vigen_hp_step(w, &t, q, p, 0.1) == 0);
        memcpy(qe[ex], q, sizeof q);
        memcpy(pe[ex], p, sizeof p);
        its[ex] = vigen_hp_stats(w)->iterations;
        if (ex) {
            /* a kick from outside: the next step starts afresh */
            p[0] += 0.01;
            double t2 = t, q2[3], p2[3];
            memcpy(q2, q, sizeof q);
            memcpy(p2, p, sizeof p);
            vigen_hp *fresh = vigen_hp_alloc(&lag, VIGEN_HP_MIDPOINT, NULL, &o);
            CHECK(vigen_hp_step(w, &t, q, p, 0.1) == 0 && vigen_hp_step(fresh, &t2, q2, p2, 0.1) == 0);
            CHECK(t == t2 && memcmp(q, q2, sizeof q) == 0 && memcmp(p, p2, sizeof p) == 0);
            vigen_hp_free(fresh);
        }
        vigen_hp_free(w);
    }
    double d = 0;
    for (int i = 0; i < 3; i++) d = fmax(d, fmax(fabs(qe[0][i] - qe[1][i]), fabs(pe[0][i] - pe[1][i])));
    CHECK_MSG(d < 1e-12, "extrapolated predictor changes the trajectory by %.3e", d);
    CHECK_MSG(its[1] < its[0], "%lu iterations with extrapolation, %lu without", its[1], its[0]);
    fprintf(stderr, "  predictor: %lu Newton iterations in 500 steps with extrapolation, %lu without\n", its[1], its[0]);
}

/* Both discrete Lagrangians are symmetric, so each stepper is its own
 * adjoint: a step with -h from the result of a step with h returns to the
 * start (time-dependent L included), to round-off. */
static void fo_dq(double t, const double *q, const double *v, double *o, void *c);
static void fo_dv(double t, const double *q, const double *v, double *o, void *c);
static void test_symmetric(void)
{
    vigen_lagrangian lc = { 3, cp_dq, cp_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_lagrangian lf = { 1, fo_dq, fo_dv, NULL, NULL, NULL, NULL, NULL };
    for (int rule = 0; rule < 2; rule++) {
        for (int prob = 0; prob < 2; prob++) {
            vigen_hp *w = vigen_hp_alloc(prob ? &lf : &lc, rule, NULL, NULL);
            const size_t n = prob ? 1 : 3;
            double t = 0.3, q[3] = { 1.0, 0.2, 0.3 }, p[3] = { 0.1, 1.2, -0.2 };
            for (int k = 0; k < 20; k++) CHECK(vigen_hp_step(w, &t, q, p, 0.1) == 0);
            double t0 = t, q0[3], p0[3], err = 0;
            memcpy(q0, q, sizeof q);
            memcpy(p0, p, sizeof p);
            for (int k = 0; k < 5; k++) {
                CHECK(vigen_hp_step(w, &t, q, p, 0.17) == 0 && vigen_hp_step(w, &t, q, p, -0.17) == 0);
                for (size_t i = 0; i < n; i++) err = fmax(err, fmax(fabs(q[i] - q0[i]), fabs(p[i] - p0[i])));
                err = fmax(err, fabs(t - t0));
            }
            CHECK_MSG(err < 1e-14, "rule %d, %s: a step with -h does not undo the step with h: %.3e", rule,
                      prob ? "forced oscillator" : "charged particle", err);
            vigen_hp_free(w);
        }
    }
}

/* ---- order 2: forced oscillator, L = v^2/2 - q^2/2 + q F cos(w t) ----------
 * q(t) = q0 cos t + p0 sin t + F (cos wt - cos t)/(1 - w^2), p = q'. */
static const double fo_F = 0.8, fo_w = 2.3;
static void fo_dq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)v; (void)c;
    o[0] = -q[0] + fo_F * cos(fo_w * t);
}
static void fo_dv(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)q; o[0] = v[0]; }
static double fo_q(double t, double q0, double p0) { return q0 * cos(t) + p0 * sin(t) + fo_F * (cos(fo_w * t) - cos(t)) / (1 - fo_w * fo_w); }
static double fo_p(double t, double q0, double p0) { return -q0 * sin(t) + p0 * cos(t) + fo_F * (-fo_w * sin(fo_w * t) + sin(t)) / (1 - fo_w * fo_w); }

static void test_order(void)
{
    vigen_lagrangian lag = { 1, fo_dq, fo_dv, NULL, NULL, NULL, NULL, NULL };
    for (int rule = 0; rule < 2; rule++) {
        double prev = 0;
        for (int k = 0; k < 4; k++) {
            long n = 100L << k;
            vigen_hp *w = vigen_hp_alloc(&lag, rule, NULL, NULL);
            double t = 0, q[1] = { 0.7 }, p[1] = { -0.3 }, err = 0;
            /* alternating h and 1.5 h: a non-uniform grid */
            double h0 = 10.0 / (n * 1.25);
            for (long s = 0; s < n; s++) {
                CHECK(vigen_hp_step(w, &t, q, p, (s & 1) ? 1.5 * h0 : h0) == 0);
                err = fmax(err, fmax(fabs(q[0] - fo_q(t, 0.7, -0.3)), fabs(p[0] - fo_p(t, 0.7, -0.3))));
            }
            CHECK_MSG(fabs(t - 10.0) < 1e-12, "t = %.17g", t);
            if (k > 0) {
                double o = log2(prev / err);
                CHECK_MSG(fabs(o - 2) < 0.1, "HP rule %d: order %.3f (errors %.3e, %.3e)", rule, o, prev, err);
                if (k == 3) fprintf(stderr, "  HP rule %d: error %.3e at n = %ld, order %.3f\n", rule, err, n, o);
            }
            prev = err;
            vigen_hp_free(w);
        }
    }
}

/* ---- t is a compensated sum ----------------------------------------------- */
static void free_dq(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)q; (void)v; o[0] = 0; }

static void test_time_sum(void)
{
    vigen_lagrangian lag = { 1, free_dq, fo_dv, NULL, NULL, NULL, NULL, NULL };
    for (int kahan = 1; kahan >= 0; kahan--) {
        vigen_solver_options o;
        vigen_solver_options_default(&o);
        o.kahan = kahan;
        vigen_hp *w = vigen_hp_alloc(&lag, VIGEN_HP_TRAPEZOIDAL, NULL, &o);
        double t = 0, q[1] = { 0 }, p[1] = { 1 }, naive = 0;
        for (int k = 0; k < 100000; k++) {
            CHECK(vigen_hp_step(w, &t, q, p, 0.1) == 0);
            naive += 0.1;
        }
        /* 10^5 * 0.1 in one multiplication is the correctly rounded exact sum */
        const double exact = 100000 * 0.1;
        if (kahan) CHECK_MSG(t == exact, "t = %.17g, exact sum %.17g", t, exact);
        else CHECK_MSG(t == naive && naive != exact, "t = %.17g, naive sum %.17g", t, naive);
        vigen_hp_free(w);
    }
}

/* ---- bad input -------------------------------------------------------------- */
static void nan_dq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)v; (void)c; (void)t;
    o[0] = q[0] > 1.0 ? NAN : -q[0];
}
/* L = sqrt(1 + v^2) - q (a constant force): p = v / sqrt(1 + v^2) stays in
 * (-1, 1), so the equation p_{n+1/2} = p_n - h/2 of both rules has no
 * solution once |p_n - h/2| >= 1 (h far too large) */
static void bm_dq(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)v; (void)q; o[0] = -1.0; }
static void bm_dv(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)q; o[0] = v[0] / sqrt(1 + v[0] * v[0]); }
/* degenerate: L = q.v - |q|^2/2 (dL/dv = q does not depend on v) */
static void dg_dq(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; o[0] = v[0] - q[0]; o[1] = v[1] - q[1]; }
static void dg_dv(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)v; o[0] = q[0]; o[1] = q[1]; }
/* partly degenerate: L = v1^2/2 + v2 q1 - |q|^2/2 */
static void pd_dq(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; o[0] = v[1] - q[0]; o[1] = -q[1]; }
static void pd_dv(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; o[0] = v[0]; o[1] = q[0]; }

static int state_kept(double t, const double *q, const double *p, double t0, const double *q0, const double *p0, size_t n)
{
    return memcmp(&t, &t0, sizeof t) == 0 && memcmp(q, q0, n * sizeof(double)) == 0 && memcmp(p, p0, n * sizeof(double)) == 0;
}

#define BIT(s) (1u << (s))
/* One step from (t, q, p) must fail with a status in the mask `want` and
 * leave the state as it was, bit for bit. */
static void expect_failure(const char *what, vigen_hp *w, double t, const double *q, const double *p, size_t n, double h,
                           unsigned want)
{
    double tt = t, qq[3], pp[3];
    memcpy(qq, q, n * sizeof(double));
    memcpy(pp, p, n * sizeof(double));
    unsigned long failed = vigen_hp_stats(w)->failed_steps;
    int st = vigen_hp_step(w, &tt, qq, pp, h);
    CHECK_MSG(st > 0 && (BIT(st) & want), "%s: status %d (%s)", what, st, vigen_strerror(st));
    CHECK_MSG(state_kept(tt, qq, pp, t, q, p, n), "%s: state changed", what);
    CHECK_MSG(vigen_hp_stats(w)->failed_steps == failed + 1, "%s: failed step not counted", what);
}

static void test_bad_input(void)
{
    const char *why = NULL;
    vigen_lagrangian lag = { 2, hh_dq, hh_dv, NULL, NULL, NULL, NULL, NULL };
    CHECK(vigen_lagrangian_validate(&lag, NULL, &why) == VIGEN_SUCCESS && why == NULL);
    vigen_lagrangian bad = lag;
    bad.dim = 0;
    CHECK(vigen_lagrangian_validate(&bad, NULL, &why) == VIGEN_EINVAL && why && strstr(why, "dim"));
    CHECK(vigen_hp_alloc(&bad, VIGEN_HP_TRAPEZOIDAL, NULL, NULL) == NULL);
    bad = lag;
    bad.dLdq = NULL;
    CHECK(vigen_lagrangian_validate(&bad, NULL, &why) == VIGEN_EINVAL && why && strstr(why, "dLdq"));
    CHECK(vigen_hp_alloc(&bad, VIGEN_HP_MIDPOINT, NULL, NULL) == NULL);
    bad = lag;
    bad.dLdv = NULL;
    CHECK(vigen_lagrangian_validate(&bad, NULL, &why) == VIGEN_EINVAL && why && strstr(why, "dLdv"));
    CHECK(vigen_lagrangian_validate(NULL, NULL, &why) == VIGEN_EINVAL && why != NULL);
    CHECK(vigen_hp_alloc(&lag, 7, NULL, NULL) == NULL);
    CHECK(vigen_hp_step(NULL, NULL, NULL, NULL, 0.1) == VIGEN_EINVAL);

    vigen_hp *w = vigen_hp_alloc(&lag, VIGEN_HP_MIDPOINT, NULL, NULL);
    const double q[2] = { 0.1, 0.2 }, p[2] = { 0.3, -0.1 };
    expect_failure("h = 0", w, 0.0, q, p, 2, 0.0, BIT(VIGEN_EINVAL));
    expect_failure("h = NaN", w, 0.0, q, p, 2, NAN, BIT(VIGEN_EINVAL));
    expect_failure("h = inf", w, 0.0, q, p, 2, INFINITY, BIT(VIGEN_EINVAL));
    expect_failure("t + h overflows", w, 1e308, q, p, 2, 1e308, BIT(VIGEN_EINVAL));
    expect_failure("t = NaN", w, NAN, q, p, 2, 0.1, BIT(VIGEN_EINVAL));
    const double qnan[2] = { NAN, 0.2 };
    expect_failure("q = NaN", w, 0.0, qnan, p, 2, 0.1, BIT(VIGEN_ENONFINITE));
    vigen_hp_free(w);

    /* NaN from dL/dq once q > 1: a step that gets there fails, state kept */
    vigen_lagrangian ln = { 1, nan_dq, fo_dv, NULL, NULL, NULL, NULL, NULL };
    for (int rule = 0; rule < 2; rule++) {
        w = vigen_hp_alloc(&ln, rule, NULL, NULL);
        double t = 0, q1[1] = { 0.95 }, p1[1] = { 1.0 };
        expect_failure("NaN from dL/dq", w, t, q1, p1, 1, 0.2, BIT(VIGEN_ENONFINITE));
        vigen_hp_free(w);
    }

    /* no solution: h far too large */
    vigen_lagrangian lb = { 1, bm_dq, bm_dv, NULL, NULL, NULL, NULL, NULL };
    for (int rule = 0; rule < 2; rule++) {
        w = vigen_hp_alloc(&lb, rule, NULL, NULL);
        double qb[1] = { 1.0 }, pb[1] = { 0.5 }, tb = 0;
        /* a small step works (the same state and workspace) */
        double tt = tb, qq[1] = { 1.0 }, pp[1] = { 0.5 };
        CHECK(vigen_hp_step(w, &tt, qq, pp, 0.01) == 0);
        expect_failure("h far too large", w, tb, qb, pb, 1, 40.0,
                       BIT(VIGEN_ENOCONV) | BIT(VIGEN_EMAXITER) | BIT(VIGEN_ESINGULAR));
        vigen_hp_free(w);
    }

    /* degenerate Lagrangians: dL/dv not invertible */
    vigen_lagrangian ld = { 2, dg_dq, dg_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_lagrangian lp = { 2, pd_dq, pd_dv, NULL, NULL, NULL, NULL, NULL };
    for (int rule = 0; rule < 2; rule++) {
        w = vigen_hp_alloc(&ld, rule, NULL, NULL);
        expect_failure("L = q.v - V", w, 0.0, q, p, 2, 0.1, BIT(VIGEN_ESINGULAR));
        vigen_hp_free(w);
        w = vigen_hp_alloc(&lp, rule, NULL, NULL);
        expect_failure("L = v1^2/2 + v2 q1 - V", w, 0.0, q, p, 2, 0.1, BIT(VIGEN_ESINGULAR));
        vigen_hp_free(w);
    }
}

int main(void)
{
    test_verlet();
    test_emitted();
    test_relativistic();
    test_charged();
    test_exact_jacobian();
    test_predictor();
    test_symmetric();
    test_order();
    test_time_sum();
    test_bad_input();
    TEST_MAIN_END();
}
