/* test_midpoint_vi.c — the mid-point variational integrator
 * (runtime/lagrangian/midpoint_vi.c), each property against a formula
 * that does not come from the code under test:
 *   - L = |v|^2/2 - V(q), V anharmonic and anisotropic: the positions of the
 *     one-step (Cresson–Safi) map satisfy the Wendlandt–Marsden two-step
 *     relation (q+ - 2q + q-)/h^2 = -1/2 [grad V((q+ + q)/2) + grad V((q + q-)/2)]
 *     to round-off, with the Jacobian from the user's second derivatives and
 *     from finite differences;
 *   - the two-step position form reproduces the one-step positions to
 *     round-off, on a non-uniform grid and with a time-dependent L;
 *   - a charged particle in an axially symmetric magnetic field (dL/dv
 *     depends on q, g = p - A(q)): canonical angular momentum conserved, the
 *     user's second derivatives (checked against differences) and finite
 *     differences give the same trajectory, Newton converges in a few
 *     iterations with either (a wrong analytic Jacobian term does not);
 *   - empirical order 2 on the forced oscillator L = v^2/2 - q^2/2 + F cos(2t) q,
 *     whose solution q = cos t - (F/3) cos 2t is verified beside the problem;
 *   - the relativistic particle L = -m c^2 sqrt(1 - |v|^2/c^2) - V(q), g in
 *     closed form: the Hamilton–Pontryagin midpoint integrator with the
 *     trivial map (the same discrete Lagrangian, another solver and another
 *     unknown) gives the same trajectory to round-off; the energy
 *     c sqrt(m^2 c^2 + |p|^2) + V stays bounded over 10^5 steps with a fitted
 *     drift far below its oscillation and, between smooth-window means of
 *     the two halves of the run, at round-off level, while a non-symplectic
 *     second-order method (Heun, written here) drifts;
 *   - the step with -h undoes the step with h (the mid-point Ld is
 *     symmetric): forward and back over 200 steps returns to the start;
 *   - Noether: q x p is conserved to round-off for rotation-invariant L
 *     (relativistic, central potential) and is not for an anisotropic one;
 *   - t advances by the compensated sum of the steps (one unit in the last
 *     place of the exact sum over 10^5 steps, and over 2000 alternating
 *     steps), or by the naive sum bit for bit without compensation;
 *   - bad input: clear status and the state unchanged bit for bit. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <vigen/lagrangian.h>
#include "testlib.h"

#define EPS 2.220446049250313e-16

#include "../data/midpoint_vi/problems.h"

/* ---- helpers --------------------------------------------------------------- */

static vigen_lagrangian lag2(vigen_lgrad_fn dLdq, vigen_lgrad_fn dLdv, void *ctx)
{
    vigen_lagrangian L;
    memset(&L, 0, sizeof L);
    L.dim = 2;
    L.dLdq = dLdq;
    L.dLdv = dLdv;
    L.ctx = ctx;
    return L;
}

/* |v|^2/2 - V_aniso (+ a force), with or without its second derivatives. */
static vigen_lagrangian aniso_lagrangian(vigen_lgrad_fn dLdq, int exact)
{
    vigen_lagrangian L = lag2(dLdq, unit_dLdv, NULL);
    if (exact) {
        L.d2Ldq2 = aniso_d2q;
        L.d2Ldqdv = zero_2x2;
        L.d2Ldv2 = unit_2x2;
    }
    return L;
}

static double maxabs2(const double *a) { return fmax(fabs(a[0]), fabs(a[1])); }

/* ---- Wendlandt–Marsden relation and the two-step form ----------------------- */

