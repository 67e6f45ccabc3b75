/* test_runtime.c — the runtime library (runtime/include/vigen/runtime.h):
 * status messages, option defaults, the stopping rule, compensated sums,
 * Newton linear algebra, the finite-difference Hessian, the driver, and the
 * stage solvers of an emitted stepper (the golden Gauss-2 and Stormer-Verlet
 * steppers in tests/data/emit/golden, emitted by `vigen emit`) on problems
 * with exact solutions.  Links against vigen_runtime (and GSL). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <vigen/runtime.h>
#include "testlib.h"
#include "../data/emit/golden/gauss2.c"
#include "../data/emit/golden/verlet.c"

/* ---- problems ---- */
static void ho_dq(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)p; (void)c; o[0] = q[0]; }
static void ho_dp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }
static double ho_H(double t, const double *q, const double *p, void *c) { (void)t; (void)c; return (q[0] * q[0] + p[0] * p[0]) / 2; }
static void qp_dq(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }
static void qp_dp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)p; (void)c; o[0] = q[0]; }
static void kep_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)p; (void)c;
    double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    o[0] = q[0] / r3;
    o[1] = q[1] / r3;
}
static void kep_dp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; o[1] = p[1]; }

static void test_status(void)
{
    for (int k = 0; k < VIGEN_STATUS_MAX; k++) {
        CHECK(vigen_strerror(k) != NULL && strlen(vigen_strerror(k)) > 5);
        for (int j = 0; j < k; j++) CHECK(strcmp(vigen_strerror(j), vigen_strerror(k)) != 0);
    }
    CHECK(strcmp(vigen_strerror(VIGEN_SUCCESS), "success") == 0);
    CHECK(strstr(vigen_strerror(-1), "unknown") != NULL);
    CHECK(strstr(vigen_strerror(VIGEN_STATUS_MAX), "unknown") != NULL);
    vigen_solver_options o;
    vigen_solver_options_default(&o);
    CHECK(o.solver == VIGEN_SOLVER_FIXED_POINT && o.kahan == 1 && o.extrapolate == 1 && o.max_iter > 0);
    CHECK(vigen_default_tol() == 1048576.0 * vigen_epsilon() && vigen_epsilon() == 0x1p-52);
}

/* The stopping rule on synthetic increment sequences. */
static void test_judge(void)
{
    vigen_iter_monitor m;
    int v = -1, k;
    /* geometric decrease to round-off, then a stall: converged */
    double seq[] = { 1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14, 1e-16, 2e-16, 3e-16 };
    vigen_iter_start(&m);
    for (k = 0; k < 10 && v < 0; k++) v = vigen_iter_judge(&m, seq[k], 1e-10, 50);
    CHECK(v == VIGEN_SUCCESS && k >= 9);
    /* pairs of equal increments (q and p partitions alternate): no false stall */
    double pairs[] = { 1e-2, 1e-2, 1e-4, 1e-4, 1e-6, 1e-6, 0.0 };
    vigen_iter_start(&m);
    v = -1;
    for (k = 0; k < 7 && v < 0; k++) v = vigen_iter_judge(&m, pairs[k], 1e-10, 50);
    CHECK(v == VIGEN_SUCCESS && k == 7);
    /* growth: divergence after three stalls */
    vigen_iter_start(&m);
    v = -1;
    for (k = 0; k < 50 && v < 0; k++) v = vigen_iter_judge(&m, pow(2.0, k), 1e-10, 50);
    CHECK(v == VIGEN_ENOCONV && k <= 6);
    /* NaN */
    vigen_iter_start(&m);
    CHECK(vigen_iter_judge(&m, 1.0, 1e-10, 50) < 0);
    CHECK(vigen_iter_judge(&m, NAN, 1e-10, 50) == VIGEN_ENONFINITE);
    /* slow decrease hits the cap */
    vigen_iter_start(&m);
    v = -1;
    for (k = 0; k < 100 && v < 0; k++) v = vigen_iter_judge(&m, pow(0.9, k), 1e-10, 20);
    CHECK(v == VIGEN_EMAXITER && k == 20);
}

