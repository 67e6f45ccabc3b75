/* test_nbody.c — the N-body splittings of the runtime (vigen/nbody.h):
 * changes of coordinates exact to round-off and canonical (J^T Omega J =
 * Omega of the linear maps, column by column); the vector field of the
 * whole H against differences of H; the interaction kick against
 * differences of H - H_kepler (H_kepler written here from its formula);
 * a two-body problem stepped by Wisdom-Holman exact at any step; the energy
 * error of Wisdom-Holman on the outer solar system falling as h^2 and the
 * corrected kernel's far smaller, in Jacobi and democratic heliocentric
 * coordinates; bad input refused with the state unchanged; the Kepler
 * splittings of the problem collection.
 *
 * The Wisdom-Holman step here is a plain composition of the flows
 * (kick h/2, drift h, kick h/2), written for these tests only. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/nbody.h>
#include <vigen/problems.h>
#include "testlib.h"

enum { NMAX = 6, DMAX = 3 * NMAX };

/* The outer solar system of the problem collection. */
static vigen_problem *oss(double *q, double *p, double *E0)
{
    vigen_problem *pb = NULL;
    CHECK(vigen_problem_create(&pb, "outer-solar-system", NULL, NULL, 0) == VIGEN_SUCCESS);
    double t;
    vigen_problem_initial(pb, &t, q, p);
    *E0 = vigen_problem_energy(pb, t, q, p);
    return pb;
}

/* HLW masses (independent of the problem file's table). */
static const double oss_mass[NMAX] = { 1.00000597682, 0.000954786104043, 0.000285583733151,
                                       0.0000437273164546, 0.0000517759138449, 1 / 1.3e8 };
static const double oss_G = 2.95912208286e-4;

static double maxdiff(const double *a, const double *b, size_t n, double *scale)
{
    double d = 0, s = 0;
    for (size_t i = 0; i < n; i++) {
        if (fabs(a[i] - b[i]) > d) d = fabs(a[i] - b[i]);
        if (fabs(b[i]) > s) s = fabs(b[i]);
    }
    if (scale) *scale = s;
    return d;
}

static void round_trips(void)
{
    double x[DMAX], p[DMAX], q[DMAX], pc[DMAX], x2[DMAX], p2[DMAX], E0;
    vigen_problem *pb = oss(x, p, &E0);
    vigen_nbody *sys;
    CHECK(vigen_nbody_alloc(&sys, NMAX, oss_G, oss_mass) == VIGEN_SUCCESS);
    /* give the Sun a velocity, so that no momentum is zero */
    p[0] = 1e-5; p[1] = -2e-5; p[2] = 3e-6;
    for (int coords = 0; coords < 2; coords++) {
        double sx, sp;
        CHECK(vigen_nbody_to_coordinates(sys, coords, x, p, q, pc) == VIGEN_SUCCESS);
        CHECK(vigen_nbody_from_coordinates(sys, coords, q, pc, x2, p2) == VIGEN_SUCCESS);
        double dx = maxdiff(x2, x, DMAX, &sx), dp = maxdiff(p2, p, DMAX, &sp);
        CHECK_MSG(dx <= 8 * DBL_EPSILON * sx && dp <= 8 * DBL_EPSILON * sp, "coords %d: round trip %.3g %.3g",
                  coords, dx / sx, dp / sp);
        /* in place gives the same */
        memcpy(x2, x, sizeof x2);
        memcpy(p2, p, sizeof p2);
        vigen_nbody_to_coordinates(sys, coords, x2, p2, x2, p2);
        CHECK(memcmp(x2, q, sizeof q) == 0 && memcmp(p2, pc, sizeof pc) == 0);
        vigen_nbody_from_coordinates(sys, coords, x2, p2, x2, p2);
        CHECK(maxdiff(x2, x, DMAX, NULL) <= 8 * DBL_EPSILON * sx);
        /* the energy is the same function of the state in both coordinates */
        double Hc = coords == VIGEN_NBODY_JACOBI ? vigen_nbody_jacobi_energy(0, q, pc, sys)
                                                 : vigen_nbody_democratic_energy(0, q, pc, sys);
        double Hx = vigen_nbody_energy(sys, x, p);
        CHECK(fabs(Hc - Hx) <= 1e-14 * fabs(Hx));
        /* jacobi: the centre of mass and the total momentum in slot 0 */
        double M = 0, X = 0, P = 0;
        for (int i = 0; i < NMAX; i++) {
            M += oss_mass[i];
            X += oss_mass[i] * x[3 * i];
            P += p[3 * i];
        }
        CHECK(fabs(q[0] - X / M) <= 1e-14 * sx && fabs(pc[0] - P) <= 1e-14 * sp);
    }
    /* canonical: the map (x, p) -> (q, pc) is linear; its Jacobian J, column
     * k the image of the unit vector e_k, satisfies J^T Omega J = Omega */
    enum { D2 = 2 * DMAX };
    static double J[D2][D2];
    for (int coords = 0; coords < 2; coords++) {
        for (int k = 0; k < D2; k++) {
            double u[D2] = { 0 }, w[D2];
            u[k] = 1;
            vigen_nbody_to_coordinates(sys, coords, u, u + DMAX, w, w + DMAX);
            for (int r = 0; r < D2; r++) J[r][k] = w[r];
        }
        double worst = 0;
        for (int a = 0; a < D2; a++)
            for (int b = 0; b < D2; b++) {
                /* (J^T Omega J)_ab = sum_i J_ia J_{i+D},b - J_{i+D},a J_ib */
                double s = 0;
                for (int i = 0; i < DMAX; i++) s += J[i][a] * J[i + DMAX][b] - J[i + DMAX][a] * J[i][b];
                double omega = (b == a + DMAX) ? 1 : (a == b + DMAX) ? -1 : 0;
                if (fabs(s - omega) > worst) worst = fabs(s - omega);
            }
        CHECK_MSG(worst <= 1e-14, "coords %d: |J^T Omega J - Omega| = %.3g", coords, worst);
    }
    vigen_nbody_free(sys);
    vigen_problem_free(pb);
}

