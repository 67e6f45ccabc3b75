/* test_nbody_bracket.c — the flow "interaction_gradient" of the Jacobi
 * splitting (vigen/nbody.h): the kick of Phi = sum_i |dB/dq_i|^2 / m'_i
 * (B = H_interaction) against an independent truth, central differences of
 * Phi (Richardson-extrapolated, at several steps) with dB/dq taken from the
 * interaction kick (itself checked against differences of H in
 * test_nbody) and the Jacobi masses m'_i = m_i M_{i-1}/M_i written here from
 * their formula; Phi's symmetries (rotations: the flow keeps the angular
 * momentum sum q_i x p_i; translations: p_0 and the q_0 row zero);
 * reversibility in the time; the identity when B = 0 (two
 * bodies, the kepler problem); bad input refused with the state
 * unchanged. */
#include <float.h>
#include <math.h>
#include <string.h>
#include <vigen/nbody.h>
#include <vigen/problems.h>
#include "testlib.h"

enum { NB = 40, DB = 3 * NB };

typedef struct {
    vigen_nbody *sys;
    size_t n;
    double mred[NB];
} system_t;

static void system_init(system_t *s, size_t n, double G, const double *m)
{
    CHECK(vigen_nbody_alloc(&s->sys, n, G, m) == VIGEN_SUCCESS);
    s->n = n;
    double M = m[0];
    for (size_t i = 1; i < n; i++) {
        s->mred[i] = m[i] * M / (M + m[i]);
        M += m[i];
    }
}

/* Phi(q) from the interaction kick: from p = 0 by time 1, p = -dB/dq. */
static double phi(const system_t *s, const double *q)
{
    double qc[DB], g[DB] = { 0 }, sum = 0;
    memcpy(qc, q, 3 * s->n * sizeof *q);
    CHECK(vigen_nbody_jacobi_interaction(0, 1, qc, g, s->sys) == VIGEN_SUCCESS);
    for (size_t i = 1; i < s->n; i++) {
        const double *gi = g + 3 * i;
        sum += (gi[0] * gi[0] + gi[1] * gi[1] + gi[2] * gi[2]) / s->mred[i];
    }
    return sum;
}

/* dPhi/dq_k: central differences at steps d and d/2, Richardson (error
 * O(d^4)). */
static double phi_derivative(const system_t *s, double *q, int k, double d)
{
    double qk = q[k], D[2];
    for (int j = 0; j < 2; j++) {
        double e = j ? d / 2 : d;
        q[k] = qk + e;
        double fp = phi(s, q);
        q[k] = qk - e;
        double fm = phi(s, q);
        D[j] = (fp - fm) / (2 * e);
    }
    q[k] = qk;
    return (4 * D[1] - D[0]) / 3;
}

/* The flow by tau from (q, 0) (so that p holds the change alone) against
 * -tau dPhi/dq by differences (steps 1e-3 and 1e-3/3 of the size of the
 * coordinate), at every `stride`-th component, relative to the largest
 * component: within tol. */
static void check_gradient(const system_t *s, double *q, double tau, int stride, double tol, const char *what)
{
    size_t d = 3 * s->n;
    double q1[DB], p1[DB] = { 0 }, p[DB] = { 0 }, big = 0, worst[2] = { 0, 0 };
    memcpy(q1, q, d * sizeof *q);
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, tau, q1, p1, s->sys) == VIGEN_SUCCESS);
    CHECK(memcmp(q1, q, d * sizeof *q) == 0);
    CHECK(p1[0] == p[0] && p1[1] == p[1] && p1[2] == p[2]);
    for (size_t k = 0; k < d; k++) big = fmax(big, fabs((p1[k] - p[k]) / tau));
    CHECK_MSG(big > 0, "%s: the flow moved nothing", what);
    for (size_t k = 0; k < d; k += (size_t)stride) {
        double flow = -(p1[k] - p[k]) / tau, scale = 1e-3 * (fabs(q[k]) + 1e-3);
        for (int j = 0; j < 2; j++) {
            double err = fabs(phi_derivative(s, q, (int)k, j ? scale / 3 : scale) - flow) / big;
            worst[j] = fmax(worst[j], err);
        }
    }
    CHECK_MSG(worst[0] <= tol && worst[1] <= tol, "%s: the flow against differences of Phi: %.3g, %.3g", what,
              worst[0], worst[1]);
    printf("%s: flow against differences of Phi %.2g, %.2g (of the largest component %.3g)\n", what, worst[0],
           worst[1], big);
}

