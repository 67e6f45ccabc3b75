/* emit_problems.h — the two benchmark problems of bench/emit_bench.c and
 * bench/emit_icount.c, with the gradient signature of vigen_grad_fn:
 *   Kepler, H = |p|^2/2 - 1/|q| in R^2 (orbits of semi-major axis 1 and
 *     period 2 pi; the exact solution from Kepler's equation), and
 *   an FPUT-beta chain of FPUT_N particles with fixed ends,
 *     H = sum p_i^2/2 + sum_{i=0..n} V(q_{i+1} - q_i),  V(r) = r^2/2 + beta r^4/4,
 *     q_0 = q_{n+1} = 0,
 *   and the Toda lattice, the same chain with V(r) = exp(-r) + r - 1.
 * Also the analytic Jacobians of the first-order systems y = (q, p),
 * y' = (dH/dp, -dH/dq), for GSL's implicit steppers, and the gradient-time
 * instrumentation (timed_dq / timed_dp). */
#ifndef EMIT_PROBLEMS_H
#define EMIT_PROBLEMS_H

#include <math.h>
#include <string.h>
#include <time.h>

#define FPUT_N 1000
#define FPUT_BETA 1.0

/* ------------------------------------------------------------------ Kepler */
static inline void kep_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)p; (void)c;
    double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    o[0] = q[0] / r3;
    o[1] = q[1] / r3;
}
static inline void kep_dp(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = p[0];
    o[1] = p[1];
}
static inline double kep_H(double t, const double *q, const double *p, void *c)
{
    (void)t; (void)c;
    return (p[0] * p[0] + p[1] * p[1]) / 2 - 1 / sqrt(q[0] * q[0] + q[1] * q[1]);
}
/* Initial state at the pericentre of the orbit with eccentricity e. */
static inline void kep_init(double e, double *q, double *p)
{
    q[0] = 1 - e; q[1] = 0;
    p[0] = 0; p[1] = sqrt((1 + e) / (1 - e));
}
/* Exact position at time t: E - e sin E = t (mean motion 1), q = (cos E - e,
 * sqrt(1 - e^2) sin E). */
static inline void kep_exact(double e, double t, double *q)
{
    double M = fmod(t, 2 * 3.14159265358979323846), E = M + e * sin(M);
    for (int k = 0; k < 50; k++) {
        double dE = (E - e * sin(E) - M) / (1 - e * cos(E));
        E -= dE;
        if (fabs(dE) < 1e-16) break;
    }
    q[0] = cos(E) - e;
    q[1] = sqrt(1 - e * e) * sin(E);
}
/* d(q', p')/d(q, p) for q' = p, p' = -q/r^3: row-major 4 x 4. */
static inline void kep_jac(const double *y, double *J)
{
    double x = y[0], z = y[1], r2 = x * x + z * z, r = sqrt(r2), r3 = r2 * r, r5 = r3 * r2;
    memset(J, 0, 16 * sizeof(double));
    J[0 * 4 + 2] = 1;
    J[1 * 4 + 3] = 1;
    J[2 * 4 + 0] = -(1 / r3 - 3 * x * x / r5);
    J[2 * 4 + 1] = 3 * x * z / r5;
    J[3 * 4 + 0] = 3 * x * z / r5;
    J[3 * 4 + 1] = -(1 / r3 - 3 * z * z / r5);
}

