/* problem_henon_heiles.c — the Henon-Heiles system
 *   H = |p|^2/2 + V(q),  V = (q1^2 + q2^2)/2 + q1^2 q2 - q2^3/3,
 * started at q = (0, 0.1), p = (sqrt(2 (E - V(q))), 0) for the energy E of
 * the parameter (orbits stay bounded for E < 1/6; around E = 1/8 most are
 * chaotic).  No reference solution; H is the only invariant. */
#include <math.h>
#include "problems_internal.h"

static double potential(const double *q)
{
    return (q[0] * q[0] + q[1] * q[1]) / 2 + q[0] * q[0] * q[1] - q[1] * q[1] * q[1] / 3;
}

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)ctx;
    return (p[0] * p[0] + p[1] * p[1]) / 2 + potential(q);
}

static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    out[0] = q[0] + 2 * q[0] * q[1];
    out[1] = q[1] + q[0] * q[0] - q[1] * q[1];
}

static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v; (void)ctx;
    out[0] = -(1 + 2 * q[1]);
    out[1] = out[2] = -2 * q[0];
    out[3] = -(1 - 2 * q[1]);
}

int vigen_pbi_henon_heiles_setup(vigen_problem *pb)
{
    if (vigen_pbi_set_dim(pb, 2) != VIGEN_SUCCESS) return VIGEN_ENOMEM;
    vigen_pbi_unit_mass(pb, dHdq, energy, d2Ldq2);
    pb->q0[1] = 0.1;
    /* E >= 0.01 > V(0, 0.1) = 0.00466..., so the square root is real */
    pb->p0[0] = sqrt(2 * (pb->param[0] - potential(pb->q0)));
    pb->period = 2 * PBI_PI;   /* of the linearisation at the origin */
    pb->default_time = 1000;
    return VIGEN_SUCCESS;
}