/* sum q_i x p_i after the flow by tau from (q, 0), relative to
 * sum |q_i| |p_i|: zero to round-off (Phi is invariant under rotations). */
static void check_angular_momentum(const system_t *s, const double *q, double tau, const char *what)
{
    size_t d = 3 * s->n;
    double q1[DB], p1[DB] = { 0 }, L[3] = { 0 }, scale = 0;
    memcpy(q1, q, d * sizeof *q);
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, tau, q1, p1, s->sys) == VIGEN_SUCCESS);
    for (size_t i = 0; i < s->n; i++) {
        const double *a = q + 3 * i, *c = p1 + 3 * i;
        L[0] += a[1] * c[2] - a[2] * c[1];
        L[1] += a[2] * c[0] - a[0] * c[2];
        L[2] += a[0] * c[1] - a[1] * c[0];
        scale += sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    double dL = fabs(L[0]) + fabs(L[1]) + fabs(L[2]);
    CHECK_MSG(scale > 0 && dL <= 1e-12 * scale, "%s: angular momentum changed by %.3g of %.3g", what, dL, scale);
}

/* By tau and back by -tau: the start to round-off. */
static void check_reversible(const system_t *s, const double *q, const double *p, double tau)
{
    size_t d = 3 * s->n;
    double qa[DB], pa[DB], back = 0, big = 0;
    memcpy(qa, q, d * sizeof *q);
    memcpy(pa, p, d * sizeof *p);
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, tau, qa, pa, s->sys) == VIGEN_SUCCESS);
    for (size_t k = 0; k < d; k++) big = fmax(big, fabs(pa[k] - p[k]));
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, -tau, qa, pa, s->sys) == VIGEN_SUCCESS);
    for (size_t k = 0; k < d; k++) back = fmax(back, fabs(pa[k] - p[k]) / (fabs(p[k]) + big));
    CHECK_MSG(big > 0 && back <= 8 * DBL_EPSILON, "by tau and back: %.3g", back);
}

/* The outer solar system (Sun + 5, masses of Hairer, Lubich and Wanner) and
 * a system of four comparable masses in 3-D. */
static void systems(void)
{
    vigen_problem *pb = NULL;
    CHECK(vigen_problem_create(&pb, "outer-solar-system", NULL, NULL, 0) == VIGEN_SUCCESS);
    static const double mass[6] = { 1.00000597682, 0.000954786104043, 0.000285583733151,
                                    0.0000437273164546, 0.0000517759138449, 1 / 1.3e8 };
    system_t s;
    double t, x[DB], p[DB], q[DB], pj[DB];
    vigen_problem_initial(pb, &t, x, p);
    system_init(&s, 6, 2.95912208286e-4, mass);
    vigen_nbody_to_jacobi(s.sys, x, p, q, pj);
    check_gradient(&s, q, 1e6, 1, 5e-7, "outer solar system");
    check_angular_momentum(&s, q, 1e9, "outer solar system");
    check_reversible(&s, q, pj, 1e8);
    vigen_nbody_free(s.sys);
    vigen_problem_free(pb);

    static const double m4[4] = { 1, 0.3, 0.2, 0.1 };
    static const double x4[12] = { 0.1, -0.2, 0.05, 1.1, 0.3, -0.2, -0.4, 2.2, 0.3, 3.1, -1.7, -0.6 };
    double p4[12] = { 0.01, 0.02, -0.01, -0.1, 0.3, 0.02, -0.2, -0.05, 0.04, 0.03, 0.05, -0.02 };
    system_init(&s, 4, 1.3, m4);
    vigen_nbody_to_jacobi(s.sys, x4, p4, q, pj);
    check_gradient(&s, q, 0.01, 1, 1e-9, "four bodies");
    check_angular_momentum(&s, q, 0.5, "four bodies");
    check_reversible(&s, q, pj, 0.01);
    vigen_nbody_free(s.sys);
}

/* 40 bodies: the scratch in the system's memory (above 32 on the stack);
 * planets of 1e-4..3e-4 on a spiral, the star at the origin (the kick
 * depends on q alone, so no momenta are needed). */