/* H_kepler of the Jacobi splitting from its formula. */
static double jacobi_kepler_energy(const double *q, const double *p)
{
    double M = oss_mass[0], H = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    double Mtot = 0;
    for (int i = 0; i < NMAX; i++) Mtot += oss_mass[i];
    H /= 2 * Mtot;
    for (int i = 1; i < NMAX; i++) {
        double Mi = M + oss_mass[i], mred = oss_mass[i] * M / Mi;
        const double *qi = q + 3 * i, *pi = p + 3 * i;
        H += (pi[0] * pi[0] + pi[1] * pi[1] + pi[2] * pi[2]) / (2 * mred)
             - oss_G * oss_mass[i] * M / sqrt(qi[0] * qi[0] + qi[1] * qi[1] + qi[2] * qi[2]);
        M = Mi;
    }
    return H;
}

/* dH/dz_k by central differences of the energy function. */
static double fd(double (*H)(double, const double *, const double *, void *), void *ctx, double *q, double *p,
                 double *z, int k)
{
    double zk = z[k], h = 1e-6 * (fabs(zk) + 1e-3);
    z[k] = zk + h;
    double fp = H(0, q, p, ctx);
    z[k] = zk - h;
    double fm = H(0, q, p, ctx);
    z[k] = zk;
    return (fp - fm) / (2 * h);
}

static double interaction_energy(double t, const double *q, const double *p, void *ctx)
{
    return vigen_nbody_jacobi_energy(t, q, p, ctx) - jacobi_kepler_energy(q, p);
}

/* Democratic heliocentric: H_kepler and H_jump from their formulas, and
 * H_interaction = H - H_kepler - H_jump. */
static double democratic_kepler_jump(const double *q, const double *p, int jump)
{
    double Mtot = 0, S[3] = { 0, 0, 0 }, H = 0;
    for (int i = 0; i < NMAX; i++) Mtot += oss_mass[i];
    for (int i = 1; i < NMAX; i++)
        for (int c = 0; c < 3; c++) S[c] += p[3 * i + c];
    if (jump) return (S[0] * S[0] + S[1] * S[1] + S[2] * S[2]) / (2 * oss_mass[0]);
    H = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / (2 * Mtot);
    for (int i = 1; i < NMAX; i++) {
        const double *qi = q + 3 * i, *pi = p + 3 * i;
        H += (pi[0] * pi[0] + pi[1] * pi[1] + pi[2] * pi[2]) / (2 * oss_mass[i])
             - oss_G * oss_mass[0] * oss_mass[i] / sqrt(qi[0] * qi[0] + qi[1] * qi[1] + qi[2] * qi[2]);
    }
    return H;
}