/* -------------------------------------------------------------------- FPUT */
static inline void fput_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)p; (void)c;
    double left = q[0] + FPUT_BETA * q[0] * q[0] * q[0];   /* V'(q_1 - wall) */
    for (int i = 0; i < FPUT_N; i++) {
        double r = (i + 1 < FPUT_N ? q[i + 1] : 0) - q[i];
        double f = r + FPUT_BETA * r * r * r;             /* V'(q_{i+1} - q_i) */
        o[i] = left - f;
        left = f;
    }
}
static inline void fput_dp(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    memcpy(o, p, FPUT_N * sizeof(double));
}
static inline double fput_H(double t, const double *q, const double *p, void *c)
{
    (void)t; (void)c;
    double e = 0, prev = 0;
    for (int i = 0; i <= FPUT_N; i++) {
        double x = i < FPUT_N ? q[i] : 0, r = x - prev;
        e += r * r / 2 + FPUT_BETA * r * r * r * r / 4;
        if (i < FPUT_N) e += p[i] * p[i] / 2;
        prev = x;
    }
    return e;
}
/* First normal mode, energy about n/4. */
static inline void fput_init(double *q, double *p)
{
    for (int i = 0; i < FPUT_N; i++) {
        q[i] = 0;
        p[i] = sin(3.14159265358979323846 * (i + 1) / (FPUT_N + 1));
    }
}
/* Analytic Jacobian, (2n) x (2n) row-major: q' = p, p'_i = -dV/dq_i. */
static inline void fput_jac(const double *y, double *J)
{
    const size_t N = 2 * FPUT_N;
    memset(J, 0, N * N * sizeof(double));
    for (size_t i = 0; i < FPUT_N; i++) {
        J[i * N + FPUT_N + i] = 1;
        double ql = i > 0 ? y[i - 1] : 0, qr = i + 1 < FPUT_N ? y[i + 1] : 0;
        double rl = y[i] - ql, rr = qr - y[i];
        double kl = 1 + 3 * FPUT_BETA * rl * rl, kr = 1 + 3 * FPUT_BETA * rr * rr;   /* V''(r) */
        size_t row = (FPUT_N + i) * N;
        J[row + i] = -(kl + kr);
        if (i > 0) J[row + i - 1] = kl;
        if (i + 1 < FPUT_N) J[row + i + 1] = kr;
    }
}

/* -------------------------------------------------------------------- Toda */
/* The Toda lattice with the same fixed ends, V(r) = exp(-r) + r - 1: one
 * exponential per bond, a gradient some ten times dearer than FPUT's for the
 * same vector work in the stepper (the gradient-share comparison). */
static inline void toda_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)p; (void)c;
    double left = 1 - exp(-q[0]);                            /* V'(q_1 - wall) */
    for (int i = 0; i < FPUT_N; i++) {
        double r = (i + 1 < FPUT_N ? q[i + 1] : 0) - q[i];
        double f = 1 - exp(-r);                               /* V'(q_{i+1} - q_i) */
        o[i] = left - f;
        left = f;
    }
}
static inline double toda_H(double t, const double *q, const double *p, void *c)
{
    (void)t; (void)c;
    double e = 0, prev = 0;
    for (int i = 0; i <= FPUT_N; i++) {
        double x = i < FPUT_N ? q[i] : 0, r = x - prev;
        e += exp(-r) + r - 1;
        if (i < FPUT_N) e += p[i] * p[i] / 2;
        prev = x;
    }
    return e;
}

/* --------------------------------------------------- gradient-time probes */
/* Callbacks that forward to probe_dq / probe_dp and add the wall time spent
 * inside them to probe_seconds (one clock read before and after each call;
 * probe_calls counts the calls so that the clock's own cost can be
 * subtracted: see probe_clock_cost). */
typedef void (*probe_grad_fn)(double t, const double *q, const double *p, double *o, void *c);
static probe_grad_fn probe_dq, probe_dp;
static double probe_seconds;
static unsigned long probe_calls;

static inline double probe_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
static inline void timed_dq(double t, const double *q, const double *p, double *o, void *c)
{
    double t0 = probe_now();
    probe_dq(t, q, p, o, c);
    probe_seconds += probe_now() - t0;
    probe_calls++;
}
static inline void timed_dp(double t, const double *q, const double *p, double *o, void *c)
{
    double t0 = probe_now();
    probe_dp(t, q, p, o, c);
    probe_seconds += probe_now() - t0;
    probe_calls++;
}
/* Seconds per clock read (the smallest of a few batches). */
static inline double probe_clock_cost(void)
{
    double best = 1;
    for (int rep = 0; rep < 5; rep++) {
        double t0 = probe_now(), x = 0;
        for (int k = 0; k < 100000; k++) x += probe_now();
        double c = (probe_now() - t0) / 100001;
        if (c < best && x > 0) best = c;
    }
    return best;
}

#endif
