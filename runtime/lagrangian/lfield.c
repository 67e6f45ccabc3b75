/* lfield.c — the flow of a Lagrangian problem in (q, p) through the
 * inverse Legendre map (lfield_internal.h). */
#include <stdlib.h>
#include <string.h>
#include "lfield_internal.h"

int vigen_lfield_init(vigen_lfield *f, const vigen_lagrangian *lag, const vigen_solver_options *opt)
{
    memset(f, 0, sizeof *f);
    f->lag = lag;
    f->opt = opt;
    f->inv = vigen_lsolve_alloc(lag->dim);
    f->v = malloc(lag->dim * sizeof(double));
    if (f->inv == NULL || f->v == NULL) {
        vigen_lfield_clear(f);
        return VIGEN_ENOMEM;
    }
    return VIGEN_SUCCESS;
}

void vigen_lfield_clear(vigen_lfield *f)
{
    vigen_lsolve_free(f->inv);
    free(f->v);
    f->inv = NULL;
    f->v = NULL;
}

/* The solver itself tells a residual that is not finite. */
static int legendre_residual(const double *v, double *r, void *ctx)
{
    vigen_lfield *f = ctx;
    f->lag->dLdv(f->t, f->q, v, r, f->lag->ctx);
    f->count->dHdp_evals++;
    for (size_t i = 0; i < f->lag->dim; i++) r[i] -= f->p[i];
    return VIGEN_SUCCESS;
}

static int legendre_jacobian(const double *v, double *J, void *ctx)
{
    vigen_lfield *f = ctx;
    f->lag->d2Ldv2(f->t, f->q, v, J, f->lag->ctx);
    return VIGEN_SUCCESS;
}

int vigen_lfield_velocity(vigen_lfield *f, const double *v_start, double t, const double *q, const double *p,
                          vigen_stats *stats)
{
    const size_t n = f->lag->dim;
    f->t = t;
    f->q = q;
    f->p = p;
    f->count = stats;
    int st = VIGEN_ESINGULAR;
    for (int attempt = 0; attempt < 2 && st == VIGEN_ESINGULAR; attempt++) {
        if (attempt == 0 && v_start == NULL) memset(f->v, 0, n * sizeof(double));
        else memcpy(f->v, attempt == 0 ? v_start : p, n * sizeof(double));
        st = vigen_lsolve_run(f->inv, f->v, legendre_residual, f->lag->d2Ldv2 ? legendre_jacobian : NULL, f,
                              f->opt, stats);
    }
    return st;
}

int vigen_lfield_eval(vigen_lfield *f, const double *v_start, double t, const double *q, const double *p,
                      double *dq, double *dp)
{
    const size_t n = f->lag->dim;
    const int st = vigen_lfield_velocity(f, v_start, t, q, p, &f->stats);
    if (st != VIGEN_SUCCESS) return st;
    memcpy(dq, f->v, n * sizeof(double));
    f->lag->dLdq(t, q, f->v, dp, f->lag->ctx);
    return vigen_lsolve_finite(dq, n) && vigen_lsolve_finite(dp, n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}