static double democratic_interaction_energy(double t, const double *q, const double *p, void *ctx)
{
    return vigen_nbody_democratic_energy(t, q, p, ctx) - democratic_kepler_jump(q, p, 0)
           - democratic_kepler_jump(q, p, 1);
}

static double democratic_jump_energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)ctx;
    return democratic_kepler_jump(q, p, 1);
}

/* A flow of one part H_k by h = 0.5 from (q, p) against h times the
 * differences of H_k: moves_q 0, a kick (p by -h dH_k/dq, q unchanged);
 * 1, a drift (q by h dH_k/dp, p unchanged); errors relative to rel |g| +
 * abs. */
static void part_check(vigen_flow_fn flow, double (*Hk)(double, const double *, const double *, void *),
                       vigen_nbody *sys, double *q, double *p, int moves_q, double rel, double abs,
                       const char *what)
{
    double q1[DMAX], p1[DMAX], h = 0.5, worst = 0;
    memcpy(q1, q, sizeof q1);
    memcpy(p1, p, sizeof p1);
    CHECK(flow(0, h, q1, p1, sys) == VIGEN_SUCCESS);
    CHECK(memcmp(moves_q ? p1 : q1, moves_q ? p : q, sizeof q1) == 0);
    for (int k = 0; k < DMAX; k++) {
        double g = fd(Hk, sys, q, p, moves_q ? p : q, k);
        double change = moves_q ? (q1[k] - q[k]) / h : -(p1[k] - p[k]) / h;
        double err = fabs(change - g) / (rel * fabs(g) + abs);
        if (err > worst) worst = err;
    }
    CHECK_MSG(worst <= 1, "the %s disagrees with differences of its part of H (%.3g)", what, worst);
}

static void fields(void)
{
    double x[DMAX], p[DMAX], q[DMAX], pc[DMAX], dq[DMAX], dp[DMAX], E0;
    vigen_problem *pb = oss(x, p, &E0);
    vigen_nbody *sys;
    vigen_nbody_alloc(&sys, NMAX, oss_G, oss_mass);
    for (int coords = 0; coords < 2; coords++) {
        vigen_split_problem sp;
        CHECK(vigen_nbody_split(sys, coords, &sp) == VIGEN_SUCCESS);
        CHECK(sp.dim == DMAX && sp.nflows == 3 && sp.ctx == sys);
        vigen_nbody_to_coordinates(sys, coords, x, p, q, pc);
        CHECK(sp.vector_field(0, q, pc, dq, dp, sp.ctx) == VIGEN_SUCCESS);
        double worst = 0;
        for (int k = 0; k < DMAX; k++) {
            double gq = fd(sp.H, sp.ctx, q, pc, q, k), gp = fd(sp.H, sp.ctx, q, pc, pc, k);
            double sq = 1e-5 * (fabs(dp[k]) + 1e-12), spp = 1e-5 * (fabs(dq[k]) + 1e-9);
            if (fabs(-gq - dp[k]) / sq > worst) worst = fabs(-gq - dp[k]) / sq;
            if (fabs(gp - dq[k]) / spp > worst) worst = fabs(gp - dq[k]) / spp;
        }
        CHECK_MSG(worst <= 1, "coords %d: the vector field disagrees with differences of H (%.3g)", coords, worst);
    }
    /* each part's flow by h = 0.5 against h times the part's gradient: the
     * kicks move p by -h dH_int/dq and leave q, the jump moves q by
     * h dH_jump/dp and leaves p */
    vigen_nbody_to_jacobi(sys, x, p, q, pc);
    part_check(vigen_nbody_jacobi_interaction, interaction_energy, sys, q, pc, 0, 1e-6, 1e-16, "Jacobi kick");
    vigen_nbody_to_democratic(sys, x, p, q, pc);
    part_check(vigen_nbody_democratic_interaction, democratic_interaction_energy, sys, q, pc, 0, 1e-5, 1e-14,
               "democratic kick");
    part_check(vigen_nbody_democratic_jump, democratic_jump_energy, sys, q, pc, 1, 1e-6, 1e-14, "jump");
    vigen_nbody_free(sys);
    vigen_problem_free(pb);
}

/* One Wisdom-Holman step (Jacobi), kick h/2, drift h, kick h/2 or (kernel
 * drift-kick-drift) drift h/2, kick h, drift h/2. */
