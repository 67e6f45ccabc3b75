/* mechanics.c — what the problems of unit mass share, H = |p|^2/2 + V(q):
 * v = dH/dp = p (the Legendre map and its inverse are the identity), and
 * their Lagrangian L = |v|^2/2 - V(q) = |v|^2 - H(q, v), dL/dq = -dH/dq,
 * with the constant blocks of second derivatives d2L/dv2 = I, d2L/dqdv = 0,
 * and the Hessian of H, [[d2V/dq2, 0], [0, I]]. */
#include <string.h>
#include "problems_internal.h"

static size_t dim_of(void *ctx) { return ((const vigen_problem *)ctx)->dim; }

void vigen_pbi_copy_v(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q;
    memcpy(out, v, dim_of(ctx) * sizeof *out);
}

void vigen_pbi_unit_block(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v;
    size_t n = dim_of(ctx);
    memset(out, 0, n * n * sizeof *out);
    for (size_t i = 0; i < n; i++) out[i * n + i] = 1;
}

void vigen_pbi_zero_block(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v;
    size_t n = dim_of(ctx);
    memset(out, 0, n * n * sizeof *out);
}

static double unit_mass_L(double t, const double *q, const double *v, void *ctx)
{
    const vigen_problem *pb = ctx;
    vigen_neumaier s = { 0, 0 };
    for (size_t i = 0; i < pb->dim; i++) vigen_neumaier_add(&s, v[i] * v[i]);
    vigen_neumaier_add(&s, -pb->ham.H(t, q, v, ctx));
    return vigen_neumaier_result(&s);
}

static void unit_mass_dLdq(double t, const double *q, const double *v, double *out, void *ctx)
{
    const vigen_problem *pb = ctx;
    pb->ham.dHdq(t, q, v, out, ctx);
    for (size_t i = 0; i < pb->dim; i++) out[i] = -out[i];
}

void vigen_pbi_separable_hessian(const vigen_problem *pb, double t, const double *q, double *out)
{
    size_t n = pb->dim;
    /* -d2V/dq2 = d2L/dq2 (any v: L is separable) into out[0 .. n^2-1], then
     * each row moved to its place in the 2n x 2n matrix, last row first (row
     * i goes from i n to 2 i n, past the rows not yet moved) */
    pb->lag.d2Ldq2(t, q, q, out, (void *)pb);
    for (size_t i = n; i-- > 0;) {
        memmove(out + 2 * i * n, out + i * n, n * sizeof *out);
        for (size_t j = 0; j < n; j++) out[2 * i * n + j] = -out[2 * i * n + j];
        memset(out + 2 * i * n + n, 0, n * sizeof *out);
    }
    memset(out + 2 * n * n, 0, 2 * n * n * sizeof *out);
}

static void unit_mass_hessian(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)p;
    const vigen_problem *pb = ctx;
    size_t n = pb->dim;
    vigen_pbi_separable_hessian(pb, t, q, out);
    for (size_t i = 0; i < n; i++) out[(n + i) * 2 * n + n + i] = 1;
}

void vigen_pbi_unit_mass(vigen_problem *pb, vigen_grad_fn dHdq, double (*H)(double, const double *, const double *, void *),
                   vigen_lhess_fn d2Ldq2)
{
    pb->ham = (vigen_hamiltonian){ .dHdq = dHdq, .dHdp = vigen_pbi_copy_v, .H = H, .separable = 1,
                                   .hessian = unit_mass_hessian };
    pb->lag = (vigen_lagrangian){ .dim = pb->dim, .dLdq = unit_mass_dLdq, .dLdv = vigen_pbi_copy_v, .L = unit_mass_L,
                                  .d2Ldq2 = d2Ldq2, .d2Ldv2 = vigen_pbi_unit_block, .d2Ldqdv = vigen_pbi_zero_block };
    pb->legendre_inverse = vigen_pbi_copy_v;
}
