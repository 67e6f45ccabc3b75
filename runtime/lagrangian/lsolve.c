/* lsolve.c — Newton's method for the small implicit systems of the
 * Lagrangian integrators (see lsolve_internal.h for the choices made). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_vector.h>
#include "lsolve_internal.h"

/* Halvings of a Newton step that lands where the residual is not finite
 * (a factor 1/1024 at most) before the solve gives up. */
#define VIGEN_LSOLVE_HALVINGS 10

struct vigen_lsolve {
    size_t n;
    double *J;          /* n x n Jacobian, row-major */
    double *r;          /* residual at x */
    double *rp;         /* residual at a perturbed x (differences) */
    double *xp;         /* perturbed x */
    double *rs, *cs;    /* row and column scales of the equilibrated matrix */
    double *xo;         /* the iterate before the step (for damping) */
    gsl_matrix *M;      /* equilibrated Jacobian, then its LU */
    gsl_permutation *perm;
    gsl_vector *b, *y;
};

vigen_lsolve *vigen_lsolve_alloc(size_t n)
{
    if (n == 0) return NULL;
    gsl_set_error_handler_off();
    vigen_lsolve *s = calloc(1, sizeof *s);
    if (s == NULL) return NULL;
    s->n = n;
    s->J = malloc(n * n * sizeof(double));
    s->r = malloc(6 * n * sizeof(double));
    s->M = gsl_matrix_alloc(n, n);
    s->perm = gsl_permutation_alloc(n);
    s->b = gsl_vector_alloc(n);
    s->y = gsl_vector_alloc(n);
    if (!s->J || !s->r || !s->M || !s->perm || !s->b || !s->y) {
        vigen_lsolve_free(s);
        return NULL;
    }
    s->rp = s->r + n;
    s->xp = s->r + 2 * n;
    s->rs = s->r + 3 * n;
    s->cs = s->r + 4 * n;
    s->xo = s->r + 5 * n;
    return s;
}

void vigen_lsolve_free(vigen_lsolve *s)
{
    if (s == NULL) return;
    free(s->J);
    free(s->r);
    if (s->M) gsl_matrix_free(s->M);
    if (s->perm) gsl_permutation_free(s->perm);
    if (s->b) gsl_vector_free(s->b);
    if (s->y) gsl_vector_free(s->y);
    free(s);
}

size_t vigen_lsolve_dim(const vigen_lsolve *s) { return s->n; }

int vigen_lsolve_finite(const double *x, size_t n)
{
    int ok = 1;
    for (size_t k = 0; k < n; k++) ok &= (x[k] - x[k] == 0);
    return ok;
}

/* The residual at x, with a NaN or infinity in it turned into
 * VIGEN_ENONFINITE whatever the callback returned. */
