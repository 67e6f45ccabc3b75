/* hires_driver.c — runs a Gauss-2 stepper emitted with --real long-double
 * (-DREAL_LD) or --real float128 (-DREAL_Q) on the harmonic oscillator
 *
 *   H = (p^2 + q^2) / 2,  q(0) = 1, p(0) = 0:  q(t) = cos t, p(t) = -sin t,
 *
 * computing everything in the stepper's type, and prints key=value lines for
 * tests/unit/test_emit_precision.c.  Built with
 *   -DSTEPPER_HEADER='"NAME.h"' -DSTEPPER_TYPE=NAME_type -DREAL_LD|-DREAL_Q
 * and the runtime.  No libquadmath: cos and sin in __float128 come from
 * their Taylor series (below), checked here against cosl/sinl.
 *
 *   hires_driver order T N0 K   errors |(q, p)(T) - (cos T, -sin T)| after
 *                               N = N0 2^k steps of h = T/N, k = 0..K:
 *                               err_<k>=...
 *   hires_driver onestep H      one step of size H from (1, 0) against the
 *                               exact one-step map of Gauss-2 (below), and
 *                               against two hand-written Gauss-2 steps: one
 *                               with the coefficients computed in the type,
 *                               one with them rounded to the next narrower
 *                               type (double for long double, long double
 *                               for float128)
 *
 * The exact one-step map: on y' = J y the Gauss method with s stages is
 * y1 = R(hJ) y0 with R the (s, s) Pade approximant of exp (Hairer & Wanner
 * II, Thm IV.3.10; Ehle 1969); for s = 2, R(z) = (1 + z/2 + z^2/12) /
 * (1 - z/2 + z^2/12).  With y = q + i p the oscillator is y' = -i y, so
 * y1 = R(-ih) y0 = (a - ib)/(a + ib) y0 with a = 1 - h^2/12, b = h/2, and from
 * y0 = 1:  q1 = (a^2 - b^2)/(a^2 + b^2),  p1 = -2ab/(a^2 + b^2).  This uses no
 * coefficient of the tableau. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include STEPPER_HEADER

#if defined(REAL_LD)
typedef long double real;
typedef double narrower;                 /* coefficients one type down */
typedef vigen_hamiltonian_ld ham_t;
typedef vigen_stepper_type_ld type_t;
#define EPSILON vigen_epsilon_ld
#elif defined(REAL_Q)
typedef vigen_float128 real;
typedef long double narrower;
typedef vigen_hamiltonian_q ham_t;
typedef vigen_stepper_type_q type_t;
#define EPSILON vigen_epsilon_q
#else
#error "define REAL_LD or REAL_Q"
#endif

extern const type_t STEPPER_TYPE;
static const type_t *T = &STEPPER_TYPE;

static void ho_dq(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)p; (void)c; o[0] = q[0]; }
static void ho_dp(real t, const real *q, const real *p, real *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }
static real ho_H(real t, const real *q, const real *p, void *c) { (void)t; (void)c; return (q[0] * q[0] + p[0] * p[0]) / 2; }

static real rabs(real x) { return x < 0 ? -x : x; }

/* cos x and sin x for |x| <= 2 by their Taylor series, summed until the terms
 * vanish in the type: the first omitted term is below 2^k/k! < 1e-40 at
 * k = 40, so the error is round-off (a few units in the last place). */
static void taylor_cos_sin(real x, real *c, real *s)
{
    real term = 1, cs = 1, sn = 0;
    for (int k = 1; k <= 60; k++) {
        term = term * x / k;
        switch (k % 4) {
        case 1: sn += term; break;
        case 2: cs -= term; break;
        case 3: sn -= term; break;
        default: cs += term; break;
        }
    }
    *c = cs;
    *s = sn;
}

static void exact(real t, real *q, real *p)
{
#if defined(REAL_LD)
    *q = cosl(t);
    *p = -sinl(t);
#else
    real c, s;
    taylor_cos_sin(t, &c, &s);
    *q = c;
    *p = -s;
#endif
}

/* sqrt(3) in the type: Newton's iteration from the long double root doubles
 * the 64 correct bits, enough for 113. */
static real sqrt3(void)
{
    real x = (real)sqrtl(3.0L);
    for (int k = 0; k < 3; k++) x = x - (x * x - 3) / (2 * x);
    return x;
}

/* One Gauss-2 step on the oscillator with coefficients a (2x2) and b,
 * written out independently of the emitted code: the stage equations
 * Q_i = q + h sum_j a_ij P_j, P_i = p - h sum_j a_ij Q_j are linear; they are
 * iterated to their fixed point (the map contracts by h rho(A) = h/sqrt(12)). */
