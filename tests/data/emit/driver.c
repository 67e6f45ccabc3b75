/* driver.c — runs an emitted stepper on problems with known solutions and
 * prints key=value lines for tests/unit/test_emit.c.  Compiled by the test with
 *   -DSTEPPER_HEADER='"NAME.h"' -DSTEPPER_TYPE=NAME_type [-DREAL_LD]
 * together with the runtime sources.
 *
 *   driver order-ho            empirical order on q'' = -q (exact cos/sin), t <= 5
 *   driver order-kepler E      empirical order on Kepler, eccentricity E, t <= 5,
 *                              exact solution from Kepler's equation
 * Errors are maxima over the trajectory; the environment variable DRIVER_FLOOR
 * sets the error below which halving stops (round-off or coefficient error).
 *   driver longrun E N H       N steps of size H on Kepler: energy error and
 *                              angular momentum error (max, early, late)
 *   driver qp                  H = q p: q0 e^t, p0 e^-t and q p conserved
 *   driver huge-h              fixed-point iteration on q'' = -q with h = 50
 *   driver newton              simplified Newton, h = 10 on q'' = -q
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include STEPPER_HEADER

#ifdef REAL_LD
typedef long double real;
typedef vigen_hamiltonian_ld ham_t;
typedef vigen_stepper_type_ld type_t;
#define R_SIN sinl
#define R_COS cosl
#define R_SQRT sqrtl
#define R_EXP expl
#define R_FABS fabsl
#else
typedef double real;
typedef vigen_hamiltonian ham_t;
typedef vigen_stepper_type type_t;
#define R_SIN sin
#define R_COS cos
#define R_SQRT sqrt
#define R_EXP exp
#define R_FABS fabs
#endif

extern const type_t STEPPER_TYPE;
static const type_t *T = &STEPPER_TYPE;

/* ---- problems ---- */
static void ho_dq(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)p; (void)c; o[0] = q[0]; }
static void ho_dp(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }
static real ho_H(real t, const real *q, const real *p, void *c) { (void)t; (void)c; return (q[0] * q[0] + p[0] * p[0]) / 2; }

static void kep_dq(real t, const real *q, const real *p, real *o, void *c)
{
    (void)t; (void)p; (void)c;
    real r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * R_SQRT(r2);
    o[0] = q[0] / r3;
    o[1] = q[1] / r3;
}
static void kep_dp(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; o[1] = p[1]; }
static real kep_H(real t, const real *q, const real *p, void *c)
{
    (void)t; (void)c;
    return (p[0] * p[0] + p[1] * p[1]) / 2 - 1 / R_SQRT(q[0] * q[0] + q[1] * q[1]);
}

static void qp_dq(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }
static void qp_dp(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)p; (void)c; o[0] = q[0]; }

/* Exact Kepler orbit with a = 1, period 2 pi, pericentre at t = 0. */
static void kepler_exact(real e, real t, real *q, real *p)
{
    real E = t;
    for (int k = 0; k < 100; k++) {
        real d = (E - e * R_SIN(E) - t) / (1 - e * R_COS(E));
        E -= d;
        if (R_FABS(d) < 1e-30L) break;
    }
    real s = R_SQRT(1 - e * e), den = 1 - e * R_COS(E);
    q[0] = R_COS(E) - e;
    q[1] = s * R_SIN(E);
    p[0] = -R_SIN(E) / den;
    p[1] = s * R_COS(E) / den;
}

/* Maximum over all steps of the error against the exact solution exact(arg,
 * t, q, p) after n steps of size Tend / n; -1 when a step fails.  The maximum
 * over the trajectory does not vanish by accident the way the error at one
 * time can. */
static double max_error(ham_t *sys, int sep, real arg, real Tend, long n, const real *q0, const real *p0,
                        void (*exact)(real, real, real *, real *))
{
    real t = 0, q[2], p[2], qe[2], pe[2], h = Tend / n;
    size_t d = sys->dim;
    for (size_t k = 0; k < d; k++) { q[k] = q0[k]; p[k] = p0[k]; }
    sys->separable = sep;
    void *w = T->alloc(sys, NULL);
    if (!w) { printf("alloc=failed\n"); exit(1); }
    double emax = 0;
    for (long j = 1; j <= n; j++) {
        if (T->step(w, &t, q, p, h) != VIGEN_SUCCESS) { T->free(w); return -1; }
        exact(arg, j * h, qe, pe);
        real e = 0;
        for (size_t k = 0; k < d; k++) e += (q[k] - qe[k]) * (q[k] - qe[k]) + (p[k] - pe[k]) * (p[k] - pe[k]);
        if ((double)R_SQRT(e) > emax) emax = (double)R_SQRT(e);
    }
    T->free(w);
    return emax;
}