static int wh_kernel_step(vigen_nbody *sys, int kernel, double h, double *q, double *p)
{
    vigen_flow_fn outer = vigen_nbody_jacobi_interaction, inner = vigen_nbody_jacobi_kepler;
    if (kernel == VIGEN_NBODY_KERNEL_DKD) {
        outer = vigen_nbody_jacobi_kepler;
        inner = vigen_nbody_jacobi_interaction;
    }
    int st = outer(0, h / 2, q, p, sys);
    if (st == VIGEN_SUCCESS) st = inner(0, h, q, p, sys);
    if (st == VIGEN_SUCCESS) st = outer(0, h / 2, q, p, sys);
    return st;
}

static int wh_step(vigen_nbody *sys, double h, double *q, double *p)
{
    return wh_kernel_step(sys, VIGEN_NBODY_KERNEL_KDK, h, q, p);
}

/* Democratic heliocentric, the kick in the middle: jump h/2, kick h/2,
 * drift h, kick h/2, jump h/2. */
static int dh_step(vigen_nbody *sys, double h, double *q, double *p)
{
    int st = vigen_nbody_democratic_jump(0, h / 2, q, p, sys);
    if (st == VIGEN_SUCCESS) st = vigen_nbody_democratic_interaction(0, h / 2, q, p, sys);
    if (st == VIGEN_SUCCESS) st = vigen_nbody_democratic_kepler(0, h, q, p, sys);
    if (st == VIGEN_SUCCESS) st = vigen_nbody_democratic_interaction(0, h / 2, q, p, sys);
    if (st == VIGEN_SUCCESS) st = vigen_nbody_democratic_jump(0, h / 2, q, p, sys);
    return st;
}

/* Two bodies: the interaction is zero, Wisdom-Holman is the exact flow;
 * against Kepler's equation for the relative orbit (e = 0.9, period 2 pi,
 * steps of 0.91 periods). */
static void two_body(void)
{
    double m[2] = { 1.0, 0.5 }, G = 1 / 1.5; /* mu = G (m0 + m1) = 1 */
    vigen_nbody *sys;
    CHECK(vigen_nbody_alloc(&sys, 2, G, m) == VIGEN_SUCCESS);
    double e = 0.9, vp = sqrt((1 + e) / (1 - e));
    /* relative orbit from the pericentre (a = 1); the centre of mass moving */
    double x[6], p[6], q[6], pc[6], V[3] = { 0.01, -0.02, 0.03 };
    double rel[3] = { 1 - e, 0, 0 }, vrel[3] = { 0, vp, 0 };
    for (int c = 0; c < 3; c++) {
        x[c] = -m[1] / 1.5 * rel[c];
        x[3 + c] = m[0] / 1.5 * rel[c];
        p[c] = m[0] * (V[c] - m[1] / 1.5 * vrel[c]);
        p[3 + c] = m[1] * (V[c] + m[0] / 1.5 * vrel[c]);
    }
    vigen_nbody_to_jacobi(sys, x, p, q, pc);
    /* 45.5 periods: the end at the apocentre, where a phase error shows
     * least (at the pericentre it is seen 19 times faster) */
    double h = 45.5 / 50 * 2 * 3.14159265358979323846;
    int nsteps = 50;
    for (int k = 0; k < nsteps; k++) CHECK(wh_step(sys, h, q, pc) == VIGEN_SUCCESS);
    vigen_nbody_from_jacobi(sys, q, pc, x, p);
    /* the truth: mean anomaly t mod 2 pi, Kepler's equation by bisection */
    double t = h * nsteps, M = remainder(t, 2 * 3.14159265358979323846), lo = -3.2, hi = 3.2;
    for (int it = 0; it < 200; it++) {
        double E = (lo + hi) / 2;
        if (E - e * sin(E) - M > 0) hi = E; else lo = E;
    }
    double E = (lo + hi) / 2, r = 1 - e * cos(E);
    double tr[3] = { cos(E) - e, sqrt(1 - e * e) * sin(E), 0 };
    double tv[3] = { -sin(E) / r, sqrt(1 - e * e) * cos(E) / r, 0 };
    double worst = 0;
    for (int c = 0; c < 3; c++) {
        double dr = (x[3 + c] - x[c]) - tr[c], dv = (p[3 + c] / m[1] - p[c] / m[0]) - tv[c];
        worst = fmax(worst, fmax(fabs(dr), fabs(dv) / vp));
        /* the centre of mass moves freely */
        double X = (m[0] * x[c] + m[1] * x[3 + c]) / 1.5;
        CHECK(fabs(X - V[c] * t) <= 1e-13 * (1 + fabs(V[c] * t)));
    }
    /* round-off only: a drift across or to the pericentre changes the
     * energy by a few eps/(1 - e) (the f and g functions' round-off at the
     * fast end), hence the period; the phase error this leaves grows with
     * the passages and the time (45 periods): relative energy errors of
     * 5e-14 per passage (the pericentre's v^2/2 - 1/r cancels 20 to 1)
     * give a phase error of about 1e-11 after 45 periods, seen at the
     * apocentre's speed; a method error (the interaction not zero, a
     * drift not exact) would be of the size of the orbit */
    CHECK_MSG(worst <= 1e-11, "two-body WH, e = 0.9, h = 0.91 periods: error %.3g", worst);
    printf("two-body WH (e = 0.9, h = 0.91 periods, 50 steps): error %.3g\n", worst);
    vigen_nbody_free(sys);
}

