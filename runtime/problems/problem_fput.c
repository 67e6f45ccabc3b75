/* problem_fput.c — the Fermi-Pasta-Ulam-Tsingou beta chain: n unit masses
 * between fixed walls (q_0 = q_{n+1} = 0),
 *   H = sum_i p_i^2/2 + sum_{i=0}^{n} [ d_i^2/2 + beta d_i^4/4 ],  d_i = q_{i+1} - q_i,
 * started at rest in the first normal mode, q_i = a sin(pi i/(n+1)).  For
 * beta = 0 the chain is linear and the mode is exact:
 *   q_i(t) = a sin(pi i/(n+1)) cos(w t),  w = 2 sin(pi/(2(n+1))),
 * which is the reference; for beta > 0 there is none. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "problems_internal.h"

typedef struct {
    size_t n;
    double beta, omega;
} chain;

static const chain *chain_of(void *ctx) { return ((const vigen_problem *)ctx)->data; }

/* d_i for i = 0..n with the walls at 0. */
static double bond(const double *q, size_t n, size_t i)
{
    double right = i < n ? q[i] : 0, left = i > 0 ? q[i - 1] : 0;
    return right - left;
}

static double potential(const chain *c, const double *q)
{
    vigen_neumaier s = { 0, 0 };
    for (size_t i = 0; i <= c->n; i++) {
        double d = bond(q, c->n, i), d2 = d * d;
        vigen_neumaier_add(&s, d2 / 2 + c->beta * d2 * d2 / 4);
    }
    return vigen_neumaier_result(&s);
}

static double kinetic(const chain *c, const double *p)
{
    vigen_neumaier s = { 0, 0 };
    for (size_t i = 0; i < c->n; i++) vigen_neumaier_add(&s, p[i] * p[i] / 2);
    return vigen_neumaier_result(&s);
}

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    const chain *c = chain_of(ctx);
    return kinetic(c, p) + potential(c, q);
}

/* dV/dq_i = F'(d_{i-1}) - F'(d_i), F'(d) = d + beta d^3 (bond i-1 joins
 * masses i-1 and i in the 0-based indexing of q). */
static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p;
    const chain *c = chain_of(ctx);
    double d = bond(q, c->n, 0), f_left = d + c->beta * d * d * d;
    for (size_t i = 0; i < c->n; i++) {
        d = bond(q, c->n, i + 1);
        double f_right = d + c->beta * d * d * d;
        out[i] = f_left - f_right;
        f_left = f_right;
    }
}

/* -d2V/dq2: tridiagonal, F''(d) = 1 + 3 beta d^2. */
static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v;
    const chain *c = chain_of(ctx);
    size_t n = c->n;
    memset(out, 0, n * n * sizeof *out);
    for (size_t i = 0; i <= n; i++) {
        double d = bond(q, n, i), k = 1 + 3 * c->beta * d * d;
        /* bond i joins masses i-1 and i (0-based), when they exist */
        if (i > 0) out[(i - 1) * n + (i - 1)] -= k;
        if (i < n) out[i * n + i] -= k;
        if (i > 0 && i < n) {
            out[(i - 1) * n + i] += k;
            out[i * n + (i - 1)] += k;
        }
    }
}

static int reference(const vigen_problem *pb, double t, double *q, double *p)
{
    const chain *c = pb->data;
    if (c->beta != 0) return 0;
    double a = pb->param[2], phase = remainder(c->omega * (t - pb->t0), 2 * PBI_PI);
    double cs = cos(phase), sn = sin(phase);
    for (size_t i = 0; i < c->n; i++) {
        double mode = a * sin(PBI_PI * (double)(i + 1) / (double)(c->n + 1));
        q[i] = mode * cs;
        p[i] = -c->omega * mode * sn;
    }
    return 1;
}

int vigen_pbi_fput_setup(vigen_problem *pb)
{
    size_t n = (size_t)pb->param[0];
    chain *c = malloc(sizeof *c);
    if (c == NULL || vigen_pbi_set_dim(pb, n) != VIGEN_SUCCESS) {
        free(c);
        return VIGEN_ENOMEM;
    }
    pb->data = c;
    c->n = n;
    c->beta = pb->param[1];
    c->omega = 2 * sin(PBI_PI / (2 * (double)(n + 1)));
    vigen_pbi_unit_mass(pb, dHdq, energy, d2Ldq2);
    for (size_t i = 0; i < n; i++) pb->q0[i] = pb->param[2] * sin(PBI_PI * (double)(i + 1) / (double)(n + 1));
    pb->period = 2 * PBI_PI / c->omega;
    pb->default_time = 100 * pb->period;
    pb->reference = reference;
    return VIGEN_SUCCESS;
}
