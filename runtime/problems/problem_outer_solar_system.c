/* problem_outer_solar_system.c — the Sun (with the inner planets' masses)
 * and Jupiter, Saturn, Uranus, Neptune, Pluto as six point masses in R^3,
 * with the data of Hairer, Lubich and Wanner, Geometric Numerical
 * Integration, sec. I.2.3 (masses relative to the Sun, distances in AU, time
 * in Earth days, G = 2.95912208286e-4):
 *   H = sum_i |p_i|^2/(2 m_i) - G sum_{i<j} m_i m_j / |q_i - q_j|,
 * q = (q_Sun, q_Jupiter, ..., q_Pluto), 18 coordinates, p_i = m_i v_i, the
 * Sun at rest at the origin.  Invariants: total linear and angular
 * momentum.  No reference solution.  Its Kepler splittings are the N-body
 * ones of the runtime (Jacobi, democratic heliocentric). */
#include <math.h>
#include "problems_internal.h"

enum { NBODY = 6 };

static const double G = 2.95912208286e-4;
static const double mass[NBODY] = {
    1.00000597682,        /* Sun and the inner planets */
    0.000954786104043,    /* Jupiter */
    0.000285583733151,    /* Saturn */
    0.0000437273164546,   /* Uranus */
    0.0000517759138449,   /* Neptune */
    1 / 1.3e8,            /* Pluto */
};
static const double position[NBODY][3] = {
    { 0, 0, 0 },
    { -3.5023653, -3.8169847, -1.5507963 },
    { 9.0755314, -3.0458353, -1.6483708 },
    { 8.3101420, -16.2901086, -7.2521278 },
    { 11.4707666, -25.7294829, -10.8169456 },
    { -15.5387357, -25.2225594, -3.1902382 },
};
static const double velocity[NBODY][3] = {
    { 0, 0, 0 },
    { 0.00565429, -0.00412490, -0.00190589 },
    { 0.00168318, 0.00483525, 0.00192462 },
    { 0.00354178, 0.00137102, 0.00055029 },
    { 0.00288930, 0.00114527, 0.00039677 },
    { 0.00276725, -0.00170702, -0.00136504 },
};

static double distance(const double *q, int i, int j)
{
    double dx = q[3 * i] - q[3 * j], dy = q[3 * i + 1] - q[3 * j + 1], dz = q[3 * i + 2] - q[3 * j + 2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* sum_{i<j} G m_i m_j / r_ij (= -V) */
static double attraction(const double *q)
{
    vigen_neumaier s = { 0, 0 };
    for (int i = 0; i < NBODY; i++)
        for (int j = i + 1; j < NBODY; j++) vigen_neumaier_add(&s, G * mass[i] * mass[j] / distance(q, i, j));
    return vigen_neumaier_result(&s);
}

/* sum_i m_i |v_i|^2/2 with v_i = x_i/m_i (x = p) or v_i = x_i (x = v) */
static double kinetic(const double *x, int x_is_momentum)
{
    vigen_neumaier s = { 0, 0 };
    for (int i = 0; i < NBODY; i++) {
        double x2 = x[3 * i] * x[3 * i] + x[3 * i + 1] * x[3 * i + 1] + x[3 * i + 2] * x[3 * i + 2];
        vigen_neumaier_add(&s, x_is_momentum ? x2 / (2 * mass[i]) : mass[i] * x2 / 2);
    }
    return vigen_neumaier_result(&s);
}

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)ctx;
    return kinetic(p, 1) - attraction(q);
}

/* dV/dq_i = sum_{j != i} G m_i m_j (q_i - q_j) / r_ij^3 */
static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    for (int k = 0; k < 3 * NBODY; k++) out[k] = 0;
    for (int i = 0; i < NBODY; i++)
        for (int j = i + 1; j < NBODY; j++) {
            double r = distance(q, i, j), f = G * mass[i] * mass[j] / (r * r * r);
            for (int c = 0; c < 3; c++) {
                double d = f * (q[3 * i + c] - q[3 * j + c]);
                out[3 * i + c] += d;
                out[3 * j + c] -= d;
            }
        }
}

static void dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    for (int k = 0; k < 3 * NBODY; k++) out[k] = p[k] / mass[k / 3];
}

/* L = sum m_i |v_i|^2/2 + G sum_{i<j} m_i m_j / r_ij */
static double lagrangian(double t, const double *q, const double *v, void *ctx)
{
    (void)t; (void)ctx;
    return kinetic(v, 0) + attraction(q);
}

static void dLdq(double t, const double *q, const double *v, double *out, void *ctx)
{
    dHdq(t, q, v, out, ctx);
    for (int k = 0; k < 3 * NBODY; k++) out[k] = -out[k];
}