/* The relative energy error, the maximum over n steps of h (the corrector
 * of the order given applied at every step's output, 0 = none), with the
 * kernel given (Jacobi). */
static double oss_energy_error_kernel(int coords, int kernel, double h, long nsteps, int order)
{
    double x[DMAX], p[DMAX], q[DMAX], pc[DMAX], qo[DMAX], po[DMAX], E0;
    vigen_problem *pb = oss(x, p, &E0);
    vigen_nbody *sys;
    vigen_nbody_alloc(&sys, NMAX, oss_G, oss_mass);
    vigen_nbody_to_coordinates(sys, coords, x, p, q, pc);
    if (order) CHECK(vigen_nbody_corrector_apply(sys, kernel, order, h, q, pc, -1) == VIGEN_SUCCESS);
    double worst = 0;
    for (long k = 1; k <= nsteps; k++) {
        int st = coords == VIGEN_NBODY_JACOBI ? wh_kernel_step(sys, kernel, h, q, pc) : dh_step(sys, h, q, pc);
        if (st != VIGEN_SUCCESS) { CHECK(0); break; }
        if (k % 10) continue;
        memcpy(qo, q, sizeof q);
        memcpy(po, pc, sizeof pc);
        if (order) vigen_nbody_corrector_apply(sys, kernel, order, h, qo, po, 1);
        vigen_nbody_from_coordinates(sys, coords, qo, po, x, p);
        double err = fabs(vigen_problem_energy(pb, 0, x, p) / E0 - 1);
        if (err > worst) worst = err;
    }
    vigen_nbody_free(sys);
    vigen_problem_free(pb);
    return worst;
}

static double oss_energy_error(int coords, double h, long nsteps, int order)
{
    return oss_energy_error_kernel(coords, VIGEN_NBODY_KERNEL_KDK, h, nsteps, order);
}

static void outer_solar_system(void)
{
    /* 200000 days (17 Jupiter periods) at h = 100, 50, 25 days */
    for (int coords = 0; coords < 2; coords++) {
        double e1 = oss_energy_error(coords, 100, 2000, 0), e2 = oss_energy_error(coords, 50, 4000, 0),
               e3 = oss_energy_error(coords, 25, 8000, 0);
        printf("%s WH: energy error %.3g %.3g %.3g (h = 100, 50, 25 days), ratios %.2f %.2f\n",
               coords ? "democratic" : "jacobi", e1, e2, e3, e1 / e2, e2 / e3);
        CHECK_MSG(e1 / e2 > 3.5 && e1 / e2 < 4.5 && e2 / e3 > 3.5 && e2 / e3 < 4.5,
                  "coords %d: WH energy error not O(h^2): ratios %.3g %.3g", coords, e1 / e2, e2 / e3);
        /* eps h^2 with eps ~ 1e-3 (Jupiter's mass): the error at 50 days is
         * far below that of a method treating the Sun's pull as a
         * perturbation, (h/T_J)^2 ~ 1e-4 */
        CHECK(e2 < 1e-6);
    }
    double wh = oss_energy_error(VIGEN_NBODY_JACOBI, 50, 4000, 0);
    for (int order = 3; order <= 17; order += 2) {
        if (order == 9 || order == 13 || order == 15) continue;
        double c = oss_energy_error(VIGEN_NBODY_JACOBI, 50, 4000, order);
        printf("jacobi WH with corrector of order %d: energy error %.3g (kernel %.3g)\n", order, c, wh);
        CHECK_MSG(c < wh / 30, "corrector of order %d: %.3g against the kernel's %.3g", order, c, wh);
    }
    /* drift-kick-drift, its own coefficients */
    double dkd = oss_energy_error_kernel(VIGEN_NBODY_JACOBI, VIGEN_NBODY_KERNEL_DKD, 50, 4000, 0);
    double dkd11 = oss_energy_error_kernel(VIGEN_NBODY_JACOBI, VIGEN_NBODY_KERNEL_DKD, 50, 4000, 11);
    printf("jacobi WH drift-kick-drift: energy error %.3g, with corrector of order 11 %.3g\n", dkd, dkd11);
    CHECK(dkd11 < dkd / 30);
    /* the order-3 corrected error falls faster than h^2 (eps h^4 above
     * eps^2 h^2) */
    double c1 = oss_energy_error(VIGEN_NBODY_JACOBI, 100, 2000, 3), c2 = oss_energy_error(VIGEN_NBODY_JACOBI, 50, 4000, 3);
    printf("jacobi WH corrected (order 3): %.3g at h = 100, %.3g at h = 50, ratio %.2f\n", c1, c2, c1 / c2);
    CHECK(c1 / c2 > 6);
}

