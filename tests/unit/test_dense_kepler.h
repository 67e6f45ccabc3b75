/* test_dense_kepler.h — what the tests of output at any time and of events
 * share: the Kepler problem H = |p|^2 / 2 - 1 / |q| (semi-major axis 1,
 * period 2 pi) started at periapsis, its exact solution from Kepler's
 * equation, and a stepper type for long double and __float128 written here
 * (Yoshida's triple jump of the Stormer-Verlet step, order 4) with the
 * dimension and vector field the drivers take from a type
 * (KEPLER_DOUBLE_ONLY defined: the double problem only).
 *
 * Exact solution (Goldstein, Classical Mechanics, sec. 3.8): with the mean
 * anomaly M = t (mean motion 1) and E - e sin E = M solved by Newton,
 *     q = (cos E - e, sqrt(1 - e^2) sin E),
 *     p = (-sin E, sqrt(1 - e^2) cos E) / (1 - e cos E). */
#ifndef VIGEN_TEST_DENSE_KEPLER_H
#define VIGEN_TEST_DENSE_KEPLER_H

#include <math.h>
#include <stdlib.h>
#include <vigen/runtime.h>

#define KEPLER_PI 3.14159265358979323846264338327950288L

/* The problem and its solution in the real type R (suffix S); SQRT, SIN,
 * COS, FLOOR of at least long double precision. */
#define KEPLER_DEFINE(R, S, SQRT, SIN, COS, FLOOR)                                       \
    static inline void kepler_dHdq##S(R t, const R *q, const R *p, R *out, void *ctx)    \
    {                                                                                    \
        (void)t; (void)p; (void)ctx;                                                     \
        const R r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * (R)SQRT(r2);                   \
        out[0] = q[0] / r3;                                                              \
        out[1] = q[1] / r3;                                                              \
    }                                                                                    \
    static inline void kepler_dHdp##S(R t, const R *q, const R *p, R *out, void *ctx)    \
    {                                                                                    \
        (void)t; (void)q; (void)ctx;                                                     \
        out[0] = p[0];                                                                   \
        out[1] = p[1];                                                                   \
    }                                                                                    \
    static inline R kepler_H##S(R t, const R *q, const R *p, void *ctx)                  \
    {                                                                                    \
        (void)t; (void)ctx;                                                              \
        return (p[0] * p[0] + p[1] * p[1]) / 2 - 1 / (R)SQRT(q[0] * q[0] + q[1] * q[1]); \
    }                                                                                    \
    static inline void kepler_start##S(R e, R *q, R *p)                                  \
    {                                                                                    \
        q[0] = 1 - e;                                                                    \
        q[1] = 0;                                                                        \
        p[0] = 0;                                                                        \
        p[1] = (R)SQRT((1 + e) / (1 - e));                                               \
    }                                                                                    \
    static inline void kepler_exact##S(R e, R t, R *q, R *p)                             \
    {                                                                                    \
        const R twopi = 2 * (R)KEPLER_PI;                                                \
        const R M = t - twopi * (R)FLOOR(t / twopi);                                     \
        R E = e > (R)0.8 ? (R)KEPLER_PI : M;                                             \
        for (int it = 0; it < 100; it++) {                                               \
            const R dE = (E - e * (R)SIN(E) - M) / (1 - e * (R)COS(E));                  \
            E -= dE;                                                                     \
            if (dE == 0 || (it > 10 && (dE < 0 ? -dE : dE) < (R)1e-30)) break;           \
        }                                                                                \
        const R c = (R)COS(E), s = (R)SIN(E), b = (R)SQRT(1 - e * e), den = 1 - e * c;   \
        q[0] = c - e;                                                                    \
        q[1] = b * s;                                                                    \
        p[0] = -s / den;                                                                 \
        p[1] = b * c / den;                                                              \
    }

/* Yoshida's triple jump of kick-drift-kick Verlet for separable H in the
 * real type R: a stepper type of one's own, with the flow for the drivers. */