/* Compensated sums: 1 + 2^20 copies of 2^-60 is exactly 1 + 2^-40. */
static void test_sums(void)
{
    static double x[(1 << 20) + 1];
    x[0] = 1;
    for (int k = 1; k <= (1 << 20); k++) x[k] = 0x1p-60;
    CHECK(vigen_sum_kahan(x, (1 << 20) + 1) == 1 + 0x1p-40);
    CHECK(vigen_sum_naive(x, (1 << 20) + 1) == 1);   /* each 2^-60 is lost: why compensation matters */
    vigen_neumaier acc;
    vigen_neumaier_init(&acc);
    for (int k = 0; k <= (1 << 20); k++) vigen_neumaier_add(&acc, x[k]);
    CHECK(vigen_neumaier_result(&acc) == 1 + 0x1p-40);
    /* Neumaier also when the addend is larger than the sum */
    vigen_neumaier_init(&acc);
    vigen_neumaier_add(&acc, 1.0);
    vigen_neumaier_add(&acc, 0x1p100);
    vigen_neumaier_add(&acc, 1.0);
    vigen_neumaier_add(&acc, -0x1p100);
    CHECK(vigen_neumaier_result(&acc) == 2.0);
    /* the carried TwoSum update */
    double q = 1, c = 0;
    for (int k = 0; k < (1 << 20); k++) q = vigen_twosum_update(q, 0x1p-60, &c);
    CHECK(q + c == 1 + 0x1p-40);
    long double ql = 1, cl = 0;
    for (int k = 0; k < 1024; k++) ql = vigen_twosum_update_ld(ql, 0x1p-70L, &cl);
    CHECK(ql + cl == 1 + 0x1p-60L);
}

/* Newton linear algebra: s = 1, n = 1, Hessian I (harmonic oscillator):
 * M = [[1, -ha], [hat, 1]]. */
static void test_newton_la(void)
{
    vigen_newton *nw = vigen_newton_alloc(1, 1);
    CHECK(nw != NULL);
    double *H = vigen_newton_hessian(nw);
    H[0] = 1; H[1] = 0; H[2] = 0; H[3] = 1;
    vigen_newton_matrix_identity(nw);
    vigen_newton_matrix_block(nw, 0, 0, 0.5, 0.5);
    CHECK(vigen_newton_factor(nw) == VIGEN_SUCCESS);
    double *r = vigen_newton_rhs(nw);
    r[0] = 1; r[1] = 0;
    CHECK(vigen_newton_solve(nw) == VIGEN_SUCCESS);
    CHECK(fabs(r[0] - 0.8) < 1e-15 && fabs(r[1] + 0.4) < 1e-15);   /* M^-1 (1, 0) = (1, -1/2) / (5/4) */
    vigen_newton_matrix_identity(nw);
    vigen_newton_matrix_block(nw, 0, 0, 1.0, -1.0);                   /* 1 + ha hat = 0 */
    CHECK(vigen_newton_factor(nw) == VIGEN_ESINGULAR);
    /* a Hessian from NaN or infinite gradients is not a singular matrix */
    const double bad[2] = { NAN, INFINITY };
    for (int b = 0; b < 2; b++) {
        H[0] = 1; H[1] = 0; H[2] = bad[b]; H[3] = 1;
        vigen_newton_matrix_identity(nw);
        vigen_newton_matrix_block(nw, 0, 0, 0.5, 0.5);
        CHECK_MSG(vigen_newton_factor(nw) == VIGEN_ENONFINITE, "Hessian entry %g: status %d", bad[b],
                  vigen_newton_factor(nw));
    }
    /* a finite matrix whose factorisation overflows: 1e300 x 1e300 */
    H[0] = 0; H[1] = 1e300; H[2] = 1e300; H[3] = 0;
    vigen_newton_matrix_identity(nw);
    vigen_newton_matrix_block(nw, 0, 0, 1e10, 1e10);
    CHECK(vigen_newton_factor(nw) == VIGEN_ENONFINITE);
    /* a non-finite right-hand side (stage gradients NaN) */
    H[0] = 1; H[1] = 0; H[2] = 0; H[3] = 1;
    vigen_newton_matrix_identity(nw);
    vigen_newton_matrix_block(nw, 0, 0, 0.5, 0.5);
    CHECK(vigen_newton_factor(nw) == VIGEN_SUCCESS);
    r[0] = NAN; r[1] = 0;
    CHECK(vigen_newton_solve(nw) == VIGEN_ENONFINITE);
    r[0] = 1; r[1] = INFINITY;
    CHECK(vigen_newton_solve(nw) == VIGEN_ENONFINITE);
    r[0] = 1; r[1] = 0;
    CHECK(vigen_newton_solve(nw) == VIGEN_SUCCESS && fabs(r[0] - 0.8) < 1e-15);
    vigen_newton_free(nw);
    CHECK(vigen_newton_alloc(0, 3) == NULL);
}

