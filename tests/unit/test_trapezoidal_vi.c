/* test_trapezoidal_vi.c — the trapezoidal variational integrator on
 * non-uniform grids (<vigen/lagrangian.h>, vigen_trapezoidal_vi_*), against
 * independent sources:
 *   - for L = 1/2 m v^2 - V(q) on a random grid, the two-step form gives the
 *     closed form q2 = q1 + (t2 - t1)/(t1 - t0) (q1 - q0)
 *     - (t2 - t0)(t2 - t1)/(2m) V'(q1), and the one-step form the leapfrog
 *     q1 = q0 + h/m p0 - h^2/(2m) V'(q0), p1 = m (q1 - q0)/h - h/2 V'(q1)
 *     (papers/004), to round-off;
 *   - the grid driver gives the trajectory of the emitted Stormer–Verlet
 *     stepper (tests/data/emit/verlet.lua) called with each step's h
 *     (driver tests/data/lagrangian/hp_vs_prk.c);
 *   - order 2 on a non-uniform grid against the exact solution of a forced
 *     oscillator (time-dependent L);
 *   - Noether: for a central potential the angular momentum q x p is
 *     conserved to round-off on a random grid;
 *   - bad input: grids that are not strictly monotone or not finite, aliased
 *     outputs, NaN from a callback in the middle of a grid (the state is the
 *     last good one and the rows written so far are those of the steps
 *     taken). */
#include <math.h>
#include <string.h>
#include <vigen/lagrangian.h>
#include "test_emit_harness.h"
#include "support/strbuf.h"

#define NOUNUSED (void)t; (void)c

/* m = 1.7, V(q) = q^4/4 - cos(2q) */
static const double lf_m = 1.7;
static double lf_dV(double q) { return q * q * q + 2 * sin(2 * q); }
static void lf_dq(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)v; o[0] = -lf_dV(q[0]); }
static void lf_dv(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)q; o[0] = lf_m * v[0]; }

static unsigned long lcg = 987654321;
static double uniform(void)
{
    lcg = (lcg * 6364136223846793005UL + 1442695040888963407UL) & 0xffffffffffffUL;
    return (double)(lcg >> 16) / 4294967296.0;
}

static void random_grid(double *t, size_t n, double t0, double hmin, double hmax)
{
    t[0] = t0;
    for (size_t k = 1; k < n; k++) t[k] = t[k - 1] + hmin + (hmax - hmin) * uniform();
}

static double rel(double a, double b) { return fabs(a - b) / fmax(1.0, fabs(b)); }