static void check_wendlandt_marsden(int exact)
{
    vigen_lagrangian L = aniso_lagrangian(aniso_dLdq, exact);
    vigen_midpoint_vi *w = vigen_midpoint_vi_alloc(&L, unit_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    enum { N = 400 };
    static double qs[N + 1][2];
    const double h = 0.0625;     /* dyadic: the times i h given to step2 are exact */
    double t = 0.0, q[2] = {0.8, -0.3}, p[2] = {0.1, 0.5};
    memcpy(qs[0], q, sizeof q);
    int st = VIGEN_SUCCESS;
    for (int i = 1; i <= N && st == VIGEN_SUCCESS; i++) {
        st = vigen_midpoint_vi_step(w, &t, q, p, h);
        memcpy(qs[i], q, sizeof q);
    }
    CHECK_MSG(st == VIGEN_SUCCESS, "status %d (%s)", st, vigen_strerror(st));
    double worst = 0.0, scale = 0.0, worst2 = 0.0;
    for (int i = 1; i < N; i++) {
        double a[2], b[2], ma[2], mb[2];
        for (int k = 0; k < 2; k++) {
            ma[k] = 0.5 * (qs[i + 1][k] + qs[i][k]);
            mb[k] = 0.5 * (qs[i][k] + qs[i - 1][k]);
        }
        aniso_gradV(ma, a);
        aniso_gradV(mb, b);
        for (int k = 0; k < 2; k++) {
            /* h^2 times the relation: every term is of the size of q */
            const double e = qs[i + 1][k] - 2.0 * qs[i][k] + qs[i - 1][k] + 0.5 * h * h * (a[k] + b[k]);
            worst = fmax(worst, fabs(e));
        }
        scale = fmax(scale, maxabs2(qs[i]));
        /* the two-step form from the one-step positions, one step ahead */
        double q2[2];
        st = vigen_midpoint_vi_step2(w, (i - 1) * h, i * h, (i + 1) * h, qs[i - 1], qs[i], q2);
        CHECK(st == VIGEN_SUCCESS);
        worst2 = fmax(worst2, fmax(fabs(q2[0] - qs[i + 1][0]), fabs(q2[1] - qs[i + 1][1])));
    }
    /* a wrong discrete Lagrangian leaves a residual of order h^4 ~ 2e-5 here */
    CHECK_MSG(worst <= 16.0 * EPS * scale, "Wendlandt-Marsden residual %.3g (scale %.3g), exact=%d",
              worst, scale, exact);
    CHECK_MSG(worst2 <= 16.0 * EPS * scale, "two-step vs one-step %.3g, exact=%d", worst2, exact);
    /* the statistics count what was called: one-step steps and two-step calls */
    const vigen_stats *s = vigen_midpoint_vi_stats(w);
    CHECK(s->steps == N + (N - 1) && s->failed_steps == 0);
    CHECK(s->iterations > 0 && s->hessian_evals > 0 && s->dHdq_evals > s->iterations);
    CHECK(s->dHdp_evals > 0);
    vigen_midpoint_vi_free(w);
}

/* Non-uniform grid, time-dependent L: step2 on the one-step positions. */
static void check_two_step_nonuniform(int exact)
{
    vigen_lagrangian L = aniso_lagrangian(forced2_dLdq, exact);
    vigen_midpoint_vi *w = vigen_midpoint_vi_alloc(&L, unit_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    enum { N = 300 };
    static double qs[N + 1][2], ts[N + 1];
    double t = 0.25, q[2] = {0.5, 0.2}, p[2] = {-0.3, 0.4};
    ts[0] = t;
    memcpy(qs[0], q, sizeof q);
    int st = VIGEN_SUCCESS;
    for (int i = 1; i <= N && st == VIGEN_SUCCESS; i++) {
        /* 8/256 .. 16/256: dyadic, so that the times and their differences
         * given to step2 are the steps taken, exactly */
        const double h = (double)(8 + (i * 5) % 9) / 256.0;
        st = vigen_midpoint_vi_step(w, &t, q, p, h);
        ts[i] = t;
        memcpy(qs[i], q, sizeof q);
    }
    CHECK_MSG(st == VIGEN_SUCCESS, "status %d", st);
    double worst = 0.0, scale = 0.0;
    for (int i = 1; i < N; i++) {
        double q2[2];
        st = vigen_midpoint_vi_step2(w, ts[i - 1], ts[i], ts[i + 1], qs[i - 1], qs[i], q2);
        CHECK(st == VIGEN_SUCCESS);
        worst = fmax(worst, fmax(fabs(q2[0] - qs[i + 1][0]), fabs(q2[1] - qs[i + 1][1])));
        scale = fmax(scale, maxabs2(qs[i]));
    }
    CHECK_MSG(worst <= 16.0 * EPS * scale, "non-uniform two-step vs one-step %.3g, exact=%d", worst, exact);
    /* backwards in time (decreasing times) the same relation holds */
    double q2[2];
    st = vigen_midpoint_vi_step2(w, ts[20], ts[19], ts[18], qs[20], qs[19], q2);
    CHECK(st == VIGEN_SUCCESS && fabs(q2[0] - qs[18][0]) <= 16.0 * EPS * scale
          && fabs(q2[1] - qs[18][1]) <= 16.0 * EPS * scale);
    vigen_midpoint_vi_free(w);
}

/* ---- order ------------------------------------------------------------------ */

static void check_order(void)
{
    vigen_lagrangian L;
    memset(&L, 0, sizeof L);
    L.dim = 1;
    L.dLdq = forced_dLdq;
    L.dLdv = id1_dLdv;
    vigen_midpoint_vi *w = vigen_midpoint_vi_alloc(&L, id1_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    const double t0 = 0.3, T = 2.0;
    double err[5], err2[5];
    for (int k = 0; k < 5; k++) {
        const long n = 10L << k;
        const double h = T / (double)n;
        double t = t0, q[1] = {forced_q(t0)}, p[1] = {forced_p(t0)};
        double e = 0.0;
        int st = VIGEN_SUCCESS;
        for (long i = 0; i < n && st == VIGEN_SUCCESS; i++) {
            st = vigen_midpoint_vi_step(w, &t, q, p, h);
            e = fmax(e, fmax(fabs(q[0] - forced_q(t)), fabs(p[0] - forced_p(t))));
        }
        CHECK(st == VIGEN_SUCCESS);
        err[k] = e;
        /* positions only: the two-step form from exact q(t0), q(t0 + h) */
        double qa[1] = {forced_q(t0)}, qb[1] = {forced_q(t0 + h)}, qc[1];
        e = 0.0;
        for (long i = 1; i < n && st == VIGEN_SUCCESS; i++) {
            st = vigen_midpoint_vi_step2(w, t0 + (i - 1) * h, t0 + i * h, t0 + (i + 1) * h, qa, qb, qc);
            e = fmax(e, fabs(qc[0] - forced_q(t0 + (i + 1) * h)));
            qa[0] = qb[0];
            qb[0] = qc[0];
        }
        CHECK(st == VIGEN_SUCCESS);
        err2[k] = e;
    }
    for (int k = 0; k + 1 < 5; k++) {
        const double o1 = log2(err[k] / err[k + 1]), o2 = log2(err2[k] / err2[k + 1]);
        CHECK_MSG(fabs(o1 - 2.0) < 0.1, "one-step order %.3f (errors %.3g, %.3g)", o1, err[k], err[k + 1]);
        CHECK_MSG(fabs(o2 - 2.0) < 0.1, "two-step order %.3f (errors %.3g, %.3g)", o2, err2[k], err2[k + 1]);
    }
    vigen_midpoint_vi_free(w);
}


/* The magnetic problem: the hand-derived second derivatives against
 * differences of the gradients; one-step runs with and without them agree;
 * the canonical angular momentum q x p is conserved (Noether, rotations);
 * the two-step form reproduces the one-step positions. */
static void check_magnetic(void)
{
    /* the second derivatives above, against central differences */
    const double q0[2] = {0.7, -0.4}, v0[2] = {0.3, 0.9}, e = 1e-6;
    double H[4], G[4], gp[2], gm[2], x[2], u[2];
    mag_d2q(0, q0, v0, H, NULL);
    mag_d2qv(0, q0, v0, G, NULL);
    double worst = 0.0;
    for (int j = 0; j < 2; j++) {
        memcpy(x, q0, sizeof x);
        x[j] += e; mag_dLdq(0, x, v0, gp, NULL);
        x[j] -= 2 * e; mag_dLdq(0, x, v0, gm, NULL);
        for (int i = 0; i < 2; i++) worst = fmax(worst, fabs((gp[i] - gm[i]) / (2 * e) - H[i * 2 + j]));
        memcpy(u, v0, sizeof u);
        u[j] += e; mag_dLdq(0, q0, u, gp, NULL);
        u[j] -= 2 * e; mag_dLdq(0, q0, u, gm, NULL);
        for (int i = 0; i < 2; i++) worst = fmax(worst, fabs((gp[i] - gm[i]) / (2 * e) - G[i * 2 + j]));
        /* d(dL/dv)_i/dq_j = d2L/dq_j dv_i = G[j][i] */
        memcpy(x, q0, sizeof x);
        x[j] += e; mag_dLdv(0, x, v0, gp, NULL);
        x[j] -= 2 * e; mag_dLdv(0, x, v0, gm, NULL);
        for (int i = 0; i < 2; i++) worst = fmax(worst, fabs((gp[i] - gm[i]) / (2 * e) - G[j * 2 + i]));
    }
    CHECK_MSG(worst < 1e-8, "magnetic second derivatives vs differences: %.3g", worst);

    vigen_midpoint_vi *w[2];
    for (int exact = 0; exact < 2; exact++) {
        vigen_lagrangian L = lag2(mag_dLdq, mag_dLdv, NULL);
        if (exact) {
            L.d2Ldq2 = mag_d2q;
            L.d2Ldqdv = mag_d2qv;
            L.d2Ldv2 = unit_2x2;
        }
        w[exact] = vigen_midpoint_vi_alloc(&L, mag_g, NULL);
        CHECK(w[exact] != NULL);
    }
    if (w[0] == NULL || w[1] == NULL) {
        vigen_midpoint_vi_free(w[0]);
        vigen_midpoint_vi_free(w[1]);
        return;
    }
    enum { N = 4000 };
    static double qs[N + 1][2];
    const double h = 0.03125;
    double t[2] = {0.0, 0.0}, q[2][2] = {{0.9, 0.1}, {0.9, 0.1}}, p[2][2] = {{0.2, 1.0}, {0.2, 1.0}};
    const double J0 = q[0][0] * p[0][1] - q[0][1] * p[0][0];
    double dJ = 0.0, diff = 0.0, scale = 0.0;
    int st = VIGEN_SUCCESS;
    memcpy(qs[0], q[1], sizeof qs[0]);
    for (int i = 1; i <= N && st == VIGEN_SUCCESS; i++) {
        for (int k = 0; k < 2 && st == VIGEN_SUCCESS; k++) st = vigen_midpoint_vi_step(w[k], &t[k], q[k], p[k], h);
        memcpy(qs[i], q[1], sizeof qs[i]);
        dJ = fmax(dJ, fabs(q[1][0] * p[1][1] - q[1][1] * p[1][0] - J0));
        for (int k = 0; k < 2; k++) diff = fmax(diff, fmax(fabs(q[0][k] - q[1][k]), fabs(p[0][k] - p[1][k])));
        scale = fmax(scale, maxabs2(q[1]));
    }
    CHECK_MSG(st == VIGEN_SUCCESS, "magnetic: status %d", st);
    CHECK_MSG(dJ < 1e-12 * fabs(J0), "magnetic: canonical angular momentum changed by %.3g", dJ);
    CHECK_MSG(diff < 1e-11, "magnetic: user second derivatives vs differences: trajectories differ by %.3g", diff);
    /* Newton from the extrapolated predictor converges quadratically: a few
     * iterations per step, with the user's derivatives as with differences
     * (a wrong Jacobian term makes it linear: twice as many or more) */
    const unsigned long it0 = vigen_midpoint_vi_stats(w[0])->iterations;
    const unsigned long it1 = vigen_midpoint_vi_stats(w[1])->iterations;
    CHECK_MSG(it0 <= 6 * N && it1 <= 6 * N, "one-step iterations: %lu (exact), %lu (differences)", it1, it0);
    double worst2 = 0.0;
    unsigned long it2[2];
    for (int k = 0; k < 2; k++) {
        it2[k] = vigen_midpoint_vi_stats(w[k])->iterations;
        for (int i = 1; i < N; i++) {
            double q2[2];
            st = vigen_midpoint_vi_step2(w[k], (i - 1) * h, i * h, (i + 1) * h, qs[i - 1], qs[i], q2);
            if (st != VIGEN_SUCCESS) break;
            worst2 = fmax(worst2, fmax(fabs(q2[0] - qs[i + 1][0]), fabs(q2[1] - qs[i + 1][1])));
        }
        CHECK(st == VIGEN_SUCCESS);
        it2[k] = vigen_midpoint_vi_stats(w[k])->iterations - it2[k];
        CHECK_MSG(it2[k] <= 6 * N, "two-step iterations: %lu (exact=%d)", it2[k], k);
    }
    CHECK_MSG(worst2 <= 16.0 * EPS * scale, "magnetic: two-step vs one-step %.3g", worst2);
    printf("magnetic: |q x p - J0| <= %.3g, exact vs differences %.3g, two-step vs one-step %.3g;"
           " Newton iterations per step %.2f, %.2f (one-step, exact and differences), %.2f, %.2f (two-step)\n",
           dJ, diff, worst2, (double)it1 / N, (double)it0 / N, (double)it2[1] / N, (double)it2[0] / N);
    vigen_midpoint_vi_free(w[0]);
    vigen_midpoint_vi_free(w[1]);
}

/* ---- the relativistic particle ------------------------------------------------ */

static vigen_lagrangian rel_lagrangian(rel_ctx *r, int exact)
{
    vigen_lagrangian L = lag2(rel_dLdq, rel_dLdv, r);
    if (exact) {
        L.d2Ldq2 = rel_d2q;
        L.d2Ldqdv = zero_2x2;
        L.d2Ldv2 = rel_d2v;
    }
    return L;
}

/* One step of Heun's method (explicit trapezoidal, order 2, not symplectic)
 * for q' = g(p), p' = dL/dq(q): the drifting reference. */
static void heun_step(rel_ctx *r, double *q, double *p, double h)
{
    double v0[2], f0[2], q1[2], p1[2], v1[2], f1[2];
    rel_g(0, q, p, v0, r);
    rel_dLdq(0, q, v0, f0, r);
    for (int k = 0; k < 2; k++) {
        q1[k] = q[k] + h * v0[k];
        p1[k] = p[k] + h * f0[k];
    }
    rel_g(0, q1, p1, v1, r);
    rel_dLdq(0, q1, v1, f1, r);
    for (int k = 0; k < 2; k++) {
        q[k] += 0.5 * h * (v0[k] + v1[k]);
        p[k] += 0.5 * h * (f0[k] + f1[k]);
    }
}

/* Least-squares slope of y against x, and the largest |y - y0|. */
typedef struct { double sx, sy, sxx, sxy; long n; double y0, amp; } fit;
static void fit_add(fit *f, double x, double y)
{
    if (f->n == 0) f->y0 = y;
    y -= f->y0;                /* the fit of the deviation: no cancellation */
    f->sx += x; f->sy += y; f->sxx += x * x; f->sxy += x * y;
    f->n++;
    f->amp = fmax(f->amp, fabs(y));
}
static double fit_slope(const fit *f)
{
    const double n = (double)f->n;
    return (n * f->sxy - f->sx * f->sy) / (n * f->sxx - f->sx * f->sx);
}

/* The mean of y[1 .. m-1] weighted by the smooth bump exp(-1/(x(1 - x))),
 * x = j/m, with compensated sums.  For a quasi-periodic y (the energy error
 * of a symplectic map on an invariant torus) such weighted Birkhoff averages
 * converge faster than any power of m (Das and Yorke, "Super convergence of
 * ergodic averages for quasiperiodic orbits", Nonlinearity 2018), where a
 * plain mean or a linear fit keeps an error of order amplitude/periods; a
 * secular drift enters in full. */
static double bump_mean(const double *y, long m)
{
    vigen_neumaier num, den;
    vigen_neumaier_init(&num);
    vigen_neumaier_init(&den);
    for (long j = 1; j < m; j++) {
        const double x = (double)j / (double)m, wgt = exp(-1.0 / (x * (1.0 - x)));
        vigen_neumaier_add(&num, wgt * y[j]);
        vigen_neumaier_add(&den, wgt);
    }
    return vigen_neumaier_result(&num) / vigen_neumaier_result(&den);
}

/* Energy over 10^5 steps, q x p (Noether), the compensated time. */
static void check_relativistic_long(void)
{
    rel_ctx r = {1.3, 1.0, 0};
    vigen_lagrangian L = rel_lagrangian(&r, 1);
    vigen_midpoint_vi *w = vigen_midpoint_vi_alloc(&L, rel_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    enum { N = 100000 };
    const double h = 0.05;
    double t = 0.0, q[2] = {1.0, 0.0}, p[2] = {0.0, 0.9};   /* speed ~ 0.57 c */
    double qh[2] = {1.0, 0.0}, ph[2] = {0.0, 0.9};
    const double J0 = q[0] * p[1] - q[1] * p[0];
    double dJ = 0.0;
    fit fe = {0}, fh = {0};
    static double de[N + 1], dh[N + 1];     /* E - E(start), mid-point VI and Heun */
    const double E0 = rel_energy(&r, q, p);
    int st = VIGEN_SUCCESS;
    long i;
    for (i = 1; i <= N && st == VIGEN_SUCCESS; i++) {
        st = vigen_midpoint_vi_step(w, &t, q, p, h);
        heun_step(&r, qh, ph, h);
        const double x = (double)i * h;
        de[i] = rel_energy(&r, q, p) - E0;
        dh[i] = rel_energy(&r, qh, ph) - E0;
        fit_add(&fe, x, de[i]);
        fit_add(&fh, x, dh[i]);
        dJ = fmax(dJ, fabs(q[0] * p[1] - q[1] * p[0] - J0));
    }
    CHECK_MSG(st == VIGEN_SUCCESS, "status %d at step %ld", st, i - 1);
    const double T = N * h, drift = fabs(fit_slope(&fe)) * T, hdrift = fabs(fit_slope(&fh)) * T;
    /* the smooth-window means of the energy over the first and the second
     * half of the run: their difference is the drift over T/2 */
    const double half = bump_mean(de + N / 2, N / 2) - bump_mean(de, N / 2);
    const double hhalf = bump_mean(dh + N / 2, N / 2) - bump_mean(dh, N / 2);
    printf("relativistic, 1e5 steps: energy deviation <= %.3g, fitted drift over the run %.3g,"
           " between smooth means of the halves %.3g; Heun: %.3g, %.3g; |q x p - J0| <= %.3g\n",
           fe.amp, drift, half, hdrift, hhalf, dJ);
    /* bounded: the midpoint rule's O(h^2) energy error, here ~1e-4 */
    CHECK(fe.amp < 2e-3);
    /* no drift: the trend is a small fraction of the oscillation and far
     * below the drift of a non-symplectic method of the same order */
    CHECK_MSG(drift < 1e-2 * fe.amp && drift < 1e-3 * hdrift, "drift %.3g", drift);
    CHECK(hdrift > fe.amp);
    /* and at round-off level, once the bounded oscillation is averaged out:
     * 10^5 energies rounded to epsilon |E| ~ 4e-16 (a drift of the same
     * order as Heun's would be 1e-2) */
    CHECK_MSG(fabs(half) < 1e-13 * fabs(E0), "drift between the halves %.3g", half);
    CHECK(fabs(hhalf) > 1e-3);
    /* Noether: rotations leave L invariant, so q x p is conserved */
    CHECK_MSG(dJ < 1e-12 * fabs(J0), "angular momentum changed by %.3g", dJ);
    /* t is the compensated sum of N steps h: within an ulp of N h */
    CHECK_MSG(fabs(t - N * h) <= nextafter(N * h, 1e300) - N * h, "t = %.17g", t);
    vigen_midpoint_vi_free(w);

    /* the control: an anisotropic potential breaks the symmetry, q x p varies */
    rel_ctx ra = {1.3, 1.0, 1};
    vigen_lagrangian La = rel_lagrangian(&ra, 0);
    w = vigen_midpoint_vi_alloc(&La, rel_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    double qa[2] = {1.0, 0.0}, pa[2] = {0.0, 0.9};
    t = 0.0;
    dJ = 0.0;
    for (i = 0; i < 200 && st == VIGEN_SUCCESS; i++) {
        st = vigen_midpoint_vi_step(w, &t, qa, pa, h);
        dJ = fmax(dJ, fabs(qa[0] * pa[1] - qa[1] * pa[0] - J0));
    }
    CHECK(st == VIGEN_SUCCESS && dJ > 1e-2);
    vigen_midpoint_vi_free(w);
}

/* The mid-point Ld is symmetric, Ld(t1, t0, q1, q0) = -Ld(t0, t1, q0, q1):
 * the step with -h from (t1, q1, p1) is the inverse of the step with h.
 * Forward steps, then the same steps backwards, return to the start up to
 * round-off (continuing the same trajectory, so the predictor sees the
 * reversal). */
static void check_reversible(void)
{
    rel_ctx r = {1.3, 1.0, 0};
    vigen_lagrangian L = rel_lagrangian(&r, 0);
    vigen_midpoint_vi *w = vigen_midpoint_vi_alloc(&L, rel_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    enum { N = 200 };
    double hs[N];
    const double q0[2] = {1.0, 0.2}, p0[2] = {-0.3, 1.1};
    double t = 0.5, q[2] = {1.0, 0.2}, p[2] = {-0.3, 1.1};
    int st = VIGEN_SUCCESS;
    for (int i = 0; i < N && st == VIGEN_SUCCESS; i++) {
        hs[i] = 0.05 * (1.0 + 0.5 * sin(0.9 * i));
        st = vigen_midpoint_vi_step(w, &t, q, p, hs[i]);
    }
    for (int i = N - 1; i >= 0 && st == VIGEN_SUCCESS; i--) st = vigen_midpoint_vi_step(w, &t, q, p, -hs[i]);
    CHECK_MSG(st == VIGEN_SUCCESS, "reversal: status %d", st);
    const double dq = fmax(fabs(q[0] - q0[0]), fabs(q[1] - q0[1])), dp = fmax(fabs(p[0] - p0[0]), fabs(p[1] - p0[1]));
    /* a non-symmetric method of order 2 misses by O(h^3) a step: about 1e-3 here */
    CHECK_MSG(dq < 1e-12 && dp < 1e-12 && fabs(t - 0.5) < 1e-13, "forward then back: %.3g, %.3g, t %.17g", dq, dp, t);
    /* small steps, then one 300 times larger: the same result as from a
     * fresh workspace (another predictor: the solution does not depend on it) */
    for (int i = 0; i < 10 && st == VIGEN_SUCCESS; i++) st = vigen_midpoint_vi_step(w, &t, q, p, 0.001);
    vigen_midpoint_vi *fresh = vigen_midpoint_vi_alloc(&L, rel_g, NULL);
    CHECK(fresh != NULL && st == VIGEN_SUCCESS);
    if (fresh != NULL) {
        double tf = t, qf[2] = {q[0], q[1]}, pf[2] = {p[0], p[1]};
        st = vigen_midpoint_vi_step(w, &t, q, p, 0.3);
        const int stf = vigen_midpoint_vi_step(fresh, &tf, qf, pf, 0.3);
        CHECK_MSG(st == VIGEN_SUCCESS && stf == VIGEN_SUCCESS, "large step: %d, fresh %d", st, stf);
        /* (the continuing workspace carries its compensation: ulps apart) */
        const double d = fmax(fmax(fabs(q[0] - qf[0]), fabs(q[1] - qf[1])), fmax(fabs(p[0] - pf[0]), fabs(p[1] - pf[1])));
        CHECK_MSG(fabs(t - tf) < 1e-15 && d < 1e-14, "large step: t %.17g vs %.17g, state %.3g apart", t, tf, d);
        vigen_midpoint_vi_free(fresh);
    }
    vigen_midpoint_vi_free(w);
}

/* Options: without compensation t is the naive running sum, bit for bit;
 * with it t is within an ulp of the exact sum (long double reference) of
 * 2000 alternating steps; without extrapolation the predictor is only
 * worse; the trajectories agree to round-off. */
static void check_options(void)
{
    rel_ctx r = {1.3, 1.0, 0};
    vigen_lagrangian L = rel_lagrangian(&r, 1);
    vigen_solver_options o;
    vigen_solver_options_default(&o);
    o.kahan = 0;
    o.extrapolate = 0;
    vigen_midpoint_vi *w0 = vigen_midpoint_vi_alloc(&L, rel_g, &o), *w1 = vigen_midpoint_vi_alloc(&L, rel_g, NULL);
    CHECK(w0 != NULL && w1 != NULL);
    if (w0 == NULL || w1 == NULL) {
        vigen_midpoint_vi_free(w0);
        vigen_midpoint_vi_free(w1);
        return;
    }
    double t0 = 0.1, t1 = 0.1, naive = 0.1, q0[2] = {1.0, 0.2}, p0[2] = {-0.3, 1.1}, q1[2] = {1.0, 0.2},
           p1[2] = {-0.3, 1.1}, diff = 0.0;
    long double exact = 0.1L;
    int st = VIGEN_SUCCESS;
    for (int i = 0; i < 2000 && st == VIGEN_SUCCESS; i++) {
        const double h = (i % 2) ? 0.0017 : 0.001;
        st = vigen_midpoint_vi_step(w0, &t0, q0, p0, h);
        if (st == VIGEN_SUCCESS) st = vigen_midpoint_vi_step(w1, &t1, q1, p1, h);
        naive += h;
        exact += (long double)h;
        for (int k = 0; k < 2; k++) diff = fmax(diff, fmax(fabs(q0[k] - q1[k]), fabs(p0[k] - p1[k])));
    }
    CHECK(st == VIGEN_SUCCESS);
    CHECK_MSG(memcmp(&t0, &naive, sizeof t0) == 0, "t without compensation %.17g, naive sum %.17g", t0, naive);
    const double te = (double)exact;
    CHECK_MSG(fabs(t1 - te) <= nextafter(te, 1e300) - te, "compensated t %.17g, exact %.17g", t1, te);
    CHECK_MSG(fabs(naive - te) > nextafter(te, 1e300) - te, "the naive sum is exact here: the test shows nothing");
    CHECK_MSG(diff < 1e-12, "options change the trajectory by %.3g", diff);
    CHECK(vigen_midpoint_vi_stats(w0)->iterations >= vigen_midpoint_vi_stats(w1)->iterations);
    vigen_midpoint_vi_free(w0);
    vigen_midpoint_vi_free(w1);
}

/* The Hamilton–Pontryagin midpoint integrator with the trivial map solves
 * the same discrete Euler–Lagrange equations (with the same momenta) for
 * (q1, v) from L alone; the Cresson–Safi form solves for q1 through g. */
static void check_relativistic_vs_hp(int exact)
{
    rel_ctx r = {1.3, 1.0, 0};
    vigen_lagrangian L = rel_lagrangian(&r, exact);
    vigen_midpoint_vi *w = vigen_midpoint_vi_alloc(&L, rel_g, NULL);
    vigen_hp *hp = vigen_hp_alloc(&L, VIGEN_HP_MIDPOINT, NULL, NULL);
    CHECK(w != NULL && hp != NULL);
    if (w == NULL || hp == NULL) {
        vigen_midpoint_vi_free(w);
        vigen_hp_free(hp);
        return;
    }
    double t = 0.0, q[2] = {1.0, 0.2}, p[2] = {-0.3, 1.1};
    double th = t, qh[2] = {1.0, 0.2}, ph[2] = {-0.3, 1.1};
    double worst = 0.0;
    int st = VIGEN_SUCCESS, sth = VIGEN_SUCCESS;
    for (int i = 0; i < 1000 && st == VIGEN_SUCCESS && sth == VIGEN_SUCCESS; i++) {
        const double h = 0.04 + 0.02 * (i % 3);
        st = vigen_midpoint_vi_step(w, &t, q, p, h);
        sth = vigen_hp_step(hp, &th, qh, ph, h);
        for (int k = 0; k < 2; k++) worst = fmax(worst, fmax(fabs(q[k] - qh[k]), fabs(p[k] - ph[k])));
    }
    CHECK_MSG(st == VIGEN_SUCCESS && sth == VIGEN_SUCCESS, "status %d, %d", st, sth);
    CHECK(t == th);
    printf("relativistic, Cresson-Safi vs Hamilton-Pontryagin midpoint (exact=%d): %.3g\n", exact, worst);
    CHECK_MSG(worst < 1e-13, "Cresson-Safi and HP midpoint differ by %.3g", worst);
    vigen_midpoint_vi_free(w);
    vigen_hp_free(hp);
}

/* ---- bad input ------------------------------------------------------------------ */

/* A Lagrangian whose dL/dq or g turns NaN once q0 exceeds a threshold, or
 * whose dL/dv does. */
typedef struct { double qmax; int which; } nan_ctx;
static void nan_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    const nan_ctx *n = c;
    aniso_dLdq(t, q, v, o, NULL);
    if (n->which == 0 && q[0] > n->qmax) o[1] = NAN;
}
static void nan_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    const nan_ctx *n = c;
    unit_dLdv(t, q, v, o, NULL);
    if (n->which == 1 && q[0] > n->qmax) o[0] = INFINITY;
}
static void nan_g(double t, const double *q, const double *p, double *o, void *c)
{
    const nan_ctx *n = c;
    unit_g(t, q, p, o, NULL);
    if (n->which == 2 && q[0] > n->qmax) o[0] = NAN;
}

/* 1-D L = v^2/2 + q^3/3 (dL/dq = q^2): for h = 10 from q = p = 1 the step
 * equation d - h p - h^2/2 (q + d/2)^2 = 0 has no real root. */
static void cubic_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    o[0] = q[0] * q[0];
}

/* Degenerate: L = q0 v1 - q1 v0 - |q|^2/2, linear in v (dL/dv = (-q1, q0)
 * does not depend on v: d2L/dv2 = 0). */
static void degen_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)c;
    o[0] = v[1] - q[0];
    o[1] = -v[0] - q[1];
}
static void degen_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    o[0] = -q[1];
    o[1] = q[0];
}
static void degen_d2q(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = o[3] = -1.0;
    o[1] = o[2] = 0.0;
}
static void degen_d2qv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = o[3] = 0.0;
    o[1] = 1.0;
    o[2] = -1.0;
}

