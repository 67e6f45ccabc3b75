/* problem_charged_particle.c — a charged particle (unit mass and charge) in
 * a static, axially symmetric magnetic field B = curl A and electric
 * potential phi, with rho = sqrt(x^2 + y^2):
 *   A(q) = (rho/3) (-y, x, 0),   B = (0, 0, rho),   phi(q) = 1/(100 rho),
 *   H = |p - A(q)|^2/2 + phi(q)       (p the canonical momentum),
 *   L = |v|^2/2 + A(q).v - phi(q),    v = p - A(q).
 * Started at q = (0, 1, 0.1) with velocity v = (0.09, 0.05, 0.2), the test
 * problem of Hairer and Lubich for the Boris method.  H is not separable.
 * Invariants: the canonical angular momentum x p_y - y p_x (H is invariant
 * under rotations about the z axis).  No reference solution. */
#include <math.h>
#include "problems_internal.h"

/* A and its first derivatives dA[i][j] = d A_j / d q_i. */
static void vector_potential(const double *q, double A[3], double dA[3][3])
{
    double x = q[0], y = q[1], rho = hypot(x, y);
    A[0] = -rho * y / 3;
    A[1] = rho * x / 3;
    A[2] = 0;
    if (dA == NULL) return;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) dA[i][j] = 0;
    dA[0][0] = -x * y / (3 * rho);
    dA[1][0] = -(rho + y * y / rho) / 3;
    dA[0][1] = (rho + x * x / rho) / 3;
    dA[1][1] = x * y / (3 * rho);
}

static double phi(const double *q) { return 1 / (100 * hypot(q[0], q[1])); }

/* dphi/dq = -(x, y, 0)/(100 rho^3) */
static void grad_phi(const double *q, double g[3])
{
    double rho = hypot(q[0], q[1]), r3 = 100 * rho * rho * rho;
    g[0] = -q[0] / r3;
    g[1] = -q[1] / r3;
    g[2] = 0;
}

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)ctx;
    double A[3];
    vector_potential(q, A, NULL);
    double w0 = p[0] - A[0], w1 = p[1] - A[1], w2 = p[2] - A[2];
    return (w0 * w0 + w1 * w1 + w2 * w2) / 2 + phi(q);
}

/* v = p - A(q): dH/dp, and the inverse Legendre map */
static void velocity(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)ctx;
    double A[3];
    vector_potential(q, A, NULL);
    for (int i = 0; i < 3; i++) out[i] = p[i] - A[i];
}

/* dH/dq_i = -sum_j v_j dA_j/dq_i + dphi/dq_i */
static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)ctx;
    double A[3], dA[3][3], g[3];
    vector_potential(q, A, dA);
    grad_phi(q, g);
    for (int i = 0; i < 3; i++) {
        double s = 0;
        for (int j = 0; j < 3; j++) s += (p[j] - A[j]) * dA[i][j];
        out[i] = g[i] - s;
    }
}

static double lagrangian(double t, const double *q, const double *v, void *ctx)
{
    (void)t; (void)ctx;
    double A[3];
    vector_potential(q, A, NULL);
    return (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / 2 + A[0] * v[0] + A[1] * v[1] + A[2] * v[2] - phi(q);
}

/* dL/dq_i = sum_j v_j dA_j/dq_i - dphi/dq_i */
static void dLdq(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)ctx;
    double A[3], dA[3][3], g[3];
    vector_potential(q, A, dA);
    grad_phi(q, g);
    for (int i = 0; i < 3; i++) out[i] = v[0] * dA[i][0] + v[1] * dA[i][1] + v[2] * dA[i][2] - g[i];
}

/* dL/dv = v + A(q) */
static void dLdv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)ctx;
    double A[3];
    vector_potential(q, A, NULL);
    for (int i = 0; i < 3; i++) out[i] = v[i] + A[i];
}

/* d2L/dq_i dv_j = dA_j/dq_i */
static void d2Ldqdv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v; (void)ctx;
    double A[3], dA[3][3];
    vector_potential(q, A, dA);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) out[3 * i + j] = dA[i][j];
}