static void test_closed_forms(void)
{
    vigen_lagrangian lag = { 1, lf_dq, lf_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_trapezoidal_vi *w = vigen_trapezoidal_vi_alloc(&lag, NULL);
    CHECK(w != NULL);
    if (!w) return;
    enum { N = 400 };
    double t[N];
    random_grid(t, N, -1.0, 0.01, 0.2);
    /* two-step form, each step from the same inputs as the closed form */
    double q[N], qc[N], err = 0;
    q[0] = qc[0] = 0.8;
    q[1] = qc[1] = 0.83;
    for (size_t k = 2; k < N; k++) {
        int st = vigen_trapezoidal_vi_step2(w, t[k - 2], t[k - 1], t[k], &q[k - 2], &q[k - 1], &q[k]);
        CHECK_MSG(st == 0, "step2 %zu: status %d", k, st);
        double closed = q[k - 1] + (t[k] - t[k - 1]) / (t[k - 1] - t[k - 2]) * (q[k - 1] - q[k - 2])
                        - (t[k] - t[k - 2]) * (t[k] - t[k - 1]) / (2 * lf_m) * lf_dV(q[k - 1]);
        err = fmax(err, rel(q[k], closed));
        /* the closed form iterated on its own */
        qc[k] = qc[k - 1] + (t[k] - t[k - 1]) / (t[k - 1] - t[k - 2]) * (qc[k - 1] - qc[k - 2])
                - (t[k] - t[k - 2]) * (t[k] - t[k - 1]) / (2 * lf_m) * lf_dV(qc[k - 1]);
    }
    CHECK_MSG(err < 1e-14, "two-step form vs closed form, step by step: %.3e", err);
    double traj = 0;
    for (size_t k = 0; k < N; k++) traj = fmax(traj, rel(q[k], qc[k]));
    CHECK_MSG(traj < 1e-12, "two-step trajectory vs closed-form recursion: %.3e", traj);
    /* backwards in time too */
    double qb;
    CHECK(vigen_trapezoidal_vi_step2(w, t[5], t[4], t[3], &q[5], &q[4], &qb) == 0);
    double closed = q[4] + (t[3] - t[4]) / (t[4] - t[5]) * (q[4] - q[5]) - (t[3] - t[5]) * (t[3] - t[4]) / (2 * lf_m) * lf_dV(q[4]);
    CHECK_MSG(rel(qb, closed) < 1e-14, "backward two-step: %.17g vs %.17g", qb, closed);

    /* one-step form, and the grid driver over the same grid */
    double tt = t[0], qq[1] = { 0.8 }, pp[1] = { 0.4 }, q1 = 0.8, p1 = 0.4;
    double e1 = 0;
    double qs[N], ps[N];
    for (size_t k = 0; k + 1 < N; k++) {
        double h = t[k + 1] - t[k];
        CHECK(vigen_trapezoidal_vi_step(w, &tt, qq, pp, h) == 0);
        double q0 = q1;
        q1 = q0 + h / lf_m * p1 - h * h / (2 * lf_m) * lf_dV(q0);
        p1 = lf_m * (q1 - q0) / h - h / 2 * lf_dV(q1);
        e1 = fmax(e1, fmax(rel(qq[0], q1), rel(pp[0], p1)));
        qs[k + 1] = q1;
        ps[k + 1] = p1;
    }
    CHECK_MSG(e1 < 1e-12, "one-step form vs the leapfrog formulas: %.3e", e1);
    double qg[1] = { 0.8 }, pg[1] = { 0.4 }, qrows[N], prows[N];
    size_t done = 99;
    CHECK(vigen_trapezoidal_vi_integrate(w, t, N, qg, pg, qrows, prows, &done) == 0 && done == N - 1);
    double eg = fabs(qrows[0] - 0.8) + fabs(prows[0] - 0.4);
    for (size_t k = 1; k < N; k++) eg = fmax(eg, fmax(rel(qrows[k], qs[k]), rel(prows[k], ps[k])));
    CHECK_MSG(eg < 1e-12, "grid driver vs the leapfrog formulas: %.3e", eg);
    CHECK(qg[0] == qrows[N - 1] && pg[0] == prows[N - 1]);
    const vigen_stats *s = vigen_trapezoidal_vi_stats(w);
    CHECK(s->steps >= (N - 2) + (N - 1) + (N - 1) && s->failed_steps == 0 && s->dHdq_evals > 0);
    vigen_trapezoidal_vi_free(w);
}

static void test_emitted_verlet(void)
{
    if (!harness_init("tvi")) return;
    if (!harness_emit("tests/data/emit/verlet.lua", "stormer_verlet", VIGEN_REAL_DOUBLE, NULL)) return;
    char *exe = harness_build("gcc", "../lagrangian/hp_vs_prk.c", "stormer_verlet", "", "tvi_verlet");
    if (exe) {
        char *cmd = vigen_strdup_printf("%s grid 1000", exe);
        char *out = harness_capture(cmd);
        CHECK_MSG(harness_value(out, "status", -1) == 0 && harness_value(out, "steps", 0) == 1000, "%s", out);
        double dq = harness_value(out, "dq", 1), dp = harness_value(out, "dp", 1);
        CHECK_MSG(dq < 1e-12 && dp < 1e-12, "grid driver vs emitted Stormer-Verlet with per-call h: dq %.3e dp %.3e", dq, dp);
        fprintf(stderr, "  grid driver vs emitted Stormer-Verlet, 1000 steps: dq %.2e, dp %.2e (relative)\n", dq, dp);
        free(out);
        free(cmd);
        free(exe);
    }
    harness_done();
}

/* forced oscillator L = v^2/2 - q^2/2 + q F cos(w t); exact solution
 * q(t) = q0 cos t + p0 sin t + F (cos wt - cos t)/(1 - w^2), p = q' */
static const double fo_F = 0.8, fo_w = 2.3;
static void fo_dq(double t, const double *q, const double *v, double *o, void *c) { (void)v; (void)c; o[0] = -q[0] + fo_F * cos(fo_w * t); }
static void fo_dv(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)q; o[0] = v[0]; }
static double fo_q(double t) { return 0.7 * cos(t) - 0.3 * sin(t) + fo_F * (cos(fo_w * t) - cos(t)) / (1 - fo_w * fo_w); }
static double fo_p(double t) { return -0.7 * sin(t) - 0.3 * cos(t) + fo_F * (-fo_w * sin(fo_w * t) + sin(t)) / (1 - fo_w * fo_w); }