/* Runs one step that must fail with `want` and leave (t, q, p) as they were. */
static void expect_step_fails(vigen_midpoint_vi *w, double t, const double *q, const double *p, double h,
                              int want, const char *what)
{
    double t1 = t, q1[2] = {q[0], q[1]}, p1[2] = {p[0], p[1]};
    const unsigned long failed = vigen_midpoint_vi_stats(w)->failed_steps;
    const int st = vigen_midpoint_vi_step(w, &t1, q1, p1, h);
    CHECK_MSG(st == want, "%s: status %d (%s), wanted %d", what, st, vigen_strerror(st), want);
    CHECK_MSG(memcmp(&t1, &t, sizeof t) == 0 && memcmp(q1, q, sizeof q1) == 0 && memcmp(p1, p, sizeof p1) == 0,
              "%s: state changed", what);
    if (want != VIGEN_EINVAL && want != VIGEN_EUNSUPPORTED)
        CHECK_MSG(vigen_midpoint_vi_stats(w)->failed_steps == failed + 1, "%s: failure not counted", what);
}

static void check_bad_input(void)
{
    /* alloc: dimension 0, missing callbacks, no Lagrangian */
    vigen_lagrangian L = lag2(aniso_dLdq, unit_dLdv, NULL);
    CHECK(vigen_midpoint_vi_alloc(NULL, unit_g, NULL) == NULL);
    L.dim = 0;
    CHECK(vigen_midpoint_vi_alloc(&L, unit_g, NULL) == NULL);
    L = lag2(NULL, unit_dLdv, NULL);
    CHECK(vigen_midpoint_vi_alloc(&L, unit_g, NULL) == NULL);
    L = lag2(aniso_dLdq, NULL, NULL);
    CHECK(vigen_midpoint_vi_alloc(&L, unit_g, NULL) == NULL);

    /* arguments: h zero or not finite, t not finite, NULL pointers */
    L = lag2(aniso_dLdq, unit_dLdv, NULL);
    vigen_midpoint_vi *w = vigen_midpoint_vi_alloc(&L, unit_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    const double q[2] = {0.8, -0.3}, p[2] = {0.1, 0.5};
    expect_step_fails(w, 0.0, q, p, 0.0, VIGEN_EINVAL, "h = 0");
    expect_step_fails(w, 0.0, q, p, NAN, VIGEN_EINVAL, "h = NaN");
    expect_step_fails(w, 0.0, q, p, INFINITY, VIGEN_EINVAL, "h = inf");
    expect_step_fails(w, INFINITY, q, p, 0.1, VIGEN_EINVAL, "t = inf");
    expect_step_fails(w, 1e308, q, p, 1.7e308, VIGEN_EINVAL, "t + h overflows");
    double t = 0.0, qq[2] = {0.8, -0.3}, pp[2] = {0.1, 0.5}, q2[2] = {7.0, 7.0};
    CHECK(vigen_midpoint_vi_step(NULL, &t, qq, pp, 0.1) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step(w, NULL, qq, pp, 0.1) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step(w, &t, NULL, pp, 0.1) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step(w, &t, qq, NULL, 0.1) == VIGEN_EINVAL);
    /* two-step: times not strictly monotone or not finite, aliasing */
    CHECK(vigen_midpoint_vi_step2(w, 0.0, 0.1, 0.1, q, p, q2) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step2(w, 0.0, 0.1, 0.05, q, p, q2) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step2(w, 0.0, 0.0, 0.1, q, p, q2) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step2(w, NAN, 0.1, 0.2, q, p, q2) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step2(w, 0.0, 0.1, INFINITY, q, p, q2) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step2(w, 0.0, 0.1, 0.2, q, qq, qq) == VIGEN_EINVAL);
    CHECK(vigen_midpoint_vi_step2(w, 0.0, 0.1, 0.2, q, NULL, q2) == VIGEN_EINVAL);
    CHECK(q2[0] == 7.0 && q2[1] == 7.0);
    CHECK(vigen_midpoint_vi_stats(w)->steps == 0);
    vigen_midpoint_vi_free(w);

    /* no g: the one-step map is unsupported, the two-step form works */
    w = vigen_midpoint_vi_alloc(&L, NULL, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    expect_step_fails(w, 0.0, q, p, 0.1, VIGEN_EUNSUPPORTED, "g = NULL");
    const double q1[2] = {0.81, -0.25};
    CHECK(vigen_midpoint_vi_step2(w, 0.0, 0.1, 0.2, q, q1, q2) == VIGEN_SUCCESS);
    vigen_midpoint_vi_free(w);

    /* NaN or infinity from dL/dq, dL/dv or g */
    for (int which = 0; which < 3; which++) {
        nan_ctx nc = {0.85, which};
        vigen_lagrangian Ln = lag2(nan_dLdq, nan_dLdv, &nc);
        w = vigen_midpoint_vi_alloc(&Ln, nan_g, NULL);
        CHECK(w != NULL);
        if (w == NULL) return;
        double tn = 0.0, qn[2] = {0.8, -0.3}, pn[2] = {1.0, 0.5};
        int st = VIGEN_SUCCESS;
        /* step until the NaN region is reached: that step fails */
        for (int i = 0; i < 100 && st == VIGEN_SUCCESS && qn[0] <= 0.84; i++)
            st = vigen_midpoint_vi_step(w, &tn, qn, pn, 0.02);
        CHECK(st == VIGEN_SUCCESS);
        if (which != 1) {
            expect_step_fails(w, tn, qn, pn, 0.5, VIGEN_ENONFINITE, which == 0 ? "NaN dL/dq" : "NaN g");
        }
        double qa[2] = {0.8, 0.0}, qb[2] = {0.9, 0.0}, qc[2] = {7.0, 7.0};
        st = vigen_midpoint_vi_step2(w, 0.0, 0.1, 0.2, qa, qb, qc);
        if (which == 2) CHECK(st == VIGEN_SUCCESS);   /* g is not used there */
        else CHECK_MSG(st == VIGEN_ENONFINITE && qc[0] == 7.0 && qc[1] == 7.0, "step2 NaN: %d", st);
        vigen_midpoint_vi_free(w);
    }

    /* Newton that cannot converge: the step equation has no solution */
    vigen_lagrangian Lc;
    memset(&Lc, 0, sizeof Lc);
    Lc.dim = 1;
    Lc.dLdq = cubic_dLdq;
    Lc.dLdv = id1_dLdv;
    w = vigen_midpoint_vi_alloc(&Lc, id1_g, NULL);
    CHECK(w != NULL);
    if (w == NULL) return;
    {
        double tc = 0.0, qc[1] = {1.0}, pc[1] = {1.0};
        const double t0 = tc, qc0 = qc[0], pc0 = pc[0];
        int st = vigen_midpoint_vi_step(w, &tc, qc, pc, 10.0);
        CHECK_MSG(st == VIGEN_ENOCONV || st == VIGEN_EMAXITER || st == VIGEN_ESINGULAR,
                  "no solution: status %d (%s)", st, vigen_strerror(st));
        CHECK(tc == t0 && qc[0] == qc0 && pc[0] == pc0);
        printf("a step equation without solution: %s\n", vigen_strerror(st));
        /* the same state with a reasonable step is fine */
        CHECK(vigen_midpoint_vi_step(w, &tc, qc, pc, 0.01) == VIGEN_SUCCESS);
    }
    vigen_midpoint_vi_free(w);

    /* a degenerate Lagrangian: the two-step form needs d2L/dv2 invertible */
    for (int exact = 0; exact < 2; exact++) {
        vigen_lagrangian Ld = lag2(degen_dLdq, degen_dLdv, NULL);
        if (exact) {
            Ld.d2Ldq2 = degen_d2q;
            Ld.d2Ldqdv = degen_d2qv;
            Ld.d2Ldv2 = zero_2x2;
        }
        w = vigen_midpoint_vi_alloc(&Ld, NULL, NULL);
        CHECK(w != NULL);
        if (w == NULL) return;
        double qa[2] = {0.8, 0.1}, qb[2] = {0.85, 0.2}, qc[2] = {7.0, 7.0};
        const int st = vigen_midpoint_vi_step2(w, 0.0, 0.1, 0.2, qa, qb, qc);
        CHECK_MSG(st == VIGEN_ESINGULAR && qc[0] == 7.0 && qc[1] == 7.0, "degenerate (exact=%d): %d", exact, st);
        CHECK(vigen_midpoint_vi_stats(w)->failed_steps == 1);
        vigen_midpoint_vi_free(w);
    }
}

int main(void)
{
    check_wendlandt_marsden(0);
    check_wendlandt_marsden(1);
    check_two_step_nonuniform(0);
    check_two_step_nonuniform(1);
    check_order();
    check_magnetic();
    check_relativistic_vs_hp(0);
    check_relativistic_vs_hp(1);
    check_relativistic_long();
    check_reversible();
    check_options();
    check_bad_input();
    TEST_MAIN_END();
}