/* Finite-difference Hessian of Kepler against the analytic one. */
static void test_hessian_fd(void)
{
    vigen_hamiltonian sys = { 2, kep_dq, kep_dp, NULL, NULL, 1, NULL };
    double q[2] = { 0.6, -0.3 }, p[2] = { 0.2, 1.1 }, hs[16], work[12];
    unsigned long nq = 0, np = 0;
    vigen_hessian_fd(&sys, 0, q, p, hs, work, 0, &nq, &np);
    CHECK(nq == 5 && np == 5);
    double r2 = q[0] * q[0] + q[1] * q[1], r = sqrt(r2), r5 = r2 * r2 * r;
    /* d(q_i / r^3)/dq_j = delta_ij / r^3 - 3 q_i q_j / r^5 */
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            double exact = (i == j ? 1 / (r2 * r) : 0) - 3 * q[i] * q[j] / r5;
            CHECK(fabs(hs[i * 4 + j] - exact) < 1e-6);
            CHECK(hs[i * 4 + 2 + j] == 0);                  /* dHdq does not depend on p */
            CHECK(hs[(2 + i) * 4 + j] == 0);                /* dHdp does not depend on q */
            CHECK(fabs(hs[(2 + i) * 4 + 2 + j] - (i == j)) < 1e-7);
        }
}

/* Gauss-2 by fixed-point iteration on q'' = -q: one step multiplies q - i p
 * by the (2,2) Pade approximant R(ih) = (1 + ih/2 - h^2/12) / (1 - ih/2 - h^2/12)
 * of exp(ih): modulus exactly 1 (q^2 + p^2 conserved) and phase
 * 2 atan((h/2) / (1 - h^2/12)) = h - h^5/720 + ...  */
static void test_gauss2_ho(void)
{
    vigen_hamiltonian sys = { 1, ho_dq, ho_dp, ho_H, NULL, 0, NULL };
    gauss2_workspace *w = gauss2_alloc(&sys, NULL);
    CHECK(w != NULL);
    double t = 0, q[1] = { 1 }, p[1] = { 0 }, dev = 0;
    for (int k = 0; k < 100; k++) {
        CHECK(gauss2_step(w, &t, q, p, 0.1) == VIGEN_SUCCESS);
        double d = fabs(q[0] * q[0] + p[0] * p[0] - 1);
        if (d > dev) dev = d;
    }
    CHECK(fabs(t - 10) < 1e-14);
    double err = hypot(q[0] - cos(10.0), p[0] + sin(10.0));
    double phase = 100 * (2 * atan(0.05 / (1 - 0.01 / 12)) - 0.1);       /* exact phase error */
    CHECK_MSG(fabs(err - 2 * sin(fabs(phase) / 2)) < 1e-3 * err, "Gauss-2 error %g, expected %g", err, fabs(phase));
    CHECK_MSG(dev < 1e-14, "q^2 + p^2 deviation %g", dev);
    const vigen_stats *S = gauss2_stats(w);
    CHECK(S->steps == 100 && S->failed_steps == 0 && S->iterations >= 100);
    /* dH/dq at both stages in every sweep, plus once at the first step's
     * start; dH/dp the same, less both stages of a last half sweep that
     * changed no stage value (at most one per step) */
    CHECK(S->dHdq_evals == 2 * S->iterations + 1 && S->dHdp_evals <= S->dHdq_evals);
    CHECK((S->dHdq_evals - S->dHdp_evals) % 2 == 0 && S->dHdq_evals - S->dHdp_evals <= 2 * S->steps);
    gauss2_free(w);

    /* Newton gives the same solution of the same stage equations */
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.solver = VIGEN_SOLVER_NEWTON;
    w = gauss2_alloc(&sys, &opt);
    double t2 = 0, q2[1] = { 1 }, p2[1] = { 0 };
    for (int k = 0; k < 100; k++) CHECK(gauss2_step(w, &t2, q2, p2, 0.1) == VIGEN_SUCCESS);
    CHECK(fabs(q2[0] - q[0]) < 1e-13 && fabs(p2[0] - p[0]) < 1e-13);
    CHECK(gauss2_stats(w)->lu_decompositions == 100 && gauss2_stats(w)->hessian_evals == 100);
    /* A-stable: h = 10 is fine for Newton, q^2 + p^2 still conserved */
    for (int k = 0; k < 10; k++) CHECK(gauss2_step(w, &t2, q2, p2, 10) == VIGEN_SUCCESS);
    CHECK(fabs(q2[0] * q2[0] + p2[0] * p2[0] - 1) < 1e-13);
    gauss2_free(w);
}