static void hand_step(real a[2][2], const real b[2], real h, real *q, real *p)
{
    real Q[2] = { *q, *q }, P[2] = { *p, *p };
    for (int it = 0; it < 400; it++) {
        real nQ[2], nP[2];
        for (int i = 0; i < 2; i++) {
            nQ[i] = *q + h * (a[i][0] * P[0] + a[i][1] * P[1]);
            nP[i] = *p - h * (a[i][0] * Q[0] + a[i][1] * Q[1]);
        }
        memcpy(Q, nQ, sizeof Q);
        memcpy(P, nP, sizeof P);
    }
    real q1 = *q + h * (b[0] * P[0] + b[1] * P[1]);
    real p1 = *p - h * (b[0] * Q[0] + b[1] * Q[1]);
    *q = q1;
    *p = p1;
}

static void gauss2_coefficients(real a[2][2], real b[2], int narrow)
{
    real r = sqrt3() / 6;
    a[0][0] = (real)1 / 4;
    a[0][1] = (real)1 / 4 - r;
    a[1][0] = (real)1 / 4 + r;
    a[1][1] = (real)1 / 4;
    b[0] = b[1] = (real)1 / 2;
    if (narrow)
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++) a[i][j] = (real)(narrower)a[i][j];
}

/* Distance of (q, p) from (qe, pe), as a double (the values printed are far
 * above the smallest double). */
static double dist(real q, real p, real qe, real pe)
{
    real dq = q - qe, dp = p - pe;
    return sqrt((double)(dq * dq + dp * dp));
}

int main(int argc, char **argv)
{
    if (argc < 2) return 2;
    ham_t sys = { 1, ho_dq, ho_dp, ho_H, NULL, 1, NULL };
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.max_iter = 400;   /* h = 1 needs about 113 / log2(sqrt(12)) = 63 sweeps in __float128 */
    if (strcmp(argv[1], "order") == 0 && argc == 5) {
        real Tend = (real)strtold(argv[2], NULL);
        long n0 = atol(argv[3]);
        int K = atoi(argv[4]);
        for (int k = 0; k <= K; k++) {
            long n = n0 << k;
            real t = 0, q[1] = { 1 }, p[1] = { 0 }, h = Tend / n, qe, pe;
            void *w = T->alloc(&sys, &opt);
            if (w == NULL) { printf("alloc=failed\n"); return 1; }
            int st = 0;
            for (long j = 0; j < n && st == 0; j++) st = T->step(w, &t, q, p, h);
            const vigen_stats *S = T->stats(w);
            exact(Tend, &qe, &pe);
            printf("status_%d=%d\nerr_%d=%.6e\nsweeps_%d=%.3f\n", k, st, k, dist(q[0], p[0], qe, pe), k,
                   (double)S->iterations / (double)(S->steps ? S->steps : 1));
            /* t is the sum of the n steps: exact to round-off of the type */
            printf("tdiff_%d=%.3e\n", k, (double)rabs(t - Tend));
            T->free(w);
        }
    } else if (strcmp(argv[1], "onestep") == 0 && argc == 3) {
        real h = (real)strtold(argv[2], NULL);
        real a2 = (1 - h * h / 12) * (1 - h * h / 12), b2 = h * h / 4, ab = (1 - h * h / 12) * (h / 2);
        real q1 = (a2 - b2) / (a2 + b2), p1 = -2 * ab / (a2 + b2);
        real t = 0, q[1] = { 1 }, p[1] = { 0 };
        void *w = T->alloc(&sys, &opt);
        if (w == NULL) { printf("alloc=failed\n"); return 1; }
        int st = T->step(w, &t, q, p, h);
        printf("onestep_status=%d\nonestep_sweeps=%lu\n", st, T->stats(w)->last_iterations);
        printf("onestep_emitted=%.6e\n", dist(q[0], p[0], q1, p1));
        T->free(w);
        real a[2][2], b[2];
        for (int narrow = 0; narrow <= 1; narrow++) {
            gauss2_coefficients(a, b, narrow);
            real hq = 1, hp = 0;
            hand_step(a, b, h, &hq, &hp);
            printf("%s=%.6e\n", narrow ? "onestep_hand_narrow" : "onestep_hand", dist(hq, hp, q1, p1));
        }
        /* the Taylor series of cos and sin against the C library in long double */
        double worst = 0;
        for (int k = -20; k <= 20; k++) {
            real x = (real)k / 10, c, s;
            taylor_cos_sin(x, &c, &s);
            double d = (double)(rabs(c - (real)cosl((long double)x)) + rabs(s - (real)sinl((long double)x)));
            if (d > worst) worst = d;
        }
        printf("taylor_vs_libm=%.3e\n", worst);
        printf("epsilon=%.17g\n", EPSILON());
    } else {
        return 2;
    }
    return 0;
}
