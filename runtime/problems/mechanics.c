/* mechanics.c — callbacks shared by the problems of unit mass, where
 * v = dH/dp = p: the Legendre map and its inverse (the identity), and the
 * constant blocks of second derivatives of L = |v|^2/2 - V(q). */
#include <string.h>
#include "problems_internal.h"

static size_t dim_of(void *ctx) { return ((const vigen_problem *)ctx)->dim; }

void pbi_copy_v(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q;
    memcpy(out, v, dim_of(ctx) * sizeof *out);
}

void pbi_unit_block(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v;
    size_t n = dim_of(ctx);
    memset(out, 0, n * n * sizeof *out);
    for (size_t i = 0; i < n; i++) out[i * n + i] = 1;
}

void pbi_zero_block(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v;
    size_t n = dim_of(ctx);
    memset(out, 0, n * n * sizeof *out);
}