static void test_order(void)
{
    vigen_lagrangian lag = { 1, fo_dq, fo_dv, NULL, NULL, NULL, NULL, NULL };
    enum { N0 = 60, K = 4 };
    /* a random grid on [0, 8], refined by halving every interval */
    double *t = malloc((((size_t)N0 << K) + 1) * sizeof(double));
    double base[N0 + 1];
    random_grid(base, N0 + 1, 0.0, 0.5, 1.5);
    for (int k = 0; k <= N0; k++) base[k] *= 8.0 / base[N0];
    double prev = 0;
    for (int k = 0; k <= K; k++) {
        size_t n = ((size_t)N0 << k) + 1;
        for (size_t i = 0; i < n; i++) {
            size_t j = i >> k, r = i & ((1u << k) - 1);
            t[i] = j < N0 ? base[j] + (base[j + 1] - base[j]) * (double)r / (double)(1u << k) : base[N0];
        }
        vigen_trapezoidal_vi *w = vigen_trapezoidal_vi_alloc(&lag, NULL);
        double q[1] = { 0.7 }, p[1] = { -0.3 };
        double *qs = malloc(n * sizeof(double)), *ps = malloc(n * sizeof(double));
        CHECK(vigen_trapezoidal_vi_integrate(w, t, n, q, p, qs, ps, NULL) == 0);
        double err = 0;
        for (size_t i = 0; i < n; i++) err = fmax(err, fmax(fabs(qs[i] - fo_q(t[i])), fabs(ps[i] - fo_p(t[i]))));
        if (k > 0) {
            double o = log2(prev / err);
            CHECK_MSG(fabs(o - 2) < 0.1, "order %.3f between refinements %d and %d (errors %.3e, %.3e)", o, k - 1, k, prev, err);
            if (k == K) fprintf(stderr, "  trapezoidal VI, random grid: error %.3e, order %.3f\n", err, o);
        }
        prev = err;
        free(qs);
        free(ps);
        vigen_trapezoidal_vi_free(w);
    }
    free(t);
}

/* central potential V = |q|^4/4 - 1/|q|: rotations are a symmetry of L */
static void cf_dq(double t, const double *q, const double *v, double *o, void *c)
{
    NOUNUSED; (void)v;
    double r2 = q[0] * q[0] + q[1] * q[1], r = sqrt(r2), g = r2 + 1.0 / (r2 * r);
    o[0] = -g * q[0];
    o[1] = -g * q[1];
}
static void cf_dv(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)q; o[0] = v[0]; o[1] = v[1]; }