/* d2L/dq_i dq_k = sum_j v_j d2A_j/dq_i dq_k - d2phi/dq_i dq_k; only x and y
 * enter.  With rho^3 = r3:
 *   A_x = -rho y/3:  xx -y^3/(3 r3),  xy -x^3/(3 r3),  yy -y (3x^2 + 2y^2)/(3 r3)
 *   A_y =  rho x/3:  xx x (2x^2 + 3y^2)/(3 r3),  xy y^3/(3 r3),  yy x^3/(3 r3)
 *   phi = 1/(100 rho):  xx (3x^2 - rho^2)/(100 rho^5),  xy 3xy/(100 rho^5),
 *                       yy (3y^2 - rho^2)/(100 rho^5) */
static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)ctx;
    double x = q[0], y = q[1], rho2 = x * x + y * y, rho = sqrt(rho2), r3 = 3 * rho2 * rho;
    double r5 = 100 * rho2 * rho2 * rho;
    double xx = v[0] * (-y * y * y / r3) + v[1] * (x * (2 * x * x + 3 * y * y) / r3) - (3 * x * x - rho2) / r5;
    double xy = v[0] * (-x * x * x / r3) + v[1] * (y * y * y / r3) - 3 * x * y / r5;
    double yy = v[0] * (-y * (3 * x * x + 2 * y * y) / r3) + v[1] * (x * x * x / r3) - (3 * y * y - rho2) / r5;
    for (int k = 0; k < 9; k++) out[k] = 0;
    out[0] = xx;
    out[1] = out[3] = xy;
    out[4] = yy;
}

/* The Hessian of H with w = p - A(q), x = (q, p):
 *   d2H/dq_i dq_k = sum_j dA_j/dq_i dA_j/dq_k - d2L/dq_i dq_k (q, w),
 *   d2H/dq_i dp_j = d2H/dp_j dq_i = -dA_j/dq_i,   d2H/dp2 = I. */
static void hessian(double t, const double *q, const double *p, double *out, void *ctx)
{
    double A[3], dA[3][3], w[3], Lqq[9];
    vector_potential(q, A, dA);
    for (int j = 0; j < 3; j++) w[j] = p[j] - A[j];
    d2Ldq2(t, q, w, Lqq, ctx);
    for (int k = 0; k < 36; k++) out[k] = 0;
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            double s = dA[i][0] * dA[k][0] + dA[i][1] * dA[k][1] + dA[i][2] * dA[k][2];
            out[i * 6 + k] = s - Lqq[3 * i + k];
            out[i * 6 + 3 + k] = -dA[i][k];
            out[(3 + k) * 6 + i] = -dA[i][k];
        }
        out[(3 + i) * 6 + 3 + i] = 1;
    }
}

static const char *const names[] = { "canonical-angular-momentum" };

static double invariant(const vigen_problem *pb, size_t k, double t, const double *q, const double *p)
{
    (void)pb; (void)k; (void)t;
    return q[0] * p[1] - q[1] * p[0];
}

int vigen_pbi_charged_particle_setup(vigen_problem *pb)
{
    static const double x0[3] = { 0, 1, 0.1 }, v0[3] = { 0.09, 0.05, 0.2 };
    if (vigen_pbi_set_dim(pb, 3) != VIGEN_SUCCESS) return VIGEN_ENOMEM;
    pb->ham = (vigen_hamiltonian){ .dHdq = dHdq, .dHdp = velocity, .H = energy, .separable = 0, .hessian = hessian };
    pb->lag = (vigen_lagrangian){ .dim = 3, .dLdq = dLdq, .dLdv = dLdv, .L = lagrangian,
                                  .d2Ldq2 = d2Ldq2, .d2Ldv2 = vigen_pbi_unit_block, .d2Ldqdv = d2Ldqdv };
    pb->legendre_inverse = velocity;
    double A[3];
    vector_potential(x0, A, NULL);
    for (int i = 0; i < 3; i++) {
        pb->q0[i] = x0[i];
        pb->p0[i] = v0[i] + A[i];
    }
    pb->period = 2 * PBI_PI;   /* of the gyration where |B| = rho = 1 */
    pb->default_time = 1000;
    pb->ninvariants = 1;
    pb->invariant_names = names;
    pb->invariant = invariant;
    return VIGEN_SUCCESS;
}