/* A huge step: the fixed-point iteration diverges and says so; the state is
 * untouched and the iteration count is reported. */
static void test_huge_step(void)
{
    vigen_hamiltonian sys = { 1, qp_dq, qp_dp, NULL, NULL, 0, NULL };
    gauss2_workspace *w = gauss2_alloc(&sys, NULL);
    double t = 0, q[1] = { 1 }, p[1] = { 0.5 };
    int st = gauss2_step(w, &t, q, p, 50);
    CHECK(st == VIGEN_ENOCONV || st == VIGEN_EMAXITER || st == VIGEN_ENONFINITE);
    CHECK(t == 0 && q[0] == 1 && p[0] == 0.5);
    CHECK(gauss2_stats(w)->last_iterations >= 1 && gauss2_stats(w)->failed_steps == 1);
    /* and a reasonable step afterwards works: H = q p, q0 e^t, p0 e^-t, q p conserved */
    for (int k = 0; k < 100; k++) CHECK(gauss2_step(w, &t, q, p, 0.01) == VIGEN_SUCCESS);
    CHECK(fabs(q[0] / exp(1.0) - 1) < 1e-9 && fabs(p[0] / (0.5 * exp(-1.0)) - 1) < 1e-9);
    CHECK(fabs(q[0] * p[0] - 0.5) < 1e-15);
    gauss2_free(w);
    CHECK(gauss2_alloc(NULL, NULL) == NULL);
    vigen_hamiltonian bad = { 0, qp_dq, qp_dp, NULL, NULL, 0, NULL };
    CHECK(gauss2_alloc(&bad, NULL) == NULL);
}

/* A gradient that turns NaN or infinite is a failed stage solve, not a
 * converged one: the step reports VIGEN_ENONFINITE and leaves the state as it
 * was, for fixed-point iteration and Newton alike.  (A maximum of the
 * increments that skipped NaN would accept such a step.) */