static void ho_exact(real arg, real t, real *q, real *p) { (void)arg; q[0] = R_COS(t); p[0] = -R_SIN(t); }
static void qp_exact(real arg, real t, real *q, real *p) { (void)arg; q[0] = R_EXP(t); p[0] = 2 * R_EXP(-t); }

static double err_ho(real arg, long n, int sep)
{
    ham_t sys = { 1, ho_dq, ho_dp, ho_H, NULL, 1, NULL };
    real q0[1] = { 1 }, p0[1] = { 0 };
    return max_error(&sys, sep, arg, 5, n, q0, p0, ho_exact);
}

static double err_kepler(real e, long n, int sep)
{
    ham_t sys = { 2, kep_dq, kep_dp, kep_H, NULL, 1, NULL };
    real q0[2], p0[2];
    kepler_exact(e, 0, q0, p0);
    return max_error(&sys, sep, e, 5, n, q0, p0, kepler_exact);
}

static double err_qp(real arg, long n, int sep)
{
    ham_t sys = { 1, qp_dq, qp_dp, NULL, NULL, 0, NULL };
    real q0[1] = { 1 }, p0[1] = { 2 };
    (void)sep;
    return max_error(&sys, 0, arg, 1, n, q0, p0, qp_exact);
}

/* Observed order from successive halvings of h: starting at the first step
 * count whose error is at most 1e-3, up to seven pairs (n, 2n) while the finer
 * error stays above floor_ (round-off) and until two successive estimates
 * agree within 0.03; the last pair's estimate is printed
 * (-1 when none).  Step counts where a step fails (h too large for the
 * stage iteration) are skipped. */
static double observed_order(double (*err)(real, long, int), real arg, int sep, double floor_, double *last)
{
    double best = -1, prev = -1, e1, e2;
    int pairs = 0;
    *last = 0;
    for (long n = 4; n <= (1L << 20) && pairs < 7; n *= 2) {
        e1 = err(arg, n, sep);
        if (e1 < 0 || e1 > 1e-3) continue;
        e2 = err(arg, 2 * n, sep);
        if (e2 < 0) continue;
        if (e2 < floor_) break;
        best = log(e1 / e2) / log(2.0);
        if (getenv("DRIVER_VERBOSE")) fprintf(stderr, "n=%ld e1=%.3e e2=%.3e order=%.3f\n", n, e1, e2, best);
        *last = e2;
        pairs++;
        if (prev >= 0 && fabs(best - prev) < 0.03) break;   /* settled */
        prev = best;
    }
    return best;
}

static void order(const char *label, double (*err)(real, long, int), real arg, double floor_)
{
    for (int sep = 1; sep >= 0; sep--) {
        double last, o = observed_order(err, arg, sep, floor_, &last);
        printf("%s_order_%s=%.3f\n%s_err_%s=%.3e\n", label, sep ? "sep" : "nonsep", o, label, sep ? "sep" : "nonsep", last);
    }
}

static real angmom(const real *q, const real *p) { return q[0] * p[1] - q[1] * p[0]; }