static void corrector_inverse(void)
{
    double x[DMAX], p[DMAX], q[DMAX], pc[DMAX], q0[DMAX], p0[DMAX], E0;
    vigen_problem *pb = oss(x, p, &E0);
    vigen_nbody *sys;
    vigen_nbody_alloc(&sys, NMAX, oss_G, oss_mass);
    vigen_nbody_to_jacobi(sys, x, p, q, pc);
    memcpy(q0, q, sizeof q);
    memcpy(p0, pc, sizeof pc);
    CHECK(vigen_nbody_corrector_apply(sys, VIGEN_NBODY_KERNEL_DKD, 11, 100, q, pc, 1) == VIGEN_SUCCESS);
    CHECK(memcmp(q, q0, sizeof q) != 0);
    CHECK(vigen_nbody_corrector_apply(sys, VIGEN_NBODY_KERNEL_DKD, 11, 100, q, pc, -1) == VIGEN_SUCCESS);
    double s;
    CHECK(maxdiff(q, q0, DMAX, &s) <= 1e-13 * s);
    CHECK(vigen_nbody_corrector_apply(sys, VIGEN_NBODY_KERNEL_DKD, 9, 100, q, pc, 1) == VIGEN_EINVAL);
    CHECK(vigen_nbody_corrector_apply(sys, 7, 3, 100, q, pc, 1) == VIGEN_EINVAL);
    CHECK(vigen_nbody_corrector_apply(sys, VIGEN_NBODY_KERNEL_KDK, 3, 100, q, pc, 0) == VIGEN_EINVAL);
    /* the order-3 corrector of the drift-kick-drift kernel: b = -1/(48 a), a = sqrt(7/40) */
    double a[8], b[8];
    CHECK(vigen_nbody_corrector_coefficients(VIGEN_NBODY_KERNEL_DKD, 3, a, b) == 1);
    CHECK(fabs(a[0] - sqrt(7.0 / 40)) < 1e-16 && fabs(fabs(b[0]) - 1 / (48 * a[0])) < 1e-16);
    vigen_nbody_free(sys);
    vigen_problem_free(pb);
}