static double bad_value;
static void bad_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)p; (void)c;
    o[0] = t > 0.55 && bad_value != 0 ? bad_value : q[0];   /* bad_value 0: repaired */
}
static void test_nonfinite_gradient(void)
{
    const double bad[2] = { NAN, INFINITY };
    for (int b = 0; b < 2; b++)
        for (int solver = 0; solver < 2; solver++) {
            bad_value = bad[b];
            vigen_hamiltonian sys = { 1, bad_dq, ho_dp, ho_H, NULL, 1, NULL };
            vigen_solver_options o;
            vigen_solver_options_default(&o);
            o.solver = solver ? VIGEN_SOLVER_NEWTON : VIGEN_SOLVER_FIXED_POINT;
            gauss2_workspace *w = gauss2_alloc(&sys, &o);
            double t = 0, q[1] = { 1 }, p[1] = { 0 };
            int st = VIGEN_SUCCESS, k = 0;
            for (; k < 10 && st == VIGEN_SUCCESS; k++) st = gauss2_step(w, &t, q, p, 0.1);
            /* steps 1..5 end at t = 0.5; step 6 has stages beyond 0.55 */
            CHECK_MSG(st == VIGEN_ENONFINITE && k == 6, "%s gradient, %s: status %d after %d steps", b ? "inf" : "NaN",
                      solver ? "Newton" : "fixed point", st, k);
            CHECK(fabs(t - 0.5) < 1e-15 && isfinite(q[0]) && isfinite(p[0]));
            CHECK(fabs(q[0] - cos(0.5)) < 1e-6 && fabs(p[0] + sin(0.5)) < 1e-6);
            gauss2_free(w);
        }
}

/* Gauss-2 with Newton and a gradient that is NaN from the first call: the
 * finite-difference Hessian is NaN, which is VIGEN_ENONFINITE (it was
 * reported as a singular matrix). */
static void nan_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)p; (void)c;
    o[0] = NAN;
}
static void test_newton_nan_first(void)
{
    vigen_hamiltonian sys = { 1, nan_dq, ho_dp, ho_H, NULL, 0, NULL };
    vigen_solver_options o;
    vigen_solver_options_default(&o);
    o.solver = VIGEN_SOLVER_NEWTON;
    gauss2_workspace *w = gauss2_alloc(&sys, &o);
    double t = 0, q[1] = { 1 }, p[1] = { 0 };
    int st = gauss2_step(w, &t, q, p, 0.1);
    CHECK_MSG(st == VIGEN_ENONFINITE, "Newton, NaN gradient: status %d", st);
    CHECK(t == 0 && q[0] == 1 && p[0] == 0 && !signbit(p[0]));
    gauss2_free(w);
}

/* Stormer-Verlet, explicit path, hostile numbers: a NaN or infinite
 * gradient (first call, mid-run) or initial state is VIGEN_ENONFINITE, a
 * non-finite t or h or an overflowing t + h VIGEN_EINVAL, each with t, q, p
 * bit for bit as they were; a step retried after a refusal gives the bits
 * of a run that never failed.  (Before, the step returned success with a
 * NaN or infinite state, and accepted t = NaN.) */