static int residual(vigen_lsolve_residual_fn rf, const double *x, double *r, size_t n, void *ctx)
{
    int st = rf(x, r, ctx);
    if (st != VIGEN_SUCCESS) return st;
    return vigen_lsolve_finite(r, n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

/* Forward differences of the residual, column by column; s->r holds r(x).
 * The step is rel * max(|x_j|, 1), then the step actually represented. */
static int jacobian_fd(vigen_lsolve *s, const double *x, vigen_lsolve_residual_fn rf, void *ctx,
                       double rel)
{
    const size_t n = s->n;
    memcpy(s->xp, x, n * sizeof(double));
    for (size_t c = 0; c < n; c++) {
        double xc = x[c], ax = fabs(xc);
        s->xp[c] = xc + rel * (ax > 1.0 ? ax : 1.0);
        double d = s->xp[c] - xc;
        int st = residual(rf, s->xp, s->rp, n, ctx);
        s->xp[c] = xc;
        if (st != VIGEN_SUCCESS) return st;
        for (size_t k = 0; k < n; k++) s->J[k * n + c] = (s->rp[k] - s->r[k]) / d;
    }
    return VIGEN_SUCCESS;
}

/* Equilibrates J into M (rows, then columns, scaled by their largest
 * magnitude, scales kept for the solves) and factorises it.  A zero row or
 * column, or a pivot below 16 n epsilon of the equilibrated matrix (whose
 * entries are at most 1), is VIGEN_ESINGULAR; a NaN or infinite entry is
 * VIGEN_ENONFINITE. */
static int factor(vigen_lsolve *s)
{
    const size_t n = s->n;
    if (!vigen_lsolve_finite(s->J, n * n)) return VIGEN_ENONFINITE;
    for (size_t i = 0; i < n; i++) {
        double m = 0.0;
        for (size_t j = 0; j < n; j++) m = fmax(m, fabs(s->J[i * n + j]));
        if (m == 0.0) return VIGEN_ESINGULAR;
        s->rs[i] = 1.0 / m;
    }
    for (size_t j = 0; j < n; j++) {
        double m = 0.0;
        for (size_t i = 0; i < n; i++) m = fmax(m, fabs(s->J[i * n + j] * s->rs[i]));
        if (m == 0.0) return VIGEN_ESINGULAR;
        s->cs[j] = 1.0 / m;
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) gsl_matrix_set(s->M, i, j, s->J[i * n + j] * s->rs[i] * s->cs[j]);
    int signum = 0;
    if (gsl_linalg_LU_decomp(s->M, s->perm, &signum) != GSL_SUCCESS) return VIGEN_ESINGULAR;
    const double small = 16.0 * (double)n * DBL_EPSILON;
    for (size_t k = 0; k < n; k++) {
        double d = fabs(gsl_matrix_get(s->M, k, k));
        if (!(d - d == 0)) return VIGEN_ENONFINITE;
        if (d <= small) return VIGEN_ESINGULAR;
    }
    return VIGEN_SUCCESS;
}

/* dx = -J^{-1} r through the equilibrated factors, into s->xp. */
static int solve(vigen_lsolve *s)
{
    const size_t n = s->n;
    for (size_t i = 0; i < n; i++) gsl_vector_set(s->b, i, -s->r[i] * s->rs[i]);
    if (gsl_linalg_LU_solve(s->M, s->perm, s->b, s->y) != GSL_SUCCESS) return VIGEN_ESINGULAR;
    for (size_t j = 0; j < n; j++) s->xp[j] = gsl_vector_get(s->y, j) * s->cs[j];
    return vigen_lsolve_finite(s->xp, n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

int vigen_lsolve_run(vigen_lsolve *s, double *x, vigen_lsolve_residual_fn rf,
                     vigen_lsolve_jacobian_fn Jf, void *ctx,
                     const vigen_solver_options *opt, vigen_stats *stats)
{
    if (s == NULL || x == NULL || rf == NULL) return VIGEN_EINVAL;
    const size_t n = s->n;
    const double tol = (opt && opt->tol > 0.0) ? opt->tol : vigen_default_tol();
    const int max_iter = (opt && opt->max_iter > 0) ? opt->max_iter : 50;
    const double rel = (opt && opt->fd_step > 0.0) ? opt->fd_step : sqrt(DBL_EPSILON);
    const double refresh_above = sqrt(tol);
    vigen_iter_monitor mon;
    vigen_iter_start(&mon);
    int st = vigen_lsolve_finite(x, n) ? residual(rf, x, s->r, n, ctx) : VIGEN_ENONFINITE;
    int have_lu = 0, iters = 0;
    double last = -1.0;
    while (st == VIGEN_SUCCESS) {
        /* a fresh Jacobian unless the iteration is already in its final,
         * fast phase and still contracting with the one it has */
        if (!have_lu || last > refresh_above || (last > tol && mon.prev2 >= 0.0 && last >= mon.prev2)) {
            st = Jf ? Jf(x, s->J, ctx) : jacobian_fd(s, x, rf, ctx, rel);
            if (st != VIGEN_SUCCESS) break;
            if (stats) stats->hessian_evals++;
            st = factor(s);
            if (stats) stats->lu_decompositions++;
            if (st != VIGEN_SUCCESS) break;
            have_lu = 1;
        }
        st = solve(s);
        if (st != VIGEN_SUCCESS) break;
        memcpy(s->xo, x, n * sizeof(double));
        double dmax = 0.0, xmax = 0.0;
        for (size_t k = 0; k < n; k++) {
            double xn = x[k] + s->xp[k];
            dmax = fmax(dmax, fabs(s->xp[k]));
            xmax = fmax(xmax, fmax(fabs(x[k]), fabs(xn)));
            x[k] = xn;
        }
        iters++;
        last = dmax == 0.0 ? 0.0 : dmax / fmax(xmax, DBL_MIN);
        const vigen_iter_monitor before = mon;
        int verdict = vigen_iter_judge(&mon, last, tol, max_iter);
        if (verdict >= 0) {
            st = verdict;
            break;
        }
        st = residual(rf, x, s->r, n, ctx);
        if (st != VIGEN_ENONFINITE) continue;
        /* The full step left the region where the residual is finite:
         * halve it until it is back.  A damped step is no evidence of
         * convergence, so the stopping rule does not see it, and the
         * Jacobian is formed afresh where the iteration now is. */
        mon = before;
        double lambda = 1.0;
        for (int k = 0; k < VIGEN_LSOLVE_HALVINGS && st == VIGEN_ENONFINITE; k++) {
            lambda *= 0.5;
            for (size_t i = 0; i < n; i++) x[i] = s->xo[i] + lambda * s->xp[i];
            st = residual(rf, x, s->r, n, ctx);
        }
        have_lu = 0;
        last = -1.0;
        /* still running into non-finite values when the budget ends */
        if (st == VIGEN_SUCCESS && iters >= max_iter) st = VIGEN_ENONFINITE;
    }
    if (stats) {
        stats->iterations += (unsigned long)iters;
        stats->last_iterations = (unsigned long)iters;
        if ((unsigned long)iters > stats->max_iterations) stats->max_iterations = (unsigned long)iters;
    }
    return st;
}