static void bad_input(void)
{
    double x[DMAX], p[DMAX], q[DMAX], pc[DMAX], q0[DMAX], p0[DMAX], E0;
    vigen_problem *pb = oss(x, p, &E0);
    vigen_nbody *sys;
    vigen_nbody_alloc(&sys, NMAX, oss_G, oss_mass);
    static const vigen_flow_fn flows[] = { vigen_nbody_jacobi_kepler, vigen_nbody_jacobi_interaction,
                                           vigen_nbody_democratic_kepler, vigen_nbody_democratic_interaction,
                                           vigen_nbody_democratic_jump };
    for (size_t f = 0; f < sizeof flows / sizeof flows[0]; f++) {
        vigen_nbody_to_coordinates(sys, f < 2 ? VIGEN_NBODY_JACOBI : VIGEN_NBODY_DEMOCRATIC, x, p, q, pc);
        q[7] = NAN;
        memcpy(q0, q, sizeof q);
        memcpy(p0, pc, sizeof pc);
        int st = flows[f](0, 10, q, pc, sys);
        CHECK_MSG(st == VIGEN_ENONFINITE, "flow %zu: NaN position gives %d", f, st);
        CHECK(memcmp(q, q0, sizeof q) == 0 && memcmp(pc, p0, sizeof pc) == 0);
        q[7] = q[4];
        CHECK(flows[f](0, NAN, q, pc, sys) == VIGEN_EINVAL);
        CHECK(flows[f](0, 10, q, pc, NULL) == VIGEN_EINVAL);
    }
    /* a collision orbit: Saturn at the Sun (Jacobi q_2 = 0) */
    vigen_nbody_to_jacobi(sys, x, p, q, pc);
    q[6] = q[7] = q[8] = 0;
    memcpy(q0, q, sizeof q);
    memcpy(p0, pc, sizeof pc);
    CHECK(vigen_nbody_jacobi_kepler(0, 10, q, pc, sys) == VIGEN_EINVAL);
    CHECK(memcmp(q, q0, sizeof q) == 0 && memcmp(pc, p0, sizeof pc) == 0);
    /* Jupiter falling straight into the Sun (Jacobi p_1 along -q_1) */
    vigen_nbody_to_jacobi(sys, x, p, q, pc);
    for (int c = 0; c < 3; c++) pc[3 + c] = -1e-6 * q[3 + c];
    memcpy(q0, q, sizeof q);
    memcpy(p0, pc, sizeof pc);
    CHECK(vigen_nbody_jacobi_kepler(0, 10, q, pc, sys) == VIGEN_EINVAL);
    CHECK(memcmp(q, q0, sizeof q) == 0 && memcmp(pc, p0, sizeof pc) == 0);
    /* bad systems */
    vigen_nbody *bad = NULL;
    double m[2] = { 1, -1 };
    CHECK(vigen_nbody_alloc(&bad, 2, 1, m) == VIGEN_EINVAL && bad == NULL);
    CHECK(vigen_nbody_alloc(&bad, 1, 1, m) == VIGEN_EINVAL);
    CHECK(vigen_nbody_alloc(&bad, 2, NAN, oss_mass) == VIGEN_EINVAL);
    vigen_nbody_free(sys);
    vigen_problem_free(pb);
}

/* The problems' splittings: names, dimensions, and a state through
 * vigen_problem_split_state and back. */
static void problem_splits(void)
{
    static const char *const names[] = { "kepler", "outer-solar-system", "jupiter-saturn" };
    for (size_t i = 0; i < 3; i++) {
        vigen_problem *pb = NULL;
        CHECK(vigen_problem_create(&pb, names[i], NULL, NULL, 0) == VIGEN_SUCCESS);
        if (!pb) continue;
        vigen_split_problem sp;
        char why[200];
        CHECK(vigen_problem_split(pb, NULL, &sp, why, sizeof why) == VIGEN_SUCCESS);
        CHECK(sp.dim == vigen_problem_dim(pb) && sp.nflows == 3);
        CHECK(strcmp(vigen_problem_split_flow_name(pb, 0), "kepler") == 0);
        CHECK(strcmp(vigen_problem_split_flow_name(pb, 1), "interaction") == 0);
        CHECK(strcmp(vigen_problem_split_flow_name(pb, 2), "interaction_gradient") == 0);
        CHECK(vigen_problem_split_flow_name(pb, 3) == NULL);
        double t, q[DMAX], p[DMAX], qs[DMAX], ps[DMAX], q2[DMAX], p2[DMAX];
        vigen_problem_initial(pb, &t, q, p);
        CHECK(vigen_problem_split_state(pb, 1, q, p, qs, ps) == VIGEN_SUCCESS);
        CHECK(fabs(sp.H(t, qs, ps, sp.ctx) / vigen_problem_energy(pb, t, q, p) - 1) < 1e-14);
        /* one step of WH keeps the energy to eps h^2 */
        double h = vigen_problem_period(pb) / 100;
        CHECK(sp.flow[1](t, h / 2, qs, ps, sp.ctx) == VIGEN_SUCCESS);
        CHECK(sp.flow[0](t, h, qs, ps, sp.ctx) == VIGEN_SUCCESS);
        CHECK(sp.flow[1](t, h / 2, qs, ps, sp.ctx) == VIGEN_SUCCESS);
        CHECK(vigen_problem_split_state(pb, 0, qs, ps, q2, p2) == VIGEN_SUCCESS);
        double dE = fabs(vigen_problem_energy(pb, t + h, q2, p2) / vigen_problem_energy(pb, t, q, p) - 1);
        CHECK_MSG(dE < (i == 0 ? 1e-14 : 1e-7), "%s: energy error %.3g after one WH step", names[i], dE);
        int dh = vigen_problem_split(pb, "democratic-heliocentric", &sp, why, sizeof why);
        if (i == 0) {
            CHECK(dh == VIGEN_EINVAL && strstr(why, "democratic") != NULL);
        } else {
            CHECK(dh == VIGEN_SUCCESS && sp.nflows == 3);
            CHECK(strcmp(vigen_problem_split_flow_name(pb, 2), "jump") == 0);
        }
        CHECK(vigen_problem_split(pb, "polar", &sp, why, sizeof why) == VIGEN_EINVAL);
        vigen_problem_free(pb);
    }
    vigen_problem *pb = NULL;
    vigen_split_problem sp;
    char why[200];
    CHECK(vigen_problem_create(&pb, "pendulum", NULL, NULL, 0) == VIGEN_SUCCESS);
    CHECK(vigen_problem_split(pb, NULL, &sp, why, sizeof why) == VIGEN_EINVAL && strstr(why, "pendulum"));
    vigen_problem_free(pb);
}