static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }
static void test_verlet_hostile(void)
{
    for (int kahan = 0; kahan < 2; kahan++)
        for (int b = 0; b < 2; b++) {
            bad_value = b ? INFINITY : NAN;
            vigen_hamiltonian sys = { 1, bad_dq, ho_dp, ho_H, NULL, 1, NULL };
            vigen_solver_options o;
            vigen_solver_options_default(&o);
            o.kahan = kahan;
            verlet_workspace *w = verlet_alloc(&sys, &o);
            double t = 0, q[1] = { 1 }, p[1] = { 0 }, t0 = 0, q0 = 1, p0 = 0;
            int st = VIGEN_SUCCESS, k = 0;
            for (; k < 10 && st == VIGEN_SUCCESS; k++) {
                t0 = t; q0 = q[0]; p0 = p[0];
                st = verlet_step(w, &t, q, p, 0.1);
            }
            /* step 6 evaluates dH/dq at t = 0.6 after updating q */
            CHECK_MSG(st == VIGEN_ENONFINITE && k == 6, "Verlet, %s gradient: status %d at step %d", b ? "inf" : "NaN",
                      st, k);
            CHECK(same_bits(t, t0) && same_bits(q[0], q0) && same_bits(p[0], p0));
            CHECK(verlet_stats(w)->failed_steps == 1 && verlet_stats(w)->steps == 5);
            /* repaired: the retried step is the step of a run without failures */
            bad_value = 0;
            CHECK(verlet_step(w, &t, q, p, 0.1) == VIGEN_SUCCESS);
            sys.dHdq = ho_dq;
            verlet_workspace *w2 = verlet_alloc(&sys, &o);
            double t2 = 0, q2[1] = { 1 }, p2[1] = { 0 };
            for (int j = 0; j < 6; j++) CHECK(verlet_step(w2, &t2, q2, p2, 0.1) == VIGEN_SUCCESS);
            CHECK(same_bits(t, t2) && same_bits(q[0], q2[0]) && same_bits(p[0], p2[0]));
            verlet_free(w2);
            verlet_free(w);
        }

    vigen_hamiltonian sys = { 1, ho_dq, ho_dp, ho_H, NULL, 1, NULL };
    verlet_workspace *w = verlet_alloc(&sys, NULL);
    /* NaN initial q, then NaN initial p */
    for (int which = 0; which < 2; which++) {
        double t = 0, q[1] = { which ? 1 : NAN }, p[1] = { which ? NAN : 0 }, qs = q[0], ps = p[0];
        CHECK(verlet_step(w, &t, q, p, 0.1) == VIGEN_ENONFINITE);
        CHECK(t == 0 && same_bits(q[0], qs) && same_bits(p[0], ps));
    }
    /* t, h and t + h: after a good step, continuing the trajectory */
    const double hs[] = { NAN, INFINITY, -INFINITY, 0.1, 1e308 };
    const double ts[] = { 0, 0, 0, NAN, 1e308 };
    for (int c = 0; c < 5; c++) {
        double t = ts[c] == ts[c] ? ts[c] : 0, q[1] = { 1 }, p[1] = { 1 };
        verlet_reset(w);
        CHECK(verlet_step(w, &t, q, p, ts[c] == 1e308 ? 1 : 0.1) == VIGEN_SUCCESS);
        if (ts[c] != ts[c]) t = NAN;
        double tb = t, qb = q[0], pb = p[0];
        int st = verlet_step(w, &t, q, p, hs[c]);
        CHECK_MSG(st == VIGEN_EINVAL, "t = %g, h = %g: status %d", tb, hs[c], st);
        CHECK(same_bits(t, tb) && same_bits(q[0], qb) && same_bits(p[0], pb));
    }
    /* h = 1e300 from t = 0: t + h is finite, the new state is not */
    double t = 0, q[1] = { 1 }, p[1] = { 1 };
    CHECK(verlet_step(w, &t, q, p, 1e300) == VIGEN_ENONFINITE);
    CHECK(t == 0 && q[0] == 1 && p[0] == 1);
    verlet_free(w);
}

/* Stormer-Verlet, explicit path: one gradient of each kind per step (the
 * last dH/dq of a step is the first of the next), and the result equals the
 * textbook kick-drift-kick formula. */
static void test_verlet(void)
{
    vigen_hamiltonian sys = { 1, ho_dq, ho_dp, ho_H, NULL, 1, NULL };
    verlet_workspace *w = verlet_alloc(&sys, NULL);
    double t = 0, q[1] = { 1 }, p[1] = { 0 }, qr = 1, pr = 0, h = 0.1;
    for (int k = 0; k < 1000; k++) {
        CHECK(verlet_step(w, &t, q, p, h) == VIGEN_SUCCESS);
        double ph = pr - h / 2 * qr;
        qr = qr + h * ph;
        pr = ph - h / 2 * qr;
    }
    CHECK(fabs(q[0] - qr) < 1e-12 && fabs(p[0] - pr) < 1e-12);
    const vigen_stats *S = verlet_stats(w);
    CHECK(S->dHdp_evals == 1000 && S->dHdq_evals == 1001 && S->fsal_reuses == 999 && S->iterations == 0);
    verlet_free(w);
}

static unsigned long observed[16];
static int nobs;
static int observer(unsigned long step, double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)q; (void)p;
    if (nobs < 16) observed[nobs++] = step;
    return ctx != NULL && step >= 6;
}