static void many_bodies(void)
{
    double m[NB], q[DB];
    m[0] = 1;
    for (int c = 0; c < 3; c++) q[c] = 0;
    for (int i = 1; i < NB; i++) {
        double r = 0.8 + 0.41 * i, ang = 1.7 * i;
        m[i] = 1e-4 * (1 + i % 3);
        q[3 * i] = r * cos(ang);
        q[3 * i + 1] = r * sin(ang);
        q[3 * i + 2] = 0.02 * (i % 4) - 0.03;
    }
    system_t s;
    system_init(&s, NB, 1, m);
    double p[DB] = { 0 };
    CHECK(vigen_nbody_to_jacobi(s.sys, q, p, q, p) == VIGEN_SUCCESS);
    /* Phi of 40 bodies carries the round-off of B's gradient, where the
     * Jacobi terms and the pair forces cancel: its differences are
     * coarser */
    check_gradient(&s, q, 1, 7, 1e-6, "40 bodies");
    check_angular_momentum(&s, q, 1, "40 bodies");
    vigen_nbody_free(s.sys);
}

/* B = 0: two bodies (the Jacobi term cancels the one pair) and the kepler
 * problem leave the state as it is. */
static void identity(void)
{
    static const double m2[2] = { 1, 0.5 };
    system_t s;
    system_init(&s, 2, 1, m2);
    double q[6] = { 0.1, 0.2, 0.3, 1, -0.5, 0.2 }, p[6] = { 0.3, 0.1, 0, 0.2, 0.7, -0.1 }, q0[6], p0[6];
    memcpy(q0, q, sizeof q);
    memcpy(p0, p, sizeof p);
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, 3.5, q, p, s.sys) == VIGEN_SUCCESS);
    CHECK(memcmp(q, q0, sizeof q) == 0 && memcmp(p, p0, sizeof p) == 0);
    vigen_nbody_free(s.sys);

    vigen_problem *pb = NULL;
    CHECK(vigen_problem_create(&pb, "kepler", NULL, NULL, 0) == VIGEN_SUCCESS);
    vigen_split_problem sp;
    char why[200];
    CHECK(vigen_problem_split(pb, NULL, &sp, why, sizeof why) == VIGEN_SUCCESS && sp.nflows == 3);
    CHECK(strcmp(vigen_problem_split_flow_name(pb, 2), "interaction_gradient") == 0);
    double t, qk[2], pk[2], qk0[2], pk0[2];
    vigen_problem_initial(pb, &t, qk, pk);
    memcpy(qk0, qk, sizeof qk);
    memcpy(pk0, pk, sizeof pk);
    CHECK(sp.flow[2](t, -0.7, qk, pk, sp.ctx) == VIGEN_SUCCESS);
    CHECK(memcmp(qk, qk0, sizeof qk) == 0 && memcmp(pk, pk0, sizeof pk) == 0);
    vigen_problem_free(pb);
}

static void names_and_bad_input(void)
{
    CHECK(strcmp(vigen_nbody_flow_name(VIGEN_NBODY_JACOBI, 2), "interaction_gradient") == 0);
    CHECK(vigen_nbody_flow_name(VIGEN_NBODY_JACOBI, 3) == NULL);
    CHECK(strcmp(vigen_nbody_flow_name(VIGEN_NBODY_DEMOCRATIC, 2), "jump") == 0);
    static const double m3[3] = { 1, 1e-3, 2e-3 };
    system_t s;
    system_init(&s, 3, 1, m3);
    vigen_split_problem sp;
    CHECK(vigen_nbody_split(s.sys, VIGEN_NBODY_JACOBI, &sp) == VIGEN_SUCCESS);
    CHECK(sp.nflows == 3 && sp.flow[2] == vigen_nbody_jacobi_interaction_gradient);
    double q[9] = { 0, 0, 0, 1, 0, 0, 0, 2, 0 }, p[9] = { 0, 0, 0, 0, 1e-3, 0, -1e-3, 0, 0 }, q0[9], p0[9];
    memcpy(q0, q, sizeof q);
    memcpy(p0, p, sizeof p);
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, NAN, q, p, s.sys) == VIGEN_EINVAL);
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, 1, q, p, NULL) == VIGEN_EINVAL);
    CHECK(memcmp(q, q0, sizeof q) == 0 && memcmp(p, p0, sizeof p) == 0);
    /* a position not finite */
    q[7] = INFINITY;
    double q1[9];
    memcpy(q1, q, sizeof q);
    CHECK(vigen_nbody_jacobi_interaction_gradient(0, 1, q, p, s.sys) == VIGEN_ENONFINITE);
    CHECK(memcmp(q, q1, sizeof q) == 0 && memcmp(p, p0, sizeof p) == 0);
    vigen_nbody_free(s.sys);
}

int main(void)
{
    systems();
    many_bodies();
    identity();
    names_and_bad_input();
    if (testlib_failures) fprintf(stderr, "%d check(s) failed\n", testlib_failures);
    return testlib_failures ? 1 : 0;
}