/* A system of 40 bodies (the scratch in the system's memory, above 32):
 * each flow by h and back by -h returns to the start, and the vector field
 * agrees with differences of H. */
static void many_bodies(void)
{
    enum { NB = 40, DB = 3 * NB };
    double m[NB], x[DB], p[DB], q[DB], pc[DB], q0[DB], p0[DB], dq[DB], dp[DB];
    m[0] = 1;
    for (int i = 1; i < NB; i++) {
        double r = 1 + 0.37 * i, ang = 2.1 * i, v = sqrt(1 / r);
        m[i] = 1e-6 * (1 + i % 3);
        x[3 * i] = r * cos(ang); x[3 * i + 1] = r * sin(ang); x[3 * i + 2] = 0.01 * (i % 5);
        p[3 * i] = -m[i] * v * sin(ang); p[3 * i + 1] = m[i] * v * cos(ang); p[3 * i + 2] = 0;
    }
    x[0] = x[1] = x[2] = p[0] = p[1] = p[2] = 0;
    vigen_nbody *sys;
    CHECK(vigen_nbody_alloc(&sys, NB, 1, m) == VIGEN_SUCCESS);
    for (int coords = 0; coords < 2; coords++) {
        vigen_split_problem sp;
        vigen_nbody_split(sys, coords, &sp);
        vigen_nbody_to_coordinates(sys, coords, x, p, q, pc);
        memcpy(q0, q, sizeof q);
        memcpy(p0, pc, sizeof pc);
        for (size_t k = 0; k < sp.nflows; k++) {
            CHECK(sp.flow[k](0, 0.3, q, pc, sp.ctx) == VIGEN_SUCCESS);
            CHECK(sp.flow[k](0, -0.3, q, pc, sp.ctx) == VIGEN_SUCCESS);
        }
        double sq, spp, eq = maxdiff(q, q0, DB, &sq), ep = maxdiff(pc, p0, DB, &spp);
        CHECK_MSG(eq <= 1e-13 * sq && ep <= 1e-13 * spp, "40 bodies, coords %d: flows and back %.3g %.3g", coords,
                  eq / sq, ep / spp);
        CHECK(sp.vector_field(0, q, pc, dq, dp, sp.ctx) == VIGEN_SUCCESS);
        /* differences of H carry an absolute error of about 1e-8 of the
         * largest component (eps |H| over the step) */
        double sdq = 0, sdp = 0;
        for (int k = 0; k < DB; k++) {
            sdq = fmax(sdq, fabs(dq[k]));
            sdp = fmax(sdp, fabs(dp[k]));
        }
        for (int k = 3; k < DB; k += 7) {
            double gq = fd(sp.H, sp.ctx, q, pc, q, k), gp = fd(sp.H, sp.ctx, q, pc, pc, k);
            CHECK_MSG(fabs(-gq - dp[k]) <= 1e-5 * fabs(dp[k]) + 1e-6 * sdp
                      && fabs(gp - dq[k]) <= 1e-5 * fabs(dq[k]) + 1e-6 * sdq,
                      "40 bodies, coords %d, k %d: %.6g %.6g %.6g %.6g", coords, k, -gq, dp[k], gp, dq[k]);
        }
    }
    vigen_nbody_free(sys);
}

int main(void)
{
    round_trips();
    fields();
    two_body();
    outer_solar_system();
    corrector_inverse();
    bad_input();
    problem_splits();
    many_bodies();
    TEST_MAIN_END();
}