#define YOSHIDA_DEFINE(R, S, CBRT)                                                                         \
    typedef struct {                                                                                       \
        vigen_hamiltonian##S sys;                                                                          \
        vigen_stats stats;                                                                                 \
        R g[2];                                                                                            \
    } yoshida_ws##S;                                                                                       \
    static inline void *yoshida_alloc##S(const vigen_hamiltonian##S *sys, const vigen_solver_options *opt) \
    {                                                                                                      \
        (void)opt;                                                                                         \
        if (sys->dim != 2) return NULL;                                                                    \
        yoshida_ws##S *w = calloc(1, sizeof *w);                                                           \
        if (w) w->sys = *sys;                                                                              \
        return w;                                                                                          \
    }                                                                                                      \
    static inline int yoshida_step##S(void *ws, R *t, R *q, R *p, R h)                                     \
    {                                                                                                      \
        yoshida_ws##S *w = ws;                                                                             \
        const R c = (R)CBRT(2.0L), w1 = 1 / (2 - c), sub[3] = { w1, -c * w1, w1 };                         \
        for (int k = 0; k < 3; k++) {                                                                      \
            const R hk = sub[k] * h;                                                                       \
            w->sys.dHdq(*t, q, p, w->g, w->sys.ctx);                                                       \
            for (int i = 0; i < 2; i++) p[i] -= hk / 2 * w->g[i];                                          \
            w->sys.dHdp(*t, q, p, w->g, w->sys.ctx);                                                       \
            for (int i = 0; i < 2; i++) q[i] += hk * w->g[i];                                              \
            w->sys.dHdq(*t, q, p, w->g, w->sys.ctx);                                                       \
            for (int i = 0; i < 2; i++) p[i] -= hk / 2 * w->g[i];                                          \
        }                                                                                                  \
        *t += h;                                                                                           \
        w->stats.steps++;                                                                                  \
        w->stats.dHdq_evals += 6;                                                                          \
        w->stats.dHdp_evals += 3;                                                                          \
        return VIGEN_SUCCESS;                                                                              \
    }                                                                                                      \
    static inline void yoshida_reset##S(void *w) { (void)w; }                                              \
    static inline const vigen_stats *yoshida_stats##S(const void *w)                                       \
    {                                                                                                      \
        return &((const yoshida_ws##S *)w)->stats;                                                         \
    }                                                                                                      \
    static inline void yoshida_free##S(void *w) { free(w); }                                               \
    static inline size_t yoshida_dim##S(const void *w) { return ((const yoshida_ws##S *)w)->sys.dim; }     \
    static inline int yoshida_field##S(void *ws, R t, const R *q, const R *p, R *dq, R *dp)                \
    {                                                                                                      \
        yoshida_ws##S *w = ws;                                                                             \
        w->sys.dHdp(t, q, p, dq, w->sys.ctx);                                                              \
        w->sys.dHdq(t, q, p, dp, w->sys.ctx);                                                              \
        for (int i = 0; i < 2; i++) dp[i] = -dp[i];                                                        \
        return VIGEN_SUCCESS;                                                                              \
    }                                                                                                      \
    static const vigen_stepper_type##S yoshida_type##S = {                                                 \
        .name = "yoshida4", .stages = 3, .order = 4, .explicit_separable = 1,                              \
        .alloc = yoshida_alloc##S, .step = yoshida_step##S, .reset = yoshida_reset##S,                     \
        .stats = yoshida_stats##S, .free = yoshida_free##S,                                                \
        .dim = yoshida_dim##S, .vector_field = yoshida_field##S,                                           \
    };

KEPLER_DEFINE(double, , sqrt, sin, cos, floor)
#ifndef KEPLER_DOUBLE_ONLY
KEPLER_DEFINE(long double, _ld, sqrtl, sinl, cosl, floorl)
YOSHIDA_DEFINE(long double, _ld, cbrtl)
#ifdef VIGEN_HAVE_FLOAT128
/* long double functions: 1e-19 relative, far below the errors tested */
KEPLER_DEFINE(vigen_float128, _q, sqrtl, sinl, cosl, floorl)
YOSHIDA_DEFINE(vigen_float128, _q, cbrtl)
#endif
#endif

/* The Kepler problem in double as the stepper sees it. */
static inline vigen_hamiltonian kepler_problem(void)
{
    vigen_hamiltonian sys = { 2, kepler_dHdq, kepler_dHdp, kepler_H, NULL, 1, NULL };
    return sys;
}

#endif