static void test_driver(void)
{
    vigen_hamiltonian sys = { 1, ho_dq, ho_dp, ho_H, NULL, 1, NULL };
    void *w = gauss2_type.alloc(&sys, NULL);
    double t = 0, q[1] = { 1 }, p[1] = { 0 };
    unsigned long done = 0;
    nobs = 0;
    CHECK(vigen_integrate(&gauss2_type, w, &t, q, p, 0.1, 10, 3, observer, NULL, &done) == VIGEN_SUCCESS);
    CHECK(done == 10 && nobs == 5 && observed[0] == 0 && observed[1] == 3 && observed[3] == 9 && observed[4] == 10);
    nobs = 0;
    int dummy;
    CHECK(vigen_integrate(&gauss2_type, w, &t, q, p, 0.1, 10, 3, observer, &dummy, &done) == VIGEN_ESTOPPED);
    CHECK(done == 6);
    CHECK(fabs(t - 1.6) < 1e-14);
    CHECK(strcmp(gauss2_type.name, "gauss2") == 0 && gauss2_type.stages == 2 && gauss2_type.order == 4);
    gauss2_type.free(w);
}

/* Starting values only change how many sweeps a step takes, never its
 * result: on Kepler (e = 0.6, 100 steps per period, 2.5 periods) Gauss-2
 * started from the previous step's stage gradients extrapolated (the
 * default), from the gradients at the step's start (extrapolate = 0), and
 * solved by Newton, ends at the same state to round-off (bit for bit on the
 * machine this was written on); the default start needs fewer sweeps. */
static void test_start_values(void)
{
    vigen_hamiltonian sys = { 2, kep_dq, kep_dp, NULL, NULL, 1, NULL };
    vigen_solver_options o[3];
    for (int k = 0; k < 3; k++) vigen_solver_options_default(&o[k]);
    o[1].extrapolate = 0;
    o[2].solver = VIGEN_SOLVER_NEWTON;
    double qf[3][2], pf[3][2], sweeps[3];
    const double h = 2 * 3.14159265358979323846 / 100;
    for (int k = 0; k < 3; k++) {
        gauss2_workspace *w = gauss2_alloc(&sys, &o[k]);
        double t = 0, q[2] = { 0.4, 0 }, p[2] = { 0, 2 };
        for (int n = 0; n < 250; n++) CHECK(gauss2_step(w, &t, q, p, h) == VIGEN_SUCCESS);
        qf[k][0] = q[0]; qf[k][1] = q[1]; pf[k][0] = p[0]; pf[k][1] = p[1];
        sweeps[k] = (double)gauss2_stats(w)->iterations / 250;
        gauss2_free(w);
    }
    for (int k = 1; k < 3; k++) {
        double d = fabs(qf[k][0] - qf[0][0]) + fabs(qf[k][1] - qf[0][1]) + fabs(pf[k][0] - pf[0][0]) + fabs(pf[k][1] - pf[0][1]);
        CHECK_MSG(d < 1e-13, "start %d ends %g away from the default", k, d);
        printf("start %d: %g away, %.2f sweeps per step (default %.2f)\n", k, d, sweeps[k], sweeps[0]);
    }
    CHECK_MSG(sweeps[0] < sweeps[1], "sweeps per step: %g (default), %g (no extrapolation)", sweeps[0], sweeps[1]);
}

/* t accumulated over 10^6 steps of h = 0.1 with and without compensation. */
static void test_time_sum(void)
{
    vigen_hamiltonian sys = { 1, ho_dq, ho_dp, ho_H, NULL, 1, NULL };
    verlet_workspace *w = verlet_alloc(&sys, NULL);
    double t = 0, q[1] = { 1 }, p[1] = { 0 };
    for (int k = 0; k < 1000000; k++) verlet_step(w, &t, q, p, 0.1);
    /* 10^6 * double(0.1) = 100000 + 5.6e-12, which rounds to 100000 */
    CHECK_MSG(fabs(t - 100000.0) <= 0x1p-36, "compensated t = %.17g", t);
    verlet_free(w);
}

int main(void)
{
    test_status();
    test_judge();
    test_sums();
    test_newton_la();
    test_hessian_fd();
    test_gauss2_ho();
    test_huge_step();
    test_nonfinite_gradient();
    test_newton_nan_first();
    test_verlet();
    test_verlet_hostile();
    test_driver();
    test_start_values();
    test_time_sum();
    TEST_MAIN_END();
}