static void test_noether(void)
{
    vigen_lagrangian lag = { 2, cf_dq, cf_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_trapezoidal_vi *w = vigen_trapezoidal_vi_alloc(&lag, NULL);
    enum { N = 20001 };
    double *t = malloc(N * sizeof(double));
    random_grid(t, N, 0.0, 0.002, 0.02);
    double q[2] = { 1.0, 0.0 }, p[2] = { 0.1, 1.1 };
    const double l0 = q[0] * p[1] - q[1] * p[0];
    double *qs = malloc(2 * N * sizeof(double)), *ps = malloc(2 * N * sizeof(double));
    CHECK(vigen_trapezoidal_vi_integrate(w, t, N, q, p, qs, ps, NULL) == 0);
    double err = 0;
    for (size_t k = 0; k < N; k++) err = fmax(err, fabs(qs[2 * k] * ps[2 * k + 1] - qs[2 * k + 1] * ps[2 * k] - l0));
    CHECK_MSG(err < 1e-12, "angular momentum on a random grid drifts by %.3e", err);
    free(t);
    free(qs);
    free(ps);
    vigen_trapezoidal_vi_free(w);
}

static void nan_dq(double t, const double *q, const double *v, double *o, void *c) { NOUNUSED; (void)v; o[0] = q[0] > 1.0 ? NAN : -q[0]; }

static void test_bad_input(void)
{
    vigen_lagrangian lag = { 1, lf_dq, lf_dv, NULL, NULL, NULL, NULL, NULL };
    vigen_lagrangian bad = lag;
    bad.dim = 0;
    CHECK(vigen_trapezoidal_vi_alloc(&bad, NULL) == NULL);
    bad = lag;
    bad.dLdv = NULL;
    CHECK(vigen_trapezoidal_vi_alloc(&bad, NULL) == NULL);
    CHECK(vigen_trapezoidal_vi_alloc(NULL, NULL) == NULL);
    vigen_trapezoidal_vi *w = vigen_trapezoidal_vi_alloc(&lag, NULL);
    double q0 = 0.1, q1 = 0.2, q2 = 42.0;
    CHECK(vigen_trapezoidal_vi_step2(w, 0.0, 0.1, 0.1, &q0, &q1, &q2) == VIGEN_EINVAL && q2 == 42.0);
    CHECK(vigen_trapezoidal_vi_step2(w, 0.0, 0.2, 0.1, &q0, &q1, &q2) == VIGEN_EINVAL && q2 == 42.0);
    CHECK(vigen_trapezoidal_vi_step2(w, 0.0, NAN, 0.3, &q0, &q1, &q2) == VIGEN_EINVAL && q2 == 42.0);
    CHECK(vigen_trapezoidal_vi_step2(w, 0.0, 0.1, 0.2, &q0, &q1, &q1) == VIGEN_EINVAL && q1 == 0.2);
    double tt = 0, q[1] = { 0.1 }, p[1] = { 0.2 };
    CHECK(vigen_trapezoidal_vi_step(w, &tt, q, p, 0.0) == VIGEN_EINVAL && tt == 0 && q[0] == 0.1 && p[0] == 0.2);
    const double nonmono[] = { 0.0, 0.1, 0.3, 0.2 }, dup[] = { 0.0, 0.0 }, nf[] = { 0.0, 0.1, INFINITY };
    size_t done = 7;
    CHECK(vigen_trapezoidal_vi_integrate(w, nonmono, 4, q, p, NULL, NULL, &done) == VIGEN_EINVAL && done == 0);
    CHECK(vigen_trapezoidal_vi_integrate(w, dup, 2, q, p, NULL, NULL, &done) == VIGEN_EINVAL && done == 0);
    CHECK(vigen_trapezoidal_vi_integrate(w, nf, 3, q, p, NULL, NULL, &done) == VIGEN_EINVAL && done == 0);
    CHECK(q[0] == 0.1 && p[0] == 0.2);
    /* one time: nothing to do; the rows hold the initial state */
    double qr[1] = { -1 }, pr[1] = { -1 };
    CHECK(vigen_trapezoidal_vi_integrate(w, nonmono, 1, q, p, qr, pr, &done) == 0 && done == 0 && qr[0] == 0.1 && pr[0] == 0.2);
    /* decreasing grids are fine */
    const double down[] = { 1.0, 0.9, 0.75, 0.7 };
    CHECK(vigen_trapezoidal_vi_integrate(w, down, 4, q, p, NULL, NULL, &done) == 0 && done == 3);
    vigen_trapezoidal_vi_free(w);

    /* NaN once q > 1, in the middle of the grid: status, the last good state */
    vigen_lagrangian ln = { 1, nan_dq, lf_dv, NULL, NULL, NULL, NULL, NULL };
    w = vigen_trapezoidal_vi_alloc(&ln, NULL);
    double grid[50];
    for (int k = 0; k < 50; k++) grid[k] = 0.1 * k;
    double qn[1] = { 0.0 }, pn[1] = { 2.0 }, qs[50], ps[50];
    for (int k = 0; k < 50; k++) qs[k] = ps[k] = -7.0;
    int st = vigen_trapezoidal_vi_integrate(w, grid, 50, qn, pn, qs, ps, &done);
    CHECK_MSG(st == VIGEN_ENONFINITE && done > 0 && done < 49, "status %d after %zu steps", st, done);
    CHECK(qn[0] == qs[done] && pn[0] == ps[done] && qn[0] <= 1.0 && qs[done + 1] == -7.0);
    CHECK(vigen_trapezoidal_vi_stats(w)->failed_steps == 1 && vigen_trapezoidal_vi_stats(w)->steps == done);
    vigen_trapezoidal_vi_free(w);
}

int main(void)
{
    test_closed_forms();
    test_emitted_verlet();
    test_order();
    test_noether();
    test_bad_input();
    TEST_MAIN_END();
}