static void dLdv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    for (int k = 0; k < 3 * NBODY; k++) out[k] = mass[k / 3] * v[k];
}

static void d2Ldv2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v; (void)ctx;
    enum { N = 3 * NBODY };
    for (int k = 0; k < N * N; k++) out[k] = 0;
    for (int k = 0; k < N; k++) out[k * N + k] = mass[k / 3];
}

/* d2L/dq2: for each pair, K = G m_i m_j (3 d d^T / r^5 - I / r^3), d = q_i - q_j,
 * the Hessian of G m_i m_j / r_ij, added to the (i,i) and (j,j) blocks and
 * subtracted from (i,j) and (j,i). */
static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v; (void)ctx;
    enum { N = 3 * NBODY };
    for (int k = 0; k < N * N; k++) out[k] = 0;
    for (int i = 0; i < NBODY; i++)
        for (int j = i + 1; j < NBODY; j++) {
            double r = distance(q, i, j), gm = G * mass[i] * mass[j], d[3];
            for (int c = 0; c < 3; c++) d[c] = q[3 * i + c] - q[3 * j + c];
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) {
                    double K = gm * (3 * d[a] * d[b] / pow(r, 5) - (a == b) / (r * r * r));
                    out[(3 * i + a) * N + 3 * i + b] += K;
                    out[(3 * j + a) * N + 3 * j + b] += K;
                    out[(3 * i + a) * N + 3 * j + b] -= K;
                    out[(3 * j + a) * N + 3 * i + b] -= K;
                }
        }
}

/* [[d2V/dq2, 0], [0, diag(1/m)]] */
static void hessian(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)p;
    enum { N = 3 * NBODY };
    vigen_pbi_separable_hessian(ctx, t, q, out);
    for (int k = 0; k < N; k++) out[(N + k) * 2 * N + N + k] = 1 / mass[k / 3];
}

static const char *const names[] = { "momentum-x", "momentum-y", "momentum-z",
                                     "angular-momentum-x", "angular-momentum-y", "angular-momentum-z" };

/* sum_i p_i (component k) or sum_i q_i x p_i (component k - 3), compensated */
static double invariant(const vigen_problem *pb, size_t k, double t, const double *q, const double *p)
{
    (void)pb; (void)t;
    vigen_neumaier s = { 0, 0 };
    size_t c = k % 3, a = (c + 1) % 3, b = (c + 2) % 3;
    for (int i = 0; i < NBODY; i++) {
        const double *x = q + 3 * i, *y = p + 3 * i;
        if (k < 3) {
            vigen_neumaier_add(&s, y[c]);
        } else {
            vigen_neumaier_add(&s, x[a] * y[b]);
            vigen_neumaier_add(&s, -x[b] * y[a]);
        }
    }
    return vigen_neumaier_result(&s);
}

int vigen_pbi_outer_solar_system_setup(vigen_problem *pb)
{
    if (vigen_pbi_set_dim(pb, 3 * NBODY) != VIGEN_SUCCESS) return VIGEN_ENOMEM;
    pb->ham = (vigen_hamiltonian){ .dHdq = dHdq, .dHdp = dHdp, .H = energy, .separable = 1, .hessian = hessian };
    pb->lag = (vigen_lagrangian){ .dim = 3 * NBODY, .dLdq = dLdq, .dLdv = dLdv, .L = lagrangian,
                                  .d2Ldq2 = d2Ldq2, .d2Ldv2 = d2Ldv2, .d2Ldqdv = vigen_pbi_zero_block };
    pb->legendre_inverse = dHdp;
    for (int i = 0; i < NBODY; i++)
        for (int c = 0; c < 3; c++) {
            pb->q0[3 * i + c] = position[i][c];
            pb->p0[3 * i + c] = mass[i] * velocity[i][c];
        }
    /* Jupiter's period from its osculating Kepler orbit about the Sun:
     * a = 1/(2/r - v^2/mu), T = 2 pi sqrt(a^3/mu), mu = G (m_Sun + m_J) */
    double mu = G * (mass[0] + mass[1]), r = distance(pb->q0, 0, 1);
    double v2 = velocity[1][0] * velocity[1][0] + velocity[1][1] * velocity[1][1] + velocity[1][2] * velocity[1][2];
    double a = 1 / (2 / r - v2 / mu);
    pb->period = 2 * PBI_PI * sqrt(a * a * a / mu);
    pb->default_time = 200000;
    pb->ninvariants = 6;
    pb->invariant_names = names;
    pb->invariant = invariant;
    return vigen_pbi_nbody_split_setup(pb, NBODY, G, mass);
}