int main(int argc, char **argv)
{
    if (argc < 2) return 2;
#ifdef REAL_LD
    double floor_ = 1e-15;
#else
    double floor_ = 1e-11;
#endif
    if (getenv("DRIVER_FLOOR")) floor_ = atof(getenv("DRIVER_FLOOR"));
    if (strcmp(argv[1], "order-ho") == 0) {
        order("ho", err_ho, 0, floor_);
    } else if (strcmp(argv[1], "order-kepler") == 0) {
        order("kepler", err_kepler, (real)atof(argv[2]), floor_);
    } else if (strcmp(argv[1], "longrun") == 0) {
        real e = (real)atof(argv[2]);
        long n = atol(argv[3]);
        real h = (real)atof(argv[4]);
        ham_t sys = { 2, kep_dq, kep_dp, kep_H, NULL, 1, NULL };
        real t = 0, q[2], p[2];
        kepler_exact(e, 0, q, p);
        real H0 = kep_H(0, q, p, NULL), L0 = angmom(q, p);
        double emax = 0, early = 0, late = 0, lmax = 0;
        void *w = T->alloc(&sys, NULL);
        int st = 0;
        for (long k = 1; k <= n && st == 0; k++) {
            st = T->step(w, &t, q, p, h);
            double de = (double)R_FABS((kep_H(t, q, p, NULL) - H0) / H0);
            double dl = (double)R_FABS((angmom(q, p) - L0) / L0);
            if (de > emax) emax = de;
            if (dl > lmax) lmax = dl;
            if (k <= n / 10 && de > early) early = de;
            if (k > n - n / 10 && de > late) late = de;
        }
        const vigen_stats *S = T->stats(w);
        printf("status=%d\nenergy_max=%.3e\nenergy_early=%.3e\nenergy_late=%.3e\nangmom_max=%.3e\n", st, emax, early,
               late, lmax);
        printf("grad_per_step=%.3f\niter_per_step=%.3f\n", (double)(S->dHdq_evals + S->dHdp_evals) / (double)S->steps,
               (double)S->iterations / (double)S->steps);
        T->free(w);
    } else if (strcmp(argv[1], "qp") == 0) {
        order("qp", err_qp, 0, floor_);
        ham_t sys = { 1, qp_dq, qp_dp, NULL, NULL, 0, NULL };
        real t = 0, q[1] = { 1 }, p[1] = { 2 };
        double inv = 0;
        void *w = T->alloc(&sys, NULL);
        int st = 0;
        for (long k = 0; k < 1000 && st == 0; k++) {
            st = T->step(w, &t, q, p, (real)0.01);
            double d = (double)R_FABS(q[0] * p[0] - 2) / 2;
            if (d > inv) inv = d;
        }
        printf("qp_status=%d\nqp_invariant=%.3e\nqp_q_relerr=%.3e\nqp_p_relerr=%.3e\n", st, inv,
               (double)R_FABS(q[0] / R_EXP(t) - 1), (double)R_FABS(p[0] / (2 * R_EXP(-t)) - 1));
        T->free(w);
    } else if (strcmp(argv[1], "huge-h") == 0) {
        /* H = q p with h = 50: the stage map has Lipschitz constant ~ h |a_ij| */
        ham_t sys = { 1, qp_dq, qp_dp, NULL, NULL, 0, NULL };
        real t = 0, q[1] = { 1 }, p[1] = { (real)0.5 };
        void *w = T->alloc(&sys, NULL);
        int st = T->step(w, &t, q, p, 50);
        const vigen_stats *S = T->stats(w);
        printf("huge_status=%d\nhuge_message=%s\nhuge_iterations=%lu\nhuge_unchanged=%d\n", st, vigen_strerror(st),
               S->last_iterations, t == 0 && q[0] == 1 && p[0] == (real)0.5);
        T->free(w);
    } else if (strcmp(argv[1], "newton") == 0) {
        /* Newton and fixed-point iteration solve the same stage equations:
         * same result to round-off at h = 0.05 on H = q p; Newton also
         * succeeds at h = 5 (fixed-point iteration diverges at h = 100), with q p
         * still conserved (a quadratic invariant of every symplectic PRK). */
        ham_t sys = { 1, qp_dq, qp_dp, NULL, NULL, 0, NULL };
        vigen_solver_options opt;
        vigen_solver_options_default(&opt);
        opt.solver = VIGEN_SOLVER_NEWTON;
        real t = 0, q[1] = { 1 }, p[1] = { (real)0.5 }, t2 = 0, q2[1] = { 1 }, p2[1] = { (real)0.5 };
        void *w = T->alloc(&sys, &opt), *w2 = T->alloc(&sys, NULL);
        int st = 0, st2 = 0;
        for (int k = 0; k < 20 && st == 0 && st2 == 0; k++) {
            st = T->step(w, &t, q, p, (real)0.05);
            st2 = T->step(w2, &t2, q2, p2, (real)0.05);
        }
        double diff = (double)(R_FABS(q[0] - q2[0]) / R_FABS(q2[0]) + R_FABS(p[0] - p2[0]) / R_FABS(p2[0]));
        printf("newton_status=%d\nnewton_vs_fp=%.3e\nnewton_iter_per_step=%.2f\n", st ? st : st2, diff,
               (double)T->stats(w)->iterations / (double)T->stats(w)->steps);
        T->free(w);
        t = 0; q[0] = 1; p[0] = (real)0.5;
        w = T->alloc(&sys, &opt);
        double inv = 0;
        for (int k = 0; k < 3 && st == 0; k++) {
            st = T->step(w, &t, q, p, 5);
            double d = (double)R_FABS(q[0] * p[0] / (real)0.5 - 1);
            if (d > inv) inv = d;
        }
        printf("newton_stiff_status=%d\nnewton_stiff_invariant=%.3e\n", st, inv);
        /* fixed-point iteration contracts only when h rho(A) L < 1: at h = 5 it
         * still converges for many-stage Gauss methods (rho(A) ~ 1/(4s)), so
         * show its divergence at h = 100, beyond every shipped tableau */
        st2 = T->step(w2, &t2, q2, p2, 100);
        printf("fp_stiff_status=%d\n", st2);
        T->free(w);
        T->free(w2);
    } else {
        return 2;
    }
    return 0;
}
